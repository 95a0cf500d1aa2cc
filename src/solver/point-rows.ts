import { BodyState } from '../store/body-store';

/*
 * The point rows of a hinge: anchor B minus anchor A, along x and y, kept at zero. With the anchors
 * rA, rB relative to the bodies' centres (world-oriented), inverse masses mA, mB and inverse
 * inertias iA, iB:
 *
 *     C = (cB + rB) - (cA + rA)
 *     J = [ -1   0   rAy |  1   0  -rBy ]        (per body: x, y, turn)
 *         [  0  -1  -rAx |  0   1   rBx ]
 *     K = J M⁻¹ Jᵀ = [ mA + mB + iA rAy² + iB rBy²     -iA rAx rAy - iB rBx rBy   ]
 *                    [ -iA rAx rAy - iB rBx rBy        mA + mB + iA rAx² + iB rBx² ]
 *
 * The solvers of these rows compute them here: the revolute joint's own Gauss-Seidel (and its rows
 * closing a loop of the tree), the hinge batch, the hinge paths and the joint tree (J through
 * Joint.fillPointRows, and the rows' bias); the mouse joint's one-body rows solve with K here too.
 * Each method is the expression, term for term and in the same order, that its callers computed:
 * floating-point sums taken in another order give other bits, and the simulation must not change.
 * Where two solvers summed the same quantity in different orders and either order in the other's
 * place changed the simulation, both orders are here, named for it (pathMassDiagonal,
 * pathMassCoupling); where they solve or bound differently, both ways are (solveX and the inverse
 * of inverseDeterminant, boundedBias and pullBound). Written out elsewhere, for V8's inlining
 * budget (see Joint.updateAnchors): the anchors' turn and separation in Joint.updateAnchors, and the
 * weld's rows (these point rows and its angle row as one 3 × 3 block).
 *
 * Small methods of numbers (an impulse is applied in place; nothing is allocated), which the
 * optimizing compiler inlines. Methods of an object each solver holds, not functions of the module:
 * V8 checks the target of every call of a module's function (in a bundle, a binding that could be
 * assigned anew), four instructions a call, where a method found through the object's class needs
 * no check once the object's class is known; with functions, a hinge grid took 1.08x the
 * instructions a step. The object holds no state.
 * @internal
 */
export class PointRows {
  /** The x of point (x, y) turned by the rotation (c, s) (an anchor turned with its body). */
  turnedX(c: number, s: number, x: number, y: number): number {
    return c * x - s * y;
  }

  /** The y of point (x, y) turned by the rotation (c, s). */
  turnedY(c: number, s: number, x: number, y: number): number {
    return s * x + c * y;
  }

  /**
   * The position error C of one point row (x or y): anchor B minus anchor A, from the bodies'
   * translations since the step began (dpA, dpB), their centres' offset then (B minus A) and the
   * anchors now.
   */
  separation(dpA: number, dpB: number, dc: number, rA: number, rB: number): number {
    return dpB - dpA + dc + rB - rA;
  }

  /**
   * The speed of the x row (J v): the velocity of B's anchor minus A's. Called with the bodies'
   * roles swapped it is A's minus B's, -J v summed in the order the hinge paths sum it.
   */
  speedX(vAx: number, wA: number, rAy: number, vBx: number, wB: number, rBy: number): number {
    return vBx - wB * rBy - vAx + wA * rAy;
  }

  /** The speed of the y row (see speedX). */
  speedY(vAy: number, wA: number, rAx: number, vBy: number, wB: number, rBx: number): number {
    return vBy + wB * rBx - vAy - wA * rAx;
  }

  /**
   * K₁₁ (with the anchors' y arms: rAy, rBy) or K₂₂ (with their x arms), given `m` = mA + mB. The
   * order of the revolute joint, the hinge batch and the weld.
   */
  massDiagonal(m: number, iA: number, armA: number, iB: number, armB: number): number {
    return m + armA * armA * iA + armB * armB * iB;
  }

  /** K₁₂ = K₂₁, in the order of massDiagonal. */
  massCoupling(iA: number, rAx: number, rAy: number, iB: number, rBx: number, rBy: number): number {
    return -rAy * rAx * iA - rBy * rBx * iB;
  }

  /**
   * K₁₁ or K₂₂ in the hinge paths' order (iA rAy rAy: the inertia first). The same value as
   * massDiagonal to rounding; either order in the other's place changed the bits of the
   * simulations that use them (a chain, a pendulum; a hinge grid with motors).
   */
  pathMassDiagonal(m: number, iA: number, armA: number, iB: number, armB: number): number {
    return m + iA * armA * armA + iB * armB * armB;
  }

  /** K₁₂ in the hinge paths' order (see pathMassDiagonal). */
  pathMassCoupling(iA: number, rAx: number, rAy: number, iB: number, rBx: number, rBy: number): number {
    return -iA * rAx * rAy - iB * rBx * rBy;
  }

