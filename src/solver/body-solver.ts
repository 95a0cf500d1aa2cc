import { IndexBound } from '../core/index-bound';
import { MAX_ROTATION_PER_SUBSTEP } from '../core/settings';
import { BodyKind, BodyState, type BodyStore } from '../store/body-store';

/**
 * Clamps the velocity of the body at state offset `s` to `maxSpeed` and `maxW`; an infinite or NaN
 * velocity becomes zero. Written so that NaN fails the comparisons and takes the clamp.
 */
export function clampVelocity(state: Float64Array, s: number, maxSpeed: number, maxW: number): void {
  const vx = state[s + BodyState.VX];
  const vy = state[s + BodyState.VY];
  const w = state[s + BodyState.W];
  const v2 = vx * vx + vy * vy;
  if (!(v2 <= maxSpeed * maxSpeed)) {
    // finite: scaled onto the limit; infinite or NaN: stopped
    const finite = v2 < Number.POSITIVE_INFINITY;
    const scale = finite ? maxSpeed / Math.sqrt(v2) : 0;
    state[s + BodyState.VX] = finite ? scale * vx : 0;
    state[s + BodyState.VY] = finite ? scale * vy : 0;
  }
  if (!(w <= maxW && w >= -maxW)) state[s + BodyState.W] = w > maxW ? maxW : w < -maxW ? -maxW : 0;
}

/** Layout of one awake body's step-constant velocity update (see prepareVelocityUpdate). */
export enum VelocityUpdate {
  /** h times the acceleration from gravity and the applied force */
  DVX = 0,
  DVY = 1,
  /** h times the angular acceleration from the applied torque */
  DW = 2,
  /** the linear damping factor 1 / (1 + h c) */
  LINEAR = 3,
  /** the angular damping divisor 1 + h c */
  ANGULAR = 4,
  STRIDE = 5,
}

/**
 * Works out, for the awake dynamic bodies (by their index in `awake`), the parts of the substeps'
 * velocity update that stay the same for the whole step: gravity, forces and damping are constant
 * over it. Read by integrateVelocities from one short record per body, in the order of `awake`,
 * instead of from eight columns at every substep.
 * @internal
 */
export function prepareVelocityUpdate(
  bodies: BodyStore,
  awake: Int32Array,
  awakeCount: number,
  h: number,
  gx: number,
  gy: number,
  out: Float64Array,
): void {
  const kind = bodies.kind;
  const invMass = bodies.invMass;
  const invInertia = bodies.invInertia;
  const gravityScale = bodies.gravityScale;
  const linearDamping = bodies.linearDamping;
  const angularDamping = bodies.angularDamping;
  const fx = bodies.fx;
  const fy = bodies.fy;
  const torque = bodies.torque;
  for (let i = 0, n = awakeCount & IndexBound.MAX; i < n; i++) {
    const b = awake[i] & IndexBound.MAX;
    if (kind[b] !== BodyKind.DYNAMIC) continue;
    const o = i * VelocityUpdate.STRIDE;
    const m = invMass[b];
    const g = gravityScale[b];
    out[o + VelocityUpdate.DVX] = h * (g * gx + m * fx[b]);
    out[o + VelocityUpdate.DVY] = h * (g * gy + m * fy[b]);
    out[o + VelocityUpdate.DW] = h * invInertia[b] * torque[b];
    out[o + VelocityUpdate.LINEAR] = 1 / (1 + h * linearDamping[b]);
    out[o + VelocityUpdate.ANGULAR] = 1 + h * angularDamping[b];
  }
}

/**
 * Velocity update of one substep for the awake bodies: gravity, forces and damping, as prepared by
 * prepareVelocityUpdate. Kinematic bodies keep their velocity. Damping is the implicit form
 * v / (1 + h c), stable for any c.
 * @internal
 */
export function integrateVelocities(
  bodies: BodyStore,
  awake: Int32Array,
  from: number,
  to: number,
  update: Float64Array,
  h: number,
  maxLinearSpeed: number,
): void {
  const state = bodies.state;
  const kind = bodies.kind;
  const maxW = MAX_ROTATION_PER_SUBSTEP / h;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const b = awake[i] & IndexBound.MAX;
    if (kind[b] !== BodyKind.DYNAMIC) continue;
    const s = b * BodyState.STRIDE;
    const o = i * VelocityUpdate.STRIDE;
    const linearFactor = update[o + VelocityUpdate.LINEAR];
    state[s + BodyState.VX] = (state[s + BodyState.VX] + update[o + VelocityUpdate.DVX]) * linearFactor;
    state[s + BodyState.VY] = (state[s + BodyState.VY] + update[o + VelocityUpdate.DVY]) * linearFactor;
    state[s + BodyState.W] =
      (state[s + BodyState.W] + update[o + VelocityUpdate.DW]) / update[o + VelocityUpdate.ANGULAR];
    clampVelocity(state, s, maxLinearSpeed, maxW);
  }
}

/**
 * Position update of one substep: accumulates the translation of the centre of mass and the rotation
 * since the step began. The rotation is a (cos, sin) pair turned by the angle h w; it is renormalised
 * only in the step's `last` substep, whose relax pass and finalizeBodies need the exact rotation.
 * The velocity is clamped to the limits first. A dynamic body's again: constraints that cannot all
 * hold (a network of joints locked against itself) can leave the solver with any velocity, and a body
 * moved by it would leave the finite numbers within a few steps. A kinematic body's as set by the
 * user: the turn below is exact only up to a quarter turn, and no body outruns the speed limit.
 * @internal
 */
export function integratePositions(
  bodies: BodyStore,
  awake: Int32Array,
  from: number,
  to: number,
  h: number,
  maxLinearSpeed: number,
  last: boolean,
): void {
  const state = bodies.state;
  const maxW = MAX_ROTATION_PER_SUBSTEP / h;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const b = awake[i] & IndexBound.MAX;
    const s = b * BodyState.STRIDE;
    clampVelocity(state, s, maxLinearSpeed, maxW);
    const vx = state[s + BodyState.VX];
    const vy = state[s + BodyState.VY];
    const w = state[s + BodyState.W];
    state[s + BodyState.DPX] += h * vx;
    state[s + BodyState.DPY] += h * vy;
    // rotate by the angle h w: its cosine and sine from their Taylor series, exact to ~2e-8 at the
    // clamp (|h w| <= pi / 4) and to rounding at everyday speeds, so the pair's length stays within
    // ~1e-7 of 1 until the last substep renormalises it (a square root and a division per body and
    // substep saved in the others)
    const x = h * w;
    const x2 = x * x;
    const rc = 1 - x2 * (0.5 - x2 * (1 / 24 - x2 * (1 / 720 - x2 / 40320)));
    const rs = x * (1 - x2 * (1 / 6 - x2 * (1 / 120 - x2 * (1 / 5040 - x2 / 362880))));
    const c = state[s + BodyState.DQC];
    const sn = state[s + BodyState.DQS];
    const nc = c * rc - sn * rs;
    const ns = sn * rc + c * rs;
    const inv = last ? 1 / Math.sqrt(nc * nc + ns * ns) : 1;
    state[s + BodyState.DQC] = nc * inv;
    state[s + BodyState.DQS] = ns * inv;
  }
}
