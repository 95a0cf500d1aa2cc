import { arcTangent2 } from '../math/arc-tangent';

/**
 * Solves the symmetric system [[a11, a12, a13], [a12, a22, a23], [a13, a23, a33]] x = b into `out`
 * by cofactors; a singular matrix gives zeros.
 */
export function solveSymmetric33(
  a11: number,
  a12: number,
  a13: number,
  a22: number,
  a23: number,
  a33: number,
  b1: number,
  b2: number,
  b3: number,
  out: Float64Array,
): void {
  const c11 = a22 * a33 - a23 * a23;
  const c12 = a13 * a23 - a12 * a33;
  const c13 = a12 * a23 - a13 * a22;
  let det = a11 * c11 + a12 * c12 + a13 * c13;
  if (det !== 0) det = 1 / det;
  const c22 = a11 * a33 - a13 * a13;
  const c23 = a12 * a13 - a11 * a23;
  const c33 = a11 * a22 - a12 * a12;
  out[0] = det * (c11 * b1 + c12 * b2 + c13 * b3);
  out[1] = det * (c12 * b1 + c22 * b2 + c23 * b3);
  out[2] = det * (c13 * b1 + c23 * b2 + c33 * b3);
}

/**
 * Angle of rotation B relative to rotation A, in (-pi, pi], from their (cos, sin) pairs, with the
 * engine's deterministic arc tangent.
 */
export function relativeAngle(aC: number, aS: number, bC: number, bS: number): number {
  // q = conj(qA) * qB
  const c = aC * bC + aS * bS;
  const s = aC * bS - aS * bC;
  return arcTangent2(s, c);
}

/**
 * Wraps an angle into (-pi, pi]. A joint's angle is the bodies' relative angle, itself in (-pi, pi],
 * minus a reference angle: unwrapped, a hinge whose bodies turn past half a turn apart would read
 * its angle 2 pi off and throw itself at its limits a full turn away.
 */
export function unwindAngle(a: number): number {
  if (a > -Math.PI && a <= Math.PI) return a;
  const turns = Math.floor((a + Math.PI) / (2 * Math.PI));
  const r = a - turns * 2 * Math.PI;
  return r > -Math.PI ? r : r + 2 * Math.PI;
}
