import { describe, expect, it } from 'vitest';
import { type Body, FulcrumError, Shape, stateHash, World } from '../../src/index';
import { drawWorld } from '../../src/render/debug-draw';

const DT = 1 / 60;

/**
 * Every kind of state at once: a stack, a pyramid, circles, capsules and polygons, a sleeping island,
 * joints of every type, sensors, a kinematic body, a bullet, destroyed bodies (free slots), pending
 * forces, plain and non-plain userData.
 */
function mixedScene(): { world: World; bodies: Body[] } {
  const world = new World({ gravity: { x: 0, y: -10 }, subSteps: 4 });
  const bodies: Body[] = [];
  const ground = world.createBody({ position: { x: 0, y: -1 }, userData: { name: 'ground', tags: [1, 2] } });
  ground.createShape(Shape.box(40, 1), { friction: 0.7 });
  ground.createShape(Shape.segment({ x: -40, y: 8 }, { x: -25, y: 0 }));

  // stack
  for (let i = 0; i < 8; i++) {
    const b = world.createBody({ type: 'dynamic', position: { x: -18, y: 0.5 + i * 1.02 } });
    b.createShape(Shape.box(0.5, 0.5), { friction: 0.6 });
    bodies.push(b);
  }
  // pyramid
  const rows = 6;
  for (let row = 0; row < rows; row++) {
    for (let i = 0; i < rows - row; i++) {
      const b = world.createBody({
        type: 'dynamic',
        position: { x: -10 + i * 1.05 + row * 0.525, y: 0.5 + row * 1.0 },
      });
      b.createShape(Shape.box(0.5, 0.5));
      bodies.push(b);
    }
  }
  // a heap of circles, capsules and polygons
  for (let i = 0; i < 24; i++) {
    const b = world.createBody({
      type: 'dynamic',
      position: { x: 2 + (i % 6) * 1.3, y: 4 + Math.floor(i / 6) * 1.4 },
      angle: i * 0.41,
    });
    switch (i % 3) {
      case 0:
        b.createShape(Shape.circle(0.45), { restitution: 0.4 });
        break;
      case 1:
        b.createShape(Shape.capsule({ x: -0.4, y: 0 }, { x: 0.4, y: 0 }, 0.22));
        break;
      default:
        b.createShape(
          Shape.polygon([
            { x: -0.5, y: -0.3 },
            { x: 0.5, y: -0.35 },
            { x: 0.25, y: 0.45 },
            { x: -0.3, y: 0.5 },
          ]),
        );
    }
    bodies.push(b);
  }
  // an island created asleep: two boxes resting on each other far away
  const s1 = world.createBody({ type: 'dynamic', position: { x: 30, y: 0.5 }, awake: false });
  s1.createShape(Shape.box(0.5, 0.5));
  const s2 = world.createBody({ type: 'dynamic', position: { x: 30, y: 1.5 }, awake: false });
  s2.createShape(Shape.box(0.5, 0.5));
  bodies.push(s1, s2);

  // joints: a pendulum chain (revolute), a spring (distance), a slider (prismatic), welds, a car
  // wheel (wheel), a motor joint and a mouse joint
  const anchor = world.createBody({ position: { x: 14, y: 12 } });
  anchor.createShape(Shape.box(0.2, 0.2));
  let prev = anchor;
  for (let i = 0; i < 4; i++) {
    const link = world.createBody({ type: 'dynamic', position: { x: 14.5 + i, y: 12 } });
    link.createShape(Shape.capsule({ x: -0.5, y: 0 }, { x: 0.5, y: 0 }, 0.1), { density: 2 });
    world.createJoint({
      type: 'revolute',
      bodyA: prev,
      bodyB: link,
      anchor: { x: 14 + i, y: 12 },
      enableLimit: i === 0,
      lowerAngle: -1,
      upperAngle: 1,
      enableMotor: i === 1,
      motorSpeed: 1,
      maxMotorTorque: 5,
      userData: { link: i },
    });
    prev = link;
    bodies.push(link);
  }
  const springBall = world.createBody({ type: 'dynamic', position: { x: 20, y: 8 } });
  springBall.createShape(Shape.circle(0.3));
  world.createJoint({
    type: 'distance',
    bodyA: anchor,
    bodyB: springBall,
    length: 3,
    enableSpring: true,
    hertz: 2,
    dampingRatio: 0.2,
    minLength: 1,
    maxLength: 5,
  });
  const slider = world.createBody({ type: 'dynamic', position: { x: 22, y: 3 } });
  slider.createShape(Shape.box(0.4, 0.2));
  world.createJoint({
    type: 'prismatic',
    bodyA: ground,
    bodyB: slider,
    anchor: { x: 22, y: 3 },
    axis: { x: 1, y: 0.2 },
    enableLimit: true,
    lower: -2,
    upper: 2,
    enableMotor: true,
    motorSpeed: 2,
    maxMotorForce: 50,
  });
  const weldA = world.createBody({ type: 'dynamic', position: { x: 25, y: 6 } });
  weldA.createShape(Shape.box(0.5, 0.1));
  const weldB = world.createBody({ type: 'dynamic', position: { x: 26, y: 6 } });
  weldB.createShape(Shape.box(0.5, 0.1));
  world.createJoint({ type: 'weld', bodyA: weldA, bodyB: weldB, anchor: { x: 25.5, y: 6 }, linearHertz: 5 });
  const chassis = world.createBody({ type: 'dynamic', position: { x: 8, y: 2 } });
  chassis.createShape(Shape.box(1, 0.25));
  for (const dx of [-0.8, 0.8]) {
    const wheel = world.createBody({ type: 'dynamic', position: { x: 8 + dx, y: 1.4 } });
    wheel.createShape(Shape.circle(0.35), { friction: 0.9 });
    world.createJoint({
      type: 'wheel',
      bodyA: chassis,
      bodyB: wheel,
      anchor: { x: 8 + dx, y: 1.4 },
      axis: { x: 0, y: 1 },
      enableSpring: true,
      hertz: 4,
      dampingRatio: 0.7,
      enableMotor: true,
      motorSpeed: -3,
      maxMotorTorque: 10,
    });
    bodies.push(wheel);
  }
  const follower = world.createBody({ type: 'dynamic', position: { x: 12, y: 5 } });
  follower.createShape(Shape.box(0.3, 0.3));
  world.createJoint({
    type: 'motor',
    bodyA: ground,
    bodyB: follower,
    linearOffset: { x: 12, y: 7 },
    angularOffset: 0.5,
    maxForce: 100,
    maxTorque: 20,
  });
  const dragged = world.createBody({ type: 'dynamic', position: { x: 5, y: 10 } });
  dragged.createShape(Shape.circle(0.4));
  world.createJoint({ type: 'mouse', body: dragged, target: { x: 7, y: 11 }, maxForce: 200 });
  bodies.push(chassis, springBall, slider, weldA, weldB, follower, dragged);

  // sensors, one on a kinematic platform moving through the heap
  const zone = world.createBody({ position: { x: 4, y: 1 } });
  zone.createShape(Shape.box(3, 1), { isSensor: true, enableSensorEvents: true });
  const platform = world.createBody({
    type: 'kinematic',
    position: { x: -4, y: 3 },
    linearVelocity: { x: 0.5, y: 0 },
    angularVelocity: 0.3,
  });
  platform.createShape(Shape.box(1.5, 0.2));
  platform.createShape(Shape.circle(0.5, { x: 0, y: 1 }), { isSensor: true, enableSensorEvents: true });
  bodies.push(platform);

  // a fast bullet and bodies destroyed again (free slots in every store)
  const bullet = world.createBody({
    type: 'dynamic',
    bullet: true,
    position: { x: -30, y: 12 },
    linearVelocity: { x: 60, y: -10 },
  });
  bullet.createShape(Shape.circle(0.1));
  bodies.push(bullet);
  for (let i = 0; i < 3; i++) {
    const doomed = world.createBody({ type: 'dynamic', position: { x: 0, y: 30 + i } });
    doomed.createShape(Shape.circle(0.5));
    world.destroyBody(doomed);
  }
  return { world, bodies };
}

