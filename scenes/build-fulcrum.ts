/** Builds a scene in Fulcrum through its public API (../shared/API.md). */
import { Shape, type ShapeDef, World } from '../src/index';
import type { Scene, SceneBody, SceneShape } from './types';

type WorldDef = NonNullable<ConstructorParameters<typeof World>[0]>;
type FulcrumBody = ReturnType<World['createBody']>;
type FulcrumJoint = ReturnType<World['createJoint']>;

export interface FulcrumScene {
  world: World;
  /** in the order of `scene.bodies` */
  bodies: FulcrumBody[];
  /** in the order of `scene.joints` */
  joints: FulcrumJoint[];
}

function geometry(shape: SceneShape) {
  switch (shape.kind) {
    case 'circle':
      return Shape.circle(shape.radius, shape.center);
    case 'box':
      return Shape.box(shape.halfWidth, shape.halfHeight, shape.center, shape.angle);
    case 'polygon':
      return Shape.polygon(shape.points, shape.radius);
    case 'capsule':
      return Shape.capsule(shape.p1, shape.p2, shape.radius);
    case 'segment':
      return Shape.segment(shape.p1, shape.p2);
  }
}

type Material = Pick<ShapeDef, 'density' | 'friction' | 'restitution' | 'filter'>;

/** only the material and filter fields the scene sets, so Fulcrum's defaults apply to the rest */
function material(shape: SceneShape): Material {
  const def: Material = {};
  if (shape.density !== undefined) def.density = shape.density;
  if (shape.friction !== undefined) def.friction = shape.friction;
  if (shape.restitution !== undefined) def.restitution = shape.restitution;
  if (shape.filter !== undefined) def.filter = { ...shape.filter };
  return def;
}

/** One body of a scene, with its shapes, in `world` (also for bodies added to a running world). */
export function createSceneBody(world: World, b: SceneBody): FulcrumBody {
  const body = world.createBody({
    type: b.type,
    position: b.position,
    angle: b.angle ?? 0,
    linearVelocity: b.linearVelocity ?? { x: 0, y: 0 },
    angularVelocity: b.angularVelocity ?? 0,
    bullet: b.bullet ?? false,
  });
  for (const shape of b.shapes) body.createShape(geometry(shape), material(shape));
  return body;
}

/** `worldDef` overrides the scene's settings (e.g. `{ enableSleep: false }` for benchmarks) */
export function buildFulcrumWorld(scene: Scene, worldDef: WorldDef = {}): FulcrumScene {
  const world = new World({ gravity: scene.gravity, ...worldDef });
  const bodies = scene.bodies.map((b) => createSceneBody(world, b));
  const joints = scene.joints.map((j) => {
    const bodyA = bodies[j.bodyA];
    const bodyB = bodies[j.bodyB];
    if (j.type === 'revolute') {
      return world.createJoint({
        type: 'revolute',
        bodyA,
        bodyB,
        anchor: j.anchor,
        collideConnected: j.collideConnected ?? false,
        enableLimit: j.limit !== undefined,
        lowerAngle: j.limit?.lower ?? 0,
        upperAngle: j.limit?.upper ?? 0,
      });
    }
    if (j.type === 'wheel') {
      return world.createJoint({
        type: 'wheel',
        bodyA,
        bodyB,
        anchor: j.anchor,
        axis: j.axis,
        enableSpring: true,
        hertz: j.spring.hertz,
        dampingRatio: j.spring.dampingRatio,
        enableMotor: j.motor !== undefined,
        motorSpeed: j.motor?.speed ?? 0,
        maxMotorTorque: j.motor?.maxTorque ?? 0,
      });
    }
    return world.createJoint({
      type: 'distance',
      bodyA,
      bodyB,
      localAnchorA: bodyA.getLocalPoint(j.anchorA),
      localAnchorB: bodyB.getLocalPoint(j.anchorB),
      length: j.length ?? Math.hypot(j.anchorB.x - j.anchorA.x, j.anchorB.y - j.anchorA.y),
      collideConnected: j.collideConnected ?? false,
      enableSpring: j.spring !== undefined,
      hertz: j.spring?.hertz ?? 0,
      dampingRatio: j.spring?.dampingRatio ?? 0,
    });
  });
  return { world, bodies, joints };
}
