import { describe, expect, it } from 'vitest';
import { rayCastGeometry, testPoint } from '../../../src/geometry/raycast';
import { Shape } from '../../../src/geometry/shapes';
import { type Geometry, makeRayHit, type Polygon, type RayHit } from '../../../src/geometry/types';
import type { Transform } from '../../../src/math/vec2';
import { random, worldCore, xf } from './brute-force';

function cast(g: Geometry, t: Transform, ox: number, oy: number, dx: number, dy: number): RayHit | null {
  const hit = makeRayHit();
  return rayCastGeometry(g, t, ox, oy, dx, dy, hit) ? hit : null;
}

function expectHit(
  hit: RayHit | null,
  fraction: number,
  nx: number,
  ny: number,
  ox: number,
  oy: number,
  dx: number,
  dy: number,
) {
  expect(hit).not.toBeNull();
  const h = hit as RayHit;
  expect(Math.abs(h.fraction - fraction)).toBeLessThan(1e-9);
  expect(Math.abs(h.pointX - (ox + fraction * dx))).toBeLessThan(1e-9);
  expect(Math.abs(h.pointY - (oy + fraction * dy))).toBeLessThan(1e-9);
  expect(Math.abs(h.normalX - nx)).toBeLessThan(1e-9);
  expect(Math.abs(h.normalY - ny)).toBeLessThan(1e-9);
}

/** Local to world with Math.cos / Math.sin. */
function toWorld(t: Transform, x: number, y: number): [number, number] {
  return [t.q.c * x - t.q.s * y + t.p.x, t.q.s * x + t.q.c * y + t.p.y];
}

/** Reference ray cast against a sharp polygon: intersect every world edge (Cramer's rule), keep the first. */
function polygonOracle(g: Polygon, t: Transform, ox: number, oy: number, dx: number, dy: number) {
  const v = worldCore(g, t).points;
  let best: { fraction: number; nx: number; ny: number } | null = null;
  let inside = true;
  for (let i = 0; i < v.length; i++) {
    const a = v[i];
    const b = v[(i + 1) % v.length];
    const ex = b.x - a.x;
    const ey = b.y - a.y;
    const len = Math.hypot(ex, ey);
    if (ey * (ox - a.x) - ex * (oy - a.y) >= 0) inside = false;
    // o + f d = a + s e  =>  f d - s e = a - o
    const det = -dx * ey + dy * ex;
    if (det === 0) continue;
    const rx = a.x - ox;
    const ry = a.y - oy;
    const f = (-rx * ey + ry * ex) / det;
    const s = (dx * ry - dy * rx) / det;
    if (f >= 0 && f <= 1 && s >= 0 && s <= 1 && (best === null || f < best.fraction)) {
      best = { fraction: f, nx: ey / len, ny: -ex / len };
    }
  }
  return inside ? null : best;
}

