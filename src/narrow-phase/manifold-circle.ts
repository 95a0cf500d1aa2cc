import { Pack } from '../geometry/packed';
import type { Manifold } from '../geometry/types';
import type { Transform } from '../math/vec2';
import type { CollideContext } from './collide-context';

/**
 * Centres closer than this share of the radii are taken as coincident: the direction between them
 * is noise there, and below ~1e-154 the squares of their offsets underflow and the "unit" normal
 * computed from them is not unit (1e-162 apart gave a normal of length 0.71).
 */
const COINCIDENT = 1e-12;

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

/** Two circles, packed in `data` (see packed.ts: a circle's one vertex is its centre). */
export function collideCircles(
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  const speculativeDistance = context.reach;
  out.pointCount = 0;
  const qa = xfA.q;
  const qb = xfB.q;
  const cax = data[baseA + Pack.VERTICES];
  const cay = data[baseA + Pack.VERTICES + 1];
  const cbx = data[baseB + Pack.VERTICES];
  const cby = data[baseB + Pack.VERTICES + 1];
  const rA = data[baseA + Pack.RADIUS];
  const rB = data[baseB + Pack.RADIUS];
  const ax = qa.c * cax - qa.s * cay + xfA.p.x;
  const ay = qa.s * cax + qa.c * cay + xfA.p.y;
  const bx = qb.c * cbx - qb.s * cby + xfB.p.x;
  const by = qb.s * cbx + qb.c * cby + xfB.p.y;
  const dx = bx - ax;
  const dy = by - ay;
  const distance = Math.sqrt(dx * dx + dy * dy);
  const separation = distance - rA - rB;
  if (!(separation < speculativeDistance)) {
    context.separatedDistance = separation;
    return;
  }
  // concentric circles have no preferred direction: push along +y
  const apart = distance > COINCIDENT * (rA + rB);
  const nx = apart ? dx / distance : 0;
  const ny = apart ? dy / distance : 1;
  out.normalX = nx;
  out.normalY = ny;
  const point = out.points[0];
  point.x = 0.5 * (ax + rA * nx + bx - rB * nx);
  point.y = 0.5 * (ay + rA * ny + by - rB * ny);
  point.separation = separation;
  point.id = 0;
  out.pointCount = 1;
}

/**
 * A circle against a capsule or segment (the rounded segment between B's two packed vertices, radius
 * B's radius: 0 for a segment), in B's frame.
 */
export function collideCircleRoundedSegment(
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  const speculativeDistance = context.reach;
  out.pointCount = 0;
  const k = baseB + Pack.VERTICES;
  const q1x = data[k];
  const q1y = data[k + 1];
  const q2x = data[k + Pack.VERTEX_STRIDE];
  const q2y = data[k + Pack.VERTEX_STRIDE + 1];
  const rB = data[baseB + Pack.RADIUS];
  const rA = data[baseA + Pack.RADIUS];
  const centerX = data[baseA + Pack.VERTICES];
  const centerY = data[baseA + Pack.VERTICES + 1];
  // circle centre in B's frame
  const qa = xfA.q;
  const qb = xfB.q;
  const wx = qa.c * centerX - qa.s * centerY + xfA.p.x - xfB.p.x;
  const wy = qa.s * centerX + qa.c * centerY + xfA.p.y - xfB.p.y;
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
  const separation = distance - rA - rB;
  if (!(separation < speculativeDistance)) {
    context.separatedDistance = separation;
    return;
  }
  let ux: number;
  let uy: number;
  if (distance > COINCIDENT * (rA + rB)) {
    ux = dx / distance;
    uy = dy / distance;
  } else {
    // centre on the core segment: use the segment's right-hand normal
    const len = Math.sqrt(ee);
    ux = ey / len;
    uy = -ex / len;
  }
  writeFromB(xfB, ux, uy, cx - rA * ux, cy - rA * uy, px + rB * ux, py + rB * uy, separation, out);
}

/**
 * Circle against a (rounded) polygon, both packed in `data` (see packed.ts; the circle's one vertex
 * is its centre), in the polygon's frame: the edge of largest separation, then the Voronoi region of
 * the centre along that edge (first vertex, face, second vertex).
 */
export function collideCirclePolygon(
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  const speculativeDistance = context.reach;
  out.pointCount = 0;
  const qa = xfA.q;
  const qb = xfB.q;
  const ax = data[baseA + Pack.VERTICES];
  const ay = data[baseA + Pack.VERTICES + 1];
  const rA = data[baseA + Pack.RADIUS];
  const wx = qa.c * ax - qa.s * ay + xfA.p.x - xfB.p.x;
  const wy = qa.s * ax + qa.c * ay + xfA.p.y - xfB.p.y;
  const cx = qb.c * wx + qb.s * wy;
  const cy = -qb.s * wx + qb.c * wy;
  const n = data[baseB + Pack.COUNT];
  const rB = data[baseB + Pack.RADIUS];
  const radius = rA + rB;
  let edge = 0;
  let maxSeparation = Number.NEGATIVE_INFINITY;
  for (let i = 0, k = baseB + Pack.VERTICES; i < n; i++, k += Pack.VERTEX_STRIDE) {
    const s = data[k + 2] * (cx - data[k]) + data[k + 3] * (cy - data[k + 1]);
    if (s > maxSeparation) {
      maxSeparation = s;
      edge = i;
    }
  }
  // beyond an edge's line: at least that far apart
  if (maxSeparation - radius >= speculativeDistance) {
    context.separatedDistance = maxSeparation - radius;
    return;
  }
  const k1 = baseB + Pack.VERTICES + Pack.VERTEX_STRIDE * edge;
  const k2 = baseB + Pack.VERTICES + Pack.VERTEX_STRIDE * (edge + 1 === n ? 0 : edge + 1);
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
      const vertexDistance = Math.sqrt(dx * dx + dy * dy);
      // a centre on the vertex gives no direction: it keeps the face's normal
      if (vertexDistance > COINCIDENT * radius) {
        distance = vertexDistance;
        ux = dx / distance;
        uy = dy / distance;
        px = vx;
        py = vy;
      }
    }
  }
  const separation = distance - radius;
  if (!(separation < speculativeDistance)) {
    context.separatedDistance = separation;
    return;
  }
  writeFromB(xfB, ux, uy, cx - rA * ux, cy - rA * uy, px + rB * ux, py + rB * uy, separation, out);
}
