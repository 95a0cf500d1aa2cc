/**
 * planck.js (a TypeScript port of Box2D v2.3). Settings: planck's defaults (8 velocity and 3 position
 * iterations per step, warm starting, continuous collision, block solver, polygon skin 0.01 m),
 * allowSleep false. Mixing (planck's own): friction sqrt(a * b), restitution max(a, b).
 * Units: metres, kilograms, seconds, radians, y up, like the scenes. planck has no capsule shape: a
 * capsule is a box plus two end circles at half density, so its mass is exact; its rotational inertia
 * is slightly off. Rounded polygons lose their rounding radius.
 * Collision filters: the scene's category and mask bits as the fixtures' filterCategoryBits and
 * filterMaskBits.
 */
import {
  Box,
  Circle,
  Edge,
  type Body as PlanckBody,
  Polygon,
  RevoluteJoint,
  type Shape,
  World,
} from 'planck';
import type { Scene, SceneShape } from '../../scenes/types';
import { type EngineAdapter, unsupportedJoint } from '../adapter';

interface Part {
  shape: Shape;
  densityScale: number;
}

function parts(shape: SceneShape): Part[] {
  switch (shape.kind) {
    case 'circle':
      return [{ shape: new Circle(shape.center ?? { x: 0, y: 0 }, shape.radius), densityScale: 1 }];
    case 'box':
      return [
        {
          shape: new Box(shape.halfWidth, shape.halfHeight, shape.center, shape.angle ?? 0),
          densityScale: 1,
        },
      ];
    case 'polygon':
      return [{ shape: new Polygon(shape.points), densityScale: 1 }];
    case 'capsule': {
      const dx = shape.p2.x - shape.p1.x;
      const dy = shape.p2.y - shape.p1.y;
      const center = { x: (shape.p1.x + shape.p2.x) / 2, y: (shape.p1.y + shape.p2.y) / 2 };
      const core = new Box(Math.hypot(dx, dy) / 2, shape.radius, center, Math.atan2(dy, dx));
      return [
        { shape: core, densityScale: 1 },
        { shape: new Circle(shape.p1, shape.radius), densityScale: 0.5 },
        { shape: new Circle(shape.p2, shape.radius), densityScale: 0.5 },
      ];
    }
    case 'segment':
      return [{ shape: new Edge(shape.p1, shape.p2), densityScale: 1 }];
  }
}

export class PlanckAdapter implements EngineAdapter {
  readonly settings = 'defaults (8 velocity, 3 position iterations), allowSleep false';
  private world: World | null = null;
  private bodies: PlanckBody[] = [];

  async init(): Promise<void> {}

  build(scene: Scene): void {
    const world = new World({ gravity: scene.gravity, allowSleep: false });
    this.world = world;
    this.bodies = scene.bodies.map((b) => {
      const body = world.createBody({
        type: b.type,
        position: b.position,
        angle: b.angle ?? 0,
        linearVelocity: b.linearVelocity ?? { x: 0, y: 0 },
        angularVelocity: b.angularVelocity ?? 0,
        bullet: b.bullet ?? false,
        allowSleep: false,
      });
      for (const shape of b.shapes) {
        for (const part of parts(shape)) {
          body.createFixture(part.shape, {
            density: (shape.density ?? 1) * part.densityScale,
            friction: shape.friction ?? 0.6,
            restitution: shape.restitution ?? 0,
            filterCategoryBits: shape.filter?.categoryBits ?? 1,
            filterMaskBits: shape.filter?.maskBits ?? 0xffff,
          });
        }
      }
      return body;
    });
    for (const j of scene.joints) {
      if (j.type !== 'revolute') unsupportedJoint('planck', j.type);
      const joint = new RevoluteJoint(
        { collideConnected: j.collideConnected ?? false },
        this.bodies[j.bodyA],
        this.bodies[j.bodyB],
        j.anchor,
      );
      world.createJoint(joint);
    }
  }

  step(dt: number): void {
    this.world!.step(dt);
  }

  readTransforms(out: Float64Array): void {
    for (let i = 0; i < this.bodies.length; i++) {
      const p = this.bodies[i].getPosition();
      out[3 * i] = p.x;
      out[3 * i + 1] = p.y;
      out[3 * i + 2] = this.bodies[i].getAngle();
    }
  }

  dispose(): void {
    this.world = null;
    this.bodies = [];
  }
}
