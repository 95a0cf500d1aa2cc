import { growF64, growI32 } from '../core/grow';
import { IndexBound } from '../core/index-bound';
import { BodyState } from '../store/body-store';
import { Anchor, HingeField, turnStepData, writeStepData } from './hinge-batch';
import type { JointContext } from './joint-context';
import { PointRows } from './point-rows';
import type { SolverJoint } from './solver-joint';

/**
 * Layout of one hinge of a path in `HingePaths.data` (doubles): the hinge batch's step data
 * (HingeField.MA .. HingeField.DCY, and HingeField.RAX .. HingeField.RBY for the current anchors),
 * with the body before the hinge on the path as A and the one after it as B, then the
 * factorization's and the projection's numbers.
 */
export enum PathField {
  /**
   * separation of the anchors (after minus before) at the last factorization; the first field after
   * HingeField's, written as a number: a bundler compiling file by file cannot read HingeField.STRIDE
   */
  EX = 19,
  EY,
  /** L = B D⁻¹ of the previous hinge (B: its coupling to this one), 2 × 2, row-major */
  L11,
  L12,
  L21,
  L22,
  /** D⁻¹, the inverse of this hinge's pivot, symmetric */
  E11,
  E12,
  E22,
  /** the forward substitution's value */
  YX,
  YY,
  /** 1 when the hinge before on the path shares this one's body A, 0 at the start of a path */
  LINK,
  STRIDE,
}

/*
 * Direct solver for the point rows of hinges that form paths: chains and ropes of revolute joints, each
 * body on at most two of them. Ordered along a path, hinge k couples only to k - 1 and k + 1 (through
 * the body they share), so the rows' effective mass A = J M⁻¹ Jᵀ is block tridiagonal with 2 × 2
 * blocks, and A = L D Lᵀ takes one pass down the path, and a solve a pass each way:
 *
 *     D_0 = A_00,   L_k = A_k,k-1 D_k-1⁻¹,   D_k = A_kk - L_k A_k,k-1ᵀ
 *
 * The body-and-joint tree of JointTree gives the same exact projection for any tree; along a path
 * this takes about a third of its arithmetic, and reads the bodies and anchors in one loop, without
 * the joints' calls.
 *
 * A is positive definite (each hinge of a path brings a body of its own), so no pivoting is needed.
 * Non-dynamic bodies at a path's end have zero inverse mass and add nothing; their velocity still
 * enters J v, so a kinematic end drives the path.
 */
/** @internal */
export class HingePaths {
  /** the hinges, path after path, each path from one end to the other */
  readonly joints: SolverJoint[] = [];
  count = 0;
  /** the fastest the hinges' position correction may pull (see JointTree's pushLimit) */
  pushLimit = 0;
  private data = new Float64Array(0);
  /** per hinge: the slots of the bodies before and after it on the path */
  private ids = new Int32Array(0);
  /** per hinge: its anchors (Anchor layout), with the body before it as A and the one after as B */
  private anchors = new Float64Array(0);
  /** whether the paths were laid anew since the last prepare (their masses must be read) */
  private laid = false;
  /** per hinge: 1 when the joint's body A comes before it on its path, -1 when B does */
  private orientation = new Float64Array(0);
  /**
   * Whether the step's last factorization carried the step data over to the next step (see factor),
   * and the world's pose epoch when that step began (JointContext.poseEpoch): while it holds, the
   * next step starts from it, without turnStepData and without its first factorization.
   */
  private carried = false;
  private stepPoseEpoch = -1;
  /** set by prepare: the first factorization of this step is the last one of the step before */
  private startFactored = false;
  /** the hinges before the last clear, and whether add() laid them again in the same places */
  private readonly previous: SolverJoint[] = [];
  private sameLayout = false;
  /** the point rows' maths (a # field, no property key: the snapshot leaves it out) */
  readonly #rows = new PointRows();

  /** Empties the list (before a build adds the paths anew). */
  clear(): void {
    this.previous.length = 0;
    for (const joint of this.joints) this.previous.push(joint);
    this.sameLayout = true;
    this.joints.length = 0;
    this.count = 0;
  }

