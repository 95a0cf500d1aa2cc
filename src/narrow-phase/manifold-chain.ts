import { frontOffset, Pack } from '../geometry/packed';
import type { Manifold } from '../geometry/types';
import type { Transform } from '../math/vec2';
import type { CollideContext } from './collide-context';
import { setRelative } from './manifold-polygon';

/*
 * A chain's one-sided segment against another shape (see Pack.ONE_SIDED). Two rules on top of the
 * two-sided manifold:
 * 1. A shape whose centre is behind the segment's line does not touch it: it passes through from the
 *    back (one-way platforms), and a body pushed deep into a chain is pushed out in front.
 * 2. The contact normal must lie between the bounds the neighbours set at the end it leans toward.
 *    A normal past them means the two-sided routine found a corner the chain does not have: the
 *    seam where two segments meet in a straight line or a hollow. A box sliding over that seam would
 *    catch on it (a "ghost" collision). There the manifold becomes the segment's face manifold: the
 *    segment's normal, and the other shape's points over the segment's extent, each with its distance
 *    from the segment's line. Past the extent the neighbour's face takes over.
 */

/** Feature ids of face-manifold points: the vertex index of the other shape in bits 0-3. */
enum ChainId {
  FACE = 1 << 10,
  /** the point is where the other shape's edge crosses the segment's first end */
  CLIPPED1 = 1 << 11,
  /** ... its second end */
  CLIPPED2 = 1 << 12,
}

/** B's transform relative to A (setRelative's layout) from the two transforms. */
function relativeTransform(xfA: Transform, xfB: Transform, out: Float64Array): void {
  setRelative(out, xfA.q.c, xfA.q.s, xfA.p.x, xfA.p.y, xfB.q.c, xfB.q.s, xfB.p.x, xfB.p.y);
}

/**
 * Whether the centre of the shape packed at `otherBase` (the mean of its vertices), placed at
 * `otherXf`, is behind the one-sided segment packed at `segBase`, placed at `segXf`.
 */
export function isBehindSegment(
  data: Float64Array,
  segBase: number,
  segXf: Transform,
  otherBase: number,
  otherXf: Transform,
  context: CollideContext,
): boolean {
  const rel = context.relative;
  relativeTransform(segXf, otherXf, rel);
  const count = data[otherBase + Pack.COUNT];
  let sx = 0;
  let sy = 0;
  for (let i = 0; i < count; i++) {
    const k = otherBase + Pack.VERTICES + Pack.VERTEX_STRIDE * i;
    sx += data[k];
    sy += data[k + 1];
  }
  sx /= count;
  sy /= count;
  const x = rel[0] * sx - rel[1] * sy + rel[2];
  const y = rel[1] * sx + rel[0] * sy + rel[3];
  return frontOffset(data, segBase, x, y) < 0;
}

/**
 * Applies rule 2 to the manifold `out` the two-sided routine made for the one-sided segment packed at
 * `segBase` (at `segXf`) and the shape at `otherBase` (at `otherXf`); `segmentIsB` when the segment
 * is the manifold's B (its normal then points from the other shape to the segment). `out` has points.
 */
export function admitChainNormal(
  data: Float64Array,
  segBase: number,
  segXf: Transform,
  otherBase: number,
  otherXf: Transform,
  segmentIsB: boolean,
  out: Manifold,
  context: CollideContext,
): void {
  const k = segBase + Pack.VERTICES;
  const nx = data[k + 2];
  const ny = data[k + 3];
  // the segment runs along t = (-ny, nx), n to its right
  const tx = -ny;
  const ty = nx;
  // the contact normal from the segment to the other shape, in the segment body's frame
  const sign = segmentIsB ? -1 : 1;
  const wx = sign * out.normalX;
  const wy = sign * out.normalY;
  const c = segXf.q.c;
  const s = segXf.q.s;
  const lx = c * wx + s * wy;
  const ly = c * wy - s * wx;
  const along = lx * tx + ly * ty;
  const up = lx * nx + ly * ny;
  // the bound at the end the normal leans toward, as (along, up) components
  const bound = segBase + (along < 0 ? Pack.LIMIT1_X : Pack.LIMIT2_X);
  const bx = data[bound];
  const by = data[bound + 1];
  const boundAlong = bx * tx + by * ty;
  const boundUp = bx * nx + by * ny;
  // between n and the bound: the bound is no nearer n than the normal
  const turn = along < 0 ? along * boundUp - up * boundAlong : boundAlong * up - boundUp * along;
  if (up >= 0 && turn >= 0) return;
  collideSegmentFace(data, segBase, segXf, otherBase, otherXf, segmentIsB, out, context);
}

