import { describe, expect, it } from 'vitest';
import { Limits } from '../../src/core/limits';
import { type Body, FulcrumError, type Joint, Shape, stateHash, World } from '../../src/index';
import { expectRejected } from '../helpers/rejects';

const DT = 1 / 60;

/**
 * A small world with every kind of body and one joint of each type, each on its own (no joint
 * network, whose solver is another matter): the stage for the range tests.
 */
function sampleWorld(def: { lengthUnitsPerMeter?: number } = {}) {
  const world = new World(def);
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  ground.createShape(Shape.box(30, 1));
  const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
  const boxShape = box.createShape(Shape.box(0.5, 0.5), { enableHitEvents: true });
  const kinematic = world.createBody({ type: 'kinematic', position: { x: 4, y: 1 } });
  kinematic.createShape(Shape.box(1, 0.2));
  const rider = world.createBody({ type: 'dynamic', position: { x: 4, y: 1.5 } });
  rider.createShape(Shape.circle(0.3));
  const pair = (x: number): [Body, Body] => {
    const a = world.createBody({ type: 'dynamic', position: { x, y: 4 } });
    a.createShape(Shape.box(0.3, 0.1));
    const b = world.createBody({ type: 'dynamic', position: { x: x + 0.6, y: 4 } });
    b.createShape(Shape.circle(0.2));
    return [a, b];
  };
  const [d, d2] = pair(-12);
  const [r] = pair(-9);
  const [p] = pair(-6);
  const [w] = pair(8);
  const [wh] = pair(11);
  const [m] = pair(14);
  const [mo] = pair(17);
  const joints = {
    distance: world.createJoint({ type: 'distance', bodyA: d, bodyB: d2, enableSpring: true, hertz: 3 }),
    revolute: world.createJoint({
      type: 'revolute',
      bodyA: ground,
      bodyB: r,
      anchor: { x: -9, y: 4 },
      enableLimit: true,
      lowerAngle: -1,
      upperAngle: 1,
      enableMotor: true,
      maxMotorTorque: 10,
    }),
    prismatic: world.createJoint({
      type: 'prismatic',
      bodyA: ground,
      bodyB: p,
      anchor: { x: -6, y: 4 },
      axis: { x: 1, y: 0 },
      enableLimit: true,
      lower: -1,
      upper: 1,
      enableMotor: true,
      maxMotorForce: 10,
    }),
    weld: world.createJoint({
      type: 'weld',
      bodyA: ground,
      bodyB: w,
      anchor: { x: 8, y: 4 },
      linearHertz: 5,
    }),
    wheel: world.createJoint({
      type: 'wheel',
      bodyA: ground,
      bodyB: wh,
      anchor: { x: 11, y: 4 },
      axis: { x: 0, y: 1 },
      enableMotor: true,
      maxMotorTorque: 10,
    }),
    mouse: world.createJoint({ type: 'mouse', body: m, target: { x: 14, y: 6 } }),
    motor: world.createJoint({ type: 'motor', bodyA: ground, bodyB: mo, maxForce: 100, maxTorque: 10 }),
  };
  for (let i = 0; i < 5; i++) world.step(DT);
  return { world, ground, box, boxShape, kinematic, joints, free: [d, d2] as const };
}

type Sample = ReturnType<typeof sampleWorld>;

/** Every body finite, with a unit rotation and under the speed limit; every joint's reaction finite. */
function expectSound(world: World, units = 1, label = ''): void {
  for (const b of world.bodies) {
    const p = b.position;
    const v = b.linearVelocity;
    const q = b.rotation;
    for (const n of [p.x, p.y, v.x, v.y, q.c, q.s, b.angularVelocity])
      expect(Number.isFinite(n), label).toBe(true);
    expect(Math.abs(q.c * q.c + q.s * q.s - 1), label).toBeLessThan(1e-9);
    if (b.isAwake) expect(Math.hypot(v.x, v.y), label).toBeLessThanOrEqual(400 * units * (1 + 1e-12));
  }
  for (const j of world.joints) {
    const f = j.getReactionForce();
    const finite = Number.isFinite(f.x) && Number.isFinite(f.y) && Number.isFinite(j.getReactionTorque());
    expect(finite, `${label} ${j.type}`).toBe(true);
  }
}

