import { describe, expect, it } from 'vitest';
import { FulcrumError } from '../../../src/core/errors';
import { computeMass } from '../../../src/geometry/mass';
import { testPoint } from '../../../src/geometry/raycast';
import { Shape } from '../../../src/geometry/shapes';
import type { Geometry, MassData } from '../../../src/geometry/types';
import { xf } from './brute-force';

const mass = (g: Geometry, density: number): MassData =>
  computeMass(g, density, { mass: 0, centerX: 0, centerY: 0, inertia: 0 });

/** Midpoint-rule integration over a grid: mass, centre and inertia about the centre. */
function integrate(g: Geometry, density: number, half: number, cells: number): MassData {
  const h = (2 * half) / cells;
  const identity = xf(0, 0, 0);
  let area = 0;
  let mx = 0;
  let my = 0;
  let polar = 0;
  for (let i = 0; i < cells; i++) {
    const x = -half + (i + 0.5) * h;
    for (let j = 0; j < cells; j++) {
      const y = -half + (j + 0.5) * h;
      if (!testPoint(g, identity, x, y)) continue;
      area += h * h;
      mx += x * h * h;
      my += y * h * h;
      polar += (x * x + y * y) * h * h;
    }
  }
  const cx = mx / area;
  const cy = my / area;
  return {
    mass: density * area,
    centerX: cx,
    centerY: cy,
    inertia: density * (polar - area * (cx * cx + cy * cy)),
  };
}

describe('computeMass', () => {
  it('box: m = rho w h, I = m (w^2 + h^2) / 12, even rotated and offset', () => {
    const m = mass(Shape.box(1.5, 0.5, { x: 2, y: -1 }, 0.7), 3);
    const w = 3;
    const h = 1;
    expect(m.mass).toBeCloseTo(3 * w * h, 12);
    expect(m.centerX).toBeCloseTo(2, 12);
    expect(m.centerY).toBeCloseTo(-1, 12);
    expect(m.inertia).toBeCloseTo((m.mass * (w * w + h * h)) / 12, 12);
  });

  it('circle: m = rho pi r^2, I = m r^2 / 2 about its centre', () => {
    const m = mass(Shape.circle(0.75, { x: 1, y: 2 }), 2);
    expect(m.mass).toBeCloseTo(2 * Math.PI * 0.75 ** 2, 14);
    expect([m.centerX, m.centerY]).toEqual([1, 2]);
    expect(m.inertia).toBeCloseTo((m.mass * 0.75 ** 2) / 2, 14);
  });

  it('capsule: rectangle plus disc, I = rho [2rL (L^2/12 + r^2/3) + pi r^2 (r^2/2 + L^2/4) + 4 r^3 L / 3]', () => {
    const r = 0.4;
    const L = 2;
    const rho = 1.5;
    const g = Shape.capsule({ x: -1, y: 1 }, { x: 1, y: 1 }, r);
    const m = mass(g, rho);
    expect(m.mass).toBeCloseTo(rho * (2 * r * L + Math.PI * r * r), 13);
    expect([m.centerX, m.centerY]).toEqual([0, 1]);
    const expected =
      rho *
      (2 * r * L * ((L * L) / 12 + (r * r) / 3) +
        Math.PI * r * r * ((r * r) / 2 + (L * L) / 4) +
        (4 * r ** 3 * L) / 3);
    expect(m.inertia).toBeCloseTo(expected, 13);
    // and against numerical integration, tilted
    const tilted = Shape.capsule({ x: -0.6, y: -0.8 }, { x: 0.6, y: 0.8 }, r);
    const numeric = integrate(tilted, rho, 1.5, 1200);
    expect(mass(tilted, rho).inertia / numeric.inertia).toBeCloseTo(1, 3);
    expect(mass(tilted, rho).inertia).toBeCloseTo(expected, 12);
  });

  it('sharp polygon: triangle with textbook values', () => {
    // right triangle legs a, b: area ab/2, centroid (a/3, b/3), I_c = m (a^2 + b^2) / 18
    const a = 3;
    const b = 2;
    const m = mass(
      Shape.polygon([
        { x: 0, y: 0 },
        { x: a, y: 0 },
        { x: 0, y: b },
      ]),
      2,
    );
    expect(m.mass).toBeCloseTo(a * b, 13);
    expect(m.centerX).toBeCloseTo(a / 3, 13);
    expect(m.centerY).toBeCloseTo(b / 3, 13);
    expect(m.inertia).toBeCloseTo((m.mass * (a * a + b * b)) / 18, 12);
  });

  it('rounded polygon: exact area and inertia matching numerical integration', () => {
    const r = 0.3;
    const rounded = Shape.polygon(Shape.box(1, 0.5).vertices, r);
    const m = mass(rounded, 1);
    expect(m.mass).toBeCloseTo(2 * 1 + 2 * (2 + 1) * r + Math.PI * r * r, 13);
    const numeric = integrate(rounded, 1, 1.5, 1500);
    expect(m.inertia / numeric.inertia).toBeCloseTo(1, 3);
    const tri = Shape.polygon(
      [
        { x: -0.5, y: -0.4 },
        { x: 0.9, y: -0.2 },
        { x: 0.1, y: 0.8 },
      ],
      0.2,
    );
    const t = mass(tri, 2);
    const tn = integrate(tri, 2, 1.3, 1500);
    expect(t.mass / tn.mass).toBeCloseTo(1, 3);
    expect(t.centerX).toBeCloseTo(tn.centerX, 3);
    expect(t.centerY).toBeCloseTo(tn.centerY, 3);
    expect(t.inertia / tn.inertia).toBeCloseTo(1, 3);
  });

  it('segment: no mass', () => {
    const m = mass(Shape.segment({ x: 0, y: 0 }, { x: 2, y: 0 }), 1);
    expect([m.mass, m.inertia, m.centerX, m.centerY]).toEqual([0, 0, 1, 0]);
  });

  it('rejects a bad density', () => {
    expect(() => mass(Shape.circle(1), -1)).toThrow(FulcrumError);
    expect(() => mass(Shape.circle(1), Number.NaN)).toThrow(/density/);
  });
});
