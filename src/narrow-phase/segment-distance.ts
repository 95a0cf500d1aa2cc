/** Closest points of two segments: P = p1 + s (p2 - p1) and Q = q1 + t (q2 - q1). */
export interface SegmentClosest {
  s: number;
  t: number;
  px: number;
  py: number;
  qx: number;
  qy: number;
  distanceSq: number;
}

export function makeSegmentClosest(): SegmentClosest {
  return { s: 0, t: 0, px: 0, py: 0, qx: 0, qy: 0, distanceSq: 0 };
}

function clamp01(x: number): number {
  return x < 0 ? 0 : Math.min(x, 1);
}

/**
 * Minimises |P(s) - Q(t)|^2 over the unit square for the segments in `segmentPair` (p1, p2, q1, q2,
 * x and y each: an array, because the narrow phase calls it for many pairs a step and a double passed
 * to a call V8 does not inline is boxed on the heap): s from the
 * infinite lines clamped to [0, 1], the best t for that s, and if t had to be clamped, the best s for
 * the clamped t. Both segments must have non-zero length (shapes guarantee at least LINEAR_SLOP).
 * Parallel segments take s = 0.
 */
export function closestBetweenSegments(segmentPair: Float64Array, out: SegmentClosest): void {
  const p1x = segmentPair[0];
  const p1y = segmentPair[1];
  const p2x = segmentPair[2];
  const p2y = segmentPair[3];
  const q1x = segmentPair[4];
  const q1y = segmentPair[5];
  const q2x = segmentPair[6];
  const q2y = segmentPair[7];
  const d1x = p2x - p1x;
  const d1y = p2y - p1y;
  const d2x = q2x - q1x;
  const d2y = q2y - q1y;
  const rx = p1x - q1x;
  const ry = p1y - q1y;
  const aa = d1x * d1x + d1y * d1y;
  const ee = d2x * d2x + d2y * d2y;
  const ab = d1x * d2x + d1y * d2y;
  const ar = d1x * rx + d1y * ry;
  const br = d2x * rx + d2y * ry;
  const denominator = aa * ee - ab * ab;
  let s = denominator > 1e-12 * aa * ee ? clamp01((ab * br - ar * ee) / denominator) : 0;
  let t = (ab * s + br) / ee;
  if (t < 0) {
    t = 0;
    s = clamp01(-ar / aa);
  } else if (t > 1) {
    t = 1;
    s = clamp01((ab - ar) / aa);
  }
  out.s = s;
  out.t = t;
  out.px = p1x + s * d1x;
  out.py = p1y + s * d1y;
  out.qx = q1x + t * d2x;
  out.qy = q1y + t * d2y;
  const dx = out.qx - out.px;
  const dy = out.qy - out.py;
  out.distanceSq = dx * dx + dy * dy;
}