  /**
   * Appends `joint` to the current path, or starts a new path with it (`startsPath`); `forward` when
   * its body A is the one before it on the path.
   */
  add(joint: SolverJoint, startsPath: boolean, forward: boolean): void {
    const k = this.count;
    if (this.ids.length < 2 * (k + 1)) {
      const cap = Math.max(16, 2 * (k + 1));
      this.data = growF64(this.data, cap * PathField.STRIDE);
      this.ids = growI32(this.ids, 2 * cap);
      this.anchors = growF64(this.anchors, Anchor.STRIDE * cap);
      this.orientation = growF64(this.orientation, cap);
    }
    const sense = forward ? 1 : -1;
    const link = startsPath ? 0 : 1;
    if (
      this.previous[k] !== joint ||
      this.orientation[k] !== sense ||
      this.data[k * PathField.STRIDE + PathField.LINK] !== link
    ) {
      this.sameLayout = false;
    }
    const a = joint.slotA;
    const b = joint.slotB;
    this.ids[2 * k] = forward ? a : b;
    this.ids[2 * k + 1] = forward ? b : a;
    const o = k * Anchor.STRIDE;
    this.anchors[o + Anchor.AX] = forward ? joint.localAnchorAx : joint.localAnchorBx;
    this.anchors[o + Anchor.AY] = forward ? joint.localAnchorAy : joint.localAnchorBy;
    this.anchors[o + Anchor.BX] = forward ? joint.localAnchorBx : joint.localAnchorAx;
    this.anchors[o + Anchor.BY] = forward ? joint.localAnchorBy : joint.localAnchorAy;
    this.laid = true;
    this.orientation[k] = sense;
    this.data[k * PathField.STRIDE + PathField.LINK] = link;
    // a hinge here is not prepared (HingePaths reads its step data itself): impulses of rows it had
    // before (limit, motor, spring) must not linger in its reaction torque
    joint.onPath = true;
    joint.forgetImpulses();
    this.joints.push(joint);
    this.count = k + 1;
  }