describe('rayCastGeometry', () => {
  it('circle: matches the quadratic root', () => {
    const g = Shape.circle(0.5, { x: 0.2, y: 0.1 });
    const t = xf(0.5, -0.5, 0.7);
    const [cx, cy] = toWorld(t, 0.2, 0.1);
    const [ox, oy, dx, dy] = [-3, -1, 10, 1.5];
    const a = dx * dx + dy * dy;
    const b = (ox - cx) * dx + (oy - cy) * dy;
    const c = (ox - cx) ** 2 + (oy - cy) ** 2 - 0.25;
    const f = (-b - Math.sqrt(b * b - a * c)) / a;
    const px = ox + f * dx;
    const py = oy + f * dy;
    expectHit(cast(g, t, ox, oy, dx, dy), f, (px - cx) / 0.5, (py - cy) / 0.5, ox, oy, dx, dy);
    expect(cast(g, t, ox, oy, -dx, -dy)).toBeNull(); // pointing away
    expect(cast(g, t, ox, oy, dx * f * 0.99, dy * f * 0.99)).toBeNull(); // too short
  });

  it('box and rotated polygons: match edge intersections on random rays', () => {
    const rnd = random(9);
    const shapes: Polygon[] = [
      Shape.box(1, 0.5),
      Shape.box(0.7, 0.3, { x: 0.2, y: -0.1 }, 0.4),
      Shape.polygon([
        { x: -0.8, y: -0.5 },
        { x: 0.9, y: -0.3 },
        { x: 1, y: 0.4 },
        { x: 0.1, y: 0.9 },
        { x: -0.6, y: 0.5 },
      ]),
    ];
    let hits = 0;
    for (let k = 0; k < 3000; k++) {
      const g = shapes[k % shapes.length];
      const t = xf(rnd() - 0.5, rnd() - 0.5, rnd() * 6.3);
      const [ox, oy, dx, dy] = [rnd() * 6 - 3, rnd() * 6 - 3, rnd() * 8 - 4, rnd() * 8 - 4];
      const expected = polygonOracle(g, t, ox, oy, dx, dy);
      const hit = cast(g, t, ox, oy, dx, dy);
      if (expected === null) {
        expect(hit).toBeNull();
      } else {
        hits++;
        expectHit(hit, expected.fraction, expected.nx, expected.ny, ox, oy, dx, dy);
      }
    }
    expect(hits).toBeGreaterThan(250);
  });

  it('capsule: flat side and round cap, analytic', () => {
    const g = Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.5);
    const t = xf(2, 1, 0.6);
    const c = Math.cos(0.6);
    const s = Math.sin(0.6);
    // flat side: local ray from (0.3, 3) straight down, hits y = 0.5 at fraction 2.5 / 4
    let [ox, oy] = toWorld(t, 0.3, 3);
    let [dx, dy] = [s * 4, -c * 4];
    expectHit(cast(g, t, ox, oy, dx, dy), 2.5 / 4, -s, c, ox, oy, dx, dy);
    // cap: local ray from (-3, 0.2) along +x hits x = -1 - sqrt(0.25 - 0.04)
    [ox, oy] = toWorld(t, -3, 0.2);
    [dx, dy] = [c * 5, s * 5];
    const hx = -1 - Math.sqrt(0.25 - 0.04);
    const [nx, ny] = [(hx + 1) / 0.5, 0.2 / 0.5];
    expectHit(cast(g, t, ox, oy, dx, dy), (hx + 3) / 5, c * nx - s * ny, s * nx + c * ny, ox, oy, dx, dy);
  });

  it('rounded box: flat face and corner arc, analytic', () => {
    const g = Shape.polygon(Shape.box(1, 1).vertices, 0.5);
    const t = xf(0, 0, 0);
    expectHit(cast(g, t, 0.3, 4, 0, -4), 2.5 / 4, 0, 1, 0.3, 4, 0, -4);
    // along the diagonal: hits the corner circle at (1, 1) + 0.5 (1, 1)/sqrt 2
    const corner = 1 + 0.5 / Math.SQRT2;
    expectHit(cast(g, t, 3, 3, -3, -3), (3 - corner) / 3, Math.SQRT1_2, Math.SQRT1_2, 3, 3, -3, -3);
  });

  it('segment: two-sided line intersection, normal facing the origin', () => {
    const g = Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 });
    const t = xf(1, 1, Math.PI / 6);
    const c = Math.cos(Math.PI / 6);
    const s = Math.sin(Math.PI / 6);
    for (const side of [1, -1]) {
      const [ox, oy] = toWorld(t, 0.4, 2 * side);
      const [dx, dy] = [-s * -3 * side, c * -3 * side];
      expectHit(cast(g, t, ox, oy, dx, dy), 2 / 3, -s * side, c * side, ox, oy, dx, dy);
    }
    // oblique ray: o + f d crosses y = 0 at x = 0.5
    const [ox, oy] = toWorld(t, -0.5, 1);
    const [lx, ly] = [1, -2];
    const [dx, dy] = [c * lx - s * ly, s * lx + c * ly];
    expectHit(cast(g, t, ox, oy, dx, dy), 0.5, -s, c, ox, oy, dx, dy);
    // along the line: hits the near end with the normal against the ray
    expectHit(cast(g, xf(0, 0, 0), -3, 0, 4, 0), 0.5, -1, 0, -3, 0, 4, 0);
    expect(cast(g, xf(0, 0, 0), -3, 0.1, 4, 0)).toBeNull();
  });

  it('follows the rule: inside origins and zero translations miss, grazing rays hit', () => {
    const identity = xf(0, 0, 0);
    const circle = Shape.circle(1);
    const box = Shape.box(1, 1);
    const capsule = Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.5);
    const rounded = Shape.polygon(Shape.box(1, 1).vertices, 0.25);
    for (const g of [circle, box, capsule, rounded]) {
      expect(cast(g, identity, 0.1, 0.2, 5, 1)).toBeNull(); // origin inside
      expect(cast(g, identity, -5, 0, 0, 0)).toBeNull(); // zero length
    }
    expect(cast(Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 }), identity, 0, 0, 0, 0)).toBeNull();
    // tangent to the circle at (0, 1)
    expectHit(cast(circle, identity, -2, 1, 4, 0), 0.5, 0, 1, -2, 1, 4, 0);
    // grazing the top edge of the box: first touches the corner (-1, 1) of the left face
    expectHit(cast(box, identity, -3, 1, 6, 0), 1 / 3, -1, 0, -3, 1, 6, 0);
    // touching a single corner
    expectHit(cast(box, identity, -2, 0, 2, 2), 0.5, -1, 0, -2, 0, 2, 2);
    // along the capsule's flat side: first touches the top of the left cap
    expectHit(cast(capsule, identity, -3, 0.5, 6, 0), (3 - 1) / 6, 0, 1, -3, 0.5, 6, 0);
    // origin on the surface: hits at 0 going in, misses going out
    expectHit(cast(circle, identity, 1, 0, -1, 0), 0, 1, 0, 1, 0, -1, 0);
    expect(cast(circle, identity, 1, 0, 1, 0)).toBeNull();
    expectHit(cast(box, identity, 1, 0, -1, 0), 0, 1, 0, 1, 0, -1, 0);
    expect(cast(box, identity, 1, 0, 1, 0)).toBeNull();
  });

  it('leaves the hit as it was on a miss, and writes all of it on a hit', () => {
    const t = xf(0.5, -0.25, 0.7);
    const shapes = [
      Shape.circle(1),
      Shape.box(1, 1),
      Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.5),
      Shape.polygon(Shape.box(1, 1).vertices, 0.25),
      Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 }),
    ];
    const marked = { fraction: 7, pointX: 8, pointY: 9, normalX: 10, normalY: 11 };
    for (const g of shapes) {
      // rays that pass the shape, stop short of it, and (but for the segment, which a ray starting on
      // it hits) start inside it
      const rays = [
        [-5, 4, 10, 0],
        [-5, 0, 1, 0],
      ];
      if (g.type !== 'segment') rays.push([0.5, -0.25, 0.01, 0.01]);
      for (const [ox, oy, dx, dy] of rays) {
        const hit = { ...marked };
        expect(rayCastGeometry(g, t, ox, oy, dx, dy, hit)).toBe(false);
        expect(hit).toEqual(marked);
      }
      // one hit, into a marked record and a fresh one: the same numbers
      const hit = { ...marked };
      expect(rayCastGeometry(g, t, -5, -0.25, 10, 0.2, hit)).toBe(true);
      expect(hit).toEqual(cast(g, t, -5, -0.25, 10, 0.2));
    }
  });
});

