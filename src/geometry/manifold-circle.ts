import type { Transform } from '../math/vec2';
import {
  PACK_COUNT,
  PACK_RADIUS,
  PACK_STRIDE,
  PACK_VERTEX_STRIDE,
  PACK_VERTICES,
  packGeometry,
} from './packed';
import type { Capsule, Circle, Manifold, Polygon, Segment } from './types';

/**
 * Writes a one-point manifold given in B's local frame: `ux, uy` is the unit normal from B to A
 * (so the A-to-B normal is its negation) and `(bx, by)`, `(ax, ay)` are the two surface points.
 */
function writeFromB(
  xfB: Transform,
  ux: number,
  uy: number,
  ax: number,
  ay: number,
  bx: number,
  by: number,
  separation: number,
  out: Manifold,
): void {
  const { c, s } = xfB.q;
  const mx = 0.5 * (ax + bx);
  const my = 0.5 * (ay + by);
  out.normalX = -(c * ux - s * uy);
  out.normalY = -(s * ux + c * uy);
  const point = out.points[0];
  point.x = c * mx - s * my + xfB.p.x;
  point.y = s * mx + c * my + xfB.p.y;
  point.separation = separation;
  point.id = 0;
  out.pointCount = 1;
}

export function collideCircles(
  a: Circle,
  xfA: Transform,
  b: Circle,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  out.pointCount = 0;
  const qa = xfA.q;
  const qb = xfB.q;
  const ax = qa.c * a.center.x - qa.s * a.center.y + xfA.p.x;
  const ay = qa.s * a.center.x + qa.c * a.center.y + xfA.p.y;
  const bx = qb.c * b.center.x - qb.s * b.center.y + xfB.p.x;
  const by = qb.s * b.center.x + qb.c * b.center.y + xfB.p.y;
  const dx = bx - ax;
  const dy = by - ay;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - a.radius - b.radius;
  if (!(separation < speculativeDistance)) return;
  // concentric circles have no preferred direction: push along +y
  const nx = distance > 0 ? dx / distance : 0;
  const ny = distance > 0 ? dy / distance : 1;
  out.normalX = nx;
  out.normalY = ny;
  const point = out.points[0];
  point.x = 0.5 * (ax + a.radius * nx + bx - b.radius * nx);
  point.y = 0.5 * (ay + a.radius * ny + by - b.radius * ny);
  point.separation = separation;
  point.id = 0;
  out.pointCount = 1;
}

/** Circle against the rounded segment q1-q2 (radius rB) of shape B, in B's frame. */
function circleVsRoundedSegment(
  a: Circle,
  xfA: Transform,
  q1x: number,
  q1y: number,
  q2x: number,
  q2y: number,
  rB: number,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  out.pointCount = 0;
  // circle centre in B's frame
  const qa = xfA.q;
  const qb = xfB.q;
  const wx = qa.c * a.center.x - qa.s * a.center.y + xfA.p.x - xfB.p.x;
  const wy = qa.s * a.center.x + qa.c * a.center.y + xfA.p.y - xfB.p.y;
  const cx = qb.c * wx + qb.s * wy;
  const cy = -qb.s * wx + qb.c * wy;
  const ex = q2x - q1x;
  const ey = q2y - q1y;
  const ee = ex * ex + ey * ey;
  let t = ((cx - q1x) * ex + (cy - q1y) * ey) / ee;
  t = t < 0 ? 0 : Math.min(t, 1);
  const px = q1x + t * ex;
  const py = q1y + t * ey;
  const dx = cx - px;
  const dy = cy - py;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - a.radius - rB;
  if (!(separation < speculativeDistance)) return;
  let ux: number;
  let uy: number;
  if (distance > 0) {
    ux = dx / distance;
    uy = dy / distance;
  } else {
    // centre exactly on the core segment: use the segment's right-hand normal
    const len = Math.sqrt(ee);
    ux = ey / len;
    uy = -ex / len;
  }
  writeFromB(
    xfB,
    ux,
    uy,
    cx - a.radius * ux,
    cy - a.radius * uy,
    px + rB * ux,
    py + rB * uy,
    separation,
    out,
  );
}

