import { growF64, growI32 } from '../core/grow';
import { IndexBound } from '../core/index-bound';
import { BodyState } from '../store/body-store';
import { GraphColoring } from './graph-color';
import type { JointContext } from './joint-context';
import { PointRows } from './point-rows';
import type { Softness } from './softness';
import type { SolverJoint } from './solver-joint';

// Layout of one hinge in `HingeBatch.data` (doubles); see SolverJoint for the meaning of the fields.
export enum HingeField {
  MA = 0,
  IA = 1,
  MB = 2,
  IB = 3,
  RAX0 = 4,
  RAY0 = 5,
  RBX0 = 6,
  RBY0 = 7,
  DCX = 8,
  DCY = 9,
  /** accumulated point impulse */
  LX = 10,
  LY = 11,
  /**
   * the anchors turned with the bodies' rotation since the step began, and the inverse of the point
   * rows' effective mass K, symmetric (see HingeBatch.solve)
   */
  RAX = 12,
  RAY = 13,
  RBX = 14,
  RBY = 15,
  M11 = 16,
  M12 = 17,
  M22 = 18,
  STRIDE = 19,
}

/**
 * Layout of a hinge's anchors (doubles): on A and on B in the bodies' frames relative to their
 * origins, as the joint holds them, then relative to their centres of mass (see writeStepData).
 */
export enum Anchor {
  AX = 0,
  AY = 1,
  BX = 2,
  BY = 3,
  CAX = 4,
  CAY = 5,
  CBX = 6,
  CBY = 7,
  STRIDE = 8,
}

/**
 * Writes the step data of hinge records `from` to `to` - 1 (HingeField.MA .. HingeField.DCY, and HingeField.RAX .. HingeField.M22 for
 * the first substep) to `d`: the bodies' inverse masses, the anchors relative to the centres of
 * mass, world-oriented, and the centres' offset. The bodies' slots are read from `ids` (2 a record),
 * the local anchors from `anchors` (Anchor layout), whose anchors relative to the centres it fills
 * in. Records are `stride` doubles apart (HingePaths' records begin with these fields). Until a
 * body's mass changes (which makes the joints' step anew), the next steps need only turnStepData.
 * @internal
 */
export function writeStepData(
  ctx: JointContext,
  rows: PointRows,
  ids: Int32Array,
  anchors: Float64Array,
  d: Float64Array,
  from: number,
  to: number,
  stride: number = HingeField.STRIDE,
): void {
  const invMass = ctx.invMass;
  const invInertia = ctx.invInertia;
  const lcx = ctx.lcx;
  const lcy = ctx.lcy;
  for (let i = from & IndexBound.MAX, n = to & IndexBound.MAX; i < n; i++) {
    const a = ids[2 * i] & IndexBound.MAX;
    const b = ids[2 * i + 1] & IndexBound.MAX;
    const base = i * stride;
    const k = i * Anchor.STRIDE;
    d[base + HingeField.MA] = invMass[a];
    d[base + HingeField.IA] = invInertia[a];
    d[base + HingeField.MB] = invMass[b];
    d[base + HingeField.IB] = invInertia[b];
    anchors[k + Anchor.CAX] = anchors[k + Anchor.AX] - lcx[a];
    anchors[k + Anchor.CAY] = anchors[k + Anchor.AY] - lcy[a];
    anchors[k + Anchor.CBX] = anchors[k + Anchor.BX] - lcx[b];
    anchors[k + Anchor.CBY] = anchors[k + Anchor.BY] - lcy[b];
  }
  turnStepData(ctx, rows, ids, anchors, d, from, to, stride);
}

/**
 * The part of writeStepData that changes every step: the anchors turned with the bodies (from
 * `anchors`' centred ones), the centres' offset, and K's inverse for the first substep. The masses
 * must be in `d` already.
 * @internal
 */
