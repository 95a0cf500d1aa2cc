// Independent reference computations for the query tests: plain formulas on world coordinates,
// no engine code beyond reading a shape's geometry and its body's pose through the public API.
import type { Geometry, ShapeHandle } from '../../src/index';

export type P = { x: number; y: number };
/** a convex core (1 point, a segment, or a counter-clockwise polygon) inflated by radius */
export type Core = { points: P[]; radius: number };

/** core of `g` placed at (x, y) turned by angle, with Math.cos / Math.sin */
export function coreAt(g: Geometry, x: number, y: number, angle: number): Core {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const local =
    g.type === 'circle'
      ? [g.center]
      : g.type === 'capsule'
        ? [g.center1, g.center2]
        : g.type === 'segment'
          ? [g.point1, g.point2]
          : g.vertices;
  return {
    points: local.map((p) => ({ x: x + c * p.x - s * p.y, y: y + s * p.x + c * p.y })),
    radius: g.type === 'segment' ? 0 : g.radius,
  };
}

export function coreOf(shape: ShapeHandle): Core {
  const p = shape.body.position;
  return coreAt(shape.geometry, p.x, p.y, shape.body.angle);
}

function pointSegmentDistance(p: P, a: P, b: P): number {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const ee = ex * ex + ey * ey;
  let t = ee === 0 ? 0 : ((p.x - a.x) * ex + (p.y - a.y) * ey) / ee;
  t = Math.max(0, Math.min(1, t));
  return Math.hypot(p.x - a.x - t * ex, p.y - a.y - t * ey);
}

function orient(a: P, b: P, c: P): number {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

function segmentsCross(a: P, b: P, c: P, d: P): boolean {
  const d1 = orient(c, d, a);
  const d2 = orient(c, d, b);
  const d3 = orient(a, b, c);
  const d4 = orient(a, b, d);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

function segmentDistance(a: P, b: P, c: P, d: P): number {
  if (segmentsCross(a, b, c, d)) return 0;
  return Math.min(
    pointSegmentDistance(a, c, d),
    pointSegmentDistance(b, c, d),
    pointSegmentDistance(c, a, b),
    pointSegmentDistance(d, a, b),
  );
}

function edges(points: P[]): [P, P][] {
  if (points.length === 1) return [[points[0], points[0]]];
  if (points.length === 2) return [[points[0], points[1]]];
  return points.map((p, i) => [p, points[(i + 1) % points.length]] as [P, P]);
}

function insidePolygon(points: P[], q: P): boolean {
  if (points.length < 3) return false;
  for (let i = 0; i < points.length; i++) {
    if (orient(points[i], points[(i + 1) % points.length], q) < 0) return false;
  }
  return true;
}

/** distance between the two cores (0 when they intersect) */
export function coreDistance(a: P[], b: P[]): number {
  if (b.some((q) => insidePolygon(a, q)) || a.some((q) => insidePolygon(b, q))) return 0;
  let best = Number.POSITIVE_INFINITY;
  for (const [p, q] of edges(a))
    for (const [r, s] of edges(b)) best = Math.min(best, segmentDistance(p, q, r, s));
  return best;
}

/** signed gap between the surfaces (negative: overlap depth is at least this much) */
export function surfaceGap(a: Core, b: Core): number {
  return coreDistance(a.points, b.points) - a.radius - b.radius;
}

/** signed distance of a point from the surface; negative inside (exact outside, sign exact inside) */
export function pointGap(core: Core, p: P): number {
  if (core.points.length >= 3 && insidePolygon(core.points, p)) return -core.radius - 1e-300;
  return coreDistance(core.points, [p]) - core.radius;
}
