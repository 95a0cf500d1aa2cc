/**
 * Test helpers for GJK, shape cast and time of impact: shape builders, a seeded random source and
 * brute-force references written independently of the engine code (edge-pair distances, point in
 * polygon), used as outside truth.
 */
import {
  type Capsule,
  type Circle,
  type Polygon,
  type Segment,
  ShapeKind,
} from '../../../src/geometry/types';
import { makeRot } from '../../../src/math/rot';
import type { Transform, Vec2 } from '../../../src/math/vec2';

export function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export function xf(x: number, y: number, angle: number): Transform {
  return { p: { x, y }, q: makeRot(angle) };
}

export function circle(x: number, y: number, radius: number): Circle {
  return { type: 'circle', kind: ShapeKind.CIRCLE, center: { x, y }, radius };
}

export function capsule(x1: number, y1: number, x2: number, y2: number, radius: number): Capsule {
  return {
    type: 'capsule',
    kind: ShapeKind.CAPSULE,
    center1: { x: x1, y: y1 },
    center2: { x: x2, y: y2 },
    radius,
  };
}

export function segment(x1: number, y1: number, x2: number, y2: number): Segment {
  return {
    type: 'segment',
    kind: ShapeKind.SEGMENT,
    point1: { x: x1, y: y1 },
    point2: { x: x2, y: y2 },
    oneSided: false,
    ghost1: null,
    ghost2: null,
  };
}

/** Convex polygon from CCW points (no three collinear). */
export function polygon(points: Vec2[], radius = 0): Polygon {
  const n = points.length;
  const normals: Vec2[] = [];
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < n; i++) {
    const a = points[i];
    const b = points[(i + 1) % n];
    const len = Math.hypot(b.x - a.x, b.y - a.y);
    normals.push({ x: (b.y - a.y) / len, y: -(b.x - a.x) / len });
    cx += a.x / n;
    cy += a.y / n;
  }
  return {
    type: 'polygon',
    kind: ShapeKind.POLYGON,
    count: n,
    vertices: points.map((p) => ({ x: p.x, y: p.y })),
    normals,
    centroid: { x: cx, y: cy },
    radius,
  };
}

export function box(hw: number, hh: number, radius = 0): Polygon {
  return polygon(
    [
      { x: -hw, y: -hh },
      { x: hw, y: -hh },
      { x: hw, y: hh },
      { x: -hw, y: hh },
    ],
    radius,
  );
}

/** Random convex polygon of 3..8 vertices within `size` of the origin (hull of random points). */
export function randomPolygon(r: () => number, size: number, radius = 0): Polygon {
  for (;;) {
    const pts: Vec2[] = [];
    const n = 3 + Math.floor(r() * 10);
    for (let i = 0; i < n; i++) {
      pts.push({ x: (2 * r() - 1) * size, y: (2 * r() - 1) * size });
    }
    const hull = convexHull(pts);
    if (hull.length >= 3 && hull.length <= 8 && polygonArea(hull) > 0.05 * size * size) {
      return polygon(hull, radius);
    }
  }
}

/** Monotone chain, CCW, drops collinear points. */
function convexHull(pts: Vec2[]): Vec2[] {
  const p = pts.slice().sort((a, b) => a.x - b.x || a.y - b.y);
  const cross = (o: Vec2, a: Vec2, b: Vec2) => (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  const lower: Vec2[] = [];
  for (const q of p) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 1e-9)
      lower.pop();
    lower.push(q);
  }
  const upper: Vec2[] = [];
  for (let i = p.length - 1; i >= 0; i--) {
    const q = p[i];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 1e-9)
      upper.pop();
    upper.push(q);
  }
  return lower.slice(0, -1).concat(upper.slice(0, -1));
}

function polygonArea(p: Vec2[]): number {
  let a = 0;
  for (let i = 0; i < p.length; i++) {
    const u = p[i];
    const v = p[(i + 1) % p.length];
    a += u.x * v.y - u.y * v.x;
  }
  return a / 2;
}

/** Core points of a shape in world coordinates (CCW for polygons). */
export function worldCore(g: Circle | Capsule | Segment | Polygon, t: Transform): Vec2[] {
  const local =
    g.kind === ShapeKind.CIRCLE
      ? [g.center]
      : g.kind === ShapeKind.CAPSULE
        ? [g.center1, g.center2]
        : g.kind === ShapeKind.SEGMENT
          ? [g.point1, g.point2]
          : g.vertices;
  return local.map((v) => ({ x: t.q.c * v.x - t.q.s * v.y + t.p.x, y: t.q.s * v.x + t.q.c * v.y + t.p.y }));
}

export function radiusOf(g: Circle | Capsule | Segment | Polygon): number {
  return g.kind === ShapeKind.SEGMENT ? 0 : g.radius;
}

function pointSegment(p: Vec2, a: Vec2, b: Vec2): number {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const ee = ex * ex + ey * ey;
  let t = ee > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / ee : 0;
  t = Math.max(0, Math.min(1, t));
  return Math.hypot(p.x - a.x - t * ex, p.y - a.y - t * ey);
}

function orient(a: Vec2, b: Vec2, c: Vec2): number {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

function segmentsCross(a: Vec2, b: Vec2, c: Vec2, d: Vec2): boolean {
  const o1 = orient(a, b, c);
  const o2 = orient(a, b, d);
  const o3 = orient(c, d, a);
  const o4 = orient(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

function inside(p: Vec2, poly: Vec2[]): boolean {
  if (poly.length < 3) return false;
  for (let i = 0; i < poly.length; i++) {
    if (orient(poly[i], poly[(i + 1) % poly.length], p) < 0) return false;
  }
  return true;
}

function edges(p: Vec2[]): [Vec2, Vec2][] {
  if (p.length === 1) return [[p[0], p[0]]];
  if (p.length === 2) return [[p[0], p[1]]];
  return p.map((v, i) => [v, p[(i + 1) % p.length]] as [Vec2, Vec2]);
}

/** Distance between the convex hulls of two world point lists (0 when they intersect), by brute force. */
export function bruteCoreDistance(a: Vec2[], b: Vec2[]): number {
  if (inside(a[0], b) || inside(b[0], a)) return 0;
  let best = Number.POSITIVE_INFINITY;
  for (const [p, q] of edges(a)) {
    for (const [u, v] of edges(b)) {
      if (segmentsCross(p, q, u, v)) return 0;
      best = Math.min(
        best,
        pointSegment(p, u, v),
        pointSegment(q, u, v),
        pointSegment(u, p, q),
        pointSegment(v, p, q),
      );
    }
  }
  return best;
}

/** Distance between two (possibly rounded) shapes, 0 when they overlap, by brute force. */
export function bruteDistance(
  ga: Circle | Capsule | Segment | Polygon,
  ta: Transform,
  gb: Circle | Capsule | Segment | Polygon,
  tb: Transform,
): number {
  return Math.max(0, bruteCoreDistance(worldCore(ga, ta), worldCore(gb, tb)) - radiusOf(ga) - radiusOf(gb));
}