  /**
   * 1 / det of the symmetric 2 × 2 matrix [[k11, k12], [k12, k22]], or the zero determinant itself
   * when it is singular (what solves with it give then is zero). Its inverse is then
   * [[d k22, -d k12], [-d k12, d k11]]: the batch and the paths keep it so; the revolute and mouse
   * joints solve with solveX and solveY instead, whose bits differ (either way in the other's place
   * changed the simulation).
   */
  inverseDeterminant(k11: number, k12: number, k22: number): number {
    let det = k11 * k22 - k12 * k12;
    if (det !== 0) det = 1 / det;
    return det;
  }

  /** x of [[k11, k12], [k12, k22]] (x, y) = (b1, b2), given `inverseDet` (inverseDeterminant). */
  solveX(inverseDet: number, k12: number, k22: number, b1: number, b2: number): number {
    return inverseDet * (k22 * b1 - k12 * b2);
  }

  /** y of the system of solveX. */
  solveY(inverseDet: number, k11: number, k12: number, b1: number, b2: number): number {
    return inverseDet * (k11 * b2 - k12 * b1);
  }

  /**
   * A row's velocity bias: `biasRate` times its position error, within ±`limit`. The batch and the
   * paths bound each point row so, as the tree bounds each of its rows.
   */
  boundedBias(biasRate: number, error: number, limit: number): number {
    return Math.max(-limit, Math.min(biasRate * error, limit));
  }

  /**
   * The factor (at most 1) that bounds the point rows' bias (bx, by) to length `max`: the revolute
   * joint and the weld bound the pull so, as a whole, where the batch and the paths bound each row.
   */
  pullBound(bx: number, by: number, max: number): number {
    const b2 = bx * bx + by * by;
    return b2 > max * max ? max / Math.sqrt(b2) : 1;
  }

  /** A soft row's impulse: from `solved`, K⁻¹ (J v + bias), and its impulse accumulated so far. */
  softImpulse(massScale: number, impulseScale: number, solved: number, accumulated: number): number {
    return -massScale * solved - impulseScale * accumulated;
  }

  /** The angular impulse on a body of the point impulse (px, py) at its anchor (rx, ry): r × p. */
  anchorMoment(rx: number, ry: number, px: number, py: number): number {
    return rx * py - ry * px;
  }

  /**
   * Applies the point impulse (px, py) to the bodies' velocities in `state`: -p at A's anchor, p at
   * B's. The moments are anchorMoment's, written out: two calls more left the revolute joint's
   * solve (solvePoint) short of inlining budget for the rest.
   */
  applyImpulse(
    state: Float64Array,
    sa: number,
    sb: number,
    mA: number,
    iA: number,
    mB: number,
    iB: number,
    rAx: number,
    rAy: number,
    rBx: number,
    rBy: number,
    px: number,
    py: number,
  ): void {
    state[sa + BodyState.VX] -= mA * px;
    state[sa + BodyState.VY] -= mA * py;
    state[sa + BodyState.W] -= iA * (rAx * py - rAy * px);
    state[sb + BodyState.VX] += mB * px;
    state[sb + BodyState.VY] += mB * py;
    state[sb + BodyState.W] += iB * (rBx * py - rBy * px);
  }

  /**
   * Applies the point impulse (px, py) and the angular impulse `turn` (B's turn relative to A's) to
   * the bodies' velocities: a hinge's warm start (its axial rows' impulse), a weld.
   */
  applyTurnImpulse(
    state: Float64Array,
    sa: number,
    sb: number,
    mA: number,
    iA: number,
    mB: number,
    iB: number,
    rAx: number,
    rAy: number,
    rBx: number,
    rBy: number,
    px: number,
    py: number,
    turn: number,
  ): void {
    state[sa + BodyState.VX] -= mA * px;
    state[sa + BodyState.VY] -= mA * py;
    state[sa + BodyState.W] -= iA * (rAx * py - rAy * px + turn);
    state[sb + BodyState.VX] += mB * px;
    state[sb + BodyState.VY] += mB * py;
    state[sb + BodyState.W] += iB * (rBx * py - rBy * px + turn);
  }

  /**
   * Writes J (see above) as two rows of 3 at `m`: A's blocks to `jA`, B's to `jB` (the joint tree's
   * layout, see Joint.fillPointRows).
   */
  writeJacobian(
    jA: Float64Array,
    jB: Float64Array,
    m: number,
    rAx: number,
    rAy: number,
    rBx: number,
    rBy: number,
  ): void {
    jA[m] = -1;
    jA[m + 1] = 0;
    jA[m + 2] = rAy;
    jA[m + 3] = 0;
    jA[m + 4] = -1;
    jA[m + 5] = -rAx;
    jB[m] = 1;
    jB[m + 1] = 0;
    jB[m + 2] = -rBy;
    jB[m + 3] = 0;
    jB[m + 4] = 1;
    jB[m + 5] = rBx;
  }
}
