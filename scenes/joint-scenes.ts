/**
 * Jointed scenes for tests and demos: pendulum, bridge, ragdolls, a car on bumpy ground, Newton's
 * cradle and the slingshot. (The joint grid and the heavy chain are in joints.ts.)
 */
import { GRAVITY, groundBody } from './common';
import type { Scene, SceneBody, SceneJoint, V } from './types';

/** A 1 m pendulum: a small heavy disc on a revolute joint at the origin, released at `angle`. */
export function pendulum({
  length = 1,
  startX = 1,
  startY = 0,
}: {
  length?: number;
  startX?: number;
  startY?: number;
} = {}): Scene {
  const d = Math.hypot(startX, startY);
  const position = { x: (startX / d) * length, y: (startY / d) * length };
  return {
    name: 'pendulum',
    gravity: GRAVITY,
    bodies: [
      { type: 'static', position: { x: 0, y: 0 }, shapes: [], tag: 'pivot' },
      { type: 'dynamic', position, shapes: [{ kind: 'circle', radius: 0.05, density: 100 }], tag: 'bob' },
    ],
    joints: [{ type: 'revolute', bodyA: 0, bodyB: 1, anchor: { x: 0, y: 0 } }],
    view: { center: { x: 0, y: -0.5 }, halfHeight: 1.5 },
  };
}

/** A rope bridge of `planks` planks between two static posts 1 m above the ground. */
export function bridge({ planks = 20 }: { planks?: number } = {}): Scene {
  const width = 1;
  const bodies: SceneBody[] = [groundBody(planks)];
  const joints: SceneJoint[] = [];
  const left = (-planks * width) / 2;
  let prev = 0;
  for (let i = 0; i < planks; i++) {
    bodies.push({
      type: 'dynamic',
      position: { x: left + width * (i + 0.5), y: 4 },
      shapes: [{ kind: 'box', halfWidth: width / 2, halfHeight: 0.0625, density: 20 }],
      tag: 'plank',
    });
    joints.push({
      type: 'revolute',
      bodyA: prev,
      bodyB: bodies.length - 1,
      anchor: { x: left + width * i, y: 4 },
    });
    prev = bodies.length - 1;
  }
  joints.push({ type: 'revolute', bodyA: prev, bodyB: 0, anchor: { x: -left, y: 4 } });
  for (let i = 0; i < 5; i++) {
    bodies.push({
      type: 'dynamic',
      position: { x: left + 3 + 3 * i, y: 6 },
      shapes: [{ kind: 'box', halfWidth: 0.4, halfHeight: 0.4 }],
      tag: 'load',
    });
  }
  return {
    name: 'bridge',
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: 3 }, halfHeight: 6 },
  };
}

/**
 * Adds a ragdoll standing with its feet at `feet`: capsule limbs on limited revolute joints. Its bodies
 * are tagged, in this order: pelvis, torso, head, then thigh, shin, arm and forearm of the left side
 * and of the right.
 */
export function ragdoll(bodies: SceneBody[], joints: SceneJoint[], feet: V): void {
  const add = (x: number, y: number, p1: V, p2: V, radius: number, tag: string): number => {
    bodies.push({
      type: 'dynamic',
      position: { x: feet.x + x, y: feet.y + y },
      shapes: [{ kind: 'capsule', p1, p2, radius, density: 1, friction: 0.6 }],
      tag,
    });
    return bodies.length - 1;
  };
  const hinge = (a: number, b: number, x: number, y: number, lower: number, upper: number) =>
    joints.push({
      type: 'revolute',
      bodyA: a,
      bodyB: b,
      anchor: { x: feet.x + x, y: feet.y + y },
      limit: { lower, upper },
    });
  const v = (y: number) => ({ x: 0, y });
  const pelvis = add(0, 1.0, v(-0.08), v(0.08), 0.12, 'pelvis');
  const torso = add(0, 1.35, v(-0.18), v(0.18), 0.14, 'torso');
  const head = add(0, 1.75, v(-0.04), v(0.04), 0.12, 'head');
  hinge(pelvis, torso, 0, 1.12, -0.3, 0.5);
  hinge(torso, head, 0, 1.62, -0.5, 0.5);
  for (const side of [-1, 1]) {
    const thigh = add(side * 0.08, 0.7, v(-0.18), v(0.18), 0.07, 'thigh');
    const shin = add(side * 0.08, 0.25, v(-0.18), v(0.18), 0.06, 'shin');
    hinge(pelvis, thigh, side * 0.08, 0.92, -0.5, 1.2);
    hinge(thigh, shin, side * 0.08, 0.47, -1.5, 0);
    const arm = add(side * 0.25, 1.3, v(-0.15), v(0.15), 0.05, 'arm');
    const forearm = add(side * 0.25, 0.98, v(-0.15), v(0.15), 0.045, 'forearm');
    hinge(torso, arm, side * 0.25, 1.48, -1.5, 2.5);
    hinge(arm, forearm, side * 0.25, 1.14, 0, 2);
  }
}

/** A row of ragdolls dropped onto the ground. */
export function ragdolls({ count = 5 }: { count?: number } = {}): Scene {
  const bodies: SceneBody[] = [groundBody(20)];
  const joints: SceneJoint[] = [];
  for (let i = 0; i < count; i++) ragdoll(bodies, joints, { x: -6 + 3 * i, y: 1 + i });
  return {
    name: 'ragdolls',
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: 3 }, halfHeight: 6 },
  };
}