const C = Limits.COORDINATE;
const A = Limits.ANGLE;
const R = Limits.RATE;
const F = Limits.FORCE;
/** a little past a bound (the next representable value would do; this reads better in messages) */
const past = (bound: number) => bound * (1 + 1e-9);

/**
 * Each entry that takes a number: its argument's name as the message names it, how to call it, and
 * the bounds of its range (values at the bounds are accepted, values past them refused).
 */
const ENTRIES: [string, (s: Sample, v: number) => unknown, number, number][] = [
  ['gravity', (s, v) => (s.world.gravity = { x: 0, y: v }), -R, R],
  ['dt', (s, v) => s.world.step(v), Limits.MIN_DT, Limits.MAX_DT],
  ['position', (s, v) => s.world.createBody({ type: 'dynamic', position: { x: v, y: 0 } }), -C, C],
  ['angle', (s, v) => s.world.createBody({ type: 'dynamic', angle: v }), -A, A],
  [
    'linearVelocity',
    (s, v) => s.world.createBody({ type: 'kinematic', linearVelocity: { x: v, y: v } }),
    -R,
    R,
  ],
  ['angularVelocity', (s, v) => s.world.createBody({ type: 'kinematic', angularVelocity: v }), -R, R],
  ['linearDamping', (s, v) => s.world.createBody({ type: 'dynamic', linearDamping: v }), 0, R],
  ['angularDamping', (s, v) => s.box.setAngularDamping(v), 0, R],
  ['gravityScale', (s, v) => s.box.setGravityScale(v), -R, R],
  ['position', (s, v) => s.box.setPosition({ x: 0, y: v }), -C, C],
  ['angle', (s, v) => s.box.setAngle(v), -A, A],
  ['angle', (s, v) => s.kinematic.setTransform({ x: 4, y: 1 }, v), -A, A],
  ['velocity', (s, v) => s.kinematic.setLinearVelocity({ x: v, y: 0 }), -R, R],
  ['angularVelocity', (s, v) => s.kinematic.setAngularVelocity(v), -R, R],
  ['force', (s, v) => s.box.applyForce({ x: v, y: v }), -F, F],
  ['point', (s, v) => s.box.applyForce({ x: 1, y: 0 }, { x: v, y: 0 }), -C, C],
  ['torque', (s, v) => s.box.applyTorque(v), -F, F],
  ['impulse', (s, v) => s.box.applyLinearImpulse({ x: v, y: 0 }), -F, F],
  ['impulse', (s, v) => s.box.applyAngularImpulse(v), -F, F],
  ['radius', (s, v) => s.box.createShape(Shape.circle(v)), Limits.MIN_SIZE, C],
  ['center', (s, v) => s.box.createShape(Shape.circle(0.5, { x: v, y: 0 })), -C, C],
  ['halfWidth', (s, v) => s.box.createShape(Shape.box(v, 0.5)), Limits.MIN_SIZE, C],
  ['angle', (s, v) => s.box.createShape(Shape.box(0.5, 0.5, { x: 0, y: 0 }, v)), -A, A],
  [
    'radius',
    (s, v) => s.box.createShape(Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, v)),
    Limits.MIN_SIZE,
    C,
  ],
  [
    'points\\[1\\]',
    (s, v) =>
      s.box.createShape(
        Shape.polygon([
          { x: 0, y: 0 },
          { x: v, y: 1 },
          { x: 0, y: 1 },
        ]),
      ),
    -C,
    C,
  ],
  [
    'radius',
    (s, v) =>
      s.box.createShape(
        Shape.polygon(
          [
            { x: 0, y: 0 },
            { x: 1, y: 0 },
            { x: 0, y: 1 },
          ],
          v,
        ),
      ),
    0,
    C,
  ],
  ['p2', (s, v) => s.ground.createShape(Shape.segment({ x: 0, y: 0 }, { x: v, y: 1 })), -C, C],
  [
    'density',
    (s, v) => s.box.createShape(Shape.circle(0.5), { density: v }),
    Limits.MIN_DENSITY,
    Limits.MAX_DENSITY,
  ],
  ['density', (s, v) => (s.boxShape.density = v), Limits.MIN_DENSITY, Limits.MAX_DENSITY],
  ['friction', (s, v) => (s.boxShape.friction = v), 0, R],
  ['restitution', (s, v) => (s.boxShape.restitution = v), 0, R],
  ['length', (s, v) => s.joints.distance.setLength(v), 0, C],
  ['maxLength', (s, v) => s.joints.distance.setLengthRange(0, v), 0, C],
  ['hertz', (s, v) => s.joints.distance.setSpring(v, 0.5), 0, R],
  ['dampingRatio', (s, v) => s.joints.revolute.setSpring(3, v), 0, R],
  ['speed', (s, v) => s.joints.revolute.setMotorSpeed(v), -R, R],
  ['torque', (s, v) => s.joints.revolute.setMaxMotorTorque(v), 0, F],
  ['upperAngle', (s, v) => s.joints.revolute.setLimits(-1, v), -1, A],
  ['upper', (s, v) => s.joints.prismatic.setLimits(-1, v), -1, C],
  ['force', (s, v) => s.joints.prismatic.setMaxMotorForce(v), 0, F],
  ['hertz', (s, v) => s.joints.wheel.setSpring(v, 0.7), 0, R],
  ['speed', (s, v) => s.joints.wheel.setMotorSpeed(v), -R, R],
  ['linearHertz', (s, v) => s.joints.weld.setStiffness(v, 0, 1), 0, R],
  ['target', (s, v) => s.joints.mouse.setTarget({ x: v, y: 0 }), -C, C],
  ['offset', (s, v) => s.joints.motor.setLinearOffset({ x: v, y: 0 }), -C, C],
  ['angle', (s, v) => s.joints.motor.setAngularOffset(v), -A, A],
  ['force', (s, v) => s.joints.motor.setMaxForce(v), 0, F],
  [
    'referenceAngle',
    (s, v) => {
      const [a, b] = s.free;
      return s.world.createJoint({
        type: 'revolute',
        bodyA: a,
        bodyB: b,
        anchor: { x: -11.7, y: 4 },
        referenceAngle: v,
      });
    },
    -A,
    A,
  ],
  [
    'hertz',
    (s, v) => s.world.createJoint({ type: 'mouse', body: s.box, target: { x: 0, y: 2 }, hertz: v }),
    0,
    R,
  ],
  [
    'maxForce',
    (s, v) => s.world.createJoint({ type: 'motor', bodyA: s.ground, bodyB: s.box, maxForce: v }),
    0,
    F,
  ],
  [
    'correctionFactor',
    (s, v) => s.world.createJoint({ type: 'motor', bodyA: s.ground, bodyB: s.box, correctionFactor: v }),
    0,
    1,
  ],
  [
    'anchor',
    (s, v) => {
      const [a, b] = s.free;
      return s.world.createJoint({ type: 'weld', bodyA: a, bodyB: b, anchor: { x: v, y: v } });
    },
    -C,
    C,
  ],
  [
    'lower',
    (s, v) => {
      const [a, b] = s.free;
      return s.world.createJoint({
        type: 'prismatic',
        bodyA: a,
        bodyB: b,
        axis: { x: 1, y: 0 },
        enableLimit: true,
        lower: v,
        upper: C,
      });
    },
    -C,
    C,
  ],
];

