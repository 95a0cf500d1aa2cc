/**
 * Random networks of jointed bodies, as a hostile user would build them: 20-50 boxes joined by
 * joints with limits, motors and springs, in trees pinned to the ground at 1-4 places or in graphs
 * with loops, with or without contacts, with masses up to 1000:1 apart. Shared by the joint network
 * tests and `npm run fuzz`.
 */
import { createRandom, type Random } from '../../scenes/random';
import { type Body, type Joint, type JointDef, Shape, World } from '../../src/index';

export type NetworkKind =
  /** revolute joints whose limits the start pose violates, some with motors; loops; contacts */
  | 'revolute-violated'
  /** prismatic joints with limits (often violated) and motors; loops; contacts */
  | 'prismatic'
  /** weld joints, rigid or soft; loops; contacts */
  | 'weld'
  /** every joint type, with limits, motors and springs; loops; contacts */
  | 'mixed'
  /** as mixed, with body masses from 1 to 1000 kg */
  | 'heavy'
  /** revolute joints with limits (satisfied at the start) and motors, a tree pinned at 1-4 places */
  | 'tree-revolute'
  /** prismatic joints with limits (satisfied at the start) and motors, a tree pinned at 1-4 places */
  | 'tree-prismatic'
  /** as tree-revolute, without motors and without contacts */
  | 'tree-revolute-bare';

export const NETWORK_KINDS: readonly NetworkKind[] = [
  'revolute-violated',
  'prismatic',
  'weld',
  'mixed',
  'heavy',
  'tree-revolute',
  'tree-prismatic',
  'tree-revolute-bare',
];

export interface Network {
  world: World;
  ground: Body;
  bodies: Body[];
  joints: Joint[];
}

const JOINT_TYPES = ['revolute', 'prismatic', 'weld', 'wheel', 'distance', 'motor'] as const;

/** A unit vector in a random direction. */
function direction(rng: Random): { x: number; y: number } {
  const a = rng.range(0, 2 * Math.PI);
  return { x: Math.cos(a), y: Math.sin(a) };
}

function jointDef(
  rng: Random,
  type: (typeof JOINT_TYPES)[number],
  a: Body,
  b: Body,
  violated: boolean,
  motors: boolean,
): JointDef {
  const pa = a.position;
  const pb = b.position;
  const anchor = { x: (pa.x + pb.x) / 2 + rng.range(-0.2, 0.2), y: (pa.y + pb.y) / 2 + rng.range(-0.2, 0.2) };
  const motor = motors && rng.nextFloat() < 0.5;
  switch (type) {
    case 'revolute': {
      // the start angle is 0 (the reference); a violated limit leaves 0 outside [lower, upper]
      const lower = violated ? rng.range(0.2, 1) * (rng.nextFloat() < 0.5 ? -1 : 1) : rng.range(-1.5, 0);
      const upper = violated ? lower + rng.range(0, 0.5) : rng.range(0, 1.5);
      return {
        type,
        bodyA: a,
        bodyB: b,
        anchor,
        enableLimit: rng.nextFloat() < 0.8,
        lowerAngle: Math.min(lower, upper),
        upperAngle: Math.max(lower, upper),
        enableMotor: motor,
        motorSpeed: rng.range(-3, 3),
        maxMotorTorque: rng.range(1, 500),
        enableSpring: rng.nextFloat() < 0.2,
        hertz: rng.range(0.5, 10),
        dampingRatio: rng.range(0, 1),
      };
    }
    case 'prismatic':
    case 'wheel': {
      const lower = violated ? rng.range(0.2, 1) * (rng.nextFloat() < 0.5 ? -1 : 1) : rng.range(-1, 0);
      const upper = violated ? lower + rng.range(0, 0.5) : rng.range(0, 1);
      const common = {
        bodyA: a,
        bodyB: b,
        anchor,
        axis: direction(rng),
        enableLimit: rng.nextFloat() < 0.8,
        lower: Math.min(lower, upper),
        upper: Math.max(lower, upper),
        enableMotor: motor,
        motorSpeed: rng.range(-3, 3),
        enableSpring: type === 'wheel' || rng.nextFloat() < 0.2,
        hertz: rng.range(0.5, 10),
        dampingRatio: rng.range(0, 1),
      };
      return type === 'wheel'
        ? { type, ...common, maxMotorTorque: rng.range(1, 500) }
        : { type, ...common, maxMotorForce: rng.range(1, 2000) };
    }
    case 'weld': {
      const soft = rng.nextFloat() < 0.3;
      return {
        type,
        bodyA: a,
        bodyB: b,
        anchor,
        linearHertz: soft ? rng.range(1, 20) : 0,
        angularHertz: soft ? rng.range(1, 20) : 0,
        dampingRatio: rng.range(0, 2),
      };
    }
    case 'distance': {
      const spring = rng.nextFloat() < 0.4;
      const d = Math.sqrt((pb.x - pa.x) ** 2 + (pb.y - pa.y) ** 2);
      return {
        type,
        bodyA: a,
        bodyB: b,
        length: d * rng.range(0.5, 1.5),
        minLength: d * rng.range(0, 0.5),
        maxLength: d * rng.range(1.5, 2),
        enableSpring: spring,
        hertz: rng.range(0.5, 10),
        dampingRatio: rng.range(0, 1),
      };
    }
    case 'motor':
      return {
        type,
        bodyA: a,
        bodyB: b,
        maxForce: rng.range(1, 1000),
        maxTorque: rng.range(1, 500),
        correctionFactor: rng.range(0, 1),
      };
  }
}

