import { describe, expect, it } from 'vitest';
import { FulcrumError, World } from '../../src/index';

/**
 * Issue 27 (known), found again by the API fuzzer (test/property, seed 27, shrunk to a kinematic body of
 * angular velocity 4.1e-300 rad/s stepped with dt = 1e300 s, a turn of 4.1 rad in one step, which came out
 * 1e-6 off; tame seeds found 20 rad/s over dt = 1 s): a kinematic body's angular velocity is not
 * clamped, and the position update assumes at most a quarter turn per substep, so fast kinematic bodies
 * turn by the wrong angle, then lose their unit rotation, then reach NaN. A kinematic body moves exactly
 * as told: each step it turns by (its angular velocity) x dt, whatever the speed, or a speed the engine
 * cannot follow is refused at the call (or clamped there: then it turns by the speed it reports).
 * Also pinned: a kinematic body told to turn keeps turning (a shapeless one fell asleep after one step
 * of 1 s, and then read 0 rad/s).
 */
function turnOneStep(omega: number, dt: number): { c: number; s: number; expected: number } | undefined {
  const world = new World({ gravity: { x: 0, y: 0 } });
  let body: ReturnType<World['createBody']>;
  try {
    body = world.createBody({ type: 'kinematic', angularVelocity: omega });
  } catch (e) {
    expect(e).toBeInstanceOf(FulcrumError);
    return undefined;
  }
  try {
    world.step(dt);
  } catch (e) {
    // a step the engine cannot take is refused at the call, and leaves the world as it was
    expect(e).toBeInstanceOf(FulcrumError);
    return undefined;
  }
  // the speed it reports after the step: the step scales a turn faster than the speed limit down to it
  // (README, Speed limits), and the body must then have turned by exactly what it reports
  const q = body.rotation;
  return { c: q.c, s: q.s, expected: body.angularVelocity * dt };
}

describe('a kinematic body', () => {
  for (const [omega, dt] of [
    [20, 1 / 60],
    [100, 1 / 60],
    [1000, 1 / 60],
    [20, 1],
    [1e8, 1 / 60],
    [1e12, 1 / 60],
    [4.124218636590431e-300, 1e300],
  ]) {
    it(`at ${omega} rad/s turns by its angular velocity x dt in a step of ${dt} s`, () => {
      const r = turnOneStep(omega, dt);
      if (!r) return;
      expect(r.expected).not.toBe(0);
      expect(Number.isFinite(r.c) && Number.isFinite(r.s)).toBe(true);
      expect(r.c * r.c + r.s * r.s).toBeCloseTo(1, 9);
      // compare as rotations (the angle is taken modulo 2 pi)
      expect(r.c).toBeCloseTo(Math.cos(r.expected), 6);
      expect(r.s).toBeCloseTo(Math.sin(r.expected), 6);
    });
  }
});
