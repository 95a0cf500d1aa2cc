import { describe, expect, it } from 'vitest';
import {
  type Body,
  FulcrumError,
  type Geometry,
  Shape,
  type ShapeHandle,
  stateHash,
  World,
} from '../../src/index';
import type { WorkerBody, WorkerJoint, WorkerShape } from '../../src/worker/index';
import { WorkerWorld } from '../../src/worker/index';
import { fulcrumErrorMessage } from '../helpers/rejects';
import { workerScript, workerWorlds } from '../helpers/worker-script';

/*
 * What fulcrum/worker's handles have beside World's: body.readState and the frame conversions, the
 * joints' reads (anchors, reaction force and torque, a revolute joint's angle and motor speed, a
 * prismatic or wheel joint's translation, a distance joint's current and rest length), all as of the
 * last step; body.scale and shape.setGeometry as commands. Each is compared with a World given the
 * same calls: the same bits, read for read, and the same state hash.
 */

const { open, keep } = workerWorlds();

/** The joint reads World's joints and WorkerJoint share (each on the types that have it). */
interface JointReads {
  type: string;
  anchorA: { x: number; y: number };
  anchorB: { x: number; y: number };
  getReactionForce(): { x: number; y: number };
  getReactionTorque(): number;
  angle: number;
  translation: number;
  currentLength: number;
  length: number;
  motorSpeed: number;
  setMotorSpeed(speed: number): void;
  setLength(length: number): void;
}

/** A pendulum on a motor, a slider, a wheel, a rope, a weld, a motor joint and a drag, all loaded. */
function build(w: World) {
  const ground = w.createBody({ position: { x: 0, y: -0.5 } });
  ground.createShape(Shape.box(40, 0.5));
  const pivot = w.createBody({ position: { x: 0, y: 12 } });
  pivot.createShape(Shape.circle(0.1));
  const body = (x: number, y: number, angle = 0) => {
    const b = w.createBody({ type: 'dynamic', position: { x, y }, angle });
    b.createShape(Shape.box(0.6, 0.3));
    return b;
  };
  const joint = (def: Record<string, unknown>) => w.createJoint(def as never) as unknown as JointReads;
  const arm = body(2, 12, 0.2);
  const slider = body(5, 8);
  const wheel = body(8, 8);
  const rope = body(-6, 9);
  const weldA = body(12, 4);
  const weldB = body(13.2, 4.1, 0.3);
  const driven = body(-14, 1);
  const dragged = body(16, 1);
  const joints = [
    joint({
      type: 'revolute',
      bodyA: pivot,
      bodyB: arm,
      anchor: { x: 0, y: 12 },
      enableMotor: true,
      motorSpeed: 1.5,
      maxMotorTorque: 40,
    }),
    joint({ type: 'prismatic', bodyA: pivot, bodyB: slider, anchor: { x: 5, y: 8 }, axis: { x: 1, y: 1 } }),
    joint({ type: 'wheel', bodyA: pivot, bodyB: wheel, anchor: { x: 8, y: 8 }, axis: { x: 0, y: 1 } }),
    joint({ type: 'distance', bodyA: pivot, bodyB: rope, localAnchorB: { x: 0.5, y: 0 } }),
    joint({ type: 'weld', bodyA: weldA, bodyB: weldB, anchor: { x: 12.6, y: 4 } }),
    joint({ type: 'motor', bodyA: ground, bodyB: driven, linearOffset: { x: -13, y: 2 }, maxForce: 200 }),
    joint({ type: 'mouse', body: dragged, target: { x: 17, y: 3 } }),
  ];
  return { bodies: [arm, slider, wheel, rope, weldA, weldB, driven, dragged], joints };
}

/** Every read of a joint, as numbers, in a fixed order: those of its type, then the common ones. */
function jointReads(j: JointReads): number[] {
  const own =
    j.type === 'revolute'
      ? [j.angle, j.motorSpeed]
      : j.type === 'prismatic' || j.type === 'wheel'
        ? [j.translation]
        : j.type === 'distance'
          ? [j.currentLength, j.length]
          : [];
  const f = j.getReactionForce();
  return [...own, j.anchorA.x, j.anchorA.y, j.anchorB.x, j.anchorB.y, f.x, f.y, j.getReactionTorque()];
}

/** readState and the frame conversions of a body, as numbers. */
function bodyReads(b: Body | WorkerBody): number[] {
  const state = new Float64Array(10);
  b.readState(state, 2);
  const p = { x: 0.3, y: -0.7 };
  const q = { x: 4, y: 9 };
  const out = [...state];
  for (const v of [
    b.getWorldPoint(p),
    b.getLocalPoint(q),
    b.getWorldVector(p),
    b.getLocalVector(q),
    b.getLinearVelocityAt(q),
  ])
    out.push(v.x, v.y);
  return out;
}

