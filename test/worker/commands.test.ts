import { describe, expect, it } from 'vitest';
import {
  type Body,
  type ContactPointData,
  FulcrumError,
  type Geometry,
  Shape,
  type ShapeHandle,
  stateHash,
  type Vec2,
  World,
} from '../../src/index';
import { type WorkerBody, type WorkerShape, WorkerWorld } from '../../src/worker/index';
import { fulcrumErrorMessage } from '../helpers/rejects';
import { workerScript, workerWorlds } from '../helpers/worker-script';

/*
 * The settings commands of fulcrum/worker (body damping, gravity scale, flags and mass data; shape
 * friction, restitution, density, filter, sensor and hit events; every joint type's setters) against
 * World: the same calls give the same bits and the same reads, and each call changes the world (a
 * run without it ends elsewhere), so that a command the worker dropped would show. Bad values throw
 * World's FulcrumError at the call and queue nothing.
 */

const { open, keep } = workerWorlds();

/** The joint setters of every type, as World's joint classes and WorkerJoint both have them. */
interface JointLike {
  setTarget(target: { x: number; y: number }): void;
  enableMotor(enable: boolean): void;
  setMotorSpeed(speed: number): void;
  setMaxMotorTorque(torque: number): void;
  setMaxMotorForce(force: number): void;
  enableLimit(enable: boolean): void;
  setLimits(lower: number, upper: number): void;
  enableSpring(enable: boolean): void;
  setSpring(hertz: number, dampingRatio: number): void;
  setLength(length: number): void;
  setLengthRange(minLength: number, maxLength: number): void;
  setStiffness(linearHertz: number, angularHertz: number, dampingRatio: number): void;
  setLinearOffset(offset: { x: number; y: number }): void;
  setAngularOffset(angle: number): void;
  setMaxForce(force: number): void;
  setMaxTorque(torque: number): void;
}

/** A scene with a body or joint for each command to act on; `kicked` are pushed at every stage. */
function build(w: World) {
  const body = (
    x: number,
    y: number,
    geometry: Geometry = Shape.box(0.5, 0.5),
    type: 'dynamic' | 'static' = 'dynamic',
  ) => {
    const b = w.createBody({ type, position: { x, y } });
    const shape = b.createShape(geometry);
    return { b, shape };
  };
  const joint = (def: Record<string, unknown>) => w.createJoint(def as never) as unknown as JointLike;
  const ground = body(0, -0.5, Shape.box(40, 0.5), 'static').b;
  const pivot = body(0, 12, Shape.circle(0.1), 'static').b;
  const crate = body(-8, 3).b;
  const puck = body(-5, 0.5);
  const fallThrough = body(-3, 1, Shape.circle(0.4));
  const ghost = body(-1.5, 1, Shape.circle(0.4));
  const sleeper = body(-16, 0.5).b;
  const link = body(2, 12, Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.2)).b;
  const sliding = body(5, 8, Shape.box(0.3, 0.3)).b;
  const wheel = body(8, 8, Shape.circle(0.4)).b;
  const ropeA = body(-12, 8, Shape.circle(0.3), 'static').b;
  const ropeB = body(-12, 6, Shape.circle(0.3)).b;
  const weldA = body(12, 4).b;
  const weldB = body(13, 4).b;
  const driven = body(-14, 1).b;
  const dragged = body(16, 1).b;
  const plank = body(25, 1.5, Shape.box(0.05, 1.5)).b;
  const shot = body(20, 1.5, Shape.circle(0.1)).b;
  const joints = {
    revolute: joint({
      type: 'revolute',
      bodyA: pivot,
      bodyB: link,
      anchor: { x: 0, y: 12 },
      motorSpeed: 2,
      maxMotorTorque: 100,
      lowerAngle: -0.3,
      upperAngle: 0.3,
      hertz: 2,
      dampingRatio: 0.1,
    }),
    prismatic: joint({
      type: 'prismatic',
      bodyA: pivot,
      bodyB: sliding,
      anchor: { x: 5, y: 8 },
      axis: { x: 1, y: 0 },
      motorSpeed: 1,
      maxMotorForce: 50,
      lower: -1,
      upper: 1,
      hertz: 2,
      dampingRatio: 0.1,
    }),
    wheel: joint({
      type: 'wheel',
      bodyA: pivot,
      bodyB: wheel,
      anchor: { x: 8, y: 8 },
      axis: { x: 0, y: 1 },
      motorSpeed: 5,
      maxMotorTorque: 20,
      lower: -0.1,
      upper: 0.1,
    }),
    distance: joint({ type: 'distance', bodyA: ropeA, bodyB: ropeB, hertz: 2, dampingRatio: 0.1 }),
    weld: joint({ type: 'weld', bodyA: weldA, bodyB: weldB, anchor: { x: 12.5, y: 4 } }),
    motor: joint({ type: 'motor', bodyA: ground, bodyB: driven, maxForce: 100, maxTorque: 50 }),
    mouse: joint({ type: 'mouse', body: dragged, target: { x: 16, y: 1 } }),
  };
  const kicked = [crate, link, sliding, wheel, ropeB, weldA, driven];
  return { crate, puck, fallThrough, ghost, sleeper, plank, shot, joints, kicked };
}

