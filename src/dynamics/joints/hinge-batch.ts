import { growF64, growI32 } from '../../core/grow';
import { S_DPX, S_DPY, S_DQC, S_DQS, S_VX, S_VY, S_W, STATE_STRIDE } from '../body-store';
import type { Softness } from '../softness';
import type { Joint } from './joint';
import type { JointContext } from './joint-context';

// Layout of one hinge in `HingeBatch.data` (doubles); see Joint for the meaning of the fields.
export const H_MA = 0;
export const H_IA = 1;
export const H_MB = 2;
export const H_IB = 3;
export const H_RAX0 = 4;
export const H_RAY0 = 5;
export const H_RBX0 = 6;
export const H_RBY0 = 7;
export const H_DCX = 8;
export const H_DCY = 9;
/** accumulated point impulse */
export const H_LX = 10;
export const H_LY = 11;
export const HINGE_STRIDE = 12;

/**
 * Writes a joint's step data (H_MA .. H_DCY) to `d` at `base`: its bodies' inverse masses, the
 * anchors relative to the centres of mass, world-oriented, and the centres' offset. The local
 * anchors (on A, then on B) are read from `anchors` at `k`.
 */
export function writeStepData(
  ctx: JointContext,
  a: number,
  b: number,
  anchors: Float64Array,
  k: number,
  d: Float64Array,
  base: number,
): void {
  d[base + H_MA] = ctx.invMass[a];
  d[base + H_IA] = ctx.invInertia[a];
  d[base + H_MB] = ctx.invMass[b];
  d[base + H_IB] = ctx.invInertia[b];
  let c = ctx.qc[a];
  let s = ctx.qs[a];
  let x = anchors[k] - ctx.lcx[a];
  let y = anchors[k + 1] - ctx.lcy[a];
  d[base + H_RAX0] = c * x - s * y;
  d[base + H_RAY0] = s * x + c * y;
  c = ctx.qc[b];
  s = ctx.qs[b];
  x = anchors[k + 2] - ctx.lcx[b];
  y = anchors[k + 3] - ctx.lcy[b];
  d[base + H_RBX0] = c * x - s * y;
  d[base + H_RBY0] = s * x + c * y;
  d[base + H_DCX] = ctx.cx[b] - ctx.cx[a];
  d[base + H_DCY] = ctx.cy[b] - ctx.cy[a];
}

/**
 * The plain hinges of a step (revolute joints without limit, motor or spring, solved by Gauss-Seidel:
 * grids, cloth, loops the tree does not take) packed into flat arrays, like the contacts: a joint
 * object keeps each field in its own heap box and is reached through a virtual call, which made
 * such joints cost more than their arithmetic. The joints pack their step data here
 * (Joint.packHinge, in place of prepare) and get their impulses back after the substeps (Joint.unpackHinge). The
 * arithmetic is the revolute joint's point rows, term for term.
 */
export class HingeBatch {
  count = 0;
  data = new Float64Array(0);
  /** body A and body B of each hinge */
  ids = new Int32Array(0);
  /** each hinge's local anchors on A and B (x, y, x, y), relative to the bodies' origins */
  anchors = new Float64Array(0);
  readonly joints: Joint[] = [];
  /** the active joints that are not in the batch, in their order */
  readonly otherActive: Joint[] = [];
  /** the iterative joints that are not in the batch, in their order */
  readonly otherIterative: Joint[] = [];

  /**
   * Prepares the step's joints (`active`, after the tree's build): the plain hinges are packed here,
   * the others prepare themselves. The other joints keep their order. Unless the tree chose anew
   * (`rebuilt`), the hinges are the same as last step and only their step data is refreshed, from
   * the anchors kept here, with last step's impulses.
   */
  prepare(active: readonly Joint[], iterative: readonly Joint[], ctx: JointContext, rebuilt: boolean): void {
    if (rebuilt) this.classify(active, iterative, ctx);
    else {
      const d = this.data;
      const ids = this.ids;
      for (let i = 0; i < this.count; i++) {
        writeStepData(ctx, ids[2 * i], ids[2 * i + 1], this.anchors, 4 * i, d, i * HINGE_STRIDE);
      }
    }
    for (const joint of this.otherActive) joint.prepare(ctx);
  }

  private classify(active: readonly Joint[], iterative: readonly Joint[], ctx: JointContext): void {
    this.joints.length = 0;
    this.otherIterative.length = 0;
    this.otherActive.length = 0;
    for (const joint of active) {
      if (joint.isPlainHinge()) this.joints.push(joint);
      else this.otherActive.push(joint);
    }
    for (const joint of iterative) if (!joint.isPlainHinge()) this.otherIterative.push(joint);
    const n = this.joints.length;
    if (this.data.length < n * HINGE_STRIDE) {
      const capacity = Math.max(64, 2 * n);
      this.data = growF64(this.data, capacity * HINGE_STRIDE);
      this.ids = growI32(this.ids, capacity * 2);
      this.anchors = growF64(this.anchors, capacity * 4);
    }
    for (let i = 0; i < n; i++) {
      this.joints[i].packHinge(ctx, this.data, i * HINGE_STRIDE, this.ids, 2 * i, this.anchors, 4 * i);
    }
    this.count = n;
  }

  /** Returns the accumulated impulses to the joints (warm start of the next step, reaction force). */
  store(ctx: JointContext): void {
    for (let i = 0; i < this.count; i++) this.joints[i].unpackHinge(this.data, i * HINGE_STRIDE, ctx);
  }

