import fc from 'fast-check';
import {
  angle,
  anyNumber,
  bits,
  dt,
  groupIndex,
  nearPoint,
  nonNegative,
  pick,
  size,
  unitish,
  vec,
} from './values';

/**
 * The API fuzzer's operations as plain data: printable, replayable in a fresh world, and shrunk by
 * fast-check field by field. Handles are named by `pick`, an index into the list of every body, shape
 * or joint made so far (destroyed ones included, so that ops on destroyed handles come up naturally).
 */

type V = { x: number; y: number };

export type GeometrySpec =
  | { kind: 'circle'; radius: number; center: V | undefined }
  | { kind: 'box'; hw: number; hh: number; center: V | undefined; angle: number | undefined }
  | { kind: 'polygon'; points: V[]; radius: number | undefined }
  | { kind: 'capsule'; p1: V; p2: V; radius: number }
  | { kind: 'segment'; p1: V; p2: V };

export interface ShapeDefSpec {
  density?: number;
  friction?: number;
  restitution?: number;
  isSensor?: boolean;
  filter?: { categoryBits?: number; maskBits?: number; groupIndex?: number };
  enableContactEvents?: boolean;
  enableSensorEvents?: boolean;
  enableHitEvents?: boolean;
}

export type BodyType = 'static' | 'kinematic' | 'dynamic';

export interface BodySpec {
  type: BodyType;
  position: V;
  angle?: number;
  linearVelocity?: V;
  angularVelocity?: number;
  linearDamping?: number;
  angularDamping?: number;
  gravityScale?: number;
  fixedRotation?: boolean;
  bullet?: boolean;
  allowSleep?: boolean;
  awake?: boolean;
}

export type JointType = 'distance' | 'revolute' | 'prismatic' | 'weld' | 'wheel' | 'mouse' | 'motor';

/** a joint definition without its bodies; fields a type does not take are dropped when it is built */
export interface JointSpec {
  type: JointType;
  anchor: V | undefined;
  localAnchorA: V | undefined;
  localAnchorB: V | undefined;
  axis: V;
  collideConnected: boolean | undefined;
  enableLimit: boolean;
  lower: number;
  upper: number;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotor: number;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
  length: number | undefined;
  minLength: number | undefined;
  maxLength: number | undefined;
  linearHertz: number | undefined;
  angularHertz: number | undefined;
  referenceAngle: number | undefined;
  target: V;
  maxForce: number | undefined;
  maxTorque: number | undefined;
  linearOffset: V | undefined;
  angularOffset: number | undefined;
  correctionFactor: number | undefined;
}

export type BodySetter =
  | { prop: 'linearDamping' | 'angularDamping' | 'gravityScale'; value: number }
  | { prop: 'fixedRotation' | 'bullet' | 'allowSleep'; value: boolean };

export type ShapeSetter =
  | { prop: 'friction' | 'restitution' | 'density'; value: number }
  | { prop: 'isSensor' | 'enableHitEvents'; value: boolean }
  | { prop: 'filter'; value: { categoryBits: number; maskBits: number; groupIndex: number } };

export type WorldSetter =
  | { prop: 'gravity'; value: V }
  | { prop: 'subSteps'; value: number }
  | { prop: 'enableSleep' | 'enableContinuous'; value: boolean }
  | { prop: 'hitEventThreshold'; value: number };

export type QuerySpec =
  | { kind: 'castRay' | 'castRayAll'; origin: V; translation: V; includeSensors: boolean | undefined }
  | { kind: 'queryAABB'; lower: V; extent: V }
  | { kind: 'queryPoint'; point: V }
  | {
      kind: 'castShape';
      geometry: GeometrySpec;
      position: V;
      angle: number;
      translation: V;
    }
  | { kind: 'overlapShape'; geometry: GeometrySpec; position: V; angle: number };

export type EventName =
  | 'contactBegin'
  | 'contactEnd'
  | 'contactHit'
  | 'sensorBegin'
  | 'sensorEnd'
  | 'preStep'
  | 'postStep'
  | 'sleep'
  | 'wake';

/** An invalid call: `target` names the call and the argument, `bad` the wrong value (see harness). */
export interface InvalidSpec {
  target: number;
  bad: number;
}

