/**
 * Soft constraint coefficients for a spring of `hertz` and `dampingRatio` stepped at `h` seconds
 * (Erin Catto, "Solver2D" / soft step): the bias rate turns position error into a velocity target,
 * the mass and impulse scales soften the constraint so it behaves like a damped spring.
 * @internal
 */
export interface Softness {
  biasRate: number;
  massScale: number;
  impulseScale: number;
}

/** @internal */
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

/**
 * A spring's rows ring at most at this share of the substep rate: a row whose own masses would make
 * it ring faster is softened to this frequency (see springInvMass).
 */
const SPRING_MAX_CYCLES_PER_SUBSTEP = 0.1;

/**
 * The inverse mass that sets a spring row's stiffness, k = (2 pi hertz)² / springInvMass: the
 * bodies' own inverse mass, `ownInvMass` (the sum of their inverse masses for a push, of their
 * inverse inertias for a turn), which does not change as they move, so that the spring is a true,
 * conservative one. The soft step's row takes its stiffness from the row's effective mass instead,
 * which changes as the bodies turn (the lever arms of its anchors): such a spring is not
 * conservative, and an undamped weld on a small box pumped itself up to the speed limit.
 *
 * But a row whose effective inverse mass `rowInvMass` is far above the own one (a small body at the
 * end of a long lever) would then ring far faster than the spring's frequency, past what the substep
 * can follow, and gained energy in networks of such springs. Its stiffness is held so that it rings
 * at SPRING_MAX_CYCLES_PER_SUBSTEP of the substep rate at most: there it follows the row's
 * effective mass, as the soft step does.
 */
export function springInvMass(hertz: number, h: number, ownInvMass: number, rowInvMass: number): number {
  const cycles = hertz * h;
  const share = cycles / SPRING_MAX_CYCLES_PER_SUBSTEP;
  return Math.max(ownInvMass, rowInvMass * share * share);
}

/**
 * The impulse of a spring row (implicit Euler, as the soft step's rows): `soft` its softness at
 * `hertz`, `ownInvMass` and `invMass` its own and effective inverse masses (see springInvMass; the
 * effective one through the joint tree where the tree weighs the row), `speed` its velocity, `C` its
 * stretch and `accumulated` its impulse so far in the substep. The compliance γ = springInvMass / a2
 * (a2 = massScale / impulseScale) makes it -(speed + biasRate C + γ accumulated) / (invMass + γ);
 * with springInvMass = invMass this is the soft step's row,
 * -massScale (speed + biasRate C) / invMass - impulseScale accumulated.
 * @internal
 */
export function springImpulse(
  soft: Softness,
  hertz: number,
  h: number,
  ownInvMass: number,
  invMass: number,
  speed: number,
  C: number,
  accumulated: number,
): number {
  // a row that cannot move (a body that cannot turn, a tree that leaves it no room) takes no impulse
  if (invMass <= 0) return 0;
  const gamma = (springInvMass(hertz, h, ownInvMass, invMass) * soft.impulseScale) / soft.massScale;
  return -(speed + soft.biasRate * C + gamma * accumulated) / (invMass + gamma);
}
