import { describe, expect, it } from 'vitest';
import { type DistanceOutput, makeDistanceOutput, shapeDistance } from '../../../src/geometry/distance';
import { makeProxy, makeShapeProxy } from '../../../src/geometry/shape-proxy';
import { GjkMemory } from '../../../src/geometry/simplex';
import type { Geometry } from '../../../src/geometry/types';
import type { Transform } from '../../../src/math/vec2';
import {
  box,
  bruteCoreDistance,
  bruteDistance,
  capsule,
  circle,
  polygon,
  radiusOf,
  randomPolygon,
  rng,
  segment,
  worldCore,
  xf,
} from './distance-fixtures';

/** one working memory for every call: each call must write before it reads */
const gjk = new GjkMemory();
const proxyA = makeShapeProxy();
const proxyB = makeShapeProxy();

function dist(ga: Geometry, ta: Transform, gb: Geometry, tb: Transform, useRadii = true): DistanceOutput {
  makeProxy(ga, proxyA);
  makeProxy(gb, proxyB);
  return shapeDistance(gjk, proxyA, ta, proxyB, tb, useRadii, makeDistanceOutput());
}

/** The output is self-consistent: |pB - pA| = distance and, when apart, pB - pA = distance * normal. */
function expectConsistent(o: DistanceOutput, tol = 1e-9): void {
  expect(Math.hypot(o.pointBX - o.pointAX, o.pointBY - o.pointAY)).toBeCloseTo(o.distance, 9);
  if (o.distance > 0) {
    expect(Math.abs(o.pointBX - o.pointAX - o.distance * o.normalX)).toBeLessThan(tol);
    expect(Math.abs(o.pointBY - o.pointAY - o.distance * o.normalY)).toBeLessThan(tol);
    expect(Math.hypot(o.normalX, o.normalY)).toBeCloseTo(1, 12);
  }
}

describe('shapeProxy', () => {
  it('holds the core points and radius of each shape kind', () => {
    const p = makeShapeProxy();
    makeProxy(circle(1, 2, 0.5), p);
    expect([p.count, p.x[0], p.y[0], p.radius]).toEqual([1, 1, 2, 0.5]);
    makeProxy(capsule(-1, 0, 1, 0, 0.25), p);
    expect([p.count, p.x[0], p.x[1], p.radius]).toEqual([2, -1, 1, 0.25]);
    makeProxy(segment(0, 0, 3, 4), p);
    expect([p.count, p.x[1], p.y[1], p.radius]).toEqual([2, 3, 4, 0]);
    makeProxy(box(1, 2, 0.1), p);
    expect([p.count, p.x[2], p.y[2], p.radius]).toEqual([4, 1, 2, 0.1]);
  });
});

