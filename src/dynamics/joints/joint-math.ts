import { arcTangent2 } from '../../math/arc-tangent';

/** Scratch output of solve22 (no allocation). */
export const solved = { x: 0, y: 0 };

/** Solves [[a11, a12], [a12, a22]] (x, y) = (b1, b2) into `solved`; a singular matrix gives zeros. */
export function solve22(a11: number, a12: number, a22: number, b1: number, b2: number): void {
  let det = a11 * a22 - a12 * a12;
  if (det !== 0) det = 1 / det;
  solved.x = det * (a22 * b1 - a12 * b2);
  solved.y = det * (a11 * b2 - a12 * b1);
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

/** Wraps an angle into (-pi, pi]. */
export function unwindAngle(a: number): number {
  if (a < -Math.PI) return a + 2 * Math.PI;
  if (a > Math.PI) return a - 2 * Math.PI;
  return a;
}