export type Op =
  | { op: 'createBody'; body: BodySpec; shapes: { geometry: GeometrySpec; def: ShapeDefSpec }[] }
  | { op: 'createShape'; body: number; geometry: GeometrySpec; def: ShapeDefSpec }
  | { op: 'destroyShape'; shape: number }
  | { op: 'destroyBody'; body: number }
  | { op: 'createJoint'; a: number; b: number; joint: JointSpec }
  | { op: 'network'; count: number; density: number; links: { a: number; b: number; joint: JointSpec }[] }
  | { op: 'destroyJoint'; joint: number }
  | { op: 'setJoint'; joint: number; setter: number; n1: number; n2: number; n3: number; flag: boolean; v: V }
  | { op: 'setTransform'; body: number; which: 'position' | 'angle' | 'both'; position: V; angle: number }
  | { op: 'setVelocity'; body: number; linear: V | undefined; angular: number | undefined }
  | { op: 'setType'; body: number; type: BodyType }
  | { op: 'setAwake'; body: number; awake: boolean }
  | { op: 'setBody'; body: number; set: BodySetter }
  | {
      op: 'apply';
      body: number;
      kind: 'force' | 'torque' | 'linearImpulse' | 'angularImpulse';
      v: V;
      n: number;
      point: V | undefined;
    }
  | { op: 'setShape'; shape: number; set: ShapeSetter }
  | { op: 'setWorld'; set: WorldSetter }
  | { op: 'query'; query: QuerySpec }
  | { op: 'step'; dt: number }
  | { op: 'steps'; count: number }
  | { op: 'snapshotRestore' }
  | { op: 'readEvents' }
  | { op: 'on'; event: EventName; budget: number; ops: Op[] }
  | { op: 'off'; handler: number }
  | { op: 'invalid'; call: InvalidSpec };

const opt = <T>(arb: fc.Arbitrary<T>): fc.Arbitrary<T | undefined> =>
  fc.option(arb, { nil: undefined, freq: 3 });

export const geometry: fc.Arbitrary<GeometrySpec> = fc.oneof(
  fc.record({ kind: fc.constant('circle' as const), radius: size, center: opt(nearPoint) }),
  fc.record({
    kind: fc.constant('box' as const),
    hw: size,
    hh: size,
    center: opt(nearPoint),
    angle: opt(angle),
  }),
  fc.record({
    kind: fc.constant('polygon' as const),
    // a random cloud is a concave outline more often than not (Shape.polygon refuses it), so half the
    // outlines are points on an ellipse, which are always in convex position
    points: fc.oneof(
      fc.array(
        fc.record({
          x: fc.double({ min: -2, max: 2, noNaN: true }),
          y: fc.double({ min: -2, max: 2, noNaN: true }),
        }),
        {
          minLength: 3,
          maxLength: 10,
        },
      ),
      fc
        .record({
          rx: fc.double({ min: 0.01, max: 2, noNaN: true }),
          ry: fc.double({ min: 0.01, max: 2, noNaN: true }),
          angles: fc.array(fc.double({ min: 0, max: 6.3, noNaN: true }), { minLength: 3, maxLength: 10 }),
        })
        .map(({ rx, ry, angles }) => angles.map((a) => ({ x: rx * Math.cos(a), y: ry * Math.sin(a) }))),
    ),
    radius: opt(nonNegative),
  }),
  fc.record({ kind: fc.constant('capsule' as const), p1: nearPoint, p2: nearPoint, radius: size }),
  fc.record({ kind: fc.constant('segment' as const), p1: nearPoint, p2: nearPoint }),
);

export const shapeDef: fc.Arbitrary<ShapeDefSpec> = fc.record(
  {
    density: nonNegative,
    friction: unitish,
    restitution: unitish,
    isSensor: fc.boolean(),
    filter: fc.record({ categoryBits: bits, maskBits: bits, groupIndex }, { requiredKeys: [] }),
    enableContactEvents: fc.boolean(),
    enableSensorEvents: fc.boolean(),
    enableHitEvents: fc.boolean(),
  },
  { requiredKeys: [] },
);

const bodyType = fc.constantFrom<BodyType>('dynamic', 'dynamic', 'dynamic', 'static', 'kinematic');

const bodySpec: fc.Arbitrary<BodySpec> = fc.record(
  {
    type: bodyType,
    position: fc.oneof({ weight: 12, arbitrary: nearPoint }, { weight: 1, arbitrary: vec }),
    angle,
    linearVelocity: vec,
    angularVelocity: anyNumber,
    linearDamping: nonNegative,
    angularDamping: nonNegative,
    gravityScale: anyNumber,
    fixedRotation: fc.boolean(),
    bullet: fc.boolean(),
    allowSleep: fc.boolean(),
    awake: fc.boolean(),
  },
  { requiredKeys: ['type', 'position'] },
);

