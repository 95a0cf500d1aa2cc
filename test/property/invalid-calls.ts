import { type Body, Shape, type ShapeHandle, World } from '../../src/index';
import type { Harness } from './harness';

/**
 * Calls that API.md says must throw a FulcrumError and leave the world exactly as it was: every kind
 * of wrong value for every kind of argument. Each entry takes the harness and an index into its list
 * of wrong values; an entry that needs a live (or destroyed) handle does nothing when there is none.
 */

const notFinite = [Number.NaN, Number.POSITIVE_INFINITY, Number.NEGATIVE_INFINITY];
const notNumber = ['1', null, {}, [1], true, 1n];
/** wrong for any number argument */
const badNumber: unknown[] = [...notFinite, ...notNumber];
/** wrong for an argument that must be >= 0 */
const badNonNegative: unknown[] = [...badNumber, -1, -1e-300, -Number.MAX_VALUE];
/** wrong for a size that must be > 0 */
const badPositive: unknown[] = [...badNonNegative, 0, -0];
const badVec: unknown[] = [
  { x: Number.NaN, y: 0 },
  { x: 0, y: Number.POSITIVE_INFINITY },
  { x: Number.NEGATIVE_INFINITY, y: Number.NaN },
  { x: 1 },
  { y: 1 },
  { x: '1', y: '2' },
  null,
  undefined,
  3,
  [1, 2],
  'origin',
];
const badBool: unknown[] = [1, 0, 'true', null, undefined, {}];
const badBodyType: unknown[] = ['wobbly', '', 'Dynamic', null, 1, {}];
const badBits: unknown[] = [-1, 0x100000000, 1.5, Number.NaN, '1', null];
const badFilter: unknown[] = [
  ...badBits.map((categoryBits) => ({ categoryBits })),
  ...badBits.map((maskBits) => ({ maskBits })),
  { groupIndex: 1.5 },
  { groupIndex: 0x80000000 },
  { groupIndex: Number.NaN },
  { category: 1 },
  null,
  'all',
];
const badQueryFilter: unknown[] = [
  { categoryBits: -1 },
  { maskBits: 1.5 },
  { includeSensors: 1 },
  { groupIndex: 0 },
  'all',
  7,
];
const badDef: unknown[] = [null, 3, 'def', { bogus: 1 }];
const badPolygon: unknown[] = [
  [],
  [{ x: 0, y: 0 }],
  [
    { x: 0, y: 0 },
    { x: 1, y: 0 },
  ],
  [
    { x: 0, y: 0 },
    { x: 1, y: 0 },
    { x: 2, y: 0 },
  ],
  [
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
  ],
  // holes in the array
  new Array(3),
  Object.assign(new Array(4), { 0: { x: 0, y: 0 }, 2: { x: 1, y: 1 }, 3: { x: 0, y: 1 } }),
  [
    { x: 0, y: 0 },
    { x: Number.NaN, y: 0 },
    { x: 1, y: 1 },
  ],
  // a concave outline (Shape.concave takes it)
  [
    { x: 0, y: 0 },
    { x: 2, y: 0 },
    { x: 2, y: 0.5 },
    { x: 0.5, y: 0.5 },
    { x: 0.5, y: 2 },
    { x: 0, y: 2 },
  ],
  // 9 distinct hull vertices (a polygon has at most 8)
  Array.from({ length: 9 }, (_, i) => ({
    x: Math.cos((2 * Math.PI * i) / 9),
    y: Math.sin((2 * Math.PI * i) / 9),
  })),
  null,
  'square',
  { length: 3 },
];
/** Outlines Shape.concave refuses: crossing, touching, doubling back, degenerate, not points. */
const badOutline: unknown[] = [
  [
    { x: 0, y: 0 },
    { x: 2, y: 2 },
    { x: 2, y: 0 },
    { x: 0, y: 2 },
  ],
  [
    { x: 0, y: 0 },
    { x: 1, y: 0 },
    { x: 1, y: 1 },
    { x: 2, y: 1 },
    { x: 2, y: 2 },
    { x: 1, y: 2 },
    { x: 1, y: 1 },
    { x: 0, y: 1 },
  ],
  [
    { x: 0, y: 0 },
    { x: 2, y: 0 },
    { x: 2, y: 2 },
    { x: 1, y: 0.001 },
    { x: 0, y: 2 },
  ],
  [
    { x: 0, y: 0 },
    { x: 2, y: 0 },
    { x: 2, y: 1 },
    { x: 3, y: 1 },
    { x: 2.5, y: 1 },
    { x: 0, y: 1 },
  ],
  [
    { x: 0, y: 0 },
    { x: 1, y: 0 },
    { x: 2, y: 0 },
  ],
  [
    { x: 0, y: 0 },
    { x: 1, y: 0 },
  ],
  Array.from({ length: 1025 }, (_, i) => ({ x: Math.cos(i / 163), y: Math.sin(i / 163) })),
  new Array(3),
  [
    { x: 0, y: 0 },
    { x: Number.NaN, y: 0 },
    { x: 1, y: 1 },
  ],
  null,
  'L',
];
const anL = [
  { x: 0, y: 0 },
  { x: 2, y: 0 },
  { x: 2, y: 0.5 },
  { x: 0.5, y: 0.5 },
  { x: 0.5, y: 2 },
  { x: 0, y: 2 },
];
const badGeometry: unknown[] = [null, {}, { type: 'circle', radius: 1 }, 'circle', 3];
const badTransform: unknown[] = [
  null,
  {},
  { position: { x: Number.NaN, y: 0 } },
  { position: { x: 0, y: 0 }, angle: Number.POSITIVE_INFINITY },
  { p: { x: 0, y: 0 }, q: { c: 2, s: 0 } },
  { p: { x: 0, y: 0 }, q: { c: Number.NaN, s: 0 } },
  { position: { x: 0, y: 0 }, bogus: 1 },
];
const badEvent: unknown[] = ['contactbegin', 'step', '', null, 1];

