import { describe, expect, it } from 'vitest';
import { FulcrumError } from '../../../src/core/errors';
import { computeShapeBounds } from '../../../src/geometry/bounds';
import { convexHull } from '../../../src/geometry/hull';
import { Pack } from '../../../src/geometry/packed';
import { Shape } from '../../../src/geometry/shapes';
import { type Polygon, ShapeKind } from '../../../src/geometry/types';
import { makeBounds } from '../../../src/math/aabb';
import { random, xf } from './brute-force';

function expectThrows(call: () => unknown, ...fragments: string[]): void {
  let error: unknown;
  try {
    call();
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(FulcrumError);
  for (const fragment of fragments) expect((error as Error).message).toContain(fragment);
}

/** Brute-force hull check: every input point is on the inner side of every hull edge. */
function expectHullOf(g: Polygon, points: { x: number; y: number }[]): void {
  const v = g.vertices;
  for (let i = 0; i < g.count; i++) {
    const a = v[i];
    const b = v[(i + 1) % g.count];
    const c = v[(i + 2) % g.count];
    const ex = b.x - a.x;
    const ey = b.y - a.y;
    const len = Math.hypot(ex, ey);
    // counter-clockwise and strictly convex (no collinear vertex)
    expect((ex * (c.y - a.y) - ey * (c.x - a.x)) / len).toBeGreaterThan(0.005 - 1e-12);
    // unit outward normal
    expect(g.normals[i].x).toBeCloseTo(ey / len, 12);
    expect(g.normals[i].y).toBeCloseTo(-ex / len, 12);
    for (const p of points) {
      expect((ex * (p.y - a.y) - ey * (p.x - a.x)) / len).toBeGreaterThan(-0.005);
    }
  }
  // every hull vertex is an input point
  for (const h of v) expect(points.some((p) => p.x === h.x && p.y === h.y)).toBe(true);
}

/** Brute-force hull vertices: p is extreme when some direction makes it the unique maximum. */
function bruteForceExtremeCount(points: { x: number; y: number }[]): number {
  let count = 0;
  for (const p of points) {
    let extreme = false;
    for (let k = 0; k < 3600 && !extreme; k++) {
      const ux = Math.cos((k * Math.PI) / 1800);
      const uy = Math.sin((k * Math.PI) / 1800);
      extreme = points.every((q) => q === p || q.x * ux + q.y * uy < p.x * ux + p.y * uy);
    }
    if (extreme) count++;
  }
  return count;
}

/**
 * How deep `p` lies inside the convex hull of `points`, from the hull's edges found by brute force:
 * a pair (a, b) is an edge when no point lies to its right. Negative or 0 on the hull.
 */
function bruteForceDepth(p: { x: number; y: number }, points: { x: number; y: number }[]): number {
  let depth = Number.POSITIVE_INFINITY;
  for (const a of points) {
    for (const b of points) {
      const ex = b.x - a.x;
      const ey = b.y - a.y;
      const len = Math.hypot(ex, ey);
      if (len === 0 || points.some((q) => ex * (q.y - a.y) - ey * (q.x - a.x) < 0)) continue;
      depth = Math.min(depth, (ex * (p.y - a.y) - ey * (p.x - a.x)) / len);
    }
  }
  return depth;
}

describe('Shape.polygon hull', () => {
  it('convexHull is the convex hull of random point sets (brute-force convexity and extreme points)', () => {
    const rnd = random(7);
    let compared = 0;
    for (let trial = 0; trial < 150; trial++) {
      const n = 3 + Math.floor(rnd() * 6);
      const points = Array.from({ length: n }, () => ({ x: rnd() * 4 - 2, y: rnd() * 4 - 2 }));
      let hull: { x: number; y: number }[];
      try {
        hull = convexHull(points, 'points');
      } catch (e) {
        expect(e).toBeInstanceOf(FulcrumError); // nearly collinear sets are rejected, never mangled
        continue;
      }
      expectHullOf(Shape.polygon(hull), points);
      const extreme = bruteForceExtremeCount(points);
      // the hull may only drop extreme points that are nearly collinear (within 0.005 m)
      expect(hull.length).toBeLessThanOrEqual(extreme);
      if (hull.length === extreme) compared++;
    }
    expect(compared).toBeGreaterThan(130);
  });

  it('refuses a point set with a point inside its hull (a concave outline), naming the point and Shape.concave', () => {
    const rnd = random(8);
    let accepted = 0;
    let refused = 0;
    for (let trial = 0; trial < 300; trial++) {
      const n = 3 + Math.floor(rnd() * 6);
      const points = Array.from({ length: n }, () => ({ x: rnd() * 4 - 2, y: rnd() * 4 - 2 }));
      const depths = points.map((p) => bruteForceDepth(p, points));
      const deepest = Math.max(...depths);
      let error: unknown;
      try {
        expectHullOf(Shape.polygon(points), points);
        accepted++;
      } catch (e) {
        error = e;
      }
      if (deepest > 0.006) {
        // a point deeper than the 0.005 m tolerance inside the hull: refused, that point named
        expect(error).toBeInstanceOf(FulcrumError);
        const message = (error as Error).message;
        expect(message).toContain('Shape.concave');
        const named = Number(/points\[(\d+)\]/.exec(message)![1]);
        expect(depths[named]).toBeGreaterThan(0.004);
        refused++;
      } else if (deepest <= 0 && error !== undefined) {
        // every point on the hull: only a degenerate (nearly collinear) set may be refused
        expect(error).toBeInstanceOf(FulcrumError);
        expect((error as Error).message).not.toContain('Shape.concave');
      }
    }
    expect(accepted).toBeGreaterThan(30);
    expect(refused).toBeGreaterThan(150);
  });

  it('refuses an L outline (area 1.75, hull 2.875) instead of taking its hull', () => {
    const l = [
      { x: 0, y: 0 },
      { x: 2, y: 0 },
      { x: 2, y: 0.5 },
      { x: 0.5, y: 0.5 },
      { x: 0.5, y: 1.5 },
      { x: 0, y: 1.5 },
    ];
    expectThrows(() => Shape.polygon(l), 'points[3]', '{ x: 0.5, y: 0.5 }', '0.5 m inside', 'Shape.concave');
  });

  it('accepts points that lie on an edge or within 0.005 m inside it', () => {
    const g = Shape.polygon([
      { x: 0, y: 0 },
      { x: 1, y: 0.004 }, // 4 mm inside the bottom edge
      { x: 2, y: 0 },
      { x: 2, y: 1 },
      { x: 2, y: 2 },
      { x: 1.999, y: 2.002 }, // welded into (2, 2)
      { x: 0, y: 2 },
    ]);
    expect(g.vertices.map((p) => [p.x, p.y])).toEqual([
      [0, 0],
      [2, 0],
      [2, 2],
      [0, 2],
    ]);
    expectThrows(
      () =>
        Shape.polygon([
          { x: 0, y: 0 },
          { x: 1, y: 0.006 }, // 6 mm inside
          { x: 2, y: 0 },
          { x: 2, y: 2 },
          { x: 0, y: 2 },
        ]),
      'points[1]',
      'Shape.concave',
    );
  });

  it('welds near points, removes collinear points and keeps counter-clockwise order', () => {
    const g = Shape.polygon([
      { x: 0, y: 0 },
      { x: 0, y: 2 },
      { x: 1, y: 0 },
      { x: 2, y: 0 }, // makes (1, 0) collinear
      { x: 2.001, y: 0.001 }, // welded into (2, 0)
      { x: 2, y: 2 },
    ]);
    expect(g.count).toBe(4);
    expect(g.vertices.map((p) => [p.x, p.y])).toEqual([
      [0, 0],
      [2, 0],
      [2, 2],
      [0, 2],
    ]);
    expect(g.centroid).toEqual({ x: 1, y: 1 });
    expect(g.type).toBe('polygon');
    expect(g.kind).toBe(ShapeKind.POLYGON);
    expect(Object.isFrozen(g) && Object.isFrozen(g.vertices) && Object.isFrozen(g.vertices[0])).toBe(true);
  });

  it('has the area centroid, not the vertex average', () => {
    // a triangle's area centroid is the vertex average; a trapezoid's is not
    const g = Shape.polygon([
      { x: 0, y: 0 },
      { x: 4, y: 0 },
      { x: 3, y: 1 },
      { x: 1, y: 1 },
    ]);
    // trapezoid with bases 4 and 2, height 1: ybar = h (b1 + 2 b2) / (3 (b1 + b2)) = 8 / 18
    expect(g.centroid.x).toBeCloseTo(2, 14);
    expect(g.centroid.y).toBeCloseTo(8 / 18, 14);
  });

  it('accepts 8 hull vertices and rejects 9', () => {
    const ring = (n: number) =>
      Array.from({ length: n }, (_, i) => ({
        x: Math.cos((2 * Math.PI * i) / n),
        y: Math.sin((2 * Math.PI * i) / n),
      }));
    expect(Shape.polygon(ring(8)).count).toBe(8);
    expectThrows(() => Shape.polygon(ring(9)), 'points', 'at most 8', 'it has 9');
  });
});

describe('Shape factories', () => {
  it('build frozen geometry with type and kind', () => {
    const c = Shape.circle(0.5, { x: 1, y: 2 });
    expect(c).toEqual({ type: 'circle', kind: ShapeKind.CIRCLE, center: { x: 1, y: 2 }, radius: 0.5 });
    expect(Object.isFrozen(c) && Object.isFrozen(c.center)).toBe(true);
    expect(Shape.circle(1).center).toEqual({ x: 0, y: 0 });
    const cap = Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.25);
    expect([cap.type, cap.kind, cap.radius]).toEqual(['capsule', ShapeKind.CAPSULE, 0.25]);
    const seg = Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 });
    expect([seg.type, seg.kind]).toEqual(['segment', ShapeKind.SEGMENT]);
    expect(Object.isFrozen(seg.point1)).toBe(true);
  });

  it('box: rotated corners, outward normals and centre', () => {
    const angle = 0.3;
    const g = Shape.box(2, 1, { x: 1, y: -1 }, angle);
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const local = [
      [-2, -1],
      [2, -1],
      [2, 1],
      [-2, 1],
    ];
    local.forEach(([x, y], i) => {
      expect(g.vertices[i].x).toBeCloseTo(1 + c * x - s * y, 14);
      expect(g.vertices[i].y).toBeCloseTo(-1 + s * x + c * y, 14);
    });
    expect(g.normals[1].x).toBeCloseTo(c, 14);
    expect(g.normals[1].y).toBeCloseTo(s, 14);
    expect(g.centroid).toEqual({ x: 1, y: -1 });
    expect(g.radius).toBe(0);
  });

  it('rejects bad input with a FulcrumError naming the argument and the value', () => {
    expectThrows(() => Shape.circle(-1), 'radius', '-1');
    expectThrows(() => Shape.circle(0), 'radius', 'got 0');
    expectThrows(() => Shape.circle(Number.NaN), 'radius', 'NaN');
    expectThrows(() => Shape.circle(1, { x: Number.POSITIVE_INFINITY, y: 0 } as never), 'center');
    expectThrows(() => Shape.circle(1, 'here' as never), 'center', '"here"');
    expectThrows(() => Shape.box(0, 1), 'halfWidth', 'got 0');
    expectThrows(() => Shape.box(1, -2), 'halfHeight', '-2');
    expectThrows(() => Shape.box(1, 1, { x: 0, y: 0 }, Number.NaN), 'angle', 'NaN');
    expectThrows(() => Shape.box(1, 1, { x: 0 } as never), 'center');
    expectThrows(() => Shape.polygon('square' as never), 'points', '"square"');
    expectThrows(() => Shape.polygon([{ x: 0, y: 0 }, { x: 1, y: 0 }, null as never]), 'points[2]', 'null');
    expectThrows(
      () =>
        Shape.polygon([
          { x: 0, y: 0 },
          { x: 1, y: 0 },
          { x: 1, y: Number.NaN },
        ]),
      'points[2]',
    );
    expectThrows(
      () =>
        Shape.polygon([
          { x: 0, y: 0 },
          { x: 1, y: 0 },
        ]),
      'points',
      'at least 3',
    );
    expectThrows(
      () =>
        Shape.polygon([
          { x: 0, y: 0 },
          { x: 1, y: 0 },
          { x: 0.001, y: 0.002 },
        ]),
      'points',
      'at least 3',
    );
    expectThrows(
      () =>
        Shape.polygon([
          { x: 0, y: 0 },
          { x: 1, y: 1 },
          { x: 2, y: 2 },
          { x: 3, y: 3.001 },
        ]),
      'points',
      'collinear',
    );
    const square = [
      { x: 0, y: 0 },
      { x: 1, y: 0 },
      { x: 1, y: 1 },
    ];
    expectThrows(() => Shape.polygon(square, -0.1), 'radius', '-0.1');
    expect(Shape.polygon(square, 0).radius).toBe(0);
    expectThrows(() => Shape.capsule({ x: 0, y: 0 }, { x: 0, y: 0 }, 1), 'p2', 'from p1');
    expectThrows(() => Shape.capsule({ x: 0, y: 0 }, { x: 0.004, y: 0 }, 1), 'p2', '0.004');
    expectThrows(() => Shape.capsule({ x: 0, y: 0 }, { x: 1, y: 0 }, 0), 'radius', 'got 0');
    expectThrows(() => Shape.capsule({ x: Number.NaN, y: 0 }, { x: 1, y: 0 }, 1), 'p1');
    expectThrows(() => Shape.segment({ x: 1, y: 1 }, { x: 1, y: 1 }), 'p2');
    expectThrows(() => Shape.segment({ x: 1, y: 1 }, undefined as never), 'p2', 'undefined');
  });
});

