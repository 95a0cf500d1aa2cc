import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';

/**
 * Found by the API fuzzer (test/property, tame run, seed 4000): a circle whose centre lies on a polygon's
 * vertex to within rounding (here the vertex is (5e-324, 5e-324) and the centre (0, 0): the offsets'
 * squares underflow to 0) got the vertex's direction 0 / 0 as its contact normal. The NaN normal reached
 * the contactBegin event and the solver, whose clamp stopped both bodies dead in mid-air.
 */
describe('a circle centred on a polygon vertex to within rounding', () => {
  it('gets a finite unit contact normal, and the pair falls under gravity', () => {
    const world = new World({ gravity: { x: 0, y: -10 } });
    const a = world.createBody({ type: 'dynamic' });
    a.createShape(
      Shape.polygon([
        { x: 5e-324, y: 5e-324 },
        { x: 1, y: 0 },
        { x: 0, y: 1 },
      ]),
    );
    const b = world.createBody({ type: 'dynamic' });
    b.createShape(Shape.circle(0.05));
    const normals: { x: number; y: number }[] = [];
    world.on('contactBegin', (e) => normals.push(e.normal));
    world.step(1 / 60);
    expect(normals).toHaveLength(1);
    const n = normals[0];
    expect(Number.isFinite(n.x) && Number.isFinite(n.y)).toBe(true);
    expect(Math.hypot(n.x, n.y)).toBeCloseTo(1, 12);
    for (let i = 1; i < 30; i++) world.step(1 / 60);
    // the contact only pushes the two apart: their centre of mass falls freely, -g t^2 / 2 = -1.25 m
    // at t = 0.5 s (semi-implicit Euler over 120 substeps: 0.4% more)
    const ma = a.mass;
    const mb = b.mass;
    const y = (ma * a.worldCenter.y + mb * b.worldCenter.y) / (ma + mb);
    const y0 = (ma * (1 / 3) + mb * 0) / (ma + mb);
    expect(y - y0).toBeCloseTo(-1.25, 1);
  });
});
