/**
 * p2-es (the maintained ES module fork of p2.js). Settings: p2's defaults (GS solver with 10
 * iterations, SAP broad phase, contact stiffness 1e6 and relaxation 4, no sleeping), except that the
 * per-body damping p2 adds by default (0.1 linear and angular) is set to 0, as no other engine damps
 * by default, and joints do not collide their bodies. p2 takes a mass per body, not a density: the
 * mass is density times area summed over the body's shapes. p2 has no per-shape friction: each
 * distinct (friction, restitution) pair of the scene becomes a Material, with a ContactMaterial per
 * pair of them using Box2D's mixing (friction sqrt(a * b), restitution max(a, b)).
 * Units: metres, kilograms, seconds, radians, y up, like the scenes. Bullets are not mapped.
 * Collision filters: category and mask bits as each shape's collisionGroup and collisionMask.
 */
import {
  Body,
  Box,
  Capsule,
  Circle,
  ContactMaterial,
  Convex,
  Line,
  Material,
  RevoluteConstraint,
  type Shape,
  World,
} from 'p2-es';
import { bodyMass } from '../../scenes/mass';
import type { Scene, SceneShape } from '../../scenes/types';
import { type EngineAdapter, unsupportedJoint } from '../adapter';

interface Placed {
  shape: Shape;
  offset: [number, number];
  angle: number;
}

function place(shape: SceneShape): Placed {
  switch (shape.kind) {
    case 'circle': {
      const c = shape.center ?? { x: 0, y: 0 };
      return { shape: new Circle({ radius: shape.radius }), offset: [c.x, c.y], angle: 0 };
    }
    case 'box': {
      const c = shape.center ?? { x: 0, y: 0 };
      const box = new Box({ width: 2 * shape.halfWidth, height: 2 * shape.halfHeight });
      return { shape: box, offset: [c.x, c.y], angle: shape.angle ?? 0 };
    }
    case 'polygon':
      return {
        shape: new Convex({ vertices: shape.points.map((p) => [p.x, p.y]) }),
        offset: [0, 0],
        angle: 0,
      };
    case 'capsule':
    case 'segment': {
      const dx = shape.p2.x - shape.p1.x;
      const dy = shape.p2.y - shape.p1.y;
      const length = Math.hypot(dx, dy);
      const placed =
        shape.kind === 'capsule' ? new Capsule({ length, radius: shape.radius }) : new Line({ length });
      const offset: [number, number] = [(shape.p1.x + shape.p2.x) / 2, (shape.p1.y + shape.p2.y) / 2];
      return { shape: placed, offset, angle: Math.atan2(dy, dx) };
    }
  }
}

const p2Types = { static: Body.STATIC, kinematic: Body.KINEMATIC, dynamic: Body.DYNAMIC } as const;

export class P2Adapter implements EngineAdapter {
  readonly settings = 'defaults (GS 10 iterations, SAP broad phase), body damping 0, no sleep';
  private world: World | null = null;
  private bodies: Body[] = [];

  async init(): Promise<void> {}

  build(scene: Scene): void {
    const world = new World({ gravity: [scene.gravity.x, scene.gravity.y] });
    this.world = world;
    const material = this.materials(scene, world);
    this.bodies = scene.bodies.map((b) => {
      const v = b.linearVelocity ?? { x: 0, y: 0 };
      const body = new Body({
        type: p2Types[b.type],
        mass: b.type === 'dynamic' ? bodyMass(b) : 0,
        position: [b.position.x, b.position.y],
        angle: b.angle ?? 0,
        velocity: [v.x, v.y],
        angularVelocity: b.angularVelocity ?? 0,
        damping: 0,
        angularDamping: 0,
        allowSleep: false,
      });
      for (const shape of b.shapes) {
        const placed = place(shape);
        placed.shape.material = material(shape);
        if (shape.filter) {
          placed.shape.collisionGroup = shape.filter.categoryBits;
          placed.shape.collisionMask = shape.filter.maskBits;
        }
        body.addShape(placed.shape, placed.offset, placed.angle);
      }
      body.updateMassProperties();
      world.addBody(body);
      return body;
    });
    for (const j of scene.joints) {
      if (j.type !== 'revolute') unsupportedJoint('p2', j.type);
      const constraint = new RevoluteConstraint(this.bodies[j.bodyA], this.bodies[j.bodyB], {
        worldPivot: [j.anchor.x, j.anchor.y],
        collideConnected: j.collideConnected ?? false,
      });
      world.addConstraint(constraint);
    }
  }

  /** one Material per distinct (friction, restitution) and a ContactMaterial for every pair of them */
  private materials(scene: Scene, world: World): (shape: SceneShape) => Material {
    const byKey = new Map<string, { material: Material; friction: number; restitution: number }>();
    const key = (s: SceneShape) => `${s.friction ?? 0.6}/${s.restitution ?? 0}`;
    for (const b of scene.bodies) {
      for (const s of b.shapes) {
        if (!byKey.has(key(s))) {
          byKey.set(key(s), {
            material: new Material(),
            friction: s.friction ?? 0.6,
            restitution: s.restitution ?? 0,
          });
        }
      }
    }
    const all = [...byKey.values()];
    for (let i = 0; i < all.length; i++) {
      for (let k = i; k < all.length; k++) {
        const a = all[i];
        const b = all[k];
        world.addContactMaterial(
          new ContactMaterial(a.material, b.material, {
            friction: Math.sqrt(a.friction * b.friction),
            restitution: Math.max(a.restitution, b.restitution),
          }),
        );
      }
    }
    return (shape) => byKey.get(key(shape))!.material;
  }

  step(dt: number): void {
    this.world!.step(dt);
  }

  readTransforms(out: Float64Array): void {
    for (let i = 0; i < this.bodies.length; i++) {
      const body = this.bodies[i];
      out[3 * i] = body.position[0];
      out[3 * i + 1] = body.position[1];
      out[3 * i + 2] = body.angle;
    }
  }

  dispose(): void {
    this.world = null;
    this.bodies = [];
  }
}
