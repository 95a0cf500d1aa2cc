import { growF64, growI32 } from '../core/grow';
import { BodyState } from '../store/body-store';
import type { JointContext } from './joint-context';
import type { SolverJoint } from './solver-joint';

/** the most axial rows solved together through the tree (their coupling matrix is square in it) */
const MAX_ENTRIES = 64;
/**
 * Each entry costs a solve over the tree per factorization: the entries times the tree's nodes are
 * held to this.
 */
const WORK = 1 << 15;
/** a row's response through the tree below this share of its response alone is rounding */
const ROUNDING = 1e-9;
/** projected Gauss-Seidel sweeps over the entries, at most, per solver pass */
const MAX_SWEEPS = 16;
/** a sweep that changes no row's speed by more than this (m/s or rad/s) ends the sweeps */
const SWEEP_TOLERANCE = 1e-6;

/** @internal Reads tree node `node`'s velocity rows after JointTree.substitute (see TreeAxials.factor). */
export interface TreeSolve {
  /** the solution vector: Block.ROWS doubles per node */
  readonly solution: Float64Array;
  readonly rowsPerNode: number;
  readonly nodeCount: number;
  /** solves the tree's factored system in place on `solution` */
  substitute(): void;
  /** projects the velocities onto the tree's rows (JointTree.project) */
  project(state: Float64Array, biasRate: number, first: boolean): void;
}

/**
 * The axial rows of the tree's joints (limits, motors, springs: rows along a direction the tree
 * leaves free), solved together through the tree.
 *
 * An arm on a pin turns about the pin, not about its centre of mass: such a row's mass is its
 * response through the tree, J P M⁻¹ Jᵀ inverted (P the projection onto the tree's rows). But the
 * rows of one tree are coupled through it: a limited chain's 40 limits all move every link.
 * Solved one at a time with their own masses through the tree, the 40 limits of a chain started a
 * radian past them did not hold it at all; with their bodies' own masses, not at all either. Here
 * every entry's response to every other's impulse is the coupling matrix C_ki = J_k P M⁻¹ J_iᵀ
 * (one tree solve per entry, at each factorization), and the rows are iterated by projected
 * Gauss-Seidel on C alone, which costs entries² per sweep instead of a tree solve per row; the sum
 * of their impulses then reaches the bodies with one projection.
 * @internal
 */
export class TreeAxials {
  /** per entry: its joint and which of the joint's axial rows (0 or 1) */
  readonly joints: SolverJoint[] = [];
  private row = new Int32Array(16);
  private nodeA = new Int32Array(16);
  private nodeB = new Int32Array(16);
  private slotA = new Int32Array(16);
  private slotB = new Int32Array(16);
  /** per entry: its Jacobian blocks at A and B (3 each), at the last factorization */
  private jac = new Float64Array(16 * 6);
  /** per entry: 1 / C_ii, or 0 for a row the tree leaves no room */
  private mass = new Float64Array(16);
  /** the coupling matrix, row-major, entries × entries */
  private coupling = new Float64Array(16 * 16);
  /** per entry: its speed J v and the impulse of this pass so far */
  private speed = new Float64Array(16);
  private impulse = new Float64Array(16);
  private readonly jA = new Float64Array(3);
  private readonly jB = new Float64Array(3);

  get count(): number {
    return this.joints.length;
  }

  /**
   * Lists the axial rows of `joints` (the tree's, in creation order) as entries while MAX_ENTRIES and
   * WORK allow, given each joint's bodies' nodes; sets the joints' axialEntry0/1. The rows left out
   * are solved by their joints with their bodies' own masses.
   */
  list(joints: readonly SolverJoint[], count: number, nodeCount: number, bodyNode: Int32Array): void {
    this.joints.length = 0;
    const limit = Math.min(MAX_ENTRIES, nodeCount > 0 ? Math.floor(WORK / nodeCount) : 0);
    let n = 0;
    for (let j = 0; j < count && n < limit; j++) {
      const joint = joints[j];
      const rows = joint.axialRows();
      for (let row = 0; row < 2 && n < limit; row++) {
        if ((rows & (1 << row)) === 0) continue;
        this.ensureCapacity(n + 1);
        this.joints.push(joint);
        this.row[n] = row;
        this.slotA[n] = joint.slotA;
        this.slotB[n] = joint.slotB;
        this.nodeA[n] = bodyNode[joint.slotA];
        this.nodeB[n] = bodyNode[joint.slotB];
        if (row === 0) joint.axialEntry0 = n;
        else joint.axialEntry1 = n;
        n++;
      }
    }
  }

  private ensureCapacity(n: number): void {
    if (n <= this.row.length) return;
    const cap = Math.max(2 * this.row.length, n);
    this.row = growI32(this.row, cap);
    this.nodeA = growI32(this.nodeA, cap);
    this.nodeB = growI32(this.nodeB, cap);
    this.slotA = growI32(this.slotA, cap);
    this.slotB = growI32(this.slotB, cap);
    this.jac = growF64(this.jac, cap * 6);
    this.mass = growF64(this.mass, cap);
    this.speed = growF64(this.speed, cap);
    this.impulse = growF64(this.impulse, cap);
    this.coupling = new Float64Array(cap * cap);
  }

