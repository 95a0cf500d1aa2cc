import type { Transform, Vec2 } from '../math/vec2';
import { type Geometry, type Polygon, type RayHit, ShapeKind } from './types';

/*
 * Ray rule, for every kind: the ray is origin + f * translation for f in [0, 1].
 * - A ray whose origin is strictly inside a solid shape (circle, capsule, polygon) does not hit it;
 *   an origin exactly on the surface hits at fraction 0 if the ray goes inwards.
 * - A zero-length translation hits nothing.
 * - A tangent (grazing) ray counts as a hit, at the touching point.
 * - Segments are two-sided: the normal faces the ray's origin. A ray along a segment's line hits
 *   its nearer end (or fraction 0 when the origin is on it), with the normal against the ray.
 * - A chain's one-sided segment is hit only by a ray from strictly in front of its line, as shapes
 *   behind it pass through it.
 * The cast runs in the shape's local frame; fraction and point come from the world ray. The casts
 * below keep the best hit so far in the caller's RayHit (fraction and normal, in the local frame);
 * rayCastGeometry turns it to the world frame. They write it only with a hit, so a miss leaves it as
 * it was.
 */

/** Ray against a disc; updates the hit when it is earlier than `best`. Origin must not be inside. */
function castDisc(
  cx: number,
  cy: number,
  r: number,
  ox: number,
  oy: number,
  dx: number,
  dy: number,
  best: number,
  hit: RayHit,
): boolean {
  const mx = ox - cx;
  const my = oy - cy;
  const dd = dx * dx + dy * dy;
  // closest approach of the ray's line to the centre, then back along the line to the circle
  const tc = -(mx * dx + my * dy) / dd;
  if (tc < 0) return false;
  const hx = mx + tc * dx;
  const hy = my + tc * dy;
  const hh = hx * hx + hy * hy;
  if (hh > r * r) return false;
  const t = Math.max(0, tc - Math.sqrt((r * r - hh) / dd));
  if (t > 1 || t >= best) return false;
  const nx = mx + t * dx;
  const ny = my + t * dy;
  const length = Math.sqrt(nx * nx + ny * ny);
  hit.fraction = t;
  hit.normalX = nx / length;
  hit.normalY = ny / length;
  return true;
}

/** Ray against edge v1-v2 pushed out by r along its normal n; only a hit within the edge's extent. */
function castOffsetEdge(
  v1x: number,
  v1y: number,
  v2x: number,
  v2y: number,
  nx: number,
  ny: number,
  r: number,
  ox: number,
  oy: number,
  dx: number,
  dy: number,
  best: number,
  hit: RayHit,
): boolean {
  const den = nx * dx + ny * dy;
  if (!(den < 0)) return false;
  const t = (nx * (v1x - ox) + ny * (v1y - oy) + r) / den;
  if (t < 0 || t > 1 || t >= best) return false;
  const ex = v2x - v1x;
  const ey = v2y - v1y;
  const along = (ox + t * dx - v1x) * ex + (oy + t * dy - v1y) * ey;
  if (along < 0 || along > ex * ex + ey * ey) return false;
  hit.fraction = t;
  hit.normalX = nx;
  hit.normalY = ny;
  return true;
}

/** Squared distance from (px, py) to the segment a-b. */
function segmentDistanceSq(ax: number, ay: number, bx: number, by: number, px: number, py: number): number {
  const ex = bx - ax;
  const ey = by - ay;
  let t = ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey);
  t = t < 0 ? 0 : Math.min(t, 1);
  const dx = px - ax - t * ex;
  const dy = py - ay - t * ey;
  return dx * dx + dy * dy;
}

/** Squared distance from (px, py) to the core polygon (0 inside). */
function polygonDistanceSq(g: Polygon, px: number, py: number): number {
  const v = g.vertices;
  let outside = false;
  for (let i = 0; i < g.count; i++) {
    if (g.normals[i].x * (px - v[i].x) + g.normals[i].y * (py - v[i].y) > 0) {
      outside = true;
      break;
    }
  }
  if (!outside) return 0;
  let best = Number.POSITIVE_INFINITY;
  for (let i = 0; i < g.count; i++) {
    const j = i + 1 === g.count ? 0 : i + 1;
    best = Math.min(best, segmentDistanceSq(v[i].x, v[i].y, v[j].x, v[j].y, px, py));
  }
  return best;
}