type Scene = ReturnType<typeof build>;

/** Each command under test, in the order the run gives them; `also` is given in every run. */
const STAGES: { name: string; command: (s: Scene) => void; also?: (s: Scene) => void }[] = [
  { name: 'setLinearDamping', command: (s) => s.crate.setLinearDamping(3) },
  { name: 'setAngularDamping', command: (s) => s.crate.setAngularDamping(4) },
  { name: 'setGravityScale', command: (s) => s.crate.setGravityScale(0.25) },
  { name: 'setFixedRotation', command: (s) => s.crate.setFixedRotation(true) },
  {
    name: 'setMassData',
    command: (s) => s.crate.setMassData({ mass: 5, inertia: 2, center: { x: 0.2, y: 0.1 } }),
  },
  { name: 'resetMassData', command: (s) => s.crate.resetMassData() },
  { name: 'setMassData without a centre', command: (s) => s.crate.setMassData({ mass: 0.5, inertia: 0.1 }) },
  { name: 'setFixedRotation false', command: (s) => s.crate.setFixedRotation(false) },
  {
    name: 'setBullet',
    command: (s) => s.shot.setBullet(true),
    also: (s) => s.shot.setLinearVelocity({ x: 400, y: 0 }),
  },
  { name: 'setAllowSleep', command: (s) => s.sleeper.setAllowSleep(false) },
  {
    name: 'friction',
    command: (s) => {
      s.puck.shape.friction = 0;
    },
    also: (s) => s.puck.b.setLinearVelocity({ x: 4, y: 0 }),
  },
  {
    name: 'restitution',
    command: (s) => {
      s.puck.shape.restitution = 0.9;
    },
    also: (s) => s.puck.b.setLinearVelocity({ x: 0, y: -5 }),
  },
  {
    name: 'density',
    command: (s) => {
      s.puck.shape.density = 7;
    },
    also: (s) => s.puck.b.applyLinearImpulse({ x: 2, y: 0 }),
  },
  {
    name: 'filter',
    command: (s) => {
      s.fallThrough.shape.filter = { categoryBits: 2, maskBits: 0xfffffffe };
    },
  },
  {
    name: 'isSensor',
    command: (s) => {
      s.ghost.shape.isSensor = true;
    },
  },
  { name: 'revolute enableMotor', command: (s) => s.joints.revolute.enableMotor(true) },
  { name: 'revolute setMotorSpeed', command: (s) => s.joints.revolute.setMotorSpeed(-3) },
  { name: 'revolute setMaxMotorTorque', command: (s) => s.joints.revolute.setMaxMotorTorque(3) },
  { name: 'revolute enableLimit', command: (s) => s.joints.revolute.enableLimit(true) },
  { name: 'revolute setLimits', command: (s) => s.joints.revolute.setLimits(-1, 1) },
  { name: 'revolute enableSpring', command: (s) => s.joints.revolute.enableSpring(true) },
  { name: 'revolute setSpring', command: (s) => s.joints.revolute.setSpring(5, 0.5) },
  { name: 'prismatic enableMotor', command: (s) => s.joints.prismatic.enableMotor(true) },
  { name: 'prismatic setMotorSpeed', command: (s) => s.joints.prismatic.setMotorSpeed(-2) },
  { name: 'prismatic setMaxMotorForce', command: (s) => s.joints.prismatic.setMaxMotorForce(5) },
  { name: 'prismatic enableLimit', command: (s) => s.joints.prismatic.enableLimit(true) },
  { name: 'prismatic setLimits', command: (s) => s.joints.prismatic.setLimits(-0.2, 0.2) },
  { name: 'prismatic enableSpring', command: (s) => s.joints.prismatic.enableSpring(true) },
  { name: 'prismatic setSpring', command: (s) => s.joints.prismatic.setSpring(4, 0.2) },
  { name: 'wheel enableMotor', command: (s) => s.joints.wheel.enableMotor(true) },
  { name: 'wheel setMotorSpeed', command: (s) => s.joints.wheel.setMotorSpeed(-5) },
  { name: 'wheel setMaxMotorTorque', command: (s) => s.joints.wheel.setMaxMotorTorque(2) },
  { name: 'wheel enableLimit', command: (s) => s.joints.wheel.enableLimit(true) },
  { name: 'wheel setLimits', command: (s) => s.joints.wheel.setLimits(-0.03, 0.03) },
  { name: 'wheel setSpring', command: (s) => s.joints.wheel.setSpring(3, 0.5) },
  { name: 'wheel enableSpring', command: (s) => s.joints.wheel.enableSpring(false) },
  { name: 'distance setLength', command: (s) => s.joints.distance.setLength(3) },
  { name: 'distance enableSpring', command: (s) => s.joints.distance.enableSpring(true) },
  { name: 'distance setSpring', command: (s) => s.joints.distance.setSpring(1, 0.05) },
  { name: 'distance setLengthRange', command: (s) => s.joints.distance.setLengthRange(2.9, 3.05) },
  { name: 'weld setStiffness', command: (s) => s.joints.weld.setStiffness(2, 1, 0.1) },
  { name: 'motor setLinearOffset', command: (s) => s.joints.motor.setLinearOffset({ x: 1, y: 2 }) },
  { name: 'motor setAngularOffset', command: (s) => s.joints.motor.setAngularOffset(0.5) },
  { name: 'motor setMaxForce', command: (s) => s.joints.motor.setMaxForce(5) },
  { name: 'motor setMaxTorque', command: (s) => s.joints.motor.setMaxTorque(0.5) },
  { name: 'mouse setTarget', command: (s) => s.joints.mouse.setTarget({ x: 17, y: 3 }) },
];