const jointSpec: fc.Arbitrary<JointSpec> = fc.record({
  type: fc.constantFrom<JointType>('distance', 'revolute', 'prismatic', 'weld', 'wheel', 'mouse', 'motor'),
  anchor: opt(nearPoint),
  localAnchorA: opt(nearPoint),
  localAnchorB: opt(nearPoint),
  axis: fc.oneof({ weight: 8, arbitrary: nearPoint }, { weight: 1, arbitrary: vec }),
  collideConnected: opt(fc.boolean()),
  enableLimit: fc.boolean(),
  lower: anyNumber,
  upper: anyNumber,
  enableMotor: fc.boolean(),
  motorSpeed: anyNumber,
  maxMotor: nonNegative,
  enableSpring: fc.boolean(),
  hertz: nonNegative,
  dampingRatio: unitish,
  length: opt(nonNegative),
  minLength: opt(nonNegative),
  maxLength: opt(nonNegative),
  linearHertz: opt(nonNegative),
  angularHertz: opt(nonNegative),
  referenceAngle: opt(angle),
  target: nearPoint,
  maxForce: opt(nonNegative),
  maxTorque: opt(nonNegative),
  linearOffset: opt(nearPoint),
  angularOffset: opt(angle),
  correctionFactor: opt(unitish),
});

const bodySetter: fc.Arbitrary<BodySetter> = fc.oneof(
  fc.record({
    prop: fc.constantFrom('linearDamping' as const, 'angularDamping' as const),
    value: nonNegative,
  }),
  fc.record({ prop: fc.constant('gravityScale' as const), value: anyNumber }),
  fc.record({
    prop: fc.constantFrom('fixedRotation' as const, 'bullet' as const, 'allowSleep' as const),
    value: fc.boolean(),
  }),
);

const shapeSetter: fc.Arbitrary<ShapeSetter> = fc.oneof(
  fc.record({ prop: fc.constantFrom('friction' as const, 'restitution' as const), value: unitish }),
  fc.record({ prop: fc.constant('density' as const), value: nonNegative }),
  fc.record({ prop: fc.constantFrom('isSensor' as const, 'enableHitEvents' as const), value: fc.boolean() }),
  fc.record({
    prop: fc.constant('filter' as const),
    value: fc.record({ categoryBits: bits, maskBits: bits, groupIndex }),
  }),
);

const worldSetter: fc.Arbitrary<WorldSetter> = fc.oneof(
  fc.record({
    prop: fc.constant('gravity' as const),
    value: fc.oneof({ weight: 6, arbitrary: fc.constant({ x: 0, y: -10 }) }, { weight: 3, arbitrary: vec }),
  }),
  fc.record({ prop: fc.constant('subSteps' as const), value: fc.integer({ min: 1, max: 64 }) }),
  fc.record({
    prop: fc.constantFrom('enableSleep' as const, 'enableContinuous' as const),
    value: fc.boolean(),
  }),
  fc.record({ prop: fc.constant('hitEventThreshold' as const), value: nonNegative }),
);

const query: fc.Arbitrary<QuerySpec> = fc.oneof(
  fc.record({
    kind: fc.constantFrom('castRay' as const, 'castRayAll' as const),
    origin: nearPoint,
    translation: vec,
    includeSensors: opt(fc.boolean()),
  }),
  fc.record({ kind: fc.constant('queryAABB' as const), lower: nearPoint, extent: nearPoint }),
  fc.record({ kind: fc.constant('queryPoint' as const), point: nearPoint }),
  fc.record({
    kind: fc.constant('castShape' as const),
    geometry,
    position: nearPoint,
    angle,
    translation: vec,
  }),
  fc.record({ kind: fc.constant('overlapShape' as const), geometry, position: nearPoint, angle }),
);

const eventName = fc.constantFrom<EventName>(
  'contactBegin',
  'contactEnd',
  'contactHit',
  'sensorBegin',
  'sensorEnd',
  'preStep',
  'postStep',
  'sleep',
  'wake',
);