function sameBits(a: number[], b: number[]): boolean {
  return a.length === b.length && a.every((x, i) => Object.is(x, b[i]));
}

describe('WorkerJoint reads', () => {
  it('are World’s reads after each step, bit for bit', async () => {
    const local = new World();
    const remote = await open();
    const L = build(local);
    const R = build(remote as unknown as World);
    // before the reply to the request that made it, a worker joint has no reads yet
    expect(() => R.joints[0].angle).toThrow(FulcrumError);
    expect(() => R.joints[0].getReactionForce()).toThrow(/await a step first/);
    for (let i = 0; i < 90; i++) {
      if (i === 40) {
        for (const s of [L, R]) {
          s.joints[0].setMotorSpeed(-2);
          s.joints[3].setLength(2.5);
        }
        // a setting reads as the command leaves it, at once
        expect(R.joints[0].motorSpeed).toBe(-2);
        expect(R.joints[3].length).toBe(2.5);
      }
      local.step(1 / 60);
      await remote.step(1 / 60);
      if (i % 10 !== 9) continue;
      for (let k = 0; k < L.joints.length; k++) {
        expect(
          sameBits(jointReads(R.joints[k]), jointReads(L.joints[k])),
          `${L.joints[k].type} at ${i}`,
        ).toBe(true);
      }
    }
    expect(await remote.stateHash()).toBe(stateHash(local));
    // the reads are of a loaded, moving world: the arm hangs on the motor, the slider has slid
    expect(Math.abs(R.joints[0].getReactionForce().y)).toBeGreaterThan(1);
    expect(Math.abs(R.joints[0].angle)).toBeGreaterThan(0.1);
    expect(Math.abs(R.joints[1].translation)).toBeGreaterThan(0.1);
    expect(R.joints[3].currentLength).toBeGreaterThan(0);
    // a read its type lacks: World's joint has no such property; a WorkerJoint says so
    expect(() => R.joints[3].angle).toThrow('angle: a distance joint has no angle');
    expect(() => R.joints[0].translation).toThrow(FulcrumError);
    // a destroyed joint's reads throw, as World's do
    local.destroyJoint(L.joints[1] as never);
    remote.destroyJoint(R.joints[1] as unknown as WorkerJoint);
    expect(fulcrumErrorMessage(() => L.joints[1].translation)).toBe('joint has been destroyed');
    expect(() => R.joints[1].translation).toThrow('joint has been destroyed');
  });

  it('of a restored world come with the restore', async () => {
    const remote = await open();
    build(remote as unknown as World);
    for (let i = 0; i < 30; i++) await remote.step(1 / 60);
    const bytes = await remote.snapshot();
    const local = World.restore(bytes);
    const restored = keep(await WorkerWorld.restore(bytes, { url: workerScript() }));
    const reads = (joints: readonly unknown[]) => (joints as JointReads[]).flatMap(jointReads);
    expect(sameBits(reads(restored.joints), reads(local.joints))).toBe(true);
  });
});

describe('WorkerBody reads', () => {
  it('readState and the frame conversions are World’s after each step, bit for bit', async () => {
    const local = new World();
    const remote = await open();
    const L = build(local);
    const R = build(remote as unknown as World);
    for (let i = 0; i < 40; i++) {
      local.step(1 / 60);
      await remote.step(1 / 60);
      if (i % 13 !== 0) continue;
      for (let k = 0; k < L.bodies.length; k++) {
        expect(sameBits(bodyReads(R.bodies[k] as unknown as WorkerBody), bodyReads(L.bodies[k]))).toBe(true);
      }
    }
    // bad input: World's message, at the call
    for (const call of [
      (b: Body) => b.getWorldPoint({ x: Number.NaN, y: 0 }),
      (b: Body) => b.getLocalVector(null as never),
      (b: Body) => b.getLinearVelocityAt({ x: 0, y: Number.POSITIVE_INFINITY }),
    ]) {
      const message = fulcrumErrorMessage(() => call(L.bodies[0]));
      expect(() => call(R.bodies[0])).toThrow(message);
    }
  });
});

