import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, stateHash, World } from '../../src/index';

function twoBodies() {
  const world = new World();
  const ground = world.createBody();
  ground.createShape(Shape.box(5, 0.5));
  const a = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
  a.createShape(Shape.box(0.5, 0.5));
  const b = world.createBody({ type: 'dynamic', position: { x: 2, y: 2 } });
  b.createShape(Shape.box(0.5, 0.5));
  for (let i = 0; i < 5; i++) world.step(1 / 60);
  return { world, ground, a, b };
}

function rejects(world: World, f: () => unknown, message: RegExp): void {
  const hash = stateHash(world);
  const joints = world.joints.length;
  expect(f).toThrow(FulcrumError);
  expect(f).toThrow(message);
  expect(stateHash(world)).toBe(hash);
  expect(world.joints.length).toBe(joints);
}

describe('joint API', () => {
  it('rejects bad definitions and leaves the world as it was', () => {
    const { world, a, b } = twoBodies();
    rejects(
      world,
      () => world.createJoint({ type: 'revolute', bodyA: a, bodyB: a, anchor: { x: 0, y: 0 } }),
      /bodyB/,
    );
    rejects(world, () => world.createJoint({ type: 'hinge', bodyA: a, bodyB: b } as never), /type.*hinge/);
    rejects(
      world,
      () => world.createJoint({ type: 'distance', bodyA: a, bodyB: b, length: -1 }),
      /length.*-1/,
    );
    rejects(
      world,
      () => world.createJoint({ type: 'distance', bodyA: a, bodyB: b, hertz: Number.NaN }),
      /hertz.*NaN/,
    );
    rejects(
      world,
      () => world.createJoint({ type: 'distance', bodyA: a, bodyB: b, minLength: 3, maxLength: 1 }),
      /minLength must be <= maxLength/,
    );
    rejects(
      world,
      () =>
        world.createJoint({
          type: 'revolute',
          bodyA: a,
          bodyB: b,
          anchor: { x: 1, y: 2 },
          lowerAngle: 1,
          upperAngle: -1,
        }),
      /lowerAngle must be <= upperAngle/,
    );
    rejects(
      world,
      () =>
        world.createJoint({
          type: 'prismatic',
          bodyA: a,
          bodyB: b,
          anchor: { x: 1, y: 2 },
          axis: { x: 0, y: 0 },
        }),
      /axis/,
    );
    rejects(
      world,
      () => world.createJoint({ type: 'mouse', body: a, target: { x: Number.POSITIVE_INFINITY, y: 0 } }),
      /target/,
    );
    rejects(
      world,
      () =>
        world.createJoint({
          type: 'weld',
          bodyA: a,
          bodyB: b,
          anchor: { x: 1, y: 2 },
          stiffness: 3,
        } as never),
      /unknown option "stiffness"/,
    );
    const gone = world.createBody({ type: 'dynamic' });
    world.destroyBody(gone);
    rejects(
      world,
      () => world.createJoint({ type: 'revolute', bodyA: a, bodyB: gone, anchor: { x: 0, y: 0 } }),
      /destroyed/,
    );
  });

  it('destroying a body destroys its joints; a destroyed joint rejects use', () => {
    const { world, a, b } = twoBodies();
    const joint = world.createJoint({ type: 'revolute', bodyA: a, bodyB: b, anchor: { x: 1, y: 2 } });
    expect(a.joints).toEqual([joint]);
    expect(world.joints).toEqual([joint]);
    world.destroyBody(b);
    expect(joint.isValid).toBe(false);
    expect(world.joints).toEqual([]);
    expect(a.joints).toEqual([]);
    expect(() => joint.getReactionForce()).toThrow(/joint has been destroyed/);
    expect(() => world.destroyJoint(joint)).toThrow(FulcrumError);
  });

  it('collideConnected: jointed bodies do not collide unless asked to', () => {
    for (const collideConnected of [false, true]) {
      const world = new World({ gravity: { x: 0, y: 0 } });
      const a = world.createBody({ type: 'dynamic', position: { x: 0, y: 0 } });
      a.createShape(Shape.box(0.5, 0.5));
      const b = world.createBody({ type: 'dynamic', position: { x: 0.8, y: 0 } }); // overlapping
      b.createShape(Shape.box(0.5, 0.5));
      world.createJoint({
        type: 'distance',
        bodyA: a,
        bodyB: b,
        length: 0.8,
        enableSpring: true,
        hertz: 0,
        maxLength: 5,
        collideConnected,
      });
      for (let i = 0; i < 30; i++) world.step(1 / 60);
      const gap = b.position.x - a.position.x;
      if (collideConnected) expect(gap).toBeGreaterThan(0.99);
      else expect(gap).toBeCloseTo(0.8, 6);
    }
  });

  it('joints keep sleeping islands together and wake them', () => {
    const { world, a, b, ground } = twoBodies();
    world.createJoint({ type: 'distance', bodyA: a, bodyB: b });
    for (let i = 0; i < 180; i++) world.step(1 / 60);
    expect(a.isAwake).toBe(false);
    expect(b.isAwake).toBe(false);
    b.applyLinearImpulse({ x: 0, y: 1 });
    expect(a.isAwake).toBe(true);
    expect(ground.isAwake).toBe(false);
  });

  it('reports the reaction force of a hanging weight: m g', () => {
    const world = new World();
    const anchor = world.createBody({ position: { x: 0, y: 0 } });
    const bob = world.createBody({ type: 'dynamic', position: { x: 0, y: -1 } });
    bob.createShape(Shape.circle(0.1), { density: 2 / (Math.PI * 0.01) });
    const joint = world.createJoint({ type: 'revolute', bodyA: anchor, bodyB: bob, anchor: { x: 0, y: 0 } });
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    const f = joint.getReactionForce();
    expect(f.x).toBeCloseTo(0, 6);
    expect(f.y).toBeCloseTo(2 * 10, 3);
  });

  it('setters change motors, limits and springs, validate, and wake the bodies', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.createBody();
    const wheel = world.createBody({ type: 'dynamic' });
    wheel.createShape(Shape.circle(0.5));
    const joint = world.createJoint({
      type: 'revolute',
      bodyA: ground,
      bodyB: wheel,
      anchor: { x: 0, y: 0 },
    });
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    expect(wheel.isAwake).toBe(false);
    joint.setMaxMotorTorque(100);
    joint.setMotorSpeed(3);
    joint.enableMotor(true);
    expect(wheel.isAwake).toBe(true);
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    expect(wheel.angularVelocity).toBeCloseTo(3, 6);
    const hash = stateHash(world);
    expect(() => joint.setMotorSpeed(Number.NaN)).toThrow(/speed.*NaN/);
    expect(() => joint.setLimits(1, -1)).toThrow(/lowerAngle must be <= upperAngle/);
    expect(() => joint.setSpring(-1, 0)).toThrow(/hertz.*-1/);
    expect(stateHash(world)).toBe(hash);
    joint.setLimits(-0.1, 0.1);
    joint.enableLimit(true);
    joint.enableMotor(false);
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    expect(Math.abs(joint.angle)).toBeLessThan(0.1 + 0.01);
  });
});