/** Operations that change the world or read it, without the ones that only make sense at top level. */
function worldOps(nested: fc.Arbitrary<Op>): fc.Arbitrary<Op> {
  return fc.oneof(
    {
      weight: 10,
      arbitrary: fc.record({
        op: fc.constant('createBody' as const),
        body: bodySpec,
        shapes: fc.array(fc.record({ geometry, def: shapeDef }), { minLength: 0, maxLength: 3 }),
      }),
    },
    {
      weight: 3,
      arbitrary: fc.record({ op: fc.constant('createShape' as const), body: pick, geometry, def: shapeDef }),
    },
    { weight: 2, arbitrary: fc.record({ op: fc.constant('destroyShape' as const), shape: pick }) },
    { weight: 3, arbitrary: fc.record({ op: fc.constant('destroyBody' as const), body: pick }) },
    {
      weight: 5,
      arbitrary: fc.record({ op: fc.constant('createJoint' as const), a: pick, b: pick, joint: jointSpec }),
    },
    {
      // a row of boxes (1 or 1000 kg/m²) joined to each other and to the first body (the ground) at random
      weight: 2,
      arbitrary: fc.record({
        op: fc.constant('network' as const),
        count: fc.integer({ min: 2, max: 12 }),
        density: fc.constantFrom(1, 1, 1000),
        links: fc.array(fc.record({ a: pick, b: pick, joint: jointSpec }), { minLength: 1, maxLength: 16 }),
      }),
    },
    { weight: 1, arbitrary: fc.record({ op: fc.constant('destroyJoint' as const), joint: pick }) },
    {
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('setJoint' as const),
        joint: pick,
        setter: fc.nat({ max: 6 }),
        n1: anyNumber,
        n2: anyNumber,
        n3: unitish,
        flag: fc.boolean(),
        v: nearPoint,
      }),
    },
    {
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('setTransform' as const),
        body: pick,
        which: fc.constantFrom('position' as const, 'angle' as const, 'both' as const),
        position: fc.oneof({ weight: 10, arbitrary: nearPoint }, { weight: 1, arbitrary: vec }),
        angle,
      }),
    },
    {
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('setVelocity' as const),
        body: pick,
        linear: opt(vec),
        angular: opt(anyNumber),
      }),
    },
    { weight: 2, arbitrary: fc.record({ op: fc.constant('setType' as const), body: pick, type: bodyType }) },
    {
      weight: 2,
      arbitrary: fc.record({ op: fc.constant('setAwake' as const), body: pick, awake: fc.boolean() }),
    },
    { weight: 2, arbitrary: fc.record({ op: fc.constant('setBody' as const), body: pick, set: bodySetter }) },
    {
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('apply' as const),
        body: pick,
        kind: fc.constantFrom(
          'force' as const,
          'torque' as const,
          'linearImpulse' as const,
          'angularImpulse' as const,
        ),
        v: vec,
        n: anyNumber,
        point: opt(nearPoint),
      }),
    },
    {
      weight: 2,
      arbitrary: fc.record({ op: fc.constant('setShape' as const), shape: pick, set: shapeSetter }),
    },
    { weight: 1, arbitrary: fc.record({ op: fc.constant('setWorld' as const), set: worldSetter }) },
    { weight: 3, arbitrary: fc.record({ op: fc.constant('query' as const), query }) },
    { weight: 1, arbitrary: fc.record({ op: fc.constant('readEvents' as const) }) },
    {
      weight: 3,
      arbitrary: fc.record({
        op: fc.constant('invalid' as const),
        call: fc.record({ target: fc.nat({ max: 10_000 }), bad: fc.nat({ max: 10_000 }) }),
      }),
    },
    { weight: 1, arbitrary: nested },
  );
}

/** What an event handler may do: change the world, and step it again from preStep and postStep. */
const handlerOp: fc.Arbitrary<Op> = worldOps(fc.record({ op: fc.constant('step' as const), dt }));

/** A whole session of calls: mostly steps between the changes, handlers registered along the way. */
export const opSequence = (maxLength: number): fc.Arbitrary<Op[]> =>
  fc.array(
    fc.oneof(
      { weight: 40, arbitrary: worldOps(fc.record({ op: fc.constant('snapshotRestore' as const) })) },
      { weight: 25, arbitrary: fc.record({ op: fc.constant('step' as const), dt }) },
      {
        weight: 6,
        arbitrary: fc.record({ op: fc.constant('steps' as const), count: fc.integer({ min: 2, max: 60 }) }),
      },
      {
        weight: 3,
        arbitrary: fc.record({
          op: fc.constant('on' as const),
          event: eventName,
          budget: fc.integer({ min: 1, max: 20 }),
          ops: fc.array(handlerOp, { minLength: 1, maxLength: 3 }),
        }),
      },
      { weight: 1, arbitrary: fc.record({ op: fc.constant('off' as const), handler: pick }) },
    ),
    { minLength: 1, maxLength, size: 'max' },
  );

/** A few bodies to start with, so that the session's ops find something to act on. */
export const initialBodies = (maxLength: number): fc.Arbitrary<Op[]> =>
  fc.array(
    fc.record({
      op: fc.constant('createBody' as const),
      body: bodySpec,
      shapes: fc.array(fc.record({ geometry, def: shapeDef }), { minLength: 1, maxLength: 2 }),
    }),
    { minLength: 0, maxLength, size: 'max' },
  );
