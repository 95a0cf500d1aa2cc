import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, World } from '../../src/index';

/**
 * Found by the API fuzzer (test/property, seeds 1000-1009 before subnormal densities were kept out of
 * tame runs): a density so small that the body's mass underflows (2.47e-322 kg/m² on a 0.1 m box gives
 * 5e-324 kg and an inertia of 0) is accepted, and then the body hangs in the air, and a weld from it to
 * the ground puts NaN into the static ground's velocity in the first step; seed 9000: touching a
 * kinematic body, it puts NaN into the kinematic body's pose. The density must be refused with a
 * FulcrumError, or the body must behave as a (very light) body.
 */
function tinyBox(world: World) {
  const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 0 } });
  try {
    body.createShape(Shape.box(0.05, 0.05), { density: 2.47e-322 });
  } catch (e) {
    expect(e).toBeInstanceOf(FulcrumError);
    return undefined;
  }
  return body;
}

describe('a body whose mass underflows', () => {
  it('falls like any body (or its density is refused)', () => {
    const world = new World({ gravity: { x: 0, y: -10 } });
    const body = tinyBox(world);
    if (!body) return;
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    // free fall for 1 s: y = -g t^2 / 2 = -5 m (the integrator's step error is under 2%)
    expect(body.position.y).toBeCloseTo(-5, 0);
    expect(Number.isFinite(body.linearVelocity.y)).toBe(true);
  });

  it('welded to the ground, leaves the ground and itself finite', () => {
    const world = new World();
    const ground = world.createBody({ position: { x: 0, y: -8 } });
    ground.createShape(Shape.box(30, 1));
    const body = tinyBox(world);
    if (!body) return;
    world.createJoint({ type: 'weld', bodyA: body, bodyB: ground });
    for (let i = 0; i < 10; i++) world.step(1 / 60);
    for (const b of [ground, body]) {
      const v = b.linearVelocity;
      const p = b.position;
      expect([v.x, v.y, b.angularVelocity, p.x, p.y].every(Number.isFinite)).toBe(true);
    }
    expect(ground.linearVelocity).toEqual({ x: 0, y: 0 });
  });

  it('touching a kinematic body and another body, leaves them all finite', () => {
    const world = new World();
    const kinematic = world.createBody({ type: 'kinematic' });
    kinematic.createShape(Shape.circle(0.05));
    const other = world.createBody({ type: 'dynamic' });
    other.createShape(Shape.circle(0.05));
    const tiny = world.createBody({ type: 'dynamic' });
    try {
      tiny.createShape(Shape.capsule({ x: 0, y: 0 }, { x: 0, y: -0.005 }, 0.11), { density: 6.4e-323 });
    } catch (e) {
      expect(e).toBeInstanceOf(FulcrumError);
      return;
    }
    for (let i = 0; i < 10; i++) world.step(1 / 60);
    for (const b of [kinematic, other, tiny]) {
      const p = b.position;
      const q = b.rotation;
      const v = b.linearVelocity;
      expect([p.x, p.y, q.c, q.s, v.x, v.y, b.angularVelocity].every(Number.isFinite)).toBe(true);
    }
    // nothing pushes a kinematic body: it stays where it was put
    expect(kinematic.position).toEqual({ x: 0, y: 0 });
  });
});