function of(list: readonly unknown[], i: number): unknown {
  return list[i % list.length];
}

const origin = { x: 0, y: 0 };
const right = { x: 1, y: 0 };

type Invalid = (h: Harness, bad: number) => void;

const bodyCall =
  (name: string, list: readonly unknown[], call: (body: Body, value: never) => unknown): Invalid =>
  (h, bad) => {
    const body = h.liveBody(bad);
    if (body)
      h.expectRejected(`body.${name}(${safe(of(list, bad))})`, () => call(body, of(list, bad) as never));
  };

const shapeCall =
  (name: string, list: readonly unknown[], call: (shape: ShapeHandle, value: never) => unknown): Invalid =>
  (h, bad) => {
    const shape = h.liveShape(bad);
    if (shape)
      h.expectRejected(`shape.${name} = ${safe(of(list, bad))}`, () => call(shape, of(list, bad) as never));
  };

const worldCall =
  (name: string, list: readonly unknown[], call: (world: World, value: never) => unknown): Invalid =>
  (h, bad) =>
    h.expectRejected(`world.${name}(${safe(of(list, bad))})`, () => call(h.world, of(list, bad) as never));

function safe(v: unknown): string {
  try {
    return typeof v === 'bigint' ? `${v}n` : (JSON.stringify(v) ?? String(v));
  } catch {
    return String(v);
  }
}

/** a joint definition that is valid apart from `patch` */
function jointCall(
  type: string,
  patch: (h: Harness, bad: number) => Record<string, unknown> | undefined,
): Invalid {
  return (h, bad) => {
    const a = h.liveBody(bad);
    const b = h.liveBody(bad + 1);
    if (!a || !b) return;
    const base: Record<string, unknown> =
      type === 'mouse' ? { type, body: a, target: origin } : { type, bodyA: a, bodyB: b };
    if (type === 'prismatic' || type === 'wheel') base.axis = right;
    const extra = patch(h, bad);
    if (!extra) return;
    const def = { ...base, ...extra };
    h.expectRejected(`createJoint(${safe(Object.keys(extra))} of ${type})`, () =>
      h.world.createJoint(def as never),
    );
  };
}