/** getAABB, testPoint at a few points and rayCast of a shape, as numbers (1/0 for hit or not). */
function shapeReads(shape: ShapeHandle | WorkerShape): number[] {
  const box = shape.getAABB();
  const c = { x: (box.lowerBound.x + box.upperBound.x) / 2, y: (box.lowerBound.y + box.upperBound.y) / 2 };
  const out = [box.lowerBound.x, box.lowerBound.y, box.upperBound.x, box.upperBound.y];
  for (const p of [c, { x: c.x + 0.45, y: c.y + 0.1 }, { x: c.x - 0.7, y: c.y }])
    out.push(shape.testPoint(p) ? 1 : 0);
  for (const [o, t] of [
    [
      { x: c.x - 5, y: c.y + 0.05 },
      { x: 10, y: 0 },
    ],
    [
      { x: c.x + 0.1, y: c.y + 5 },
      { x: 0, y: -10 },
    ],
    [
      { x: c.x - 5, y: c.y + 5 },
      { x: 1, y: 0 },
    ],
  ]) {
    const hit = shape.rayCast(o, t);
    out.push(
      hit === null ? 0 : 1,
      hit?.point.x ?? 0,
      hit?.point.y ?? 0,
      hit?.normal.x ?? 0,
      hit?.normal.y ?? 0,
      hit?.fraction ?? 0,
    );
  }
  return out;
}

describe('WorkerShape reads', () => {
  it('getAABB, testPoint and rayCast are World’s after each step, bit for bit', async () => {
    const local = new World();
    const remote = await open();
    const L = shapes(local);
    const R = shapes(remote as unknown as World);
    const all = (s: Shapes) => [s.crate, s.ball, s.plank].map((x) => x.shape);
    for (let i = 0; i < 45; i++) {
      if (i === 20) for (const s of [L, R]) s.plank.body.scale(1.4);
      local.step(1 / 60);
      await remote.step(1 / 60);
      if (i % 11 !== 0) continue;
      const expected = all(L).flatMap((x) => shapeReads(x));
      expect(
        sameBits(
          all(R).flatMap((x) => shapeReads(x)),
          expected,
        ),
        `step ${i}`,
      ).toBe(true);
    }
    // the rays and points did hit: reads of an empty answer would prove little
    expect(all(R).map((x) => x.testPoint(x.body.worldCenter))).toEqual([true, true, true]);
    for (const x of all(R)) {
      const c = x.body.worldCenter;
      const hit = x.rayCast({ x: c.x, y: c.y + 5 }, { x: 0, y: -10 });
      expect(hit?.normal.y).toBeGreaterThan(0);
    }
    // bad input: World's message, at the call
    for (const call of [
      (x: ShapeHandle) => x.testPoint({ x: Number.NaN, y: 0 }),
      (x: ShapeHandle) => x.rayCast({ x: 0, y: 0 }, null as never),
    ]) {
      const message = fulcrumErrorMessage(() => call(all(L)[0] as ShapeHandle));
      expect(() => call(all(R)[0] as ShapeHandle)).toThrow(message);
    }
  });
});

/** A crate, a ball and a plank on the ground, for the geometry commands. */
function shapes(w: World) {
  const ground = w.createBody();
  ground.createShape(Shape.box(20, 0.5));
  const make = (x: number, geometry: Geometry) => {
    // low enough to land at once: a scale about the centre of mass changes nothing in free fall
    const b = w.createBody({ type: 'dynamic', position: { x, y: 1.2 }, angle: 0.3 });
    return { body: b, shape: b.createShape(geometry) as ShapeHandle | WorkerShape };
  };
  return {
    crate: make(-3, Shape.box(0.5, 0.5)),
    ball: make(0, Shape.circle(0.5)),
    plank: make(3, Shape.box(1.5, 0.2)),
  };
}
type Shapes = ReturnType<typeof shapes>;

/** The geometry commands, in order; each run without one of them ends elsewhere. */
const GEOMETRY_STAGES: [string, (s: Shapes) => void][] = [
  ['scale by one factor', (s) => s.crate.body.scale(1.5)],
  ['scale a circle', (s) => s.ball.body.scale(0.6, { x: 0, y: 0 })],
  ['scale along the axes', (s) => s.plank.body.scale({ x: 1.3, y: 0.8 }, { x: 3, y: 1 })],
  [
    'setGeometry',
    (s) =>
      (s.crate.shape as ShapeHandle).setGeometry(
        Shape.polygon([
          { x: -1, y: -0.4 },
          { x: 1, y: -0.4 },
          { x: 0, y: 0.9 },
        ]),
      ),
  ],
  [
    'setGeometry of a circle',
    (s) => (s.ball.shape as ShapeHandle).setGeometry(Shape.circle(0.8, { x: 0.2, y: 0 })),
  ],
];

