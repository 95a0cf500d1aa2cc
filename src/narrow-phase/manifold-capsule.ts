import { LINEAR_SLOP } from '../geometry/constants';
import { Pack } from '../geometry/packed';
import type { Manifold } from '../geometry/types';
import type { Transform } from '../math/vec2';
import type { CollideContext } from './collide-context';
import { closestBetweenSegments } from './segment-distance';

/** sin of the largest angle between two capsules that still rest on each other with two points */
const PARALLEL_SIN = 0.1;

/** Closest points below this core distance give no direction: fall back to A's side normal. */
const MIN_DIRECTION_DISTANCE = 0.1 * LINEAR_SLOP;

/** Id of the single point (two-point manifolds use 0 and 1: the end of B the point came from). */
const SINGLE_POINT_ID = 2;

/**
 * A point for writePoint, in A's frame (CollideContext.candidate): a point (x, y) on B's core, the
 * normal n from A to B, B's core separation along n and the two radii.
 */
enum CandidatePoint {
  X = 0,
  Y = 1,
  NX = 2,
  NY = 3,
  CORE_SEPARATION = 4,
  RA = 5,
  RB = 6,
}

/** Writes manifold point `index` from `candidate`, with feature id `id`. */
function writePoint(candidate: Float64Array, xfA: Transform, out: Manifold, index: number, id: number): void {
  const coreSeparation = candidate[CandidatePoint.CORE_SEPARATION];
  const rA = candidate[CandidatePoint.RA];
  const rB = candidate[CandidatePoint.RB];
  // halfway between A's surface (x - (s - rA) n) and B's surface (x - rB n)
  const shift = 0.5 * (rA - rB - coreSeparation);
  const mx = candidate[CandidatePoint.X] + shift * candidate[CandidatePoint.NX];
  const my = candidate[CandidatePoint.Y] + shift * candidate[CandidatePoint.NY];
  const { c, s } = xfA.q;
  const point = out.points[index];
  point.x = c * mx - s * my + xfA.p.x;
  point.y = s * mx + c * my + xfA.p.y;
  point.separation = coreSeparation - rA - rB;
  point.id = id;
}

/**
 * Two rounded segments (capsules, or a capsule and a segment of radius 0) packed in `data`, worked
 * in A's frame. Nearly parallel segments whose projections overlap get two
 * points (B's ends clipped to A's extent) along A's side normal, so that a capsule lying on another
 * is stable; otherwise one point between the closest points of the cores.
 */