export const invalidCalls: Invalid[] = [
  worldCall('step', badNonNegative, (w, v) => w.step(v)),
  worldCall(
    'createBody(position)',
    badVec.filter((v) => v !== undefined),
    (w, v) => w.createBody({ type: 'dynamic', position: v }),
  ),
  worldCall('createBody(angle)', badNumber, (w, v) => w.createBody({ type: 'dynamic', angle: v })),
  worldCall(
    'createBody(linearVelocity)',
    badVec.filter((v) => v !== undefined),
    (w, v) => w.createBody({ type: 'kinematic', linearVelocity: v }),
  ),
  worldCall('createBody(angularDamping)', badNonNegative, (w, v) => w.createBody({ angularDamping: v })),
  worldCall('createBody(type)', badBodyType, (w, v) => w.createBody({ type: v })),
  worldCall(
    'createBody(bullet)',
    badBool.filter((v) => v !== undefined),
    (w, v) => w.createBody({ bullet: v }),
  ),
  worldCall('createBody', badDef, (w, v) => w.createBody(v)),
  worldCall('gravity =', badVec, (w, v) => {
    w.gravity = v;
  }),
  worldCall('subSteps =', [0, -1, 1.5, 65, Number.NaN, '4', null], (w, v) => {
    w.subSteps = v;
  }),
  worldCall('enableSleep =', badBool, (w, v) => {
    w.enableSleep = v;
  }),
  worldCall('hitEventThreshold =', badNonNegative, (w, v) => {
    w.hitEventThreshold = v;
  }),
  worldCall('on', badEvent, (w, v) => w.on(v, () => {})),
  worldCall('on(handler)', [null, 'f', {}, 1], (w, v) => w.on('contactBegin', v)),
  worldCall('destroyBody', [null, {}, 1, 'body'], (w, v) => w.destroyBody(v)),
  worldCall('destroyJoint', [null, {}, 1, 'joint'], (w, v) => w.destroyJoint(v)),
  worldCall('castRay(origin)', badVec, (w, v) => w.castRay(v, right)),
  worldCall('castRay(translation)', badVec, (w, v) => w.castRay(origin, v)),
  worldCall('castRayAll(filter)', badQueryFilter, (w, v) => w.castRayAll(origin, right, v)),
  worldCall(
    'queryAABB',
    [null, {}, { lowerBound: { x: Number.NaN, y: 0 }, upperBound: right }, { lowerBound: origin }],
    (w, v) => w.queryAABB(v),
  ),
  worldCall('queryPoint', badVec, (w, v) => w.queryPoint(v)),
  worldCall('castShape(geometry)', badGeometry, (w, v) => w.castShape(v, { position: origin }, right)),
  worldCall('castShape(transform)', badTransform, (w, v) => w.castShape(Shape.circle(0.5), v, right)),
  worldCall('overlapShape(transform)', badTransform, (w, v) => w.overlapShape(Shape.box(1, 1), v)),
  worldCall('overlapShape(filter)', badQueryFilter, (w, v) =>
    w.overlapShape(Shape.box(1, 1), { position: origin }, v),
  ),
  worldCall('Shape.circle', badPositive, (_, v) => Shape.circle(v as number)),
  worldCall('Shape.box', badPositive, (_, v) => Shape.box(1, v as number)),
  worldCall('Shape.box(angle)', badNumber, (_, v) => Shape.box(1, 1, origin, v as number)),
  worldCall('Shape.polygon', badPolygon, (_, v) => Shape.polygon(v as never)),
  worldCall('Shape.polygon(radius)', badNonNegative, (_, v) =>
    Shape.polygon(
      [
        { x: 0, y: 0 },
        { x: 1, y: 0 },
        { x: 0, y: 1 },
      ],
      v as number,
    ),
  ),
  worldCall('Shape.concave', badOutline, (_, v) => Shape.concave(v as never)),
  worldCall('Shape.decompose', badOutline, (_, v) => Shape.decompose(v as never)),
  worldCall('Shape.capsule', [origin, { x: 1e-4, y: 0 }, ...badVec], (_, v) =>
    Shape.capsule(origin, v as never, 0.5),
  ),
  worldCall('Shape.segment', [origin, ...badVec], (_, v) => Shape.segment(v as never, origin)),
  worldCall('World.restore', [null, new Uint8Array(0), new Uint8Array(40), 'bytes'], (_, v) =>
    World.restore(v as never),
  ),
  (h, bad) => {
    // a snapshot with one byte changed
    const bytes = h.world.snapshot();
    let i = bad % bytes.length;
    if (i === 6 || i === 7) i = 8; // bytes 6 and 7 are reserved: the reader ignores them
    bytes[i] ^= 1 + (bad % 255);
    h.expectRejected(`World.restore(snapshot with byte ${i} changed)`, () => World.restore(bytes));
  },
  bodyCall('setPosition', badVec, (b, v) => b.setPosition(v)),
  bodyCall('setAngle', badNumber, (b, v) => b.setAngle(v)),
  bodyCall('setTransform', badNumber, (b, v) => b.setTransform(origin, v)),
  bodyCall('setLinearVelocity', badVec, (b, v) => b.setLinearVelocity(v)),
  bodyCall('setAngularVelocity', badNumber, (b, v) => b.setAngularVelocity(v)),
  bodyCall('setType', badBodyType, (b, v) => b.setType(v)),
  bodyCall('setAwake', badBool, (b, v) => b.setAwake(v)),
  bodyCall('setLinearDamping', badNonNegative, (b, v) => b.setLinearDamping(v)),
  bodyCall('setGravityScale', badNumber, (b, v) => b.setGravityScale(v)),
  bodyCall('setFixedRotation', badBool, (b, v) => b.setFixedRotation(v)),
  bodyCall('applyForce', badVec, (b, v) => b.applyForce(v)),
  bodyCall(
    'applyForce(point)',
    badVec.filter((v) => v !== undefined),
    (b, v) => b.applyForce(right, v),
  ),
  bodyCall('applyTorque', badNumber, (b, v) => b.applyTorque(v)),
  bodyCall('applyLinearImpulse', badVec, (b, v) => b.applyLinearImpulse(v)),
  bodyCall('applyAngularImpulse', badNumber, (b, v) => b.applyAngularImpulse(v)),
  bodyCall('getWorldPoint', badVec, (b, v) => b.getWorldPoint(v)),
  bodyCall('createShape(geometry)', badGeometry, (b, v) => b.createShape(v)),
  bodyCall(
    'createShape(def)',
    [
      ...badNonNegative.map((density) => ({ density })),
      ...badNonNegative.map((friction) => ({ friction })),
      { restitution: -1 },
      { isSensor: 'yes' },
      { enableHitEvents: 1 },
      ...badFilter.map((filter) => ({ filter })),
      ...badDef,
    ],
    (b, v) => b.createShape(Shape.circle(0.5), v),
  ),
  bodyCall(
    'createShape(concave, def)',
    [
      { density: -1 },
      { friction: Number.NaN },
      { isSensor: 1 },
      ...badFilter.map((filter) => ({ filter })),
      ...badDef,
    ],
    (b, v) => b.createShape(Shape.concave(anL), v),
  ),
  bodyCall(
    'createShape(a hand-made concave shape)',
    [
      { type: 'concave', outline: anL, pieces: Shape.concave(anL).pieces },
      Object.freeze({
        type: 'concave',
        outline: Object.freeze(anL.slice()),
        pieces: Object.freeze([Shape.circle(1)]),
      }),
      Object.freeze({ type: 'concave', outline: Object.freeze(anL.slice()), pieces: Object.freeze([]) }),
    ],
    (b, v) => b.createShape(v),
  ),
  bodyCall('destroyShape', [null, {}, 'shape'], (b, v) => b.destroyShape(v)),
  (h) => {
    // a segment on a dynamic body
    const body = h.bodies.find((b) => b.isValid && b.type === 'dynamic');
    if (body)
      h.expectRejected('dynamic body.createShape(segment)', () =>
        body.createShape(Shape.segment(origin, right)),
      );
  },
  (h, bad) => {
    // a shape of another body
    const body = h.liveBody(bad);
    const shape = h.liveShape(bad + 1);
    if (body && shape && shape.body !== body)
      h.expectRejected('body.destroyShape(a shape of another body)', () => body.destroyShape(shape));
  },
  (h) => {
    // a dynamic type for a body with a segment
    const shape = h.shapes.find((s) => s.isValid && s.type === 'segment');
    if (shape)
      h.expectRejected("setType('dynamic') of a body with a segment", () => shape.body.setType('dynamic'));
  },
  shapeCall('friction', badNonNegative, (s, v) => {
    s.friction = v;
  }),
  shapeCall('restitution', badNonNegative, (s, v) => {
    s.restitution = v;
  }),
  shapeCall('density', badNonNegative, (s, v) => {
    s.density = v;
  }),
  shapeCall('filter', badFilter, (s, v) => {
    s.filter = v;
  }),
  shapeCall('isSensor', badBool, (s, v) => {
    s.isSensor = v;
  }),
  shapeCall('testPoint', badVec, (s, v) => s.testPoint(v)),
  shapeCall('rayCast', badVec, (s, v) => s.rayCast(v, right)),
  // destroyed handles
  (h, bad) => {
    const body = h.deadBody(bad);
    if (!body) return;
    const uses: [string, () => unknown][] = [
      ['world.destroyBody', () => h.world.destroyBody(body)],
      ['setPosition', () => body.setPosition(origin)],
      ['setLinearVelocity', () => body.setLinearVelocity(right)],
      ['applyForce', () => body.applyForce(right)],
      ['createShape', () => body.createShape(Shape.circle(1))],
      ['position', () => body.position],
      ['shapes', () => body.shapes],
      ['joints', () => body.joints],
      ['setType', () => body.setType('dynamic')],
    ];
    const [name, use] = uses[bad % uses.length];
    h.expectRejected(`${name} of a destroyed body`, use);
  },
  (h, bad) => {
    const shape = h.deadShape(bad);
    if (!shape) return;
    const uses: [string, () => unknown][] = [
      ['destroyShape', () => shape.body.destroyShape(shape)],
      ['friction =', () => (shape.friction = 0.1)],
      ['filter', () => shape.filter],
      ['getAABB', () => shape.getAABB()],
      ['testPoint', () => shape.testPoint(origin)],
    ];
    const [name, use] = uses[bad % uses.length];
    h.expectRejected(`${name} of a destroyed shape`, use);
  },
  (h, bad) => {
    const joint = h.deadJoint(bad);
    if (!joint) return;
    const uses: [string, () => unknown][] = [
      ['world.destroyJoint', () => h.world.destroyJoint(joint)],
      ['getReactionForce', () => joint.getReactionForce()],
      ['getReactionTorque', () => joint.getReactionTorque()],
      ['anchorA', () => joint.anchorA],
    ];
    const [name, use] = uses[bad % uses.length];
    h.expectRejected(`${name} of a destroyed joint`, use);
  },
  (h, bad) => {
    // handles of another world
    const other = new World();
    const body = other.createBody({ type: 'dynamic' });
    const mine = h.liveBody(bad);
    const uses: [string, () => unknown][] = [
      ['destroyBody', () => h.world.destroyBody(body)],
      ['createJoint', () => mine && h.world.createJoint({ type: 'weld', bodyA: mine, bodyB: body })],
      ['mouse', () => h.world.createJoint({ type: 'mouse', body, target: origin })],
    ];
    const [name, use] = uses[bad % uses.length];
    if (name === 'createJoint' && !mine) return;
    h.expectRejected(`${name} with a body of another world`, use);
  },
  // joints
  (h, bad) => {
    const body = h.liveBody(bad);
    if (body)
      h.expectRejected('createJoint(bodyA = bodyB)', () =>
        h.world.createJoint({ type: 'revolute', bodyA: body, bodyB: body, anchor: origin }),
      );
  },
  worldCall('createJoint', [...badDef, { type: 'rope' }, { type: null }], (w, v) => w.createJoint(v)),
  jointCall('revolute', (_, bad) => ({
    anchor: of(
      badVec.filter((v) => v !== undefined),
      bad,
    ),
  })),
  jointCall('revolute', () => ({ anchor: origin, localAnchorA: origin })),
  jointCall('revolute', (_, bad) => ({ lowerAngle: 1, upperAngle: of([0, -1, Number.NaN], bad) })),
  jointCall('revolute', (_, bad) => ({ maxMotorTorque: of(badNonNegative, bad) })),
  jointCall('revolute', (_, bad) => ({ hertz: of(badNonNegative, bad) })),
  jointCall('revolute', (_, bad) => ({
    enableLimit: of(
      badBool.filter((v) => v !== undefined),
      bad,
    ),
  })),
  jointCall('prismatic', (_, bad) => ({ axis: of([origin, { x: 1e-12, y: 0 }, ...badVec], bad) })),
  jointCall('prismatic', (_, bad) => ({ lower: of([2, Number.NaN, '0'], bad), upper: 1 })),
  jointCall('wheel', (_, bad) => ({ dampingRatio: of(badNonNegative, bad) })),
  jointCall('weld', (_, bad) => ({ linearHertz: of(badNonNegative, bad) })),
  jointCall('weld', (_, bad) => ({ referenceAngle: of(badNumber, bad) })),
  jointCall('distance', (_, bad) => ({ length: of(badNonNegative, bad) })),
  jointCall('distance', () => ({ minLength: 2, maxLength: 1 })),
  jointCall('distance', () => ({ anchor: origin })),
  jointCall('mouse', (_, bad) => ({ target: of(badVec, bad) })),
  jointCall('mouse', (_, bad) => ({ maxForce: of(badNonNegative, bad) })),
  jointCall('motor', (_, bad) => ({ maxTorque: of(badNonNegative, bad) })),
  jointCall('motor', (_, bad) => ({
    linearOffset: of(
      badVec.filter((v) => v !== undefined),
      bad,
    ),
  })),
  jointCall('motor', () => ({ bogus: 1 })),
  (h, bad) => {
    const joint = h.liveJoint(bad);
    if (!joint) return;
    const j = joint as unknown as Record<string, (...args: unknown[]) => unknown>;
    const calls: [string, unknown[]][] = [
      ['setMotorSpeed', [of(badNumber, bad)]],
      ['setMaxMotorTorque', [of(badNonNegative, bad)]],
      ['setMaxMotorForce', [of(badNonNegative, bad)]],
      ['setLimits', [1, of([0, Number.NaN, -1], bad)]],
      ['setSpring', [of(badNonNegative, bad), 0.5]],
      ['setSpring', [1, of(badNonNegative, bad)]],
      ['enableMotor', [of(badBool, bad)]],
      ['enableLimit', [of(badBool, bad)]],
      ['enableSpring', [of(badBool, bad)]],
      ['setLength', [of(badNonNegative, bad)]],
      ['setLengthRange', [2, 1]],
      ['setStiffness', [of(badNonNegative, bad), 0, 0]],
      ['setTarget', [of(badVec, bad)]],
      ['setLinearOffset', [of(badVec, bad)]],
      ['setAngularOffset', [of(badNumber, bad)]],
      ['setMaxForce', [of(badNonNegative, bad)]],
      ['setMaxTorque', [of(badNonNegative, bad)]],
    ];
    const own = calls.filter(([name]) => typeof j[name] === 'function');
    if (own.length === 0) return;
    const [name, args] = own[bad % own.length];
    h.expectRejected(`${joint.type}.${name}(${args.map(safe).join(', ')})`, () => j[name].apply(joint, args));
  },
];