  /**
   * Takes each entry's Jacobian at the current positions and, through the freshly factored tree,
   * its response and so the coupling matrix and the entries' masses. A row the tree leaves (almost)
   * no room to move gets mass 0 and no impulse: its response, measured against its response on its
   * two bodies alone (J M⁻¹ Jᵀ), is rounding.
   */
  factor(ctx: JointContext, tree: TreeSolve): void {
    const n = this.joints.length;
    const state = ctx.state;
    const jac = this.jac;
    for (let i = 0; i < n; i++) {
      this.joints[i].axialJacobian(state, this.row[i], this.jA, this.jB);
      const o = 6 * i;
      for (let c = 0; c < 3; c++) {
        jac[o + c] = this.jA[c];
        jac[o + 3 + c] = this.jB[c];
      }
    }
    const x = tree.solution;
    const rows = tree.rowsPerNode;
    const coupling = this.coupling;
    for (let i = 0; i < n; i++) {
      x.fill(0, 0, rows * tree.nodeCount);
      const nodeA = this.nodeA[i];
      const nodeB = this.nodeB[i];
      const o = 6 * i;
      for (let c = 0; c < 3; c++) {
        if (nodeA !== -1) x[rows * nodeA + c] = jac[o + c];
        if (nodeB !== -1) x[rows * nodeB + c] = jac[o + 3 + c];
      }
      tree.substitute();
      // column i: every entry's speed response to a unit impulse on entry i
      for (let k = 0; k < n; k++) {
        const ok = 6 * k;
        const a = this.nodeA[k];
        const b = this.nodeB[k];
        let response = 0;
        for (let c = 0; c < 3; c++) {
          if (a !== -1) response += jac[ok + c] * x[rows * a + c];
          if (b !== -1) response += jac[ok + 3 + c] * x[rows * b + c];
        }
        coupling[k * n + i] = response;
      }
      const own =
        (nodeA === -1 ? 0 : rowInvMass(ctx, this.slotA[i], jac, o)) +
        (nodeB === -1 ? 0 : rowInvMass(ctx, this.slotB[i], jac, o + 3));
      const k = coupling[i * n + i];
      this.mass[i] = k > ROUNDING * own ? 1 / k : 0;
    }
  }

  /**
   * One pass over the entries: projected Gauss-Seidel on the coupling matrix (each joint solves its
   * rows of an entry given the entry's speed and mass: SolverJoint.solveAxial), then the impulses applied
   * to the bodies and carried over the tree by a projection (`useBias`: with the tree's bias).
   */
  solve(ctx: JointContext, tree: TreeSolve, useBias: boolean): void {
    const n = this.joints.length;
    if (n === 0) return;
    const state = ctx.state;
    const jac = this.jac;
    const speed = this.speed;
    const impulse = this.impulse;
    const coupling = this.coupling;
    for (let i = 0; i < n; i++) {
      const sa = this.slotA[i] * BodyState.STRIDE;
      const sb = this.slotB[i] * BodyState.STRIDE;
      const o = 6 * i;
      speed[i] =
        jac[o] * state[sa + BodyState.VX] +
        jac[o + 1] * state[sa + BodyState.VY] +
        jac[o + 2] * state[sa + BodyState.W] +
        jac[o + 3] * state[sb + BodyState.VX] +
        jac[o + 4] * state[sb + BodyState.VY] +
        jac[o + 5] * state[sb + BodyState.W];
      impulse[i] = 0;
    }
    for (let sweep = 0; sweep < MAX_SWEEPS; sweep++) {
      let change = 0;
      for (let i = 0; i < n; i++) {
        const mass = this.mass[i];
        if (mass === 0) continue;
        const d = this.joints[i].solveAxial(ctx, this.row[i], speed[i], mass, useBias);
        if (d === 0) continue;
        impulse[i] += d;
        for (let k = 0; k < n; k++) speed[k] += coupling[k * n + i] * d;
        change = Math.max(change, Math.abs(d) / mass);
      }
      if (change <= SWEEP_TOLERANCE) break;
    }
    let moved = false;
    for (let i = 0; i < n; i++) {
      const p = impulse[i];
      if (p === 0) continue;
      moved = true;
      const sa = this.slotA[i] * BodyState.STRIDE;
      const sb = this.slotB[i] * BodyState.STRIDE;
      const a = this.slotA[i];
      const b = this.slotB[i];
      const o = 6 * i;
      state[sa + BodyState.VX] += ctx.invMass[a] * jac[o] * p;
      state[sa + BodyState.VY] += ctx.invMass[a] * jac[o + 1] * p;
      state[sa + BodyState.W] += ctx.invInertia[a] * jac[o + 2] * p;
      state[sb + BodyState.VX] += ctx.invMass[b] * jac[o + 3] * p;
      state[sb + BodyState.VY] += ctx.invMass[b] * jac[o + 4] * p;
      state[sb + BodyState.W] += ctx.invInertia[b] * jac[o + 5] * p;
    }
    // the impulses moved their two bodies only: the tree carries them (P (v + M⁻¹ Jᵀ λ) = v + P M⁻¹ Jᵀ λ
    // for v on the tree's rows), and the tree's joints take their share of the load
    if (moved) tree.project(state, useBias ? ctx.jointSoftness.biasRate : 0, false);
  }
}

/** A row's inverse mass on one body alone, J M⁻¹ Jᵀ, for its Jacobian block at `jac[o..o+3]`. */
function rowInvMass(ctx: JointContext, slot: number, jac: Float64Array, o: number): number {
  return (
    ctx.invMass[slot] * (jac[o] * jac[o] + jac[o + 1] * jac[o + 1]) +
    ctx.invInertia[slot] * jac[o + 2] * jac[o + 2]
  );
}
