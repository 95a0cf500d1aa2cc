import { MAX_ROTATION_PER_SUBSTEP } from '../core/settings';
import { BodyKind, type BodyStore, S } from './body-store';

/**
 * Clamps the velocity of the body at state offset `s` to `maxSpeed` and `maxW`; an infinite or NaN
 * velocity becomes zero. Written so that NaN fails the comparisons and takes the clamp.
 */
export function clampVelocity(state: Float64Array, s: number, maxSpeed: number, maxW: number): void {
  const vx = state[s + S.VX];
  const vy = state[s + S.VY];
  const w = state[s + S.W];
  const v2 = vx * vx + vy * vy;
  if (!(v2 <= maxSpeed * maxSpeed)) {
    // finite: scaled onto the limit; infinite or NaN: stopped
    const finite = v2 < Number.POSITIVE_INFINITY;
    const scale = finite ? maxSpeed / Math.sqrt(v2) : 0;
    state[s + S.VX] = finite ? scale * vx : 0;
    state[s + S.VY] = finite ? scale * vy : 0;
  }
  if (!(w <= maxW && w >= -maxW)) state[s + S.W] = w > maxW ? maxW : w < -maxW ? -maxW : 0;
}

/**
 * Velocity update of one substep for the awake bodies: gravity, forces and damping.
 * Kinematic bodies keep their velocity. Damping is the implicit form v / (1 + h c), stable for any c.
 */
export function integrateVelocities(
  bodies: BodyStore,
  awake: Int32Array,
  awakeCount: number,
  h: number,
  gx: number,
  gy: number,
  maxLinearSpeed: number,
): void {
  const state = bodies.state;
  const kind = bodies.kind;
  const invMass = bodies.invMass;
  const invInertia = bodies.invInertia;
  const gravityScale = bodies.gravityScale;
  const linearDamping = bodies.linearDamping;
  const angularDamping = bodies.angularDamping;
  const fx = bodies.fx;
  const fy = bodies.fy;
  const torque = bodies.torque;
  const maxW = MAX_ROTATION_PER_SUBSTEP / h;
  for (let i = 0; i < awakeCount; i++) {
    const b = awake[i];
    if (kind[b] !== BodyKind.DYNAMIC) continue;
    const s = b * S.STRIDE;
    const m = invMass[b];
    const g = gravityScale[b];
    const linearFactor = 1 / (1 + h * linearDamping[b]);
    const vx = (state[s + S.VX] + h * (g * gx + m * fx[b])) * linearFactor;
    const vy = (state[s + S.VY] + h * (g * gy + m * fy[b])) * linearFactor;
    const w = (state[s + S.W] + h * invInertia[b] * torque[b]) / (1 + h * angularDamping[b]);
    state[s + S.VX] = vx;
    state[s + S.VY] = vy;
    state[s + S.W] = w;
    clampVelocity(state, s, maxLinearSpeed, maxW);
  }
}

/**
 * Position update of one substep: accumulates the translation of the centre of mass and the rotation
 * since the step began. The rotation is a (cos, sin) pair turned by the angle h w and renormalised.
 * A dynamic body's velocity is clamped to the limits again first: constraints that cannot all hold
 * (a network of joints locked against itself) can leave the solver with any velocity, and a body
 * moved by it would leave the finite numbers within a few steps.
 */
export function integratePositions(
  bodies: BodyStore,
  awake: Int32Array,
  awakeCount: number,
  h: number,
  maxLinearSpeed: number,
): void {
  const state = bodies.state;
  const kind = bodies.kind;
  const maxW = MAX_ROTATION_PER_SUBSTEP / h;
  for (let i = 0; i < awakeCount; i++) {
    const b = awake[i];
    const s = b * S.STRIDE;
    if (kind[b] === BodyKind.DYNAMIC) clampVelocity(state, s, maxLinearSpeed, maxW);
    const vx = state[s + S.VX];
    const vy = state[s + S.VY];
    const w = state[s + S.W];
    state[s + S.DPX] += h * vx;
    state[s + S.DPY] += h * vy;
    // rotate by the angle h w: its cosine and sine from their Taylor series (|h w| <= pi / 4, so the
    // angle is exact to ~1e-5 at the clamp and to rounding at everyday speeds), then renormalise
    const x = h * w;
    const x2 = x * x;
    const rc = 1 - x2 * (0.5 - x2 * (1 / 24 - x2 / 720));
    const rs = x * (1 - x2 * (1 / 6 - x2 * (1 / 120 - x2 / 5040)));
    const c = state[s + S.DQC];
    const sn = state[s + S.DQS];
    const nc = c * rc - sn * rs;
    const ns = sn * rc + c * rs;
    const inv = 1 / Math.sqrt(nc * nc + ns * ns);
    state[s + S.DQC] = nc * inv;
    state[s + S.DQS] = ns * inv;
  }
}
