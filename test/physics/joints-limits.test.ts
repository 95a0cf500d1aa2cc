import { describe, expect, it } from 'vitest';
import { type Body, type RevoluteJoint, Shape, World } from '../../src/index';

const DT = 1 / 60;
/** the documented position-correction speed of joints (rad/s): Settings, JOINT_PUSH_MAX_TURN */
const PUSH_TURN = 3;

/**
 * A chain of `links` boxes (0.5 m pin to pin, 1 kg) hanging from a hinge at the origin, each hinge
 * after the first limited to [-0.2, 0.2] rad but built at 0.2 + `past` rad: curled into a spiral,
 * every limit `past` radians past.
 */
function curledChain(links: number, past: number, limitFirst: boolean) {
  const world = new World();
  const ground = world.createBody();
  const half = 0.25;
  let x = 0;
  let y = 0;
  let angle = 0;
  let prev: Body = ground;
  const joints: RevoluteJoint[] = [];
  for (let i = 0; i < links; i++) {
    const link = world.createBody({
      type: 'dynamic',
      position: { x: x + half * Math.cos(angle), y: y + half * Math.sin(angle) },
      angle,
    });
    link.createShape(Shape.box(half, 0.05), { density: 1 / (4 * half * 0.05) });
    const limited = i > 0 || limitFirst;
    joints.push(
      world.createJoint({
        type: 'revolute',
        bodyA: prev,
        bodyB: link,
        anchor: { x, y },
        referenceAngle: 0,
        enableLimit: limited,
        lowerAngle: i === 0 ? -Math.PI : -0.2,
        upperAngle: i === 0 ? Math.PI : 0.2,
      }),
    );
    x += 2 * half * Math.cos(angle);
    y += 2 * half * Math.sin(angle);
    angle += 0.2 + past;
    prev = link;
  }
  return { world, joints: joints.slice(1) };
}

function worstPast(joints: readonly RevoluteJoint[]): number {
  let worst = 0;
  for (const j of joints) worst = Math.max(worst, j.angle - 0.2, -0.2 - j.angle);
  return worst;
}

function widestGap(joints: readonly RevoluteJoint[]): number {
  let gap = 0;
  for (const j of joints) {
    const a = j.anchorA;
    const b = j.anchorB;
    gap = Math.max(gap, Math.hypot(b.x - a.x, b.y - a.y));
  }
  return gap;
}

describe('joint limits', () => {
  for (const limitFirst of [true, false]) {
    it(`a 40-link chain started 1 rad past its limits is back inside within 1 s, links within 1 cm (first hinge ${limitFirst ? 'limited to ±π' : 'free'})`, () => {
      const { world, joints } = curledChain(40, 1, limitFirst);
      let gap = 0;
      let back = -1;
      for (let s = 1; s <= 60; s++) {
        world.step(DT);
        gap = Math.max(gap, widestGap(joints));
        // pushed back no faster than the documented push speed (and no slower than half of it)
        if (s === 6) {
          expect(worstPast(joints)).toBeGreaterThan(1 - PUSH_TURN * s * DT - 1e-9);
          expect(worstPast(joints)).toBeLessThan(1 - 0.5 * PUSH_TURN * s * DT);
        }
        if (back === -1 && worstPast(joints) < 0.01) back = s;
      }
      expect(back).toBeGreaterThan(0);
      expect(back * DT).toBeLessThanOrEqual(1);
      expect(gap).toBeLessThan(0.01);
    });
  }

  it('a hinge turned past half a turn from its reference reads its angle in (-π, π] and holds its limits', () => {
    // the relative angle of the bodies is in (-π, π] and the reference angle near π: unwrapped, the
    // joint angle read 2π off and the limits threw the arm a full turn round
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.createBody({ angle: 3 });
    const arm = world.createBody({ type: 'dynamic', position: { x: 1, y: 0 }, angle: -3 });
    arm.createShape(Shape.box(1, 0.1));
    const joint = world.createJoint({
      type: 'revolute',
      bodyA: ground,
      bodyB: arm,
      anchor: { x: 0, y: 0 },
      enableLimit: true,
      lowerAngle: -0.1,
      upperAngle: 0.1,
    });
    expect(joint.angle).toBe(0);
    arm.setAngularVelocity(2);
    let worst = 0;
    let fastest = 0;
    for (let s = 0; s < 120; s++) {
      world.step(DT);
      expect(joint.angle).toBeGreaterThan(-Math.PI);
      expect(joint.angle).toBeLessThanOrEqual(Math.PI);
      worst = Math.max(worst, Math.abs(joint.angle));
      fastest = Math.max(fastest, Math.abs(arm.angularVelocity));
    }
    // the arm runs into its upper limit within a substep's travel and stays
    expect(worst).toBeLessThan(0.1 + 2 * (DT / 4) + 1e-9);
    expect(fastest).toBeLessThanOrEqual(2);
  });

  it('a motor driving an arm against its limit stops there, its torque at the motor limit', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ground = world.createBody();
    const arm = world.createBody({ type: 'dynamic', position: { x: 1, y: 0 } });
    arm.createShape(Shape.box(1, 0.1), { density: 5 });
    const joint = world.createJoint({
      type: 'revolute',
      bodyA: ground,
      bodyB: arm,
      anchor: { x: 0, y: 0 },
      enableLimit: true,
      lowerAngle: -0.5,
      upperAngle: 0.5,
      enableMotor: true,
      motorSpeed: 4,
      maxMotorTorque: 20,
    });
    for (let s = 0; s < 120; s++) world.step(DT);
    expect(joint.angle).toBeGreaterThan(0.5 - 0.01);
    expect(joint.angle).toBeLessThan(0.5 + 0.01);
    expect(Math.abs(arm.angularVelocity)).toBeLessThan(1e-3);
    // the limit takes the motor's whole torque: the net torque on the arm is zero
    expect(Math.abs(joint.getReactionTorque())).toBeLessThan(1e-6);
  });
});