describe('shapeDistance: analytic values', () => {
  it('two circles', () => {
    const o = dist(circle(0.2, 0, 0.5), xf(1, 2, 0.3), circle(0, 0, 0.25), xf(4, 6, -1));
    // centre of A is (1, 2) + rot(0.3) * (0.2, 0)
    const c = xf(1, 2, 0.3).q;
    const ax = 1 + 0.2 * c.c;
    const ay = 2 + 0.2 * c.s;
    const d = Math.hypot(4 - ax, 6 - ay);
    expect(Math.abs(o.distance - (d - 0.75))).toBeLessThan(1e-12);
    expect(Math.abs(o.normalX - (4 - ax) / d)).toBeLessThan(1e-12);
    expect(Math.abs(o.pointAX - (ax + (0.5 * (4 - ax)) / d))).toBeLessThan(1e-12);
    expectConsistent(o);
  });

  it('two axis-aligned boxes face to face, and with an offset corner', () => {
    const o = dist(box(1, 1), xf(0, 0, 0), box(0.5, 2), xf(3, 0.7, 0));
    expect(Math.abs(o.distance - 1.5)).toBeLessThan(1e-12);
    expect([o.normalX, o.normalY]).toEqual([1, 0]);
    expect(o.pointAX).toBe(1);
    // corner to corner: B's lower-left corner (2.5, 1.5) vs A's upper-right corner (1, 1)
    const k = dist(box(1, 1), xf(0, 0, 0), box(0.5, 0.5), xf(3, 2, 0));
    expect(Math.abs(k.distance - Math.hypot(1.5, 0.5))).toBeLessThan(1e-12);
    expectConsistent(k);
  });

  it('a box rotated 45 degrees, corner toward a face', () => {
    const o = dist(box(1, 1), xf(0, 0, 0), box(0.5, 0.5), xf(3, 0.1, Math.PI / 4));
    expect(Math.abs(o.distance - (3 - 1 - 0.5 * Math.SQRT2))).toBeLessThan(1e-12);
    expect(Math.abs(o.normalX - 1)).toBeLessThan(1e-12);
    expectConsistent(o);
  });

  it('capsules: parallel, crossing at a distance, and against a rounded box', () => {
    const o = dist(capsule(-1, 0, 1, 0, 0.1), xf(0, 0, 0), capsule(-3, 0, 3, 0, 0.2), xf(0.5, 1, 0));
    expect(Math.abs(o.distance - 0.7)).toBeLessThan(1e-12);
    expectConsistent(o);
    // perpendicular capsule whose end points at the middle of the other
    const p = dist(capsule(-1, 0, 1, 0, 0.1), xf(0, 0, 0), capsule(0, 0, 0, 2, 0.1), xf(0.3, 0.5, 0));
    expect(Math.abs(p.distance - 0.3)).toBeLessThan(1e-12);
    // capsule end toward a rounded box corner along the diagonal
    const q = dist(box(1, 1, 0.05), xf(0, 0, 0), capsule(0, 0, 1, 1, 0.1), xf(2, 2, 0));
    expect(Math.abs(q.distance - (Math.SQRT2 - 0.15))).toBeLessThan(1e-12);
    expectConsistent(q);
  });

  it('rotated polygon (triangle) vertex toward a segment', () => {
    const tri = polygon([
      { x: 0, y: 1 },
      { x: -1, y: -1 },
      { x: 1, y: -1 },
    ]);
    // rotate by pi so the apex (0, 1) points down to (5, -1); segment along y = -3
    const o = dist(tri, xf(5, 0, Math.PI), segment(-10, -3, 10, -3), xf(0, 0, 0));
    expect(Math.abs(o.distance - 2)).toBeLessThan(1e-12);
    expect(Math.abs(o.pointAX - 5)).toBeLessThan(1e-12);
    expect(Math.abs(o.normalY + 1)).toBeLessThan(1e-12);
  });

  it('without radii, returns the distance of the cores', () => {
    const o = dist(circle(0, 0, 1), xf(0, 0, 0), circle(0, 0, 1), xf(3, 4, 0), false);
    expect(o.distance).toBe(5);
    expect([o.pointAX, o.pointAY, o.pointBX, o.pointBY]).toEqual([0, 0, 3, 4]);
  });

  it('accurate far from the world origin', () => {
    const o = dist(box(1, 1), xf(1e5, -2e5, 0.7), box(1, 1), xf(1e5 + 5, -2e5, 0.7));
    // same orientation, offset of 5 along x: compare with the same pair at the origin
    const ref = dist(box(1, 1), xf(0, 0, 0.7), box(1, 1), xf(5, 0, 0.7));
    expect(Math.abs(o.distance - ref.distance)).toBeLessThan(1e-9);
  });
});