const STAGE_STEPS = 20;

/** Every read a body has that the commands change, as numbers (exact bits compared). */
function bodyReads(body: Body | WorkerBody): number[] {
  const c = body.localCenter;
  return [
    body.mass,
    body.inertia,
    c.x,
    c.y,
    body.linearDamping,
    body.angularDamping,
    body.gravityScale,
    body.fixedRotation ? 1 : 0,
    body.bullet ? 1 : 0,
    body.allowSleep ? 1 : 0,
    body.isAwake ? 1 : 0,
  ];
}

function shapeReads(shape: ShapeHandle | WorkerShape): number[] {
  const f = shape.filter;
  return [
    shape.friction,
    shape.restitution,
    shape.density,
    f.categoryBits,
    f.maskBits,
    f.groupIndex,
    shape.isSensor ? 1 : 0,
    shape.enableHitEvents ? 1 : 0,
  ];
}

function sameBits(a: number[], b: number[]): boolean {
  return a.length === b.length && a.every((x, i) => Object.is(x, b[i]));
}

/**
 * Runs the stages on `world` (or those up to `skip`, without its command), STAGE_STEPS steps each
 * after its command and the kicks; `after(stage, scene)` after each stage's steps.
 */
async function run(world: World, after: (stage: number, scene: Scene) => unknown, skip = -1): Promise<Scene> {
  const scene = build(world);
  for (let i = 0; i < STAGES.length; i++) {
    const stage = STAGES[i];
    if (i !== skip) stage.command(scene);
    stage.also?.(scene);
    for (const body of scene.kicked) {
      body.applyLinearImpulse({ x: 0.4, y: 1.5 });
      body.applyAngularImpulse(0.05);
    }
    for (let k = 0; k < STAGE_STEPS; k++) await world.step(1 / 60);
    await after(i, scene);
    if (i === skip) break;
  }
  return scene;
}

