import { arcTangent2 } from './arc-tangent';
import type { Rot } from './vec2';

// Cody-Waite split of pi/2 so that the range reduction keeps full precision for everyday angles.
const HALF_PI_HI = 1.5707963267341256; // leading 33 bits of pi/2
const HALF_PI_LO = 6.077100506506192e-11; // pi/2 - HALF_PI_HI
const TWO_OVER_PI = 0.6366197723675814;

// Taylor coefficients; on |r| <= pi/4 the truncation error is below 1e-16.
function sinPoly(r: number): number {
  const r2 = r * r;
  let p = -1 / 1307674368000;
  p = p * r2 + 1 / 6227020800;
  p = p * r2 - 1 / 39916800;
  p = p * r2 + 1 / 362880;
  p = p * r2 - 1 / 5040;
  p = p * r2 + 1 / 120;
  p = p * r2 - 1 / 6;
  return r + r * r2 * p;
}

function cosPoly(r: number): number {
  const r2 = r * r;
  let p = 1 / 20922789888000;
  p = p * r2 - 1 / 87178291200;
  p = p * r2 + 1 / 479001600;
  p = p * r2 - 1 / 3628800;
  p = p * r2 + 1 / 40320;
  p = p * r2 - 1 / 720;
  p = p * r2 + 1 / 24;
  p = p * r2 - 1 / 2;
  return 1 + r2 * p;
}

/**
 * Deterministic cosine/sine of an angle, written into `out`.
 * Uses only + - * / and floor, so it gives the same bits on every JavaScript engine
 * (Math.sin and Math.cos are not specified to the last bit).
 */
export function makeRotInto(angle: number, out: Rot): Rot {
  const k = Math.floor(angle * TWO_OVER_PI + 0.5);
  const r = angle - k * HALF_PI_HI - k * HALF_PI_LO;
  const s = sinPoly(r);
  const c = cosPoly(r);
  const quadrant = k - 4 * Math.floor(k / 4);
  if (quadrant === 0) {
    out.c = c;
    out.s = s;
  } else if (quadrant === 1) {
    out.c = -s;
    out.s = c;
  } else if (quadrant === 2) {
    out.c = -c;
    out.s = -s;
  } else {
    out.c = s;
    out.s = -c;
  }
  return out;
}

export function makeRot(angle: number): Rot {
  return makeRotInto(angle, { c: 1, s: 0 });
}

/**
 * Angle of a rotation in [-pi, pi]. For output only (it never feeds the step), but the same bits on
 * every engine too: Math.atan2 is not specified to the last bit, and Chromium 156.0.8078.108's gave
 * other bits than Node 20's for the bench's pyramid after one step (body.angle, read by the browser
 * bench's test that compares Chromium's transforms with Node's).
 */
export function rotAngle(c: number, s: number): number {
  return arcTangent2(s, c);
}
