/**
 * Rapier 2D (@dimforge/rapier2d-compat: WASM inlined as base64, so it loads in Node with no file
 * access). Settings: Rapier's defaults (timestep 1/60 unless the step asks otherwise, 4 solver
 * iterations, 1 internal PGS iteration, friction and restitution combined by averaging), sleeping
 * off per body (setCanSleep(false)), joints with contacts between their bodies disabled.
 * Units: metres, kilograms, seconds, radians, y up, like the scenes. Capsules are Rapier's vertical
 * capsule, turned and moved onto the scene's segment.
 * Collision filters: category and mask bits as collision groups (membership << 16 | filter; the
 * scenes' bits fit 16).
 */
import RAPIER from '@dimforge/rapier2d-compat';
import type { Scene, SceneBody, SceneShape } from '../../scenes/types';
import { type EngineAdapter, localPoint, unsupportedJoint } from '../adapter';

function colliderDesc(shape: SceneShape): RAPIER.ColliderDesc {
  switch (shape.kind) {
    case 'circle': {
      const c = shape.center ?? { x: 0, y: 0 };
      return RAPIER.ColliderDesc.ball(shape.radius).setTranslation(c.x, c.y);
    }
    case 'box': {
      const c = shape.center ?? { x: 0, y: 0 };
      return RAPIER.ColliderDesc.cuboid(shape.halfWidth, shape.halfHeight)
        .setTranslation(c.x, c.y)
        .setRotation(shape.angle ?? 0);
    }
    case 'polygon': {
      const points = new Float32Array(shape.points.flatMap((p) => [p.x, p.y]));
      const desc = shape.radius
        ? RAPIER.ColliderDesc.roundConvexHull(points, shape.radius)
        : RAPIER.ColliderDesc.convexHull(points);
      if (!desc) throw new Error('rapier: convex hull failed');
      return desc;
    }
    case 'capsule': {
      const dx = shape.p2.x - shape.p1.x;
      const dy = shape.p2.y - shape.p1.y;
      return RAPIER.ColliderDesc.capsule(Math.hypot(dx, dy) / 2, shape.radius)
        .setTranslation((shape.p1.x + shape.p2.x) / 2, (shape.p1.y + shape.p2.y) / 2)
        .setRotation(Math.atan2(dy, dx) - Math.PI / 2);
    }
    case 'segment':
      return RAPIER.ColliderDesc.segment(shape.p1, shape.p2);
  }
}

function bodyDesc(b: SceneBody): RAPIER.RigidBodyDesc {
  const desc =
    b.type === 'dynamic'
      ? RAPIER.RigidBodyDesc.dynamic()
      : b.type === 'kinematic'
        ? RAPIER.RigidBodyDesc.kinematicVelocityBased()
        : RAPIER.RigidBodyDesc.fixed();
  const v = b.linearVelocity ?? { x: 0, y: 0 };
  return desc
    .setTranslation(b.position.x, b.position.y)
    .setRotation(b.angle ?? 0)
    .setLinvel(v.x, v.y)
    .setAngvel(b.angularVelocity ?? 0)
    .setCcdEnabled(b.bullet ?? false)
    .setCanSleep(false);
}

export class RapierAdapter implements EngineAdapter {
  settings = 'defaults, setCanSleep(false)';
  private world: RAPIER.World | null = null;
  private bodies: RAPIER.RigidBody[] = [];

  async init(): Promise<void> {
    await RAPIER.init();
  }

  build(scene: Scene): void {
    this.dispose();
    const world = new RAPIER.World(scene.gravity);
    this.world = world;
    this.settings = `defaults (${world.numSolverIterations} solver iterations, ${world.numInternalPgsIterations} PGS iteration), setCanSleep(false)`;
    this.bodies = scene.bodies.map((b) => {
      const body = world.createRigidBody(bodyDesc(b));
      for (const shape of b.shapes) {
        const desc = colliderDesc(shape)
          .setDensity(shape.density ?? 1)
          .setFriction(shape.friction ?? 0.6)
          .setRestitution(shape.restitution ?? 0);
        // membership in the high 16 bits, filter in the low ones (the scene's filters fit 16 bits)
        if (shape.filter)
          desc.setCollisionGroups(
            ((shape.filter.categoryBits & 0xffff) << 16) | (shape.filter.maskBits & 0xffff),
          );
        world.createCollider(desc, body);
      }
      return body;
    });
    for (const j of scene.joints) {
      if (j.type !== 'revolute') unsupportedJoint('rapier', j.type);
      const a = scene.bodies[j.bodyA];
      const b = scene.bodies[j.bodyB];
      const data = RAPIER.JointData.revolute(localPoint(a, j.anchor), localPoint(b, j.anchor));
      const joint = world.createImpulseJoint(data, this.bodies[j.bodyA], this.bodies[j.bodyB], true);
      joint.setContactsEnabled(j.collideConnected ?? false);
    }
  }

  step(dt: number): void {
    const world = this.world!;
    if (world.timestep !== dt) world.timestep = dt;
    world.step();
  }

  readTransforms(out: Float64Array): void {
    for (let i = 0; i < this.bodies.length; i++) {
      const p = this.bodies[i].translation();
      out[3 * i] = p.x;
      out[3 * i + 1] = p.y;
      out[3 * i + 2] = this.bodies[i].rotation();
    }
  }

  dispose(): void {
    this.world?.free();
    this.world = null;
    this.bodies = [];
  }
}