  /**
   * Applies the kept impulses; as Joint.warmStartGuarded, a hinge whose warm start would throw a body
   * past `speedLimit` or `turnLimit` leaves the velocities as they were and forgets its impulse.
   */
  warmStart(state: Float64Array, speedLimit: number, turnLimit: number): void {
    const d = this.data;
    const ids = this.ids;
    const v2 = speedLimit * speedLimit;
    for (let i = 0, n = this.count; i < n; i++) {
      const base = i * HINGE_STRIDE;
      const sa = ids[2 * i] * STATE_STRIDE;
      const sb = ids[2 * i + 1] * STATE_STRIDE;
      const mA = d[base + H_MA];
      const iA = d[base + H_IA];
      const mB = d[base + H_MB];
      const iB = d[base + H_IB];
      let c = state[sa + S_DQC];
      let s = state[sa + S_DQS];
      const rAx = c * d[base + H_RAX0] - s * d[base + H_RAY0];
      const rAy = s * d[base + H_RAX0] + c * d[base + H_RAY0];
      c = state[sb + S_DQC];
      s = state[sb + S_DQS];
      const rBx = c * d[base + H_RBX0] - s * d[base + H_RBY0];
      const rBy = s * d[base + H_RBX0] + c * d[base + H_RBY0];
      const px = d[base + H_LX];
      const py = d[base + H_LY];
      const vAx = state[sa + S_VX];
      const vAy = state[sa + S_VY];
      const wA = state[sa + S_W];
      const vBx = state[sb + S_VX];
      const vBy = state[sb + S_VY];
      const wB = state[sb + S_W];
      // `+ 0` as the revolute joint's warm start adds its (here zero) axial impulse: the same bits
      const nAx = vAx - mA * px;
      const nAy = vAy - mA * py;
      const nwA = wA - iA * (rAx * py - rAy * px + 0);
      const nBx = vBx + mB * px;
      const nBy = vBy + mB * py;
      const nwB = wB + iB * (rBx * py - rBy * px + 0);
      // written so that NaN fails the test too
      if (
        nAx * nAx + nAy * nAy <= v2 &&
        nBx * nBx + nBy * nBy <= v2 &&
        Math.abs(nwA) <= turnLimit &&
        Math.abs(nwB) <= turnLimit
      ) {
        state[sa + S_VX] = nAx;
        state[sa + S_VY] = nAy;
        state[sa + S_W] = nwA;
        state[sb + S_VX] = nBx;
        state[sb + S_VY] = nBy;
        state[sb + S_W] = nwB;
      } else {
        d[base + H_LX] = 0;
        d[base + H_LY] = 0;
      }
    }
  }

  /** One Gauss-Seidel pass over the hinges' point rows, soft with `useBias`, rigid without. */
  solve(state: Float64Array, soft: Softness, useBias: boolean): void {
    const d = this.data;
    const ids = this.ids;
    // read in every call, so that both passes give the loads type feedback (a load that only the
    // bias pass made left the compiled code without it: deoptimised, the function stayed unoptimised)
    const softBiasRate = soft.biasRate;
    const softMassScale = soft.massScale;
    const softImpulseScale = soft.impulseScale;
    const biasRate = useBias ? softBiasRate : 0;
    const massScale = useBias ? softMassScale : 1;
    const impulseScale = useBias ? softImpulseScale : 0;
    for (let i = 0, n = this.count; i < n; i++) {
      const base = i * HINGE_STRIDE;
      const sa = ids[2 * i] * STATE_STRIDE;
      const sb = ids[2 * i + 1] * STATE_STRIDE;
      const mA = d[base + H_MA];
      const iA = d[base + H_IA];
      const mB = d[base + H_MB];
      const iB = d[base + H_IB];
      let c = state[sa + S_DQC];
      let s = state[sa + S_DQS];
      const rAx = c * d[base + H_RAX0] - s * d[base + H_RAY0];
      const rAy = s * d[base + H_RAX0] + c * d[base + H_RAY0];
      c = state[sb + S_DQC];
      s = state[sb + S_DQS];
      const rBx = c * d[base + H_RBX0] - s * d[base + H_RBY0];
      const rBy = s * d[base + H_RBX0] + c * d[base + H_RBY0];
      const sepX = state[sb + S_DPX] - state[sa + S_DPX] + d[base + H_DCX] + rBx - rAx;
      const sepY = state[sb + S_DPY] - state[sa + S_DPY] + d[base + H_DCY] + rBy - rAy;
      let vAx = state[sa + S_VX];
      let vAy = state[sa + S_VY];
      let wA = state[sa + S_W];
      let vBx = state[sb + S_VX];
      let vBy = state[sb + S_VY];
      let wB = state[sb + S_W];
      const bx = vBx - wB * rBy - vAx + wA * rAy + biasRate * sepX;
      const by = vBy + wB * rBx - vAy - wA * rAx + biasRate * sepY;
      const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
      const k12 = -rAy * rAx * iA - rBy * rBx * iB;
      const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
      let det = k11 * k22 - k12 * k12;
      if (det !== 0) det = 1 / det;
      const lx = d[base + H_LX];
      const ly = d[base + H_LY];
      const px = -massScale * (det * (k22 * bx - k12 * by)) - impulseScale * lx;
      const py = -massScale * (det * (k11 * by - k12 * bx)) - impulseScale * ly;
      d[base + H_LX] = lx + px;
      d[base + H_LY] = ly + py;
      vAx -= mA * px;
      vAy -= mA * py;
      wA -= iA * (rAx * py - rAy * px);
      vBx += mB * px;
      vBy += mB * py;
      wB += iB * (rBx * py - rBy * px);
      state[sa + S_VX] = vAx;
      state[sa + S_VY] = vAy;
      state[sa + S_W] = wA;
      state[sb + S_VX] = vBx;
      state[sb + S_VY] = vBy;
      state[sb + S_W] = wB;
    }
  }
}