describe('WorkerWorld settings commands', () => {
  it('give the same bits and reads as World, and each changes the world', async () => {
    const local = new World();
    const localHashes: number[] = [];
    const localReads: number[][] = [];
    await run(local, (_, s) => {
      localHashes.push(stateHash(local));
      localReads.push([
        ...[s.crate, s.sleeper, s.shot, s.puck.shape.body].flatMap(bodyReads),
        ...[s.puck.shape, s.fallThrough.shape, s.ghost.shape].flatMap(shapeReads),
      ]);
    });

    const remote = await open();
    const remoteHashes: number[] = [];
    const remoteReads: number[][] = [];
    await run(remote as unknown as World, async (_, s) => {
      remoteHashes.push(await remote.stateHash());
      remoteReads.push([
        ...[s.crate, s.sleeper, s.shot, s.puck.shape.body].flatMap(bodyReads),
        ...[s.puck.shape, s.fallThrough.shape, s.ghost.shape].flatMap(shapeReads),
      ]);
    });

    expect(remoteHashes).toEqual(localHashes);
    for (let i = 0; i < STAGES.length; i++) {
      expect(sameBits(remoteReads[i], localReads[i]), STAGES[i].name).toBe(true);
    }

    // each command matters: without it, the world is elsewhere by the end of its stage
    const unchanged: string[] = [];
    for (let skip = 0; skip < STAGES.length; skip++) {
      const without = new World();
      let hash = 0;
      await run(
        without,
        (stage) => {
          if (stage === skip) hash = stateHash(without);
        },
        skip,
      );
      if (hash === localHashes[skip]) unchanged.push(STAGES[skip].name);
    }
    expect(unchanged).toEqual([]);
  });
});