/** The face manifold of rule 2 (see the top of the file), written over `out`. */
function collideSegmentFace(
  data: Float64Array,
  segBase: number,
  segXf: Transform,
  otherBase: number,
  otherXf: Transform,
  segmentIsB: boolean,
  out: Manifold,
  context: CollideContext,
): void {
  const k = segBase + Pack.VERTICES;
  const p1x = data[k];
  const p1y = data[k + 1];
  const nx = data[k + 2];
  const ny = data[k + 3];
  const tx = -ny;
  const ty = nx;
  const length = (data[k + Pack.VERTEX_STRIDE] - p1x) * tx + (data[k + Pack.VERTEX_STRIDE + 1] - p1y) * ty;
  const rel = context.relative;
  relativeTransform(segXf, otherXf, rel);
  const rc = rel[0];
  const rs = rel[1];
  const count = data[otherBase + Pack.COUNT];
  const radius = data[otherBase + Pack.RADIUS];
  // the other shape's vertices facing the segment: its one point, or the edge most against n
  let i1 = 0;
  let i2 = count === 1 ? 0 : 1;
  if (count > 2) {
    let least = Number.POSITIVE_INFINITY;
    for (let i = 0; i < count; i++) {
      const v = otherBase + Pack.VERTICES + Pack.VERTEX_STRIDE * i;
      const ex = rc * data[v + 2] - rs * data[v + 3];
      const ey = rs * data[v + 2] + rc * data[v + 3];
      const facing = ex * nx + ey * ny;
      if (facing < least) {
        least = facing;
        i1 = i;
      }
    }
    i2 = i1 + 1 === count ? 0 : i1 + 1;
  }
  // the two vertices as (u along t from p1, w along n from the line)
  const v1 = otherBase + Pack.VERTICES + Pack.VERTEX_STRIDE * i1;
  const v2 = otherBase + Pack.VERTICES + Pack.VERTEX_STRIDE * i2;
  const x1 = rc * data[v1] - rs * data[v1 + 1] + rel[2] - p1x;
  const y1 = rs * data[v1] + rc * data[v1 + 1] + rel[3] - p1y;
  const x2 = rc * data[v2] - rs * data[v2 + 1] + rel[2] - p1x;
  const y2 = rs * data[v2] + rc * data[v2 + 1] + rel[3] - p1y;
  let u1 = x1 * tx + y1 * ty;
  let w1 = x1 * nx + y1 * ny;
  let u2 = x2 * tx + y2 * ty;
  let w2 = x2 * nx + y2 * ny;
  let id1 = ChainId.FACE | i1;
  let id2 = ChainId.FACE | i2;
  if (u1 > u2) {
    const u = u1;
    u1 = u2;
    u2 = u;
    const w = w1;
    w1 = w2;
    w2 = w;
    const id = id1;
    id1 = id2;
    id2 = id;
  }
  out.pointCount = 0;
  context.separatingAxis = 0;
  context.separatedDistance = -1;
  if (u2 < 0 || u1 > length) return;
  // clip to the segment's extent (a single point, u1 = u2, is inside it here)
  if (u1 < 0) {
    w1 += ((w2 - w1) * (0 - u1)) / (u2 - u1);
    u1 = 0;
    id1 |= ChainId.CLIPPED1;
  }
  if (u2 > length) {
    w2 = w1 + ((w2 - w1) * (length - u1)) / (u2 - u1);
    u2 = length;
    id2 |= ChainId.CLIPPED2;
  }
  const sign = segmentIsB ? -1 : 1;
  const c = segXf.q.c;
  const s = segXf.q.s;
  out.normalX = sign * (c * nx - s * ny);
  out.normalY = sign * (s * nx + c * ny);
  const reach = context.reach;
  const points = count === 1 ? 1 : 2;
  for (let j = 0; j < points; j++) {
    const u = j === 0 ? u1 : u2;
    const separation = (j === 0 ? w1 : w2) - radius;
    if (!(separation < reach)) continue;
    // halfway between the segment's line and the other shape's surface
    const h = 0.5 * separation;
    const px = p1x + u * tx + h * nx;
    const py = p1y + u * ty + h * ny;
    const point = out.points[out.pointCount++];
    point.x = c * px - s * py + segXf.p.x;
    point.y = s * px + c * py + segXf.p.y;
    point.separation = separation;
    point.id = j === 0 ? id1 : id2;
  }
}
