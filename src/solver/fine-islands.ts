import { growF64, growI32, growU8 } from '../core/grow';
import { IndexBound } from '../core/index-bound';
import { findRoot, unionRoots } from '../core/union-find';
import { BodyKind, type BodyStore } from '../store/body-store';
import { VelocityUpdate } from './body-solver';
import { ContactConstraints } from './contact-solver';
import type { SolverJoint } from './solver-joint';

/** the most times an island's substeps are multiplied to carry a heavy load */
export const MAX_FINE_FACTOR = 4;

/**
 * The islands stepped with finer substeps than the world's: those that carry a load too heavy for
 * their contacts to be as stiff as it needs at the world's substeps (see stiffenLoadedContacts and
 * the softness levels' limit in contact-solver.ts). An island is a set of awake bodies joined by
 * touching contacts or joints; one with a joint stays at the world's substeps, the joint solvers
 * stepping every joint together.
 * @internal
 */
export class FineIslands {
  /** per body slot: 1 for a body stepped with finer substeps in this step */
  fine = new Uint8Array(0);
  /** the awake bodies stepped with the world's substeps, by ascending slot */
  coarse = new Int32Array(0);
  coarseCount = 0;
  /** the bodies stepped with finer substeps, by ascending slot */
  bodies = new Int32Array(0);
  count = 0;
  /** the velocity update of `bodies` (see prepareVelocityUpdate) */
  update = new Float64Array(0);
  /** the constraints of those islands while they are stepped (see moveFineConstraints) */
  readonly constraints = new ContactConstraints();
  /** union-find parent per body slot */
  private parent = new Int32Array(0);
  /** per island root: 1 when the island has a support, 2 when it has a joint */
  private marks = new Uint8Array(0);

  /**
   * Marks the bodies of the islands that have a support of `cc` and no joint, and lists them apart
   * from the other awake bodies. Returns whether there are any.
   */
  split(
    cc: ContactConstraints,
    bodies: BodyStore,
    awake: Int32Array,
    awakeCount: number,
    joints: readonly SolverJoint[],
  ): boolean {
    if (this.fine.length < bodies.capacity) {
      this.fine = growU8(this.fine, bodies.capacity);
      this.parent = growI32(this.parent, bodies.capacity);
      this.marks = growU8(this.marks, bodies.capacity);
      this.coarse = growI32(this.coarse, bodies.capacity);
      this.bodies = growI32(this.bodies, bodies.capacity);
    }
    const parent = this.parent;
    const marks = this.marks;
    const kind = bodies.kind;
    for (let i = 0; i < awakeCount; i++) {
      const b = awake[i];
      parent[b] = b;
      marks[b] = 0;
    }
    this.joinContacts(cc, kind);
    for (const joint of joints) {
      const a = joint.slotA;
      const b = joint.slotB;
      if (kind[a] === BodyKind.DYNAMIC && kind[b] === BodyKind.DYNAMIC) unionRoots(this.parent, a, b);
    }
    for (let j = 0; j < cc.supportCount; j++) {
      const i = cc.supports[j] >> 1;
      const a = cc.ids[i * 3];
      const b = cc.ids[i * 3 + 1];
      marks[findRoot(this.parent, kind[a] === BodyKind.DYNAMIC ? a : b)] |= 1;
    }
    for (const joint of joints) {
      const a = joint.slotA;
      const b = joint.slotB;
      if (kind[a] === BodyKind.DYNAMIC) marks[findRoot(this.parent, a)] |= 2;
      if (kind[b] === BodyKind.DYNAMIC) marks[findRoot(this.parent, b)] |= 2;
    }
    return this.list(cc, kind, awake, awakeCount);
  }

  /** Joins the islands of the moving bodies of each constraint (see listAwakeBodies in solver.ts). */
  private joinContacts(cc: ContactConstraints, kind: Uint8Array): void {
    const ids = cc.ids;
    for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
      const a = ids[i * 3] & IndexBound.MAX;
      const b = ids[i * 3 + 1] & IndexBound.MAX;
      if (kind[a] === BodyKind.DYNAMIC && kind[b] === BodyKind.DYNAMIC) unionRoots(this.parent, a, b);
    }
  }

  private list(cc: ContactConstraints, kind: Uint8Array, awake: Int32Array, awakeCount: number): boolean {
    const fine = this.fine;
    const ids = cc.ids;
    // the fixed bodies of the constraints are read too (moveFineConstraints): cleared first
    for (let k = 0, n = (3 * cc.count) & IndexBound.MAX; k < n; k++) {
      if (k % 3 !== 2) fine[ids[k]] = 0;
    }
    let coarse = 0;
    let count = 0;
    for (let i = 0; i < awakeCount; i++) {
      const b = awake[i];
      const isFine = kind[b] === BodyKind.DYNAMIC && this.marks[findRoot(this.parent, b)] === 1;
      fine[b] = isFine ? 1 : 0;
      if (isFine) this.bodies[count++] = b;
      else this.coarse[coarse++] = b;
    }
    this.coarseCount = coarse;
    this.count = count;
    if (this.update.length < count * VelocityUpdate.STRIDE)
      this.update = growF64(this.update, 2 * count * VelocityUpdate.STRIDE);
    return count > 0;
  }
}