export function collideRoundedSegmentPair(
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  const candidate = context.candidate;
  const closest = context.closest;
  const segmentPair = context.segments;
  const a = baseA + Pack.VERTICES;
  const b = baseB + Pack.VERTICES;
  const a1x = data[a];
  const a1y = data[a + 1];
  const a2x = data[a + Pack.VERTEX_STRIDE];
  const a2y = data[a + Pack.VERTEX_STRIDE + 1];
  const rA = data[baseA + Pack.RADIUS];
  const b1x = data[b];
  const b1y = data[b + 1];
  const b2x = data[b + Pack.VERTEX_STRIDE];
  const b2y = data[b + Pack.VERTEX_STRIDE + 1];
  const rB = data[baseB + Pack.RADIUS];
  candidate[CandidatePoint.RA] = rA;
  candidate[CandidatePoint.RB] = rB;
  const speculativeDistance = context.reach;
  out.pointCount = 0;
  const qa = xfA.q;
  const qb = xfB.q;
  // B's relative transform: q = qA^T qB, p = qA^T (pB - pA)
  const c = qa.c * qb.c + qa.s * qb.s;
  const s = qa.c * qb.s - qa.s * qb.c;
  const dx = xfB.p.x - xfA.p.x;
  const dy = xfB.p.y - xfA.p.y;
  const px = qa.c * dx + qa.s * dy;
  const py = -qa.s * dx + qa.c * dy;
  const q1x = c * b1x - s * b1y + px;
  const q1y = s * b1x + c * b1y + py;
  const q2x = c * b2x - s * b2y + px;
  const q2y = s * b2x + c * b2y + py;

  segmentPair[0] = a1x;
  segmentPair[1] = a1y;
  segmentPair[2] = a2x;
  segmentPair[3] = a2y;
  segmentPair[4] = q1x;
  segmentPair[5] = q1y;
  segmentPair[6] = q2x;
  segmentPair[7] = q2y;
  closestBetweenSegments(segmentPair, closest);
  const radius = rA + rB;
  const limit = speculativeDistance + radius;
  if (!(closest.distanceSq < limit * limit)) return;
  const distance = Math.sqrt(closest.distanceSq);

  const ex = a2x - a1x;
  const ey = a2y - a1y;
  const lengthA = Math.sqrt(ex * ex + ey * ey);
  const ux = ex / lengthA;
  const uy = ey / lengthA;
  // A's side normal, turned towards B
  let sx = uy;
  let sy = -ux;
  const towardsB =
    distance > MIN_DIRECTION_DISTANCE
      ? sx * (closest.qx - closest.px) + sy * (closest.qy - closest.py)
      : sx * (q1x + q2x - a1x - a2x) + sy * (q1y + q2y - a1y - a2y);
  if (towardsB < 0) {
    sx = -sx;
    sy = -sy;
  }

  const fx = q2x - q1x;
  const fy = q2y - q1y;
  const lengthB = Math.sqrt(fx * fx + fy * fy);
  const t1 = (q1x - a1x) * ux + (q1y - a1y) * uy;
  const t2 = (q2x - a1x) * ux + (q2y - a1y) * uy;
  const overlap = Math.min(Math.max(t1, t2), lengthA) - Math.max(Math.min(t1, t2), 0);
  const parallel = Math.abs(ux * fy - uy * fx) <= PARALLEL_SIN * lengthB;

  out.normalX = qa.c * sx - qa.s * sy;
  out.normalY = qa.s * sx + qa.c * sy;
  if (parallel && overlap > LINEAR_SLOP) {
    // clip B's core to A's extent [0, lengthA] along u; each end keeps the id of the end it came from
    for (let k = 0; k < 2; k++) {
      const tk = k === 0 ? t1 : t2;
      let x = k === 0 ? q1x : q2x;
      let y = k === 0 ? q1y : q2y;
      const bound = tk < 0 ? 0 : Math.min(tk, lengthA);
      if (bound !== tk) {
        const w = (bound - t1) / (t2 - t1);
        x = q1x + w * fx;
        y = q1y + w * fy;
      }
      const coreSeparation = (x - a1x) * sx + (y - a1y) * sy;
      if (coreSeparation - radius < speculativeDistance) {
        candidate[CandidatePoint.X] = x;
        candidate[CandidatePoint.Y] = y;
        candidate[CandidatePoint.NX] = sx;
        candidate[CandidatePoint.NY] = sy;
        candidate[CandidatePoint.CORE_SEPARATION] = coreSeparation;
        writePoint(candidate, xfA, out, out.pointCount, k);
        out.pointCount += 1;
      }
    }
    return;
  }
  if (distance > MIN_DIRECTION_DISTANCE) {
    sx = (closest.qx - closest.px) / distance;
    sy = (closest.qy - closest.py) / distance;
    out.normalX = qa.c * sx - qa.s * sy;
    out.normalY = qa.s * sx + qa.c * sy;
  }
  const coreSeparation = (closest.qx - closest.px) * sx + (closest.qy - closest.py) * sy;
  if (!(coreSeparation - radius < speculativeDistance)) return;
  candidate[CandidatePoint.X] = closest.qx;
  candidate[CandidatePoint.Y] = closest.qy;
  candidate[CandidatePoint.NX] = sx;
  candidate[CandidatePoint.NY] = sy;
  candidate[CandidatePoint.CORE_SEPARATION] = coreSeparation;
  writePoint(candidate, xfA, out, 0, SINGLE_POINT_ID);
  out.pointCount = 1;
}
