import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, World } from '../../src/index';

/**
 * Issue 27 (known), found again by the API fuzzer (test/property: "rotation not unit (c²+s² =
 * 1.3e43)" and a kinematic body whose rotation became (0, 0)): angles of about 1e18 and more are
 * accepted but give a rotation that is not a unit pair (NaN from 1e20), which the step then spreads.
 * Every accepted angle must give a unit rotation, or be refused with a FulcrumError.
 */
const angles = [1e15, 1e18, 1e20, 1e100, 1e300, -Number.MAX_VALUE];

function expectUnit(q: { c: number; s: number }): void {
  expect(Number.isFinite(q.c) && Number.isFinite(q.s)).toBe(true);
  expect(q.c * q.c + q.s * q.s).toBeCloseTo(1, 12);
}

describe('a huge angle', () => {
  for (const angle of angles) {
    it(`${angle} gives a unit rotation through createBody, setAngle and setTransform, and a finite step`, () => {
      const world = new World();
      world.createBody({ position: { x: 0, y: -1 } }).createShape(Shape.box(10, 1));
      const calls: (() => { rotation: { c: number; s: number } })[] = [
        () => world.createBody({ type: 'dynamic', position: { x: 0, y: 1 }, angle }),
        () => {
          const b = world.createBody({ type: 'dynamic', position: { x: 2, y: 1 } });
          b.setAngle(angle);
          return b;
        },
        () => {
          const b = world.createBody({ type: 'kinematic', position: { x: -2, y: 1 } });
          b.setTransform({ x: -2, y: 1 }, angle);
          return b;
        },
      ];
      const bodies = [];
      for (const call of calls) {
        try {
          bodies.push(call());
        } catch (e) {
          expect(e).toBeInstanceOf(FulcrumError);
        }
      }
      for (const b of bodies) expectUnit(b.rotation);
      for (const b of bodies) (b as ReturnType<World['createBody']>).createShape(Shape.box(0.5, 0.5));
      for (let i = 0; i < 30; i++) world.step(1 / 60);
      for (const b of bodies) {
        expectUnit(b.rotation);
        const p = (b as ReturnType<World['createBody']>).position;
        expect(Number.isFinite(p.x) && Number.isFinite(p.y)).toBe(true);
      }
    });
  }
});