describe('WorkerWorld settings commands with bad values', () => {
  it('throw World’s FulcrumError at the call, naming the argument and the value, and queue nothing', async () => {
    const local = new World();
    const remote = await open();
    const make = (w: World) => {
      const s = build(w);
      const gone = w.createBody({ type: 'dynamic' });
      const goneShape = gone.createShape(Shape.circle(1));
      const goneJoint = w.createJoint({
        type: 'revolute',
        bodyA: s.crate,
        bodyB: s.sleeper,
      }) as unknown as JointLike;
      w.destroyJoint(goneJoint as never);
      w.destroyBody(gone);
      return { ...s, gone, goneShape, goneJoint };
    };
    const L = make(local);
    const R = make(remote as unknown as World);
    const set = (target: object, key: string, value: unknown) => () => {
      (target as Record<string, unknown>)[key] = value;
    };
    // each call with what its message must name: the argument, and the value given
    const calls: [string, (x: typeof L) => unknown][] = [
      ['linearDamping', (x) => x.crate.setLinearDamping(-1)],
      ['linearDamping', (x) => x.crate.setLinearDamping(Number.NaN)],
      ['angularDamping', (x) => x.crate.setAngularDamping(Number.POSITIVE_INFINITY)],
      ['gravityScale', (x) => x.crate.setGravityScale(Number.NaN)],
      ['fixedRotation', (x) => x.crate.setFixedRotation('yes' as never)],
      ['bullet', (x) => x.crate.setBullet(1 as never)],
      ['allowSleep', (x) => x.crate.setAllowSleep(null as never)],
      ['massData', (x) => x.crate.setMassData(null as never)],
      ['massData.mass', (x) => x.crate.setMassData({ mass: 0, inertia: 1 })],
      ['massData.inertia', (x) => x.crate.setMassData({ mass: 1, inertia: -1 })],
      [
        'massData.center',
        (x) => x.crate.setMassData({ mass: 1, inertia: 1, center: { x: Number.NaN, y: 0 } }),
      ],
      [
        'massData has an unknown option "weight"',
        (x) => x.crate.setMassData({ mass: 1, inertia: 1, weight: 2 } as never),
      ],
      ['body has been destroyed', (x) => x.gone.setMassData({ mass: 1, inertia: 1 })],
      ['body has been destroyed', (x) => x.gone.setLinearDamping(1)],
      ['body has been destroyed', (x) => x.gone.resetMassData()],
      ['friction', (x) => set(x.puck.shape, 'friction', -1)()],
      ['restitution', (x) => set(x.puck.shape, 'restitution', Number.NaN)()],
      ['density', (x) => set(x.puck.shape, 'density', -2)()],
      ['filter.groupIndex', (x) => set(x.puck.shape, 'filter', { groupIndex: 0.5 })()],
      ['filter.maskBits', (x) => set(x.puck.shape, 'filter', { maskBits: -1 })()],
      ['filter', (x) => set(x.puck.shape, 'filter', null)()],
      ['filter has an unknown option "categories"', (x) => set(x.puck.shape, 'filter', { categories: 1 })()],
      ['isSensor', (x) => set(x.puck.shape, 'isSensor', 'no')()],
      ['enableHitEvents', (x) => set(x.puck.shape, 'enableHitEvents', 0)()],
      ['shape has been destroyed', (x) => set(x.goneShape, 'friction', 1)()],
      ['enable', (x) => x.joints.revolute.enableMotor('on' as never)],
      ['speed', (x) => x.joints.revolute.setMotorSpeed(Number.NaN)],
      ['torque', (x) => x.joints.revolute.setMaxMotorTorque(-1)],
      ['lowerAngle', (x) => x.joints.revolute.setLimits(1, -1)],
      ['lowerAngle', (x) => x.joints.revolute.setLimits(Number.NaN, 0)],
      ['hertz', (x) => x.joints.revolute.setSpring(-1, 0)],
      ['dampingRatio', (x) => x.joints.revolute.setSpring(1, -1)],
      ['force', (x) => x.joints.prismatic.setMaxMotorForce(-5)],
      ['lower', (x) => x.joints.prismatic.setLimits(2, 1)],
      ['enable', (x) => x.joints.wheel.enableLimit(null as never)],
      ['upper', (x) => x.joints.wheel.setLimits(0, Number.POSITIVE_INFINITY)],
      ['length', (x) => x.joints.distance.setLength(-1)],
      ['minLength', (x) => x.joints.distance.setLengthRange(3, 2)],
      ['maxLength', (x) => x.joints.distance.setLengthRange(1, Number.NaN)],
      ['angularHertz', (x) => x.joints.weld.setStiffness(1, Number.NaN, 0)],
      ['offset', (x) => x.joints.motor.setLinearOffset({ x: Number.NaN, y: 0 })],
      ['angle', (x) => x.joints.motor.setAngularOffset(Number.POSITIVE_INFINITY)],
      ['force', (x) => x.joints.motor.setMaxForce(-1)],
      ['torque', (x) => x.joints.motor.setMaxTorque(Number.NaN)],
      ['target', (x) => x.joints.mouse.setTarget({ x: Number.POSITIVE_INFINITY, y: 0 })],
      ['joint has been destroyed', (x) => x.goneJoint.setMotorSpeed(1)],
      // World checks the speed before it looks at the joint
      ['speed', (x) => x.goneJoint.setMotorSpeed(Number.NaN)],
    ];
    const before = [L, R].map((x) => [
      ...[x.crate, x.sleeper].flatMap(bodyReads),
      ...[x.puck.shape, x.fallThrough.shape].flatMap(shapeReads),
    ]);
    for (const [named, call] of calls) {
      const expected = fulcrumErrorMessage(() => call(L));
      expect(expected).toContain(named);
      if (!/destroyed|unknown option/.test(named)) expect(expected).toMatch(/got /);
      expect(() => call(R)).toThrow(expected);
      try {
        call(R);
      } catch (e) {
        expect(e).toBeInstanceOf(FulcrumError);
      }
    }
    // a setter of another joint type: World's joint has no such method; a WorkerJoint says so
    expect(() => R.joints.distance.setMotorSpeed(1)).toThrow(
      'setMotorSpeed: a distance joint has no setMotorSpeed()',
    );
    expect(() => R.joints.revolute.setLength(1)).toThrow(FulcrumError);
    // nothing changed, here or in the worker
    const after = [L, R].map((x) => [
      ...[x.crate, x.sleeper].flatMap(bodyReads),
      ...[x.puck.shape, x.fallThrough.shape].flatMap(shapeReads),
    ]);
    expect(sameBits(after[1], before[1])).toBe(true);
    for (let i = 0; i < 30; i++) {
      local.step(1 / 60);
      await remote.step(1 / 60);
    }
    expect(await remote.stateHash()).toBe(stateHash(local));
    expect(sameBits(after[0], before[0])).toBe(true);
  });
});