export function turnStepData(
  ctx: JointContext,
  rows: PointRows,
  ids: Int32Array,
  anchors: Float64Array,
  d: Float64Array,
  from: number,
  to: number,
  stride: number = HingeField.STRIDE,
): void {
  const qc = ctx.qc;
  const qs = ctx.qs;
  const cx = ctx.cx;
  const cy = ctx.cy;
  for (let i = from & IndexBound.MAX, n = to & IndexBound.MAX; i < n; i++) {
    const a = ids[2 * i] & IndexBound.MAX;
    const b = ids[2 * i + 1] & IndexBound.MAX;
    const base = i * stride;
    const k = i * Anchor.STRIDE;
    let c = qc[a];
    let s = qs[a];
    let x = anchors[k + Anchor.CAX];
    let y = anchors[k + Anchor.CAY];
    const rAx = rows.turnedX(c, s, x, y);
    const rAy = rows.turnedY(c, s, x, y);
    c = qc[b];
    s = qs[b];
    x = anchors[k + Anchor.CBX];
    y = anchors[k + Anchor.CBY];
    const rBx = rows.turnedX(c, s, x, y);
    const rBy = rows.turnedY(c, s, x, y);
    d[base + HingeField.RAX0] = rAx;
    d[base + HingeField.RAY0] = rAy;
    d[base + HingeField.RBX0] = rBx;
    d[base + HingeField.RBY0] = rBy;
    d[base + HingeField.DCX] = cx[b] - cx[a];
    d[base + HingeField.DCY] = cy[b] - cy[a];
    // no body has turned yet since the step began: the first substep's anchors are the step's own
    d[base + HingeField.RAX] = rAx;
    d[base + HingeField.RAY] = rAy;
    d[base + HingeField.RBX] = rBx;
    d[base + HingeField.RBY] = rBy;
    storeInverseMass(rows, d, base, rAx, rAy, rBx, rBy);
  }
}

/**
 * The plain hinges of a step (revolute joints without limit, motor or spring, solved by Gauss-Seidel:
 * grids, cloth, loops the tree does not take) packed into flat arrays, like the contacts: a joint
 * object keeps each field in its own heap box and is reached through a virtual call, which made
 * such joints cost more than their arithmetic. The joints pack their step data here
 * (SolverJoint.packHinge, in place of prepare). Their impulses stay here from step to step (a hinge's
 * reaction force reads them here) and go back to the joints when the batch is made anew
 * (SolverJoint.unpackHinge): handing them over every step took a call per hinge (3 % of a hinge grid's
 * step). The arithmetic is the point rows' (solver/point-rows.ts), as the revolute joint's, but for
 * two things kept for the simulation's bits: the batch keeps K's inverse and solves with it, where
 * the joint solves K by Cramer's rule, and it bounds the pull row by row, where the joint bounds it
 * as a whole.
 * @internal
 */
export class HingeBatch {
  count = 0;
  data = new Float64Array(0);
  /** body A and body B of each hinge */
  ids = new Int32Array(0);
  /** each hinge's anchors (Anchor layout) */
  anchors = new Float64Array(0);
  joints: SolverJoint[] = [];
  /** the last batch's records and hinges while classify makes the next (two sets, swapped) */
  private spareData = new Float64Array(0);
  private spareAnchors = new Float64Array(0);
  private spareJoints: SolverJoint[] = [];
  /** the colouring that orders the hinges (see orderByColor) */
  private readonly coloring = new GraphColoring();
  /** the point rows' maths (a # field, no property key: the snapshot leaves it out) */
  readonly #rows = new PointRows();
  /** the active joints that are not in the batch, in their order */
  readonly otherActive: SolverJoint[] = [];
  /** 1/h of the last step the batch solved (the hinges' reaction forces) */
  invH = 0;
  /** the iterative joints that are not in the batch, in their order */
  readonly otherIterative: SolverJoint[] = [];
  /**
   * The world's pose epoch when the step began, and whether its last relax carried the step data
   * over to the next step (see relax): then, unless a pose changed since, the next step needs no
   * turnStepData.
   */
  private stepPoseEpoch = -1;
  private carried = false;