describe('shapeDistance: overlap and degenerate input', () => {
  it('overlapping shapes give distance 0; the points meet; core overlap gives a zero normal', () => {
    const o = dist(box(1, 1), xf(0, 0, 0), box(1, 1), xf(1.5, 0.2, 0.3));
    expect(o.distance).toBe(0);
    expect([o.normalX, o.normalY]).toEqual([0, 0]);
    expect(o.pointAX).toBe(o.pointBX);
    // radii overlap while the cores are apart: the point is halfway between the surfaces
    const c = dist(circle(0, 0, 1), xf(0, 0, 0), circle(0, 0, 1), xf(1.5, 0, 0));
    expect(c.distance).toBe(0);
    expect(c.pointAX).toBeCloseTo(0.75, 12);
    expect(c.normalX).toBe(1);
  });

  it('identical points, touching cores and collinear segments', () => {
    const same = dist(circle(0, 0, 0.5), xf(1, 1, 0), circle(0, 0, 0.5), xf(1, 1, 0));
    expect(same.distance).toBe(0);
    expect(Number.isFinite(same.pointAX)).toBe(true);
    // boxes sharing a face exactly
    const touch = dist(box(1, 1), xf(0, 0, 0), box(1, 1), xf(2, 0.5, 0));
    expect(touch.distance).toBe(0);
    // collinear segments apart along their common line
    const col = dist(segment(0, 0, 1, 0), xf(0, 0, 0), segment(0, 0, 1, 0), xf(3, 0, 0));
    expect(Math.abs(col.distance - 2)).toBeLessThan(1e-12);
    expect([col.normalX, col.normalY]).toEqual([1, 0]);
    // collinear overlapping segments
    const over = dist(segment(0, 0, 2, 0), xf(0, 0, 0), segment(0, 0, 2, 0), xf(1, 0, 0));
    expect(over.distance).toBe(0);
    // a circle whose centre lies on a segment
    const on = dist(segment(-1, 0, 1, 0), xf(0, 0, 0), circle(0, 0, 0.1), xf(0.3, 0, 0));
    expect(on.distance).toBe(0);
  });
});

describe('shapeDistance: random shapes against brute force', () => {
  const kinds = ['polygon', 'circle', 'capsule', 'segment'] as const;
  function randomShape(r: () => number): Geometry {
    const k = kinds[Math.floor(r() * 4)];
    const size = 0.2 + 2 * r();
    if (k === 'circle') return circle(r() - 0.5, r() - 0.5, 0.05 + r() * size);
    if (k === 'capsule') return capsule(-size, r() - 0.5, size, r() - 0.5, 0.05 + 0.3 * r());
    if (k === 'segment') return segment(-size, r() - 0.5, size * r(), size);
    return randomPolygon(r, size, r() < 0.5 ? 0 : 0.2 * r());
  }

  it('matches the brute-force edge-pair distance within 1e-9 on 3,000 random pairs', () => {
    const r = rng(7);
    let maxIterations = 0;
    let separated = 0;
    for (let i = 0; i < 3000; i++) {
      const ga = randomShape(r);
      const gb = randomShape(r);
      const ta = xf(20 * r() - 10, 20 * r() - 10, 8 * r() - 4);
      const tb = xf(ta.p.x + 8 * r() - 4, ta.p.y + 8 * r() - 4, 8 * r() - 4);
      const o = dist(ga, ta, gb, tb);
      const ref = bruteDistance(ga, ta, gb, tb);
      expect(Math.abs(o.distance - ref)).toBeLessThan(1e-9);
      expectConsistent(o);
      if (ref > 0) {
        separated++;
        // the witness point on A is (distance + radius of B) away from the core of B
        const dA = bruteCoreDistance([{ x: o.pointAX, y: o.pointAY }], worldCore(gb, tb));
        expect(Math.abs(dA - o.distance - radiusOf(gb))).toBeLessThan(1e-9);
      }
      maxIterations = Math.max(maxIterations, o.iterations);
    }
    expect(separated).toBeGreaterThan(1000);
    expect(maxIterations).toBeLessThan(20);
  });

  it('is deterministic: the same inputs give the same bits', () => {
    const run = () => {
      const r = rng(99);
      const bits: number[] = [];
      for (let i = 0; i < 300; i++) {
        const ga = randomShape(r);
        const gb = randomShape(r);
        const o = dist(ga, xf(r(), r(), 6 * r()), gb, xf(3 * r(), 3 * r(), 6 * r()));
        bits.push(o.distance, o.pointAX, o.pointAY, o.pointBX, o.pointBY, o.normalX, o.normalY);
      }
      return new Float64Array(bits);
    };
    const a = run();
    const b = run();
    expect(Buffer.from(a.buffer).equals(Buffer.from(b.buffer))).toBe(true);
  });
});