function stepped(steps: number): { world: World; bodies: Body[] } {
  const scene = mixedScene();
  for (let i = 0; i < steps; i++) scene.world.step(DT);
  return scene;
}

/** Bytes equal, with the first differing offset in the message when they are not. */
function expectSameBytes(a: Uint8Array, b: Uint8Array, what: string): void {
  let first = -1;
  for (let i = 0; i < Math.min(a.length, b.length); i++) {
    if (a[i] !== b[i]) {
      first = i;
      break;
    }
  }
  expect({ lengths: [a.length, b.length], firstDifference: first }, what).toEqual({
    lengths: [a.length, a.length],
    firstDifference: -1,
  });
}

/**
 * Everything a user may ask of a world between steps without changing it: every query (sensors
 * included, hits and misses, casts that start inside), the shapes' own tests, reads of events,
 * joints and bodies, and a debug drawing of everything.
 */
function readEverything(world: World): void {
  const sensors = { includeSensors: true };
  world.castRay({ x: -40, y: 5 }, { x: 80, y: -4 });
  world.castRay({ x: 4, y: 1 }, { x: 0, y: -3 }, sensors);
  world.castRayAll({ x: -40, y: 0.5 }, { x: 80, y: 0.2 }, sensors);
  world.castRayAll({ x: 14, y: 30 }, { x: 0.3, y: -40 });
  world.queryAABB({ lowerBound: { x: -20, y: -2 }, upperBound: { x: 30, y: 15 } });
  world.queryPoint({ x: 4, y: 1 });
  world.castShape(Shape.circle(0.3), { position: { x: -20, y: 3 }, angle: 0.2 }, { x: 40, y: -2 });
  world.castShape(Shape.box(0.4, 0.2), { position: { x: -10, y: 0.5 } }, { x: 1, y: 0 }, sensors);
  world.overlapShape(Shape.box(6, 3), { position: { x: 3, y: 3 } });
  world.overlapShape(Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.2), {
    p: { x: 14, y: 12 },
    q: { c: 0, s: 1 },
  });
  for (const body of world.bodies) {
    body.getLinearVelocityAt({ x: 1, y: 2 });
    for (const shape of body.shapes) {
      shape.testPoint({ x: 0, y: 0 });
      shape.rayCast({ x: -50, y: 1 }, { x: 100, y: 2 });
      shape.getAABB();
    }
  }
  for (const joint of world.joints) {
    joint.getReactionForce();
    joint.getReactionTorque();
  }
  const events = world.events;
  expect(events).toBeDefined();
  const none = () => {};
  const draw = {
    drawPolygon: none,
    drawCircle: none,
    drawCapsule: none,
    drawLine: none,
    drawPoint: none,
    drawAABB: none,
    drawTransform: none,
  };
  drawWorld(world, draw, {
    shapes: true,
    wireframe: false,
    joints: true,
    aabbs: true,
    contacts: true,
    contactNormals: true,
    velocities: true,
    centersOfMass: true,
    sleeping: true,
  });
}