describe('WorkerBody.getContacts', () => {
  it('answers what World’s does, after the commands before it', async () => {
    const local = new World();
    const remote = await open();
    const make = (w: World) => {
      const ground = w.createBody();
      const groundShape = ground.createShape(Shape.box(10, 0.5));
      const box = w.createBody({ type: 'dynamic', position: { x: 0, y: 1 }, angle: 0.1 });
      const boxShape = box.createShape(Shape.box(0.5, 0.5));
      const ball = w.createBody({ type: 'dynamic', position: { x: 0.2, y: 2.2 } });
      const ballShape = ball.createShape(Shape.circle(0.4));
      return { bodies: [ground, box, ball], shapes: [groundShape, boxShape, ballShape] };
    };
    const L = make(local);
    const R = make(remote as unknown as World);
    for (let i = 0; i < 60; i++) {
      local.step(1 / 60);
      await remote.step(1 / 60);
    }
    /** A body's contacts as numbers: shape indices, normal, and each point's numbers. */
    const flat = (
      contacts: { shapeA: unknown; shapeB: unknown; normal: Vec2; points: ContactPointData[] }[],
      shapes: unknown[],
    ) =>
      contacts.flatMap((c) => [
        shapes.indexOf(c.shapeA),
        shapes.indexOf(c.shapeB),
        c.normal.x,
        c.normal.y,
        ...c.points.flatMap((p) => [p.point.x, p.point.y, p.separation, p.normalImpulse]),
      ]);
    for (let i = 0; i < 3; i++) {
      const expected = flat(L.bodies[i].getContacts(), L.shapes);
      const got = flat(await (R.bodies[i] as unknown as WorkerBody).getContacts(), R.shapes);
      expect(sameBits(got, expected)).toBe(true);
    }
    // the box touches the ground and the ball: two contacts of two points and one
    expect(L.bodies[1].getContacts().map((c) => c.points.length)).toEqual([1, 2]);
    // a shape destroyed since the step: its contacts are gone from the answer, as on World
    L.bodies[2].destroyShape(L.shapes[2]);
    R.bodies[2].destroyShape(R.shapes[2]);
    const expected = flat(L.bodies[1].getContacts(), L.shapes);
    expect(expected.length).toBeGreaterThan(0);
    expect(
      sameBits(flat(await (R.bodies[1] as unknown as WorkerBody).getContacts(), R.shapes), expected),
    ).toBe(true);
    expect(L.bodies[1].getContacts().length).toBe(1);
  });
});

describe('a restored WorkerWorld', () => {
  it('reads the settings and mass data the snapshot holds, as World.restore’s world does', async () => {
    const remote = await open();
    // the first half of the stages: settings changed on bodies, shapes and joints
    await run(remote as unknown as World, () => {}, 20);
    const bytes = await remote.snapshot();
    const local = World.restore(bytes);
    const restored = await WorkerWorld.restore(bytes, { url: workerScript() });
    keep(restored);
    const localBodies = [...local.bodies];
    const restoredBodies = [...restored.bodies];
    expect(restoredBodies.length).toBe(localBodies.length);
    const all = (bodies: (Body | WorkerBody)[]) =>
      bodies.flatMap((b) => [...bodyReads(b), ...b.shapes.flatMap((s) => shapeReads(s as ShapeHandle))]);
    expect(sameBits(all(restoredBodies), all(localBodies))).toBe(true);
    // the values are the commands' (a crate of mass 0.5 with its rotation free, a sensor, a filter)
    expect(restoredBodies.some((b) => b.mass === 0.5 && b.linearDamping === 3)).toBe(true);
    expect(restoredBodies.some((b) => b.shapes.some((s) => s.isSensor))).toBe(true);
    expect(restoredBodies.some((b) => b.shapes.some((s) => s.filter.categoryBits === 2))).toBe(true);
  });
});
