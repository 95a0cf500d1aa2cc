import type { Body } from '../api/body';
import type { World } from '../api/world';
import { FulcrumError } from '../core/errors';
import type { Vec2 } from '../math/vec2';
import { Anchor, HingeField, writeStepData } from '../solver/hinge-batch';
import type { JointContext } from '../solver/joint-context';
import { relativeAngle } from '../solver/joint-math';
import { BodyState } from '../store/body-store';
import type { WorldCore } from '../world/world-core';
import type { JointType } from './registry';

/**
 * Base of every joint: two bodies, an anchor on each (in the body's frame, relative to its origin),
 * and the solver's per-step data. Joints are solved in the same substeps as contacts: warm start,
 * solve with position correction (soft), relax without it.
 */
export abstract class Joint {
  abstract readonly type: JointType;
  readonly world: World;
  readonly bodyA: Body;
  readonly bodyB: Body;
  readonly collideConnected: boolean;
  userData: unknown;
  /** @internal */
  destroyed = false;
  /** @internal the bodies' slots, fixed for the joint's life */
  readonly slotA: number;
  /** @internal */
  readonly slotB: number;
  /** @internal the engine state of the joint's world: a handle changes the world through it */
  protected readonly core: WorldCore;
  /** @internal anchors in the bodies' frames, relative to their origins */
  localAnchorAx: number;
  /** @internal */
  localAnchorAy: number;
  /** @internal */
  localAnchorBx: number;
  /** @internal */
  localAnchorBy: number;

  // Solver data of the current step.
  /** @internal */
  protected a = 0;
  /** @internal */
  protected b = 0;
  /** @internal */
  protected mA = 0;
  /** @internal */
  protected iA = 0;
  /** @internal */
  protected mB = 0;
  /** @internal */
  protected iB = 0;
  /** @internal anchors relative to the centres of mass, world-oriented, at the start of the step */
  protected rAx0 = 0;
  /** @internal */
  protected rAy0 = 0;
  /** @internal */
  protected rBx0 = 0;
  /** @internal */
  protected rBy0 = 0;
  /** @internal centre of B minus centre of A at the start of the step */
  protected dcx = 0;
  /** @internal */
  protected dcy = 0;
  /** @internal anchors rotated by the bodies' rotation so far in this step (see updateAnchors) */
  protected rAx = 0;
  /** @internal */
  protected rAy = 0;
  /** @internal */
  protected rBx = 0;
  /** @internal */
  protected rBy = 0;
  /** @internal separation of the anchors (B minus A) after updateAnchors */
  protected sepX = 0;
  /** @internal */
  protected sepY = 0;
  /** @internal */
  protected invH = 0;
  /** @internal set each step: the rigid rows of this joint are solved by the JointTree */
  inTree = false;
  /** @internal this hinge's record in the hinge batch while it is there (see HingeBatch), or -1 */
  batchIndex = -1;
  /** @internal this hinge's slot in the last hinge batch while the batch is made anew and takes it along */
  carriedSlot = -1;
  /** @internal set each step: a tree joint that HingePaths solves (it needs no prepare then) */
  onPath = false;
  /** @internal set each step: this hinge closes a loop of the tree; its point rows use closureMass */
  closure = false;
  /** @internal this joint's index among the tree's closures, when `closure` */
  closureIndex = -1;
  /** @internal effective mass matrix (2 × 2) of the point rows through the tree, when `closure` */
  readonly closureMass = new Float64Array(4);