/** Builds network `kind` from `seed` in a new world (default settings). */
export function buildNetwork(kind: NetworkKind, seed: number): Network {
  const rng = createRandom(seed * 7919 + NETWORK_KINDS.indexOf(kind));
  const world = new World();
  const ground = world.createBody({ position: { x: 0, y: 0 } });
  ground.createShape(Shape.box(30, 0.5));
  const tree = kind.startsWith('tree');
  const contacts = kind !== 'tree-revolute-bare';
  const motors = kind !== 'tree-revolute-bare';
  const violated = kind === 'revolute-violated' || (kind === 'prismatic' && rng.nextFloat() < 0.7);
  const heavy = kind === 'heavy';
  const count = 20 + rng.int(31);
  const bodies: Body[] = [];
  for (let i = 0; i < count; i++) {
    const body = world.createBody({
      type: 'dynamic',
      position: { x: rng.range(-6, 6), y: rng.range(2, 12) },
      angle: rng.range(-Math.PI, Math.PI),
    });
    const hw = rng.range(0.1, 0.6);
    const hh = rng.range(0.1, 0.6);
    const mass = heavy ? (rng.nextFloat() < 0.3 ? 1000 : 1) : rng.range(0.5, 5);
    body.createShape(Shape.box(hw, hh), {
      density: mass / (4 * hw * hh),
      // contacts off: no shape collides with another (the ground is the only other category)
      filter: contacts ? undefined : { categoryBits: 2, maskBits: 0 },
    });
    bodies.push(body);
  }
  const types: readonly (typeof JOINT_TYPES)[number][] =
    kind === 'revolute-violated' || kind === 'tree-revolute' || kind === 'tree-revolute-bare'
      ? ['revolute']
      : kind === 'prismatic' || kind === 'tree-prismatic'
        ? ['prismatic']
        : kind === 'weld'
          ? ['weld']
          : JOINT_TYPES;
  const pick = () => types[rng.int(types.length)];
  const joints: Joint[] = [];
  const join = (a: Body, b: Body) =>
    joints.push(world.createJoint(jointDef(rng, pick(), a, b, violated, motors)));
  // a spanning tree: each body hangs on an earlier one or, for the first 1-4, on the ground
  const pins = 1 + rng.int(4);
  for (let i = 0; i < count; i++) {
    if (i < pins) join(ground, bodies[i]);
    else join(bodies[rng.int(i)], bodies[i]);
  }
  if (!tree) {
    // loops: extra joints between random pairs, and a few more pins
    const extra = 2 + rng.int(Math.ceil(count / 3));
    for (let k = 0; k < extra; k++) {
      const i = rng.int(count);
      let j = rng.int(count + 1) - 1;
      if (j === i) j = (i + 1) % count;
      join(j === -1 ? ground : bodies[j], bodies[i]);
    }
  }
  return { world, ground, bodies, joints };
}

/** What a network did over a run: NaN, bodies at the speed limit, the largest point-joint gap. */
export interface NetworkRun {
  /** first step at which some body state was not finite, or -1 */
  nanStep: number;
  /** bodies that reached 99 % of the speed limit at some step */
  atClamp: number;
  /** largest speed seen (m/s) */
  maxSpeed: number;
}

const MAX_SPEED = 400;

/** Steps `network` `steps` times at 60 Hz and reports what went wrong. */
export function runNetwork(network: Network, steps: number): NetworkRun {
  const { world, bodies } = network;
  const atClamp = new Set<Body>();
  let maxSpeed = 0;
  for (let s = 0; s < steps; s++) {
    world.step(1 / 60);
    for (const body of bodies) {
      const p = body.position;
      const v = body.linearVelocity;
      const w = body.angularVelocity;
      if (!Number.isFinite(p.x + p.y + v.x + v.y + w + body.angle))
        return { nanStep: s, atClamp: atClamp.size, maxSpeed };
      const speed = Math.sqrt(v.x * v.x + v.y * v.y);
      if (speed > maxSpeed) maxSpeed = speed;
      if (speed >= 0.99 * MAX_SPEED) atClamp.add(body);
    }
  }
  return { nanStep: -1, atClamp: atClamp.size, maxSpeed };
}