/**
 * A car (chassis 2.5 m x 0.5 m, wheels 0.4 m on sprung wheel joints with motors) on ground with
 * bumps 0.15 m high every 2 m, made of static segments, ending in a hill.
 */
export function carOnHills({
  length = 60,
  motorSpeed = -12,
}: {
  length?: number;
  motorSpeed?: number;
} = {}): Scene {
  const ground: SceneBody = { type: 'static', position: { x: 0, y: 0 }, shapes: [], tag: 'ground' };
  const points: V[] = [{ x: -10, y: 0 }];
  for (let x = 0; x < length; x += 2) points.push({ x: x + 1, y: 0.15 }, { x: x + 2, y: 0 });
  points.push({ x: length + 10, y: 3 }, { x: length + 20, y: 3 });
  for (let i = 1; i < points.length; i++)
    ground.shapes.push({ kind: 'segment', p1: points[i - 1], p2: points[i], friction: 0.9 });
  const chassis: SceneBody = {
    type: 'dynamic',
    position: { x: 0, y: 1 },
    shapes: [{ kind: 'box', halfWidth: 1.25, halfHeight: 0.25, density: 1 }],
    tag: 'chassis',
  };
  const wheel = (x: number): SceneBody => ({
    type: 'dynamic',
    position: { x, y: 0.45 },
    shapes: [{ kind: 'circle', radius: 0.4, density: 1, friction: 0.9 }],
    tag: 'wheel',
  });
  const joints: SceneJoint[] = [-0.9, 0.9].map((x, i) => ({
    type: 'wheel' as const,
    bodyA: 1,
    bodyB: 2 + i,
    anchor: { x, y: 0.45 },
    axis: { x: 0, y: 1 },
    spring: { hertz: 4, dampingRatio: 0.7 },
    motor: { speed: motorSpeed, maxTorque: 30 },
  }));
  return {
    name: 'car',
    gravity: GRAVITY,
    bodies: [ground, chassis, wheel(-0.9), wheel(0.9)],
    joints,
    view: { center: { x: 0, y: 2 }, halfHeight: 5 },
  };
}

/**
 * Newton's cradle: `count` steel balls on 2 m strings, the first pulled aside. The balls hang `gap`
 * apart: touching balls would be solved as one block in the step of the impact and share the momentum,
 * while a small gap lets each impact happen in its own substep, one after the other.
 */
export function newtonsCradle({ count = 5, gap = 0.02 }: { count?: number; gap?: number } = {}): Scene {
  const r = 0.25;
  const bodies: SceneBody[] = [{ type: 'static', position: { x: 0, y: 4 }, shapes: [], tag: 'frame' }];
  const joints: SceneJoint[] = [];
  for (let i = 0; i < count; i++) {
    const x = (i - (count - 1) / 2) * (2 * r + gap);
    const pulled = i === 0;
    const position = pulled ? { x: x - 2, y: 4 } : { x, y: 2 };
    bodies.push({
      type: 'dynamic',
      position,
      shapes: [{ kind: 'circle', radius: r, density: 7.8, restitution: 1, friction: 0 }],
      tag: 'ball',
    });
    joints.push({
      type: 'distance',
      bodyA: 0,
      bodyB: i + 1,
      anchorA: { x, y: 4 },
      anchorB: position,
      length: 2,
    });
  }
  return {
    name: 'newtons-cradle',
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: 2.5 }, halfHeight: 3 },
  };
}

/**
 * The slingshot: a bird held by a spring to the anchor of the sling, a tower of planks and a target.
 * Pull the bird back and let it go (in a demo through a mouse joint; in a test with an impulse).
 */
export function slingshot(): Scene {
  const anchor: V = { x: -8, y: 2 };
  const bodies: SceneBody[] = [
    groundBody(30),
    { type: 'static', position: anchor, shapes: [], tag: 'sling' },
    {
      type: 'dynamic',
      position: anchor,
      shapes: [{ kind: 'circle', radius: 0.3, density: 4, restitution: 0.3 }],
      tag: 'bird',
    },
  ];
  const joints: SceneJoint[] = [
    {
      type: 'distance',
      bodyA: 1,
      bodyB: 2,
      anchorA: anchor,
      anchorB: anchor,
      length: 0,
      spring: { hertz: 3, dampingRatio: 0.3 },
    },
  ];
  for (let level = 0; level < 3; level++) {
    const y = level * 1.2;
    for (const x of [6, 8]) {
      bodies.push({
        type: 'dynamic',
        position: { x, y: y + 0.5 },
        shapes: [{ kind: 'box', halfWidth: 0.1, halfHeight: 0.5, density: 0.6 }],
        tag: 'wood',
      });
    }
    bodies.push({
      type: 'dynamic',
      position: { x: 7, y: y + 1.1 },
      shapes: [{ kind: 'box', halfWidth: 1.2, halfHeight: 0.1, density: 0.6 }],
      tag: 'wood',
    });
  }
  bodies.push({
    type: 'dynamic',
    position: { x: 7, y: 0.35 },
    shapes: [{ kind: 'circle', radius: 0.35, density: 1 }],
    tag: 'target',
  });
  return {
    name: 'slingshot',
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: 3 }, halfHeight: 7 },
  };
}