  /**
   * Prepares the step's joints (`active`, after the tree's build): the plain hinges are packed here,
   * the others prepare themselves. The other joints keep their order. Unless the tree chose anew
   * (`rebuilt`), the hinges are the same as last step and only their step data is refreshed, from
   * the anchors kept here, with last step's impulses.
   */
  prepare(
    active: readonly SolverJoint[],
    iterative: readonly SolverJoint[],
    ctx: JointContext,
    rebuilt: boolean,
  ): void {
    const poseEpoch = ctx.poseEpoch;
    const carry = this.carried && this.stepPoseEpoch === poseEpoch;
    if (rebuilt) this.classify(active, iterative, ctx, carry);
    else if (!carry) turnStepData(ctx, this.#rows, this.ids, this.anchors, this.data, 0, this.count);
    this.carried = false;
    this.stepPoseEpoch = poseEpoch;
    for (const joint of this.otherActive) joint.prepare(ctx);
  }

  /**
   * Makes the batch anew. With `carry` (the last step's relax carried the step data over and no pose
   * or mass was set since), a hinge that stays takes its carried record along to its new place
   * instead of step data worked out afresh: the same bits as when the batch is kept.
   */
  private classify(
    active: readonly SolverJoint[],
    iterative: readonly SolverJoint[],
    ctx: JointContext,
    carry: boolean,
  ): void {
    // the last batch's hinges take their impulses back (those that stay bring them in again)
    const previous = this.joints;
    for (let i = 0; i < this.count; i++) {
      previous[i].unpackHinge(this.data, i * HingeField.STRIDE, this.invH);
      if (carry) previous[i].carriedSlot = i;
    }
    const previousCount = this.count;
    const previousData = this.data;
    const previousAnchors = this.anchors;
    this.data = this.spareData;
    this.anchors = this.spareAnchors;
    this.spareData = previousData;
    this.spareAnchors = previousAnchors;
    const joints = this.spareJoints;
    this.spareJoints = previous;
    this.joints = joints;
    this.count = 0;
    joints.length = 0;
    this.otherIterative.length = 0;
    this.otherActive.length = 0;
    for (const joint of active) {
      if (joint.isPlainHinge()) joints.push(joint);
      else if (!joint.onPath) this.otherActive.push(joint);
    }
    for (const joint of iterative) if (!joint.isPlainHinge()) this.otherIterative.push(joint);
    this.orderByColor(ctx);
    const n = joints.length;
    if (this.data.length < n * HingeField.STRIDE) {
      const capacity = Math.max(64, 2 * n);
      this.data = growF64(this.data, capacity * HingeField.STRIDE);
      this.anchors = growF64(this.anchors, capacity * Anchor.STRIDE);
    }
    if (this.ids.length < 2 * n) this.ids = growI32(this.ids, Math.max(128, 4 * n));
    for (let i = 0; i < n; i++) {
      const joint = joints[i];
      joint.packHinge(ctx, this.data, this.ids, this.anchors, i);
      const k = joint.carriedSlot;
      if (k < 0) continue;
      // copied field by field: a subarray view per hinge is an allocation
      for (let f = 0; f < HingeField.STRIDE; f++)
        this.data[i * HingeField.STRIDE + f] = previousData[k * HingeField.STRIDE + f];
      for (let f = 0; f < Anchor.STRIDE; f++) {
        this.anchors[i * Anchor.STRIDE + f] = previousAnchors[k * Anchor.STRIDE + f];
      }
    }
    for (let i = 0; i < previousCount; i++) previous[i].carriedSlot = -1;
    this.count = n;
  }

  /**
   * Orders the hinges by graph colour, taken in creation order (see GraphColoring; no shuffle): then
   * consecutive hinges share no body, and the processor overlaps them instead of waiting for the
   * velocities the previous one stored (a grid's hinges, made two per body, each waited on the last:
   * soft pass 0.8x the time). The order follows from the creation order alone, so it is
   * deterministic; in a hinge grid it also leaves the joints a little closer (max separation 6.7 mm
   * instead of 6.8).
   */
  private orderByColor(ctx: JointContext): void {
    const joints = this.joints;
    const n = joints.length;
    const coloring = this.coloring;
    coloring.begin(ctx.invMass.length, n);
    for (let i = 0; i < n; i++) {
      const a = joints[i].slotA;
      const b = joints[i].slotB;
      const movableA = ctx.invMass[a] > 0 || ctx.invInertia[a] > 0;
      const movableB = ctx.invMass[b] > 0 || ctx.invInertia[b] > 0;
      coloring.add(i, movableA ? a : -1, movableB ? b : -1);
    }
    coloring.finish(false);
    const ordered = joints.slice();
    for (let i = 0; i < n; i++) joints[i] = ordered[coloring.order[i]];
  }

  /** Ends the step: the impulses stay here, and the step's 1/h makes them the reaction forces. */
  store(ctx: JointContext): void {
    this.invH = ctx.invH;
  }

  /**
   * Applies the kept impulses; as SolverJoint.warmStartGuarded, a hinge whose warm start would throw a body
   * past `speedLimit` or `turnLimit` leaves the velocities as they were and forgets its impulse.
   */
  warmStart(state: Float64Array, speedLimit: number, turnLimit: number): void {
    // nothing to do, and in a world without hinges these calls never get hot: the interpreter would
    // put the doubles read below on the heap at every call
    if (this.count === 0) return;
    const rows = this.#rows;
    const d = this.data;
    const ids = this.ids;
    const v2 = speedLimit * speedLimit;
    for (let i = 0, n = this.count & IndexBound.MAX; i < n; i++) {
      const base = i * HingeField.STRIDE;
      const sa = (ids[2 * i] & IndexBound.MAX) * BodyState.STRIDE;
      const sb = (ids[2 * i + 1] & IndexBound.MAX) * BodyState.STRIDE;
      const mA = d[base + HingeField.MA];
      const iA = d[base + HingeField.IA];
      const mB = d[base + HingeField.MB];
      const iB = d[base + HingeField.IB];
      const rAx = d[base + HingeField.RAX];
      const rAy = d[base + HingeField.RAY];
      const rBx = d[base + HingeField.RBX];
      const rBy = d[base + HingeField.RBY];
      const vAx = state[sa + BodyState.VX];
      const vAy = state[sa + BodyState.VY];
      const wA = state[sa + BodyState.W];
      const vBx = state[sb + BodyState.VX];
      const vBy = state[sb + BodyState.VY];
      const wB = state[sb + BodyState.W];
      const px = d[base + HingeField.LX];
      const py = d[base + HingeField.LY];
      // applyPointTurnImpulse with a zero axial impulse, as the revolute joint's warm start adds its
      // own (the same bits), worked out before it is stored: applied and then taken back when the
      // guard fails, it cost a hinge grid 1.05x the step
      const nAx = vAx - mA * px;
      const nAy = vAy - mA * py;
      const nwA = wA - iA * (rows.anchorMoment(rAx, rAy, px, py) + 0);
      const nBx = vBx + mB * px;
      const nBy = vBy + mB * py;
      const nwB = wB + iB * (rows.anchorMoment(rBx, rBy, px, py) + 0);
      // written so that NaN fails the test too
      if (
        nAx * nAx + nAy * nAy <= v2 &&
        nBx * nBx + nBy * nBy <= v2 &&
        Math.abs(nwA) <= turnLimit &&
        Math.abs(nwB) <= turnLimit
      ) {
        state[sa + BodyState.VX] = nAx;
        state[sa + BodyState.VY] = nAy;
        state[sa + BodyState.W] = nwA;
        state[sb + BodyState.VX] = nBx;
        state[sb + BodyState.VY] = nBy;
        state[sb + BodyState.W] = nwB;
      } else {
        d[base + HingeField.LX] = 0;
        d[base + HingeField.LY] = 0;
      }
    }
  }

  /**
   * One soft Gauss-Seidel pass over the hinges' point rows, with the anchors and mass the warm start
   * found (the bodies have not turned since).
   */
  solve(state: Float64Array, soft: Softness, pushLimit: number): void {
    if (this.count === 0) return; // as in warmStart
    const rows = this.#rows;
    const d = this.data;
    const ids = this.ids;
    const biasRate = soft.biasRate;
    const massScale = soft.massScale;
    const impulseScale = soft.impulseScale;
    for (let i = 0, n = this.count & IndexBound.MAX; i < n; i++) {
      const base = i * HingeField.STRIDE;
      const sa = (ids[2 * i] & IndexBound.MAX) * BodyState.STRIDE;
      const sb = (ids[2 * i + 1] & IndexBound.MAX) * BodyState.STRIDE;
      const rAx = d[base + HingeField.RAX];
      const rAy = d[base + HingeField.RAY];
      const rBx = d[base + HingeField.RBX];
      const rBy = d[base + HingeField.RBY];
      const vAx = state[sa + BodyState.VX];
      const vAy = state[sa + BodyState.VY];
      const wA = state[sa + BodyState.W];
      const vBx = state[sb + BodyState.VX];
      const vBy = state[sb + BodyState.VY];
      const wB = state[sb + BodyState.W];
      // the pull bounded, as in the other joints (see JointTree's pushLimit)
      const errorX = rows.separation(
        state[sa + BodyState.DPX],
        state[sb + BodyState.DPX],
        d[base + HingeField.DCX],
        rAx,
        rBx,
      );
      const errorY = rows.separation(
        state[sa + BodyState.DPY],
        state[sb + BodyState.DPY],
        d[base + HingeField.DCY],
        rAy,
        rBy,
      );
      const bx = rows.speedX(vAx, wA, rAy, vBx, wB, rBy) + rows.boundedBias(biasRate, errorX, pushLimit);
      const by = rows.speedY(vAy, wA, rAx, vBy, wB, rBx) + rows.boundedBias(biasRate, errorY, pushLimit);
      const lx = d[base + HingeField.LX];
      const ly = d[base + HingeField.LY];
      const m12 = d[base + HingeField.M12];
      const px = rows.softImpulse(massScale, impulseScale, d[base + HingeField.M11] * bx + m12 * by, lx);
      const py = rows.softImpulse(massScale, impulseScale, m12 * bx + d[base + HingeField.M22] * by, ly);
      d[base + HingeField.LX] = lx + px;
      d[base + HingeField.LY] = ly + py;
      const mA = d[base + HingeField.MA];
      const iA = d[base + HingeField.IA];
      const mB = d[base + HingeField.MB];
      const iB = d[base + HingeField.IB];
      rows.applyImpulse(state, sa, sb, mA, iA, mB, iB, rAx, rAy, rBx, rBy, px, py);
    }
  }

  /**
   * One rigid Gauss-Seidel pass over the hinges' point rows after the bodies moved: turns the anchors
   * with the bodies and works out K's inverse anew, and keeps both for the next substep's warm start
   * and soft pass (velocities change until then, positions do not). A loop of its own: one loop for
   * both passes, with a flag, ran the soft pass 1.1x and this one 1.27x slower (micro-benchmark).
   * The step's `last` relax also carries the step data over to the next step: the anchors it turned
   * are those at the bodies' final rotation (the step's start for the next one), and the centres'
   * offset moves by the step's translations; turnStepData would work out the same to rounding.
   */
  relax(state: Float64Array, last: boolean): void {
    if (this.count === 0) return; // as in warmStart
    // set before the loop, which must end the function (see listAwakeBodies in world/solve.ts): set
    // after it, the store deoptimized the loop's compiled code at every last relax of a step
    if (last) this.carried = true;
    const rows = this.#rows;
    const d = this.data;
    const ids = this.ids;
    for (let i = 0, n = this.count & IndexBound.MAX; i < n; i++) {
      const base = i * HingeField.STRIDE;
      const sa = (ids[2 * i] & IndexBound.MAX) * BodyState.STRIDE;
      const sb = (ids[2 * i + 1] & IndexBound.MAX) * BodyState.STRIDE;
      // each field read once into a local: TurboFan loads (and bounds-checks) a typed-array element
      // again at every read after a store to the same array
      const mA = d[base + HingeField.MA];
      const iA = d[base + HingeField.IA];
      const mB = d[base + HingeField.MB];
      const iB = d[base + HingeField.IB];
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
      if (last) {
        d[base + HingeField.RAX0] = rAx;
        d[base + HingeField.RAY0] = rAy;
        d[base + HingeField.RBX0] = rBx;
        d[base + HingeField.RBY0] = rBy;
        d[base + HingeField.DCX] += state[sb + BodyState.DPX] - state[sa + BodyState.DPX];
        d[base + HingeField.DCY] += state[sb + BodyState.DPY] - state[sa + BodyState.DPY];
      }
      // K's inverse, as storeInverseMass, but kept in locals for the impulse below (reading it back
      // from the record cost the grid 3 %)
      const k11 = rows.massDiagonal(mA + mB, iA, rAy, iB, rBy);
      const k12 = rows.massCoupling(iA, rAx, rAy, iB, rBx, rBy);
      const k22 = rows.massDiagonal(mA + mB, iA, rAx, iB, rBx);
      const det = rows.inverseDeterminant(k11, k12, k22);
      const m11 = det * k22;
      const m12 = -det * k12;
      const m22 = det * k11;
      d[base + HingeField.M11] = m11;
      d[base + HingeField.M12] = m12;
      d[base + HingeField.M22] = m22;
      const wA = state[sa + BodyState.W];
      const wB = state[sb + BodyState.W];
      const bx = rows.speedX(state[sa + BodyState.VX], wA, rAy, state[sb + BodyState.VX], wB, rBy);
      const by = rows.speedY(state[sa + BodyState.VY], wA, rAx, state[sb + BodyState.VY], wB, rBx);
      const px = -(m11 * bx + m12 * by);
      const py = -(m12 * bx + m22 * by);
      d[base + HingeField.LX] += px;
      d[base + HingeField.LY] += py;
      rows.applyImpulse(state, sa, sb, mA, iA, mB, iB, rAx, rAy, rBx, rBy, px, py);
    }
  }
}

/** Writes the inverse of the hinge's point-row effective mass K at the turned anchors to `d` at `base`. */
function storeInverseMass(
  rows: PointRows,
  d: Float64Array,
  base: number,
  rAx: number,
  rAy: number,
  rBx: number,
  rBy: number,
): void {
  const mA = d[base + HingeField.MA];
  const iA = d[base + HingeField.IA];
  const mB = d[base + HingeField.MB];
  const iB = d[base + HingeField.IB];
  const k11 = rows.massDiagonal(mA + mB, iA, rAy, iB, rBy);
  const k12 = rows.massCoupling(iA, rAx, rAy, iB, rBx, rBy);
  const k22 = rows.massDiagonal(mA + mB, iA, rAx, iB, rBx);
  const det = rows.inverseDeterminant(k11, k12, k22);
  d[base + HingeField.M11] = det * k22;
  d[base + HingeField.M12] = -det * k12;
  d[base + HingeField.M22] = det * k11;
}