async function geometryRun(world: World, skip = -1) {
  const s = shapes(world);
  const hashes: number[] = [];
  const geometries: unknown[] = [];
  const mass: number[] = [];
  for (let i = 0; i < GEOMETRY_STAGES.length; i++) {
    if (i !== skip) GEOMETRY_STAGES[i][1](s);
    for (let k = 0; k < 20; k++) await world.step(1 / 60);
    hashes.push(
      world instanceof World ? stateHash(world) : await (world as unknown as WorkerWorld).stateHash(),
    );
    geometries.push([s.crate, s.ball, s.plank].map((x) => x.shape.geometry));
    mass.push(
      ...[s.crate, s.ball, s.plank].flatMap((x) => [x.body.mass, x.body.inertia, x.body.localCenter.x]),
    );
  }
  return { s, hashes, geometries, mass };
}

describe('WorkerBody.scale and WorkerShape.setGeometry', () => {
  it('give World’s bits, geometries and mass data, and each changes the world', async () => {
    const local = await geometryRun(new World());
    const remote = await geometryRun((await open()) as unknown as World);
    expect(remote.hashes).toEqual(local.hashes);
    expect(remote.geometries).toEqual(local.geometries);
    expect(sameBits(remote.mass, local.mass)).toBe(true);
    for (let skip = 0; skip < GEOMETRY_STAGES.length; skip++) {
      const without = await geometryRun(new World(), skip);
      expect(without.hashes[skip], GEOMETRY_STAGES[skip][0]).not.toBe(local.hashes[skip]);
    }
  });

  it('a geometry given after a scale, while the scale is on its way, is the one that stays', async () => {
    const remote = await open();
    const R = shapes(remote as unknown as World);
    const shape = R.crate.shape as WorkerShape;
    R.crate.body.scale(2);
    const scaled = remote.step(1 / 60);
    const triangle = Shape.polygon([
      { x: -1, y: -0.4 },
      { x: 1, y: -0.4 },
      { x: 0, y: 0.9 },
    ]);
    shape.setGeometry(triangle);
    await scaled;
    expect(shape.geometry).toBe(triangle);
    await remote.step(1 / 60);
    expect(shape.geometry).toBe(triangle);
    // and a scale after it reads the worker's scaled triangle once its step is back: World's
    R.crate.body.scale(0.5);
    await remote.step(1 / 60);
    const local = new World();
    const L = shapes(local);
    L.crate.body.scale(2);
    local.step(1 / 60);
    (L.crate.shape as ShapeHandle).setGeometry(triangle);
    local.step(1 / 60);
    L.crate.body.scale(0.5);
    local.step(1 / 60);
    expect(shape.geometry).not.toBe(triangle);
    expect(shape.geometry).toEqual(L.crate.shape.geometry);
    expect(await remote.stateHash()).toBe(stateHash(local));
  });

  it('refuse bad input with World’s FulcrumError at the call, and queue nothing', async () => {
    const local = new World();
    const remote = await open();
    const L = shapes(local);
    const R = shapes(remote as unknown as World);
    const segment = Shape.segment({ x: 0, y: 0 }, { x: 1, y: 0 });
    const calls: [string, (s: Shapes) => unknown][] = [
      ['factor', (s) => s.crate.body.scale(0)],
      ['factor', (s) => s.crate.body.scale(Number.NaN)],
      ['factor', (s) => s.crate.body.scale({ x: 1, y: Number.POSITIVE_INFINITY })],
      ['factor', (s) => s.crate.body.scale(null as never)],
      ['point', (s) => s.crate.body.scale(2, { x: Number.NaN, y: 0 })],
      // a circle takes one factor only
      ['factor', (s) => s.ball.body.scale({ x: 2, y: 1 })],
      // the body's origin would leave the world's bounds
      ['factor', (s) => s.crate.body.scale(1e9, { x: 1e4, y: 0 })],
      ['geometry', (s) => (s.crate.shape as ShapeHandle).setGeometry(null as never)],
      ['geometry', (s) => (s.crate.shape as ShapeHandle).setGeometry({ type: 'circle', radius: 1 } as never)],
      ['segment', (s) => (s.crate.shape as ShapeHandle).setGeometry(segment)],
    ];
    for (const [named, call] of calls) {
      const message = fulcrumErrorMessage(() => call(L));
      expect(message).toContain(named);
      expect(() => call(R)).toThrow(message);
      try {
        call(R);
      } catch (e) {
        expect(e).toBeInstanceOf(FulcrumError);
      }
    }
    for (let i = 0; i < 30; i++) {
      local.step(1 / 60);
      await remote.step(1 / 60);
    }
    expect(await remote.stateHash()).toBe(stateHash(local));
    expect(R.crate.shape.geometry).toEqual(L.crate.shape.geometry);
  });
});