export function collideCircleCapsule(
  a: Circle,
  xfA: Transform,
  b: Capsule,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  const p = b.center1;
  const q = b.center2;
  circleVsRoundedSegment(a, xfA, p.x, p.y, q.x, q.y, b.radius, xfB, speculativeDistance, out);
}

export function collideCircleSegment(
  a: Circle,
  xfA: Transform,
  b: Segment,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  const p = b.point1;
  const q = b.point2;
  circleVsRoundedSegment(a, xfA, p.x, p.y, q.x, q.y, 0, xfB, speculativeDistance, out);
}

/**
 * Circle against a (rounded) polygon, both packed in `data` (see packed.ts; the circle's one vertex
 * is its centre), in the polygon's frame: the edge of largest separation, then the Voronoi region of
 * the centre along that edge (first vertex, face, second vertex).
 */
export function collideCirclePackedPolygon(
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  out.pointCount = 0;
  const qa = xfA.q;
  const qb = xfB.q;
  const ax = data[baseA + PACK_VERTICES];
  const ay = data[baseA + PACK_VERTICES + 1];
  const rA = data[baseA + PACK_RADIUS];
  const wx = qa.c * ax - qa.s * ay + xfA.p.x - xfB.p.x;
  const wy = qa.s * ax + qa.c * ay + xfA.p.y - xfB.p.y;
  const cx = qb.c * wx + qb.s * wy;
  const cy = -qb.s * wx + qb.c * wy;
  const n = data[baseB + PACK_COUNT];
  const rB = data[baseB + PACK_RADIUS];
  const radius = rA + rB;
  let edge = 0;
  let maxSeparation = Number.NEGATIVE_INFINITY;
  for (let i = 0, k = baseB + PACK_VERTICES; i < n; i++, k += PACK_VERTEX_STRIDE) {
    const s = data[k + 2] * (cx - data[k]) + data[k + 3] * (cy - data[k + 1]);
    if (s > maxSeparation) {
      maxSeparation = s;
      edge = i;
    }
  }
  if (maxSeparation - radius >= speculativeDistance) return;
  const k1 = baseB + PACK_VERTICES + PACK_VERTEX_STRIDE * edge;
  const k2 = baseB + PACK_VERTICES + PACK_VERTEX_STRIDE * (edge + 1 === n ? 0 : edge + 1);
  const v1x = data[k1];
  const v1y = data[k1 + 1];
  const v2x = data[k2];
  const v2y = data[k2 + 1];
  let ux = data[k1 + 2];
  let uy = data[k1 + 3];
  // closest point of the core polygon and the core distance (face case by default)
  let px = cx - maxSeparation * ux;
  let py = cy - maxSeparation * uy;
  let distance = maxSeparation;
  if (maxSeparation > 0) {
    const ex = v2x - v1x;
    const ey = v2y - v1y;
    // beyond the first vertex, beyond the second, or neither (the face)
    const vertex = (cx - v1x) * ex + (cy - v1y) * ey < 0 ? 1 : (cx - v2x) * ex + (cy - v2y) * ey > 0 ? 2 : 0;
    if (vertex !== 0) {
      const vx = vertex === 1 ? v1x : v2x;
      const vy = vertex === 1 ? v1y : v2y;
      const dx = cx - vx;
      const dy = cy - vy;
      distance = Math.sqrt(dx * dx + dy * dy);
      ux = dx / distance;
      uy = dy / distance;
      px = vx;
      py = vy;
    }
  }
  const separation = distance - radius;
  if (!(separation < speculativeDistance)) return;
  writeFromB(xfB, ux, uy, cx - rA * ux, cy - rA * uy, px + rB * ux, py + rB * uy, separation, out);
}

const scratch = new Float64Array(2 * PACK_STRIDE);

/** Circle against a (rounded) polygon, from geometry objects (`collide`): packs them (see above). */
export function collideCirclePolygon(
  a: Circle,
  xfA: Transform,
  b: Polygon,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  packGeometry(a, scratch, 0);
  packGeometry(b, scratch, PACK_STRIDE);
  collideCirclePackedPolygon(scratch, 0, xfA, PACK_STRIDE, xfB, speculativeDistance, out);
}