  /** @internal */
  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    localAnchorA: Vec2,
    localAnchorB: Vec2,
    collideConnected: boolean,
    userData: unknown,
  ) {
    this.world = world;
    this.core = world.core;
    this.bodyA = bodyA;
    this.bodyB = bodyB;
    this.slotA = bodyA.slot;
    this.slotB = bodyB.slot;
    this.localAnchorAx = localAnchorA.x;
    this.localAnchorAy = localAnchorA.y;
    this.localAnchorBx = localAnchorB.x;
    this.localAnchorBy = localAnchorB.y;
    this.collideConnected = collideConnected;
    this.userData = userData;
  }

  /** @internal */
  check(): void {
    if (this.destroyed) throw new FulcrumError('joint has been destroyed');
  }

  get isValid(): boolean {
    return !this.destroyed;
  }

  /** @internal Validates a setter's call and wakes both bodies so the change takes effect. */
  protected changing(): void {
    this.check();
    if (this.core.locked) throw new FulcrumError('the world is locked during step()');
    this.core.jointEpoch++;
    this.core.wake(this.slotA);
    this.core.wake(this.slotB);
  }

  /** Anchor on body A, in world coordinates. */
  get anchorA(): Vec2 {
    this.check();
    return this.bodyA.getWorldPoint({ x: this.localAnchorAx, y: this.localAnchorAy });
  }

  /** Anchor on body B, in world coordinates. */
  get anchorB(): Vec2 {
    this.check();
    return this.bodyB.getWorldPoint({ x: this.localAnchorBx, y: this.localAnchorBy });
  }

  /** Force (N) the joint applied to body B over the last substep. */
  abstract getReactionForce(): Vec2;
  /** Torque (N·m) the joint applied to body B over the last substep. */
  abstract getReactionTorque(): number;

  /** @internal Reads body data and anchors for this step. */
  prepareBase(ctx: JointContext): void {
    const work = this.core.work;
    const d = work.jointRecord;
    this.writeBase(ctx, d, work.jointIds, work.jointAnchors, 0);
    this.mA = d[HingeField.MA];
    this.iA = d[HingeField.IA];
    this.mB = d[HingeField.MB];
    this.iB = d[HingeField.IB];
    this.rAx0 = d[HingeField.RAX0];
    this.rAy0 = d[HingeField.RAY0];
    this.rBx0 = d[HingeField.RBX0];
    this.rBy0 = d[HingeField.RBY0];
    this.dcx = d[HingeField.DCX];
    this.dcy = d[HingeField.DCY];
    this.rAx = this.rAx0;
    this.rAy = this.rAy0;
    this.rBx = this.rBx0;
    this.rBy = this.rBy0;
  }

  /**
   * Sets the bodies' slots and the step's 1/h, and writes the step's body data and anchors as the
   * hinge batch's record `i`: the slots to `ids`, the local anchors to `anchors`, the step data
   * (HingeField.MA .. HingeField.M22) to `d`.
   */
  private writeBase(
    ctx: JointContext,
    d: Float64Array,
    ids: Int32Array,
    anchors: Float64Array,
    i: number,
  ): void {
    const a = this.slotA;
    const b = this.slotB;
    this.a = a;
    this.b = b;
    this.invH = ctx.invH;
    ids[2 * i] = a;
    ids[2 * i + 1] = b;
    const k = i * Anchor.STRIDE;
    anchors[k + Anchor.AX] = this.localAnchorAx;
    anchors[k + Anchor.AY] = this.localAnchorAy;
    anchors[k + Anchor.BX] = this.localAnchorBx;
    anchors[k + Anchor.BY] = this.localAnchorBy;
    writeStepData(ctx, this.core.work.pointRows, ids, anchors, d, i, i + 1);
  }

  /**
   * @internal Rotates the anchors by the bodies' rotation so far in the step and measures their
   * separation: PointRows.turnedX, turnedY and separation, written out. Every joint's warm start and
   * solve inline this, and each call would cost their inlining budgets (V8 inlines up to 920 bytes
   * of bytecode into a function; a weld's solve is at 860 with this as it is): through the methods,
   * a grid of welds took 1.06x the instructions a step (1.27x with the weld's rows through them too).
   */
  protected updateAnchors(state: Float64Array): void {
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    let c = state[sa + BodyState.DQC];
    let s = state[sa + BodyState.DQS];
    this.rAx = c * this.rAx0 - s * this.rAy0;
    this.rAy = s * this.rAx0 + c * this.rAy0;
    c = state[sb + BodyState.DQC];
    s = state[sb + BodyState.DQS];
    this.rBx = c * this.rBx0 - s * this.rBy0;
    this.rBy = s * this.rBx0 + c * this.rBy0;
    this.sepX = state[sb + BodyState.DPX] - state[sa + BodyState.DPX] + this.dcx + this.rBx - this.rAx;
    this.sepY = state[sb + BodyState.DPY] - state[sa + BodyState.DPY] + this.dcy + this.rBy - this.rAy;
  }

  /**
   * @internal Per axial row (0 and 1, see axialRows): its entry among the rows the JointTree weighs
   * through the tree this step, or -1 when the row is solved with the two bodies' own masses.
   */
  axialEntry0 = -1;
  /** @internal */
  axialEntry1 = -1;

  /**
   * @internal The rows this joint solves iteratively beside its tree rows (limits, motors, springs)
   * along up to two directions, as bits: 1 for axial row 0, 2 for axial row 1.
   */
  axialRows(): number {
    return 0;
  }

  /**
   * @internal The Jacobian blocks (3 each) at A and B of axial row `row`, at the current positions:
   * by default the relative rotation of B to A.
   */
  axialJacobian(_state: Float64Array, _row: number, jA: Float64Array, jB: Float64Array): void {
    jA[0] = 0;
    jA[1] = 0;
    jA[2] = -1;
    jB[0] = 0;
    jB[1] = 0;
    jB[2] = 1;
  }

  /**
   * @internal Solves the rows of axial row `row` (its spring, motor, limits: rows that share its
   * Jacobian) once, given the row's current `speed` (J v) and effective `mass`, and returns the
   * impulse to apply along the row. The rows follow one another: each sees the speed the ones
   * before it left (speed + impulse / mass). Used by the JointTree for rows it weighs through the
   * tree (TreeAxials) and by the joint itself for the others, with its bodies' own mass.
   */
  solveAxial(_ctx: JointContext, _row: number, _speed: number, _mass: number, _useBias: boolean): number {
    return 0;
  }

  /**
   * @internal Whether, when it would close a loop of the tree, solve() can act through the tree
   * (JointTree closures); joints that cannot stay plain Gauss-Seidel then.
   */
  canCloseLoop(): boolean {
    return false;
  }

  /** @internal Whether solve() has rows to iterate while the tree solver owns the rigid ones. */
  iteratesInTree(): boolean {
    return false;
  }

  /** @internal Number of rigid rows this joint can give the direct tree solver (0 = none). */
  treeRows(): number {
    return 0;
  }

  /**
   * @internal Updates the anchors and writes the tree rows of joint `j` of the tree: the Jacobian
   * blocks of A and B (rows × 3 at 9j, stride 3) and the position errors (at 3j); with `limits`, a
   * limit the bodies reach within the substep as one more row (see fillLimitRow). Returns the number
   * of rows written.
   */
  treeFill(
    _ctx: JointContext,
    _jA: Float64Array,
    _jB: Float64Array,
    _err: Float64Array,
    _j: number,
    _limits: boolean,
  ): number {
    return 0;
  }

  /** @internal the limit the tree holds as a row this substep: 1 lower, -1 upper, 0 none */
  treeLimit = 0;

  /**
   * Chooses the limit the tree holds as row `row` of tree joint `j` this substep and writes it; returns
   * the joint's row count with it. A limit is held once the bodies reach it (`roomLower` or
   * `roomUpper`, the room left, at or below 0); a held limit lets go when its row pulled last time
   * (its impulse, `lowerImpulse` or `upperImpulse`, turned negative) while the bodies were within a
   * substep's push of it (`slop`): deeper, it holds on while stabilize pushes them back. `jac` holds
   * the row's Jacobian towards more room above the lower limit (A's block, then B's). A limit not
   * held is an iterative row (TreeAxials: it brakes the bodies as they come close).
   *
   * Held by the tree, a limited chain's limits are exact together: as iterative rows, even through
   * the tree, the 40 limits of a chain started a radian past them did not hold it at all.
   * @internal
   */
  protected fillLimitRow(
    ctx: JointContext,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    row: number,
    jac: ArrayLike<number>,
    slop: number,
    roomLower: number,
    roomUpper: number,
    lowerImpulse: number,
    upperImpulse: number,
  ): number {
    if (!ctx.tree.keepLimits) {
      const lower = roomLower <= 0 && !(this.treeLimit === 1 && lowerImpulse < 0 && roomLower > -slop);
      const upper = roomUpper <= 0 && !(this.treeLimit === -1 && upperImpulse < 0 && roomUpper > -slop);
      this.treeLimit = lower && (!upper || roomLower <= roomUpper) ? 1 : upper ? -1 : 0;
    }
    if (this.treeLimit === 0) return row;
    const sign = this.treeLimit;
    const m = 9 * j + 3 * row;
    for (let c = 0; c < 3; c++) {
      jA[m + c] = sign * jac[c];
      jB[m + c] = sign * jac[3 + c];
    }
    // the row keeps the bodies from going further; stabilize moves them back (see JointTree)
    err[3 * j + row] = sign === 1 ? roomLower : roomUpper;
    ctx.tree.markLimitRow(j, row);
    return row + 1;
  }

  /**
   * @internal Adds the tree solver's impulse on the tree rows: minus `solution[o..]` (the rows'
   * multipliers; an array and an index, as doubles passed to a call would be boxed), to `keep` (1 or
   * 0) times the impulse accumulated so far.
   */
  treeAddImpulse(_solution: Float64Array, _o: number, _keep: number): void {}

  /**
   * Writes the angular row (B keeps its angle to A) as row `row` of tree joint `j`: its error is
   * `angle0`, the angle error at the step's start, plus the bodies' turn since.
   * @internal
   */
  protected fillAngleRow(
    state: Float64Array,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    row: number,
    angle0: number,
  ): void {
    const m = 9 * j + 3 * row;
    jA[m] = 0;
    jA[m + 1] = 0;
    jA[m + 2] = -1;
    jB[m] = 0;
    jB[m + 1] = 0;
    jB[m + 2] = 1;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    err[3 * j + row] =
      angle0 +
      relativeAngle(
        state[sa + BodyState.DQC],
        state[sa + BodyState.DQS],
        state[sb + BodyState.DQC],
        state[sb + BodyState.DQS],
      );
  }

  /** @internal Writes the two point rows (anchor B minus anchor A) of tree joint `j`; anchors must be current. */
  protected fillPointRows(jA: Float64Array, jB: Float64Array, err: Float64Array, j: number): void {
    this.core.work.pointRows.writeJacobian(jA, jB, 9 * j, this.rAx, this.rAy, this.rBx, this.rBy);
    err[3 * j] = this.sepX;
    err[3 * j + 1] = this.sepY;
    // a third row of zeros, which a weld overwrites with its angular row
    this.clearTreeRows(jA, jB, err, j, 2);
  }

  /**
   * Zeros rows `first`..2 of tree joint `j`: the tree works in blocks of three rows, and a joint with
   * fewer leaves the rest empty.
   * @internal
   */
  protected clearTreeRows(
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    first: number,
  ): void {
    for (let c = 9 * j + 3 * first; c < 9 * j + 9; c++) {
      jA[c] = 0;
      jB[c] = 0;
    }
    for (let r = first; r < 3; r++) err[3 * j + r] = 0;
  }

  /**
   * @internal Whether this step the joint is a plain hinge for the HingeBatch: point rows only,
   * solved by Gauss-Seidel (not in the tree, no closure, no limit, motor or spring).
   */
  isPlainHinge(): boolean {
    return false;
  }

  /** @internal Whether the joint is a hinge with its point rows alone (no limit, motor or spring). */
  isFreeHinge(): boolean {
    return false;
  }

  /**
   * @internal Prepares the step of a plain hinge (instead of prepare) and writes its solver data to
   * the hinge batch (see HingeBatch).
   */
  packHinge(ctx: JointContext, data: Float64Array, ids: Int32Array, anchors: Float64Array, i: number): void {
    this.writeBase(ctx, data, ids, anchors, i);
  }

  /**
   * @internal Takes back the point impulse accumulated in `data` at `base` (by the hinge batch or
   * HingePaths) and the 1/h of its step.
   */
  unpackHinge(_data: Float64Array, _base: number, _invH: number): void {}

  /** @internal */
  abstract prepare(ctx: JointContext): void;
  /** @internal */
  abstract warmStart(ctx: JointContext): void;
  /** @internal Sets the accumulated impulses to zero: the next warm start starts from nothing. */
  abstract forgetImpulses(): void;

  /**
   * @internal Warm starts, unless that would throw a body past twice the speed limits: then the
   * velocities stay as they were and the impulses are forgotten. Only constraints that cannot all
   * hold and have torn apart (a network of hinges locked against itself) accumulate impulses like
   * that: they grew ×55 per step until they overflowed and turned the island to NaN.
   */
  warmStartGuarded(ctx: JointContext): void {
    const state = ctx.state;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    const vAx = state[sa + BodyState.VX];
    const vAy = state[sa + BodyState.VY];
    const wA = state[sa + BodyState.W];
    const vBx = state[sb + BodyState.VX];
    const vBy = state[sb + BodyState.VY];
    const wB = state[sb + BodyState.W];
    this.warmStart(ctx);
    const v2 = ctx.warmSpeedLimit * ctx.warmSpeedLimit;
    const w = ctx.warmTurnLimit;
    const nAx = state[sa + BodyState.VX];
    const nAy = state[sa + BodyState.VY];
    const nBx = state[sb + BodyState.VX];
    const nBy = state[sb + BodyState.VY];
    // written so that NaN fails the test too
    if (
      nAx * nAx + nAy * nAy <= v2 &&
      nBx * nBx + nBy * nBy <= v2 &&
      Math.abs(state[sa + BodyState.W]) <= w &&
      Math.abs(state[sb + BodyState.W]) <= w
    ) {
      return;
    }
    state[sa + BodyState.VX] = vAx;
    state[sa + BodyState.VY] = vAy;
    state[sa + BodyState.W] = wA;
    state[sb + BodyState.VX] = vBx;
    state[sb + BodyState.VY] = vBy;
    state[sb + BodyState.W] = wB;
    this.forgetImpulses();
  }
  /** @internal */
  abstract solve(ctx: JointContext, useBias: boolean): void;
}
