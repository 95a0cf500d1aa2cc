import type { Transform } from '../math/vec2';

/**
 * Motion of a body over one step: its centre of mass goes from c1 to c2 and its rotation from q1
 * to q2 (cos, sin pairs). localCenter is the centre of mass in the body frame.
 */
export interface Sweep {
  localCenterX: number;
  localCenterY: number;
  c1X: number;
  c1Y: number;
  c2X: number;
  c2Y: number;
  q1C: number;
  q1S: number;
  q2C: number;
  q2S: number;
}

export function makeSweep(): Sweep {
  return { localCenterX: 0, localCenterY: 0, c1X: 0, c1Y: 0, c2X: 0, c2Y: 0, q1C: 1, q1S: 0, q2C: 1, q2S: 0 };
}

/**
 * Body transform at fraction t of the sweep: the centre moves linearly, the rotation is the
 * normalised linear interpolation of q1 and q2 (no trigonometry; valid while the rotation over the
 * step is below pi, where the interpolated vector cannot vanish).
 */
export function getSweepTransform(sweep: Sweep, t: number, out: Transform): Transform {
  const u = 1 - t;
  const cx = u * sweep.c1X + t * sweep.c2X;
  const cy = u * sweep.c1Y + t * sweep.c2Y;
  let c = u * sweep.q1C + t * sweep.q2C;
  let s = u * sweep.q1S + t * sweep.q2S;
  const len = Math.sqrt(c * c + s * s);
  if (len > 0) {
    c /= len;
    s /= len;
  } else {
    c = sweep.q1C;
    s = sweep.q1S;
  }
  out.q.c = c;
  out.q.s = s;
  // the body origin sits at c - q * localCenter
  out.p.x = cx - (c * sweep.localCenterX - s * sweep.localCenterY);
  out.p.y = cy - (s * sweep.localCenterX + c * sweep.localCenterY);
  return out;
}

/**
 * Upper bound of the rate of change of the interpolated angle, per unit of t. For nlerp between
 * rotations an angle theta apart the rate peaks at the midpoint at 2 tan(theta / 2), computed here from
 * the dot and cross products as 2 sin / (1 + cos).
 */
export function sweepAngularBound(sweep: Sweep): number {
  const cos = sweep.q1C * sweep.q2C + sweep.q1S * sweep.q2S;
  const sin = Math.abs(sweep.q1C * sweep.q2S - sweep.q1S * sweep.q2C);
  const denom = 1 + cos;
  // at or beyond a half turn nlerp is invalid; return a huge bound so that callers stay conservative
  return denom > 1e-12 ? (2 * sin) / denom : 2e12;
}