describe('world snapshots', () => {
  it('queries, shape tests, event reads and debug drawing between steps leave the snapshot bytes as they were', () => {
    const plain = mixedScene().world;
    const queried = mixedScene().world;
    for (let i = 0; i < 90; i++) {
      plain.step(DT);
      queried.step(DT);
      readEverything(queried);
      if (i % 30 === 29) expectSameBytes(queried.snapshot(), plain.snapshot(), `after step ${i + 1}`);
    }
    // restoring either gives the same future, also when only one of them is queried on
    const fromPlain = World.restore(plain.snapshot());
    const fromQueried = World.restore(queried.snapshot());
    for (let i = 0; i < 120; i++) {
      fromPlain.step(DT);
      fromQueried.step(DT);
      readEverything(fromQueried);
      expect(stateHash(fromQueried), `step ${i + 1}`).toBe(stateHash(fromPlain));
    }
    expectSameBytes(fromQueried.snapshot(), fromPlain.snapshot(), 'restored copies');
  });

  it('a snapshot does not depend on another world stepping in between (no stale normal of a manifold without points)', () => {
    // two circles near enough for their tight boxes to overlap, too far for a contact point: the
    // manifold is computed and has no points
    const circles = () => {
      const world = new World({ gravity: { x: 0, y: 0 } });
      world.createBody({ type: 'dynamic' }).createShape(Shape.circle(0.5));
      world.createBody({ type: 'dynamic', position: { x: 0.75, y: 0.75 } }).createShape(Shape.circle(0.5));
      return world;
    };
    // a tilted box resting on a tilted plank: its manifolds have normals far from the axes
    const other = new World();
    other.createBody().createShape(Shape.box(5, 0.5, { x: 0, y: 0 }, 0.6435));
    other
      .createBody({ type: 'dynamic', position: { x: 0, y: 1.2 } })
      .createShape(Shape.box(0.5, 0.5, { x: 0, y: 0 }, 0.6435));
    const alone = circles();
    for (let i = 0; i < 3; i++) alone.step(DT);
    const interleaved = circles();
    for (let i = 0; i < 3; i++) {
      other.step(DT);
      interleaved.step(DT);
    }
    expect(alone.contactCount).toBe(1);
    expectSameBytes(interleaved.snapshot(), alone.snapshot(), 'circles');
  });

  it('a restored world steps bit-identically to the original', () => {
    const { world, bodies } = stepped(120);
    // pending forces are state too
    bodies[3].applyForce({ x: 40, y: 0 });
    bodies[20].applyTorque(3);
    const awakeBefore = world.awakeBodyCount;
    expect(awakeBefore).toBeLessThan(world.bodyCount); // the sleeping island is still asleep
    const bytes = world.snapshot();
    const restored = World.restore(bytes);
    expect(stateHash(restored)).toBe(stateHash(world));
    expect(restored.bodyCount).toBe(world.bodyCount);
    expect(restored.awakeBodyCount).toBe(awakeBefore);
    expect(restored.contactCount).toBe(world.contactCount);
    expect(restored.joints.map((j) => j.type)).toEqual(world.joints.map((j) => j.type));
    for (let i = 0; i < 300; i++) {
      world.step(DT);
      restored.step(DT);
      expect(stateHash(restored), `step ${i + 1}`).toBe(stateHash(world));
    }
    expect(restored.contactCount).toBe(world.contactCount);
    expect(restored.awakeBodyCount).toBe(world.awakeBodyCount);
  });

  it('restored handles act on the same bodies: the worlds stay identical after the same calls', () => {
    const { world } = stepped(60);
    const restored = World.restore(world.snapshot());
    const pairs = [world, restored].map((w) => [...w.bodies]);
    expect(pairs[1].length).toBe(pairs[0].length);
    for (const [w, list] of [
      [world, pairs[0]],
      [restored, pairs[1]],
    ] as const) {
      for (const b of list) expect(b.world).toBe(w);
      list[10].setLinearVelocity({ x: 3, y: 4 });
      list[list.length - 2].applyLinearImpulse({ x: 0, y: 2 });
      w.destroyBody(list[5]);
      w.destroyJoint(w.joints[2]);
      const extra = w.createBody({ type: 'dynamic', position: { x: 1, y: 15 } });
      extra.createShape(Shape.box(0.3, 0.6));
      w.createJoint({ type: 'distance', bodyA: extra, bodyB: list[12], length: 2 });
      list[30].setAwake(false);
    }
    for (let i = 0; i < 120; i++) {
      world.step(DT);
      restored.step(DT);
      expect(stateHash(restored), `step ${i + 1}`).toBe(stateHash(world));
    }
    // the restored world's joints and shapes point at its own handles
    for (const j of restored.joints) {
      expect(j.world).toBe(restored);
      expect(j.bodyA.world).toBe(restored);
      expect(j.bodyB.world).toBe(restored);
    }
    for (const b of restored.bodies) for (const s of b.shapes) expect(s.body).toBe(b);
  });

  it('snapshot -> restore -> snapshot gives identical bytes', () => {
    const { world } = stepped(90);
    const bytes = world.snapshot();
    const again = World.restore(bytes).snapshot();
    expect(again.length).toBe(bytes.length);
    expect(Buffer.from(again).equals(Buffer.from(bytes))).toBe(true);
    // and a snapshot is a function of the state: the same world twice gives the same bytes
    expect(Buffer.from(world.snapshot()).equals(Buffer.from(bytes))).toBe(true);
  });

  it('a snapshot does not change when the world changes afterwards', () => {
    const { world, bodies } = stepped(30);
    const bytes = world.snapshot();
    const copy = bytes.slice();
    const hash = stateHash(World.restore(bytes));
    for (let i = 0; i < 30; i++) world.step(DT);
    world.destroyBody(bodies[0]);
    world.createBody({ type: 'dynamic' }).createShape(Shape.circle(1));
    expect(Buffer.from(bytes).equals(Buffer.from(copy))).toBe(true);
    expect(stateHash(World.restore(bytes))).toBe(hash);
    // and the restored world shares nothing with the original
    const restored = World.restore(bytes);
    const before = stateHash(world);
    for (let i = 0; i < 10; i++) restored.step(DT);
    expect(stateHash(world)).toBe(before);
  });

  it('keeps world settings and plain userData, drops other userData', () => {
    const world = new World({
      gravity: { x: 1, y: -3 },
      subSteps: 7,
      enableSleep: false,
      enableContinuous: false,
      lengthUnitsPerMeter: 50,
    });
    world.hitEventThreshold = 2.5;
    class Sprite {}
    const a = world.createBody({ type: 'dynamic', userData: { name: 'a', list: [1, 2, { x: -0 }] } });
    const shape = a.createShape(Shape.circle(1), { userData: 'wheel' });
    const b = world.createBody({ type: 'dynamic', position: { x: 3, y: 0 }, userData: new Sprite() });
    b.createShape(Shape.box(1, 1), { userData: () => 1 });
    world.createJoint({ type: 'distance', bodyA: a, bodyB: b, userData: 42 });
    const restored = World.restore(world.snapshot());
    expect(restored.gravity).toEqual({ x: 1, y: -3 });
    expect(restored.subSteps).toBe(7);
    expect(restored.enableSleep).toBe(false);
    expect(restored.hitEventThreshold).toBe(2.5);
    expect(restored.enableContinuous).toBe(false);
    expect(restored.core.settings).toEqual(world.core.settings);
    const [ra, rb] = [...restored.bodies];
    expect(ra.userData).toEqual({ name: 'a', list: [1, 2, { x: -0 }] });
    expect(Object.is((ra.userData as { list: [0, 0, { x: number }] }).list[2].x, -0)).toBe(true);
    expect(ra.userData).not.toBe(a.userData);
    expect(ra.shapes[0].userData).toBe('wheel');
    expect(ra.shapes[0].geometry).toEqual(shape.geometry);
    expect(rb.userData).toBeUndefined();
    expect(rb.shapes[0].userData).toBeUndefined();
    expect(restored.joints[0].userData).toBe(42);
    // restored geometry is still accepted by the API
    ra.createShape(rb.shapes[0].geometry);
  });

  it('event handlers are not kept', () => {
    const world = new World();
    let calls = 0;
    world.on('postStep', () => calls++);
    const restored = World.restore(world.snapshot());
    restored.step(DT);
    expect(calls).toBe(0);
    world.step(DT);
    expect(calls).toBe(1);
  });

  it('rejects bad input with a FulcrumError naming the argument', () => {
    const { world } = stepped(5);
    const bytes = world.snapshot();
    const bad = (value: unknown, message: RegExp) => {
      expect(() => World.restore(value as Uint8Array)).toThrow(FulcrumError);
      expect(() => World.restore(value as Uint8Array)).toThrow(message);
    };
    bad(undefined, /bytes must be a Uint8Array/);
    bad([1, 2, 3], /bytes must be a Uint8Array/);
    bad(bytes.buffer, /bytes must be a Uint8Array/);
    bad('FLCS', /bytes must be a Uint8Array/);
    bad(new Uint8Array(0), /bytes .*truncated/);
    bad(bytes.subarray(0, 10), /bytes .*truncated/);
    bad(bytes.subarray(0, bytes.length - 1), /bytes .*truncated/);
    bad(bytes.subarray(0, bytes.length >> 1), /bytes .*truncated/);
    const magic = bytes.slice();
    magic[0] = 0x58;
    bad(magic, /bytes .*magic/);
    const version = bytes.slice();
    version[4] = 99;
    bad(version, /bytes .*version 99/);
    for (const at of [6, 7]) {
      const reserved = bytes.slice();
      reserved[at] = 1;
      bad(reserved, /bytes .*reserved header bytes/);
    }
    const build = bytes.slice();
    build[8] ^= 1;
    bad(build, /bytes .*different build/);
    const damaged = bytes.slice();
    damaged[damaged.length >> 1] ^= 0x40;
    bad(damaged, /bytes .*damaged/);
    const longer = new Uint8Array(bytes.length + 3);
    longer.set(bytes);
    bad(longer, /bytes .*extra bytes/);
  });

  it('snapshots may be taken from step and event handlers', () => {
    const world = new World();
    world.createBody({ type: 'dynamic' }).createShape(Shape.circle(1));
    const ground = world.createBody({ position: { x: 0, y: -1.5 } });
    ground.createShape(Shape.box(5, 0.5), { enableContactEvents: true });
    let error: unknown;
    world.on('preStep', () => {
      // preStep runs before the lock: allowed
      world.snapshot();
    });
    world.on('contactBegin', () => {
      try {
        world.snapshot();
      } catch (e) {
        error = e;
      }
    });
    for (let i = 0; i < 60; i++) world.step(DT);
    // events are delivered after the step: snapshots are allowed there too
    expect(error).toBeUndefined();
  });
});