describe('testPoint', () => {
  it('is inside or on the surface; segments contain nothing', () => {
    const t = xf(1, 0, Math.PI / 2);
    const rounded = Shape.polygon(Shape.box(1, 1).vertices, 0.5);
    expect(testPoint(Shape.circle(1), t, 1, 0.99)).toBe(true);
    expect(testPoint(Shape.circle(1), t, 1, 1.01)).toBe(false);
    expect(testPoint(Shape.box(2, 0.5), t, 1.4, 1.9)).toBe(true); // rotated: tall in world
    expect(testPoint(Shape.box(2, 0.5), t, 1.6, 0)).toBe(false);
    expect(testPoint(Shape.box(1, 1), xf(0, 0, 0), 1, 1)).toBe(true);
    expect(testPoint(rounded, xf(0, 0, 0), 1.3, 1.3)).toBe(true);
    expect(testPoint(rounded, xf(0, 0, 0), 1.4, 1.4)).toBe(false);
    expect(testPoint(rounded, xf(0, 0, 0), 0, 1.5)).toBe(true);
    const capsule = Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.5);
    expect(testPoint(capsule, xf(0, 0, 0), 1.3, 0.3)).toBe(true);
    expect(testPoint(capsule, xf(0, 0, 0), 1.4, 0.4)).toBe(false);
    expect(testPoint(Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 }), xf(0, 0, 0), 0, 0)).toBe(false);
  });
});