  /**
   * Reads the step's masses and anchors (once a step, before the first factorization), unless the
   * last step carried them over and no pose or mass was set since (paths laid again the same way
   * keep their records).
   */
  prepare(ctx: JointContext): void {
    if (this.count === 0) return;
    const carry =
      this.carried &&
      this.stepPoseEpoch === ctx.poseEpoch &&
      (!this.laid || (this.sameLayout && this.count === this.previous.length));
    // the masses and centres change only with a body's mass, which lays the paths anew
    if (!carry) {
      if (this.laid)
        writeStepData(ctx, this.#rows, this.ids, this.anchors, this.data, 0, this.count, PathField.STRIDE);
      else turnStepData(ctx, this.#rows, this.ids, this.anchors, this.data, 0, this.count, PathField.STRIDE);
    }
    this.startFactored = carry;
    this.carried = false;
    this.stepPoseEpoch = ctx.poseEpoch;
    this.laid = false;
  }

  /** Whether the step's first factorization is the last one of the step before (see prepare). */
  get factoredAtStart(): boolean {
    return this.startFactored;
  }

  /**
   * Turns the anchors with the bodies, measures the separations and factors A at the current
   * positions. The step's `last` factorization also carries the step data over to the next step (as
   * HingeBatch.relax does): its turned anchors and centres' offset are the next step's, and so is
   * the factorization itself.
   */
  factor(state: Float64Array, last: boolean): void {
    const rows = this.#rows;
    const d = this.data;
    const ids = this.ids;
    // the previous hinge's anchor on the body after it, and its D⁻¹ (times 0 at a path's start)
    let qx = 0;
    let qy = 0;
    let e11 = 0;
    let e12 = 0;
    let e22 = 0;
    for (let k = 0, n = this.count & IndexBound.MAX; k < n; k++) {
      const base = k * PathField.STRIDE;
      const sa = (ids[2 * k] & IndexBound.MAX) * BodyState.STRIDE;
      const sb = (ids[2 * k + 1] & IndexBound.MAX) * BodyState.STRIDE;
      // every field read once and before the stores (see HingeBatch.relax)
      const mA = d[base + HingeField.MA];
      const iA = d[base + HingeField.IA];
      const mB = d[base + HingeField.MB];
      const iB = d[base + HingeField.IB];
      const link = d[base + PathField.LINK];
      const dcx = d[base + HingeField.DCX];
      const dcy = d[base + HingeField.DCY];
      const rAx0 = d[base + HingeField.RAX0];
      const rAy0 = d[base + HingeField.RAY0];
      const rBx0 = d[base + HingeField.RBX0];
      const rBy0 = d[base + HingeField.RBY0];
      let c = state[sa + BodyState.DQC];
      let s = state[sa + BodyState.DQS];
      const rAx = rows.turnedX(c, s, rAx0, rAy0);
      const rAy = rows.turnedY(c, s, rAx0, rAy0);
      c = state[sb + BodyState.DQC];
      s = state[sb + BodyState.DQS];
      const rBx = rows.turnedX(c, s, rBx0, rBy0);
      const rBy = rows.turnedY(c, s, rBx0, rBy0);
      d[base + HingeField.RAX] = rAx;
      d[base + HingeField.RAY] = rAy;
      d[base + HingeField.RBX] = rBx;
      d[base + HingeField.RBY] = rBy;
      const dpAx = state[sa + BodyState.DPX];
      const dpAy = state[sa + BodyState.DPY];
      const dpBx = state[sb + BodyState.DPX];
      const dpBy = state[sb + BodyState.DPY];
      d[base + PathField.EX] = rows.separation(dpAx, dpBx, dcx, rAx, rBx);
      d[base + PathField.EY] = rows.separation(dpAy, dpBy, dcy, rAy, rBy);
      if (last) {
        d[base + HingeField.RAX0] = rAx;
        d[base + HingeField.RAY0] = rAy;
        d[base + HingeField.RBX0] = rBx;
        d[base + HingeField.RBY0] = rBy;
        d[base + HingeField.DCX] = dcx + (dpBx - dpAx);
        d[base + HingeField.DCY] = dcy + (dpBy - dpAy);
      }
      // the coupling to the previous hinge through body A (B of that one): the velocity of this
      // hinge's rows per unit impulse on the previous one's, -(m 1 + i r⊥ q⊥ᵀ)
      const b11 = -link * (mA + iA * rAy * qy);
      const b12 = link * iA * rAy * qx;
      const b21 = link * iA * rAx * qy;
      const b22 = -link * (mA + iA * rAx * qx);
      const l11 = b11 * e11 + b12 * e12;
      const l12 = b11 * e12 + b12 * e22;
      const l21 = b21 * e11 + b22 * e12;
      const l22 = b21 * e12 + b22 * e22;
      d[base + PathField.L11] = l11;
      d[base + PathField.L12] = l12;
      d[base + PathField.L21] = l21;
      d[base + PathField.L22] = l22;
      // the pivot: this hinge's own effective mass K less what the previous hinges take of it
      const d11 = rows.pathMassDiagonal(mA + mB, iA, rAy, iB, rBy) - (l11 * b11 + l12 * b12);
      const d12 = rows.pathMassCoupling(iA, rAx, rAy, iB, rBx, rBy) - (l11 * b21 + l12 * b22);
      const d22 = rows.pathMassDiagonal(mA + mB, iA, rAx, iB, rBx) - (l21 * b21 + l22 * b22);
      const det = rows.inverseDeterminant(d11, d12, d22);
      e11 = det * d22;
      e12 = -det * d12;
      e22 = det * d11;
      d[base + PathField.E11] = e11;
      d[base + PathField.E12] = e12;
      d[base + PathField.E22] = e22;
      qx = rBx;
      qy = rBy;
    }
    if (last) this.carried = true;
  }

  /**
   * Projects the velocities onto the hinges' rows, J v = -biasRate C, with the last factorization
   * (see JointTree.project; `first` as there).
   */
  project(state: Float64Array, biasRate: number, first: boolean): void {
    const rows = this.#rows;
    const d = this.data;
    const limit = this.pushLimit;
    const ids = this.ids;
    const n = this.count & IndexBound.MAX;
    // forward: y_k = -(J v + bias)_k - L_k y_k-1
    let yx = 0;
    let yy = 0;
    for (let k = 0; k < n; k++) {
      const base = k * PathField.STRIDE;
      const sa = (ids[2 * k] & IndexBound.MAX) * BodyState.STRIDE;
      const sb = (ids[2 * k + 1] & IndexBound.MAX) * BodyState.STRIDE;
      const wA = state[sa + BodyState.W];
      const wB = state[sb + BodyState.W];
      // -(J v + bias): the speed with the bodies' roles swapped is -J v (see PointRows.speedX)
      const rx =
        rows.speedX(
          state[sb + BodyState.VX],
          wB,
          d[base + HingeField.RBY],
          state[sa + BodyState.VX],
          wA,
          d[base + HingeField.RAY],
        ) - rows.boundedBias(biasRate, d[base + PathField.EX], limit);
      const ry =
        rows.speedY(
          state[sb + BodyState.VY],
          wB,
          d[base + HingeField.RBX],
          state[sa + BodyState.VY],
          wA,
          d[base + HingeField.RAX],
        ) - rows.boundedBias(biasRate, d[base + PathField.EY], limit);
      const nx = rx - (d[base + PathField.L11] * yx + d[base + PathField.L12] * yy);
      yy = ry - (d[base + PathField.L21] * yx + d[base + PathField.L22] * yy);
      yx = nx;
      d[base + PathField.YX] = yx;
      d[base + PathField.YY] = yy;
    }
    // backward: λ_k = D_k⁻¹ y_k - L_k+1ᵀ λ_k+1, applied to the bodies as it is found
    let px = 0;
    let py = 0;
    let l11 = 0;
    let l12 = 0;
    let l21 = 0;
    let l22 = 0;
    const keep = first ? 0 : 1;
    for (let k = n - 1; k >= 0; k--) {
      const base = k * PathField.STRIDE;
      const y1 = d[base + PathField.YX];
      const y2 = d[base + PathField.YY];
      const e12 = d[base + PathField.E12];
      const nx = d[base + PathField.E11] * y1 + e12 * y2 - (l11 * px + l21 * py);
      const ny = e12 * y1 + d[base + PathField.E22] * y2 - (l12 * px + l22 * py);
      px = nx;
      py = ny;
      l11 = d[base + PathField.L11];
      l12 = d[base + PathField.L12];
      l21 = d[base + PathField.L21];
      l22 = d[base + PathField.L22];
      const mA = d[base + HingeField.MA];
      const iA = d[base + HingeField.IA];
      const mB = d[base + HingeField.MB];
      const iB = d[base + HingeField.IB];
      const rAx = d[base + HingeField.RAX];
      const rAy = d[base + HingeField.RAY];
      const rBx = d[base + HingeField.RBX];
      const rBy = d[base + HingeField.RBY];
      d[base + HingeField.LX] = keep * d[base + HingeField.LX] + px;
      d[base + HingeField.LY] = keep * d[base + HingeField.LY] + py;
      const sa = (ids[2 * k] & IndexBound.MAX) * BodyState.STRIDE;
      const sb = (ids[2 * k + 1] & IndexBound.MAX) * BodyState.STRIDE;
      rows.applyImpulse(state, sa, sb, mA, iA, mB, iB, rAx, rAy, rBx, rBy, px, py);
    }
  }

  /**
   * Hands each hinge its impulse of the step (reaction force), turned to the joint's own sense in
   * place: the next step's first projection sets it anew.
   */
  store(ctx: JointContext): void {
    const d = this.data;
    for (let k = 0; k < this.count; k++) {
      const base = k * PathField.STRIDE;
      const sense = this.orientation[k];
      d[base + HingeField.LX] *= sense;
      d[base + HingeField.LY] *= sense;
      this.joints[k].unpackHinge(d, base, ctx.invH);
    }
  }
}