describe('computeShapeBounds', () => {
  it('is the tight world box including the radius', () => {
    const out = makeBounds();
    const packed = new Float64Array(Pack.STRIDE);
    const t = xf(1, 2, Math.PI / 4);
    computeShapeBounds(Shape.box(1, 1), t, out, packed);
    expect(out.minX).toBeCloseTo(1 - Math.SQRT2, 14);
    expect(out.maxY).toBeCloseTo(2 + Math.SQRT2, 14);
    computeShapeBounds(Shape.polygon(Shape.box(1, 1).vertices, 0.5), xf(0, 0, 0), out, packed);
    expect(out).toEqual({ minX: -1.5, minY: -1.5, maxX: 1.5, maxY: 1.5 });
    computeShapeBounds(Shape.circle(0.5, { x: 1, y: 0 }), xf(0, 0, Math.PI / 2), out, packed);
    expect(out.minX).toBeCloseTo(-0.5, 14);
    expect(out.minY).toBeCloseTo(0.5, 14);
    computeShapeBounds(Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.25), xf(0, 0, 0), out, packed);
    expect(out).toEqual({ minX: -1.25, minY: -0.25, maxX: 1.25, maxY: 0.25 });
    computeShapeBounds(Shape.segment({ x: -1, y: 0 }, { x: 1, y: 3 }), xf(1, 1, 0), out, packed);
    expect(out).toEqual({ minX: 0, minY: 1, maxX: 2, maxY: 4 });
  });
});