/** Sharp polygon: clip the ray against every edge's half plane; the last entering edge gives the normal. */
function castSharpPolygon(g: Polygon, ox: number, oy: number, dx: number, dy: number, hit: RayHit): boolean {
  let lower = 0;
  let upper = 1;
  let edge = -1;
  for (let i = 0; i < g.count; i++) {
    const n = g.normals[i];
    const num = n.x * (g.vertices[i].x - ox) + n.y * (g.vertices[i].y - oy); // > 0: origin inside this plane
    const den = n.x * dx + n.y * dy;
    if (den === 0) {
      if (num < 0) return false; // parallel and outside
    } else if (den < 0) {
      const t = num / den;
      if (t > lower || (edge < 0 && t === lower)) {
        lower = t;
        edge = i;
      }
    } else {
      upper = Math.min(upper, num / den);
    }
    if (upper < lower) return false;
  }
  // no entering edge ahead of the origin: the origin is inside
  if (edge < 0) return false;
  hit.fraction = lower;
  hit.normalX = g.normals[edge].x;
  hit.normalY = g.normals[edge].y;
  return true;
}

/** Rounded polygon: offset edges within their extents, and a disc at every vertex. */
function castRoundedPolygon(
  g: Polygon,
  ox: number,
  oy: number,
  dx: number,
  dy: number,
  hit: RayHit,
): boolean {
  const r = g.radius;
  if (polygonDistanceSq(g, ox, oy) < r * r) return false;
  const v = g.vertices;
  let best = Number.POSITIVE_INFINITY;
  for (let i = 0; i < g.count; i++) {
    const j = i + 1 === g.count ? 0 : i + 1;
    const n = g.normals[i];
    if (castOffsetEdge(v[i].x, v[i].y, v[j].x, v[j].y, n.x, n.y, r, ox, oy, dx, dy, best, hit))
      best = hit.fraction;
    if (castDisc(v[i].x, v[i].y, r, ox, oy, dx, dy, best, hit)) best = hit.fraction;
  }
  return best <= 1;
}

function castCapsule(
  a: Vec2,
  b: Vec2,
  r: number,
  ox: number,
  oy: number,
  dx: number,
  dy: number,
  hit: RayHit,
): boolean {
  if (segmentDistanceSq(a.x, a.y, b.x, b.y, ox, oy) < r * r) return false;
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const length = Math.sqrt(ex * ex + ey * ey);
  const nx = ey / length;
  const ny = -ex / length;
  let best = Number.POSITIVE_INFINITY;
  if (castOffsetEdge(a.x, a.y, b.x, b.y, nx, ny, r, ox, oy, dx, dy, best, hit)) best = hit.fraction;
  if (castOffsetEdge(b.x, b.y, a.x, a.y, -nx, -ny, r, ox, oy, dx, dy, best, hit)) best = hit.fraction;
  if (castDisc(a.x, a.y, r, ox, oy, dx, dy, best, hit)) best = hit.fraction;
  if (castDisc(b.x, b.y, r, ox, oy, dx, dy, best, hit)) best = hit.fraction;
  return best <= 1;
}

