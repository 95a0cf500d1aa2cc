/**
 * Soft constraint coefficients for a spring of `hertz` and `dampingRatio` stepped at `h` seconds
 * (Erin Catto, "Solver2D" / soft step): the bias rate turns position error into a velocity target,
 * the mass and impulse scales soften the constraint so it behaves like a damped spring.
 */
export interface Softness {
  biasRate: number;
  massScale: number;
  impulseScale: number;
}

export function makeSoftness(hertz: number, dampingRatio: number, h: number, out: Softness): Softness {
  if (hertz === 0) {
    out.biasRate = 0;
    out.massScale = 1;
    out.impulseScale = 0;
    return out;
  }
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * dampingRatio + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  out.biasRate = omega / a1;
  out.massScale = a2 * a3;
  out.impulseScale = a3;
  return out;
}
