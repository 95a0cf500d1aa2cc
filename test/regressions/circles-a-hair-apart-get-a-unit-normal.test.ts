import { describe, expect, it } from 'vitest';
import { type Geometry, Shape, World } from '../../src/index';

/**
 * Found by the API fuzzer (test/property, seed 2035 of a fuzz run): two circles whose centres were
 * 1.6e-162 apart got a contact normal of length 0.71, not 1. The square of so small an offset is
 * subnormal, and the offset divided by the square root of it is no unit vector. Centres that close
 * (closer than 1e-12 of the radii) are taken as coincident: the circle pushes along a fixed direction.
 */
function beginNormal(other: Geometry, offset: number): { x: number; y: number } {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const a = world.createBody({ type: 'dynamic', position: { x: offset, y: 0 } });
  a.createShape(Shape.circle(0.05));
  const b = world.createBody({ type: 'dynamic' });
  b.createShape(other);
  world.step(1 / 60);
  expect(world.events.contactBegin).toHaveLength(1);
  const n = world.events.contactBegin[0].normal;
  for (const body of [a, b]) {
    expect(Number.isFinite(body.position.x) && Number.isFinite(body.position.y)).toBe(true);
  }
  return n;
}

describe('a circle a hair away from the centre of another shape', () => {
  for (const offset of [-1.5717277847026288e-162, 1e-300, 5e-324, -1e-20]) {
    for (const [name, geometry] of [
      ['circle', Shape.circle(0.05)],
      ['capsule', Shape.capsule({ x: 0, y: -0.05 }, { x: 0, y: 0.05 }, 0.05)],
      ['box (a vertex at the offset)', Shape.box(0.05, 0.05, { x: 0.05, y: 0.05 })],
    ] as const) {
      it(`(${name}, ${offset} apart) gets a unit contact normal`, () => {
        const n = beginNormal(geometry, offset);
        expect(Math.hypot(n.x, n.y)).toBeCloseTo(1, 12);
      });
    }
  }
});