function castSegment(a: Vec2, b: Vec2, ox: number, oy: number, dx: number, dy: number, hit: RayHit): boolean {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const fx = a.x - ox;
  const fy = a.y - oy;
  const den = dx * ey - dy * ex;
  if (den === 0) {
    if (fx * dy - fy * dx !== 0) return false; // parallel, off the line
    // on the line: the ray meets the nearer end, or starts on the segment
    const dd = dx * dx + dy * dy;
    const t1 = (fx * dx + fy * dy) / dd;
    const t2 = ((b.x - ox) * dx + (b.y - oy) * dy) / dd;
    const first = Math.min(t1, t2);
    const last = Math.max(t1, t2);
    if (last < 0 || first > 1) return false;
    const length = Math.sqrt(dd);
    hit.fraction = Math.max(first, 0);
    hit.normalX = -dx / length;
    hit.normalY = -dy / length;
    return true;
  }
  const t = (fx * ey - fy * ex) / den;
  const s = (fx * dy - fy * dx) / den;
  if (t < 0 || t > 1 || s < 0 || s > 1) return false;
  const length = Math.sqrt(ex * ex + ey * ey);
  const sign = ey * dx - ex * dy > 0 ? -1 : 1; // normal (ey, -ex) turned against the ray
  hit.fraction = t;
  hit.normalX = (sign * ey) / length;
  hit.normalY = (-sign * ex) / length;
  return true;
}

/** Whether (x, y) is strictly in front of the one-sided segment a-b: right of the way from a to b. */
function isInFront(a: Vec2, b: Vec2, x: number, y: number): boolean {
  return (x - a.x) * (b.y - a.y) - (y - a.y) * (b.x - a.x) > 0;
}

/**
 * Casts the world ray origin + f * translation (f in [0, 1]) against `g` placed at `xf`. On a hit,
 * writes the fraction, world point and outward world unit normal into `out` and returns true.
 */
export function rayCastGeometry(
  g: Geometry,
  xf: Transform,
  originX: number,
  originY: number,
  translationX: number,
  translationY: number,
  out: RayHit,
): boolean {
  if (translationX === 0 && translationY === 0) return false;
  const { c, s } = xf.q;
  const rx = originX - xf.p.x;
  const ry = originY - xf.p.y;
  const ox = c * rx + s * ry;
  const oy = -s * rx + c * ry;
  const dx = c * translationX + s * translationY;
  const dy = -s * translationX + c * translationY;
  let found: boolean;
  if (g.kind === ShapeKind.CIRCLE) {
    const mx = ox - g.center.x;
    const my = oy - g.center.y;
    found =
      mx * mx + my * my >= g.radius * g.radius &&
      castDisc(g.center.x, g.center.y, g.radius, ox, oy, dx, dy, 2, out);
  } else if (g.kind === ShapeKind.CAPSULE) {
    found = castCapsule(g.center1, g.center2, g.radius, ox, oy, dx, dy, out);
  } else if (g.kind === ShapeKind.POLYGON) {
    found =
      g.radius > 0 ? castRoundedPolygon(g, ox, oy, dx, dy, out) : castSharpPolygon(g, ox, oy, dx, dy, out);
  } else {
    found =
      (!g.oneSided || isInFront(g.point1, g.point2, ox, oy)) &&
      castSegment(g.point1, g.point2, ox, oy, dx, dy, out);
  }
  if (!found) return false;
  const fraction = out.fraction;
  const nx = out.normalX;
  const ny = out.normalY;
  out.pointX = originX + fraction * translationX;
  out.pointY = originY + fraction * translationY;
  out.normalX = c * nx - s * ny;
  out.normalY = s * nx + c * ny;
  return true;
}

/** True when the world point (x, y) is inside or on the surface of `g` at `xf`. Segments contain nothing. */
export function testPoint(g: Geometry, xf: Transform, x: number, y: number): boolean {
  const { c, s } = xf.q;
  const rx = x - xf.p.x;
  const ry = y - xf.p.y;
  const px = c * rx + s * ry;
  const py = -s * rx + c * ry;
  if (g.kind === ShapeKind.CIRCLE) {
    const dx = px - g.center.x;
    const dy = py - g.center.y;
    return dx * dx + dy * dy <= g.radius * g.radius;
  }
  if (g.kind === ShapeKind.CAPSULE) {
    return (
      segmentDistanceSq(g.center1.x, g.center1.y, g.center2.x, g.center2.y, px, py) <= g.radius * g.radius
    );
  }
  if (g.kind === ShapeKind.POLYGON) return polygonDistanceSq(g, px, py) <= g.radius * g.radius;
  return false;
}