describe('accepted ranges', () => {
  it('the values reported to break the step are refused at the call, naming the argument and value', () => {
    const s = sampleWorld();
    const { world, box, ground } = s;
    expectRejected(world, () => world.createBody({ type: 'dynamic', angle: 1e21 }), /angle.*1e\+21/);
    expectRejected(world, () => box.setAngle(1e18), /angle.*1000000000000000000/);
    expectRejected(world, () => box.setTransform({ x: 0, y: 0 }, -1e21), /angle.*-1e\+21/);
    expectRejected(world, () => box.createShape(Shape.box(1, 1, { x: 0, y: 0 }, 1e21)), /angle.*1e\+21/);
    expectRejected(world, () => box.createShape(Shape.circle(1e200)), /radius.*1e\+200/);
    expectRejected(world, () => s.joints.distance.setSpring(1e200, 0.5), /hertz.*1e\+200/);
    expectRejected(world, () => s.joints.weld.setStiffness(0, 1e200, 1), /angularHertz.*1e\+200/);
    expectRejected(
      world,
      () => world.createJoint({ type: 'mouse', body: box, target: { x: 0, y: 3 }, hertz: 1e200 }),
      /hertz.*1e\+200/,
    );
    expectRejected(world, () => box.createShape(Shape.circle(1), { density: 1e308 }), /density.*1e\+308/);
    expectRejected(world, () => (s.boxShape.density = 1e308), /density.*1e\+308/);
    expectRejected(world, () => world.createBody({ position: { x: 1e308, y: 1e308 } }), /position.*1e\+308/);
    expectRejected(world, () => ground.setPosition({ x: 1e308, y: 0 }), /position.*1e\+308/);
    expectRejected(
      world,
      () => world.createJoint({ type: 'revolute', bodyA: ground, bodyB: box, referenceAngle: 1e21 }),
      /referenceAngle.*1e\+21/,
    );
    expectRejected(world, () => s.joints.motor.setAngularOffset(1e21), /angle.*1e\+21/);
    expectRejected(world, () => world.step(16.7), /dt.*16\.7/);
    expectRejected(world, () => world.castRayAll({ x: 0, y: 0 }, { x: 1.7e308, y: 0 }), /translation/);
    expectRejected(
      world,
      () => world.castShape(Shape.circle(0.5), { position: { x: 0, y: 5 }, angle: 1e50 }, { x: 0, y: -5 }),
      /transform\.angle.*1e\+50/,
    );
    expect(() => new World({ lengthUnitsPerMeter: 1e-300 })).toThrow(/lengthUnitsPerMeter.*1e-300/);
  });

  it('Shape.polygon refuses holes and non-vectors with a FulcrumError naming the element', () => {
    // biome-ignore lint/suspicious/noSparseArray: the sparse array is the case under test
    const sparse = [, , ,] as never;
    expect(() => Shape.polygon(sparse)).toThrow(FulcrumError);
    expect(() => Shape.polygon(sparse)).toThrow(/points\[0\].*undefined/);
    expect(() => Shape.polygon([1, 2, 3] as never)).toThrow(/points\[0\].*1/);
    expect(() => Shape.polygon([{ x: 0, y: 0 }, null, { x: 0, y: 1 }] as never)).toThrow(/points\[1\].*null/);
    expect(() =>
      Shape.polygon([
        { x: 0, y: 0 },
        { x: 1, y: 0 },
        { x: '1', y: 1 },
      ] as never),
    ).toThrow(/points\[2\]/);
  });

  it('hand-made geometry outside the ranges is refused by createShape', () => {
    const { world, box } = sampleWorld();
    const huge = Object.freeze({ ...Shape.circle(1), radius: 1e200 });
    expectRejected(world, () => box.createShape(huge as never), /geometry/);
    const tiny = Object.freeze({ ...Shape.capsule({ x: 0, y: 0 }, { x: 1, y: 0 }, 1), radius: 1e-200 });
    expectRejected(world, () => box.createShape(tiny as never), /geometry/);
    const box1 = Shape.box(0.5, 0.5);
    const skewed = Object.freeze({ ...box1, normals: box1.normals.map((n) => ({ x: 2 * n.x, y: 2 * n.y })) });
    expectRejected(world, () => box.createShape(skewed as never), /geometry/);
  });

  it('each entry refuses a value past its range and NaN, and leaves the world as it was', () => {
    for (const [argument, call, min, max] of ENTRIES) {
      const s = sampleWorld();
      const named = new RegExp(argument);
      const low = min === 0 ? -1e-300 : min > 0 ? min * (1 - 1e-9) : past(min);
      expectRejected(s.world, () => call(s, past(max)), named);
      expectRejected(s.world, () => call(s, low), named);
      expectRejected(s.world, () => call(s, Number.NaN), named);
    }
  });

  it('values at the edges of every range keep the world finite and under the speed limits', () => {
    for (const [argument, call, min, max] of ENTRIES) {
      for (const value of [min, max]) {
        const s = sampleWorld();
        call(s, value);
        for (let i = 0; i < 60; i++) s.world.step(DT);
        expectSound(s.world, 1, `${argument} = ${value}`);
      }
    }
  });

  it('a kinematic body set to turn faster than a quarter turn per substep turns exactly that', () => {
    for (const [speed, subSteps] of [
      [1000, 4],
      [1e9, 4],
      [-1e6, 8],
    ]) {
      const world = new World({ subSteps });
      const paddle = world.createBody({ type: 'kinematic', angularVelocity: speed });
      paddle.createShape(Shape.box(1, 0.1));
      world.step(DT);
      const limit = Math.PI / 4 / (DT / subSteps);
      expect(paddle.angularVelocity).toBeCloseTo(Math.sign(speed) * limit, 9);
      // a quarter turn per substep: half a turn after 4 substeps, a whole turn after 8 (the substep's
      // turn is a Taylor series, good to ~2.5e-8 at a quarter turn: see integratePositions)
      const turned = (Math.sign(speed) * Math.PI * subSteps) / 4;
      const q = paddle.rotation;
      expect(Math.abs(q.c - Math.cos(turned))).toBeLessThan(2.5e-8 * subSteps);
      expect(Math.abs(q.s - Math.sin(turned))).toBeLessThan(2.5e-8 * subSteps);
      expect(q.c * q.c + q.s * q.s).toBeCloseTo(1, 12);
    }
  });

  it('a kinematic body below the limits follows its velocity exactly; above the speed limit it is held to it', () => {
    const world = new World();
    const slow = world.createBody({
      type: 'kinematic',
      angularVelocity: 100,
      linearVelocity: { x: 3, y: -4 },
    });
    const fast = world.createBody({ type: 'kinematic', linearVelocity: { x: 3e6, y: 4e6 } });
    for (let i = 0; i < 60; i++) world.step(DT);
    // one second: 100 rad turned (the rotation's error grows by at most ~1e-9 a substep)
    expect(slow.rotation.c).toBeCloseTo(Math.cos(100), 6);
    expect(slow.rotation.s).toBeCloseTo(Math.sin(100), 6);
    expect(slow.position.x).toBeCloseTo(3, 9);
    expect(slow.position.y).toBeCloseTo(-4, 9);
    // 400 m/s along the direction it was given
    expect(fast.linearVelocity.x).toBeCloseTo(240, 9);
    expect(fast.linearVelocity.y).toBeCloseTo(320, 9);
    expect(fast.position.x).toBeCloseTo(240, 6);
    expect(fast.position.y).toBeCloseTo(320, 6);
  });

  it('a world holding every extreme at once stays finite for 600 steps', () => {
    const world = new World({ gravity: { x: 0, y: -Limits.RATE } });
    const ground = world.createBody({ position: { x: 0, y: -1 } });
    ground.createShape(Shape.box(1e6, 1), { friction: R, restitution: R });
    ground.createShape(Shape.segment({ x: -C, y: 0 }, { x: C, y: 0 }));
    // the heaviest body the ranges allow, and the lightest one resting on it
    const heavy = world.createBody({ type: 'dynamic', position: { x: 0, y: 1e6 } });
    heavy.createShape(Shape.box(1e6, 1e6), { density: Limits.MAX_DENSITY, restitution: R });
    const light = world.createBody({ type: 'dynamic', position: { x: 0, y: 2e6 + 1e-6 }, gravityScale: R });
    light.createShape(Shape.circle(Limits.MIN_SIZE), { density: Limits.MIN_DENSITY, friction: R });
    const thin = world.createBody({ type: 'dynamic', position: { x: 3, y: 2e6 + 0.01 }, angularVelocity: R });
    thin.createShape(Shape.capsule({ x: -C, y: 0 }, { x: C, y: 0 }, Limits.MIN_SIZE), {
      density: Limits.MIN_DENSITY,
    });
    const far = world.createBody({
      type: 'dynamic',
      position: { x: C, y: C },
      angle: A,
      linearVelocity: { x: R, y: -R },
    });
    far.createShape(
      Shape.polygon(
        [
          { x: -C, y: -C },
          { x: C, y: -C },
          { x: 0, y: C },
        ],
        C,
      ),
    );
    const spinner = world.createBody({
      type: 'kinematic',
      position: { x: -20, y: 2e6 },
      linearVelocity: { x: R, y: R },
      angularVelocity: -R,
    });
    spinner.createShape(Shape.box(5, 0.1));
    const joints: Joint[] = [
      world.createJoint({
        type: 'motor',
        bodyA: ground,
        bodyB: light,
        linearOffset: { x: C, y: -C },
        angularOffset: -A,
        maxForce: F,
        maxTorque: F,
        correctionFactor: 1,
      }),
      world.createJoint({
        type: 'mouse',
        body: heavy,
        target: { x: -C, y: C },
        maxForce: F,
        hertz: R,
        dampingRatio: R,
      }),
      world.createJoint({
        type: 'revolute',
        bodyA: ground,
        bodyB: thin,
        anchor: { x: 3, y: 2e6 },
        enableMotor: true,
        motorSpeed: R,
        maxMotorTorque: F,
        enableSpring: true,
        hertz: R,
        dampingRatio: R,
        referenceAngle: A,
      }),
    ];
    for (let i = 0; i < 600; i++) {
      light.applyForce({ x: F, y: -F });
      light.applyTorque(-F);
      heavy.applyLinearImpulse({ x: -F, y: F }, { x: C, y: C });
      world.step(i % 2 === 0 ? Limits.MAX_DT : Limits.MIN_DT);
      expectSound(world);
    }
    expect(joints.every((j) => j.isValid)).toBe(true);
    expect(stateHash(world)).toBeTypeOf('number');
  });

  it('lengthUnitsPerMeter at the edges of its range', () => {
    for (const units of [Limits.MIN_UNITS, Limits.MAX_UNITS]) {
      const world = new World({ lengthUnitsPerMeter: units, gravity: { x: 0, y: -10 * units } });
      const ground = world.createBody({ position: { x: 0, y: -units } });
      ground.createShape(Shape.box(Math.max(20 * units, 1), Math.max(units, 0.01)));
      const ball = world.createBody({
        type: 'dynamic',
        position: { x: 0, y: 3 * units },
        linearVelocity: { x: 0, y: -1e3 * units },
      });
      ball.createShape(Shape.circle(Math.max(0.5 * units, Limits.MIN_SIZE)));
      for (let i = 0; i < 120; i++) world.step(DT);
      expectSound(world, units);
    }
    expect(() => new World({ lengthUnitsPerMeter: Limits.MAX_UNITS * 2 })).toThrow(/lengthUnitsPerMeter/);
  });
});
