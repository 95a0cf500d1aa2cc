import { findRoot, unionRoots } from '../core/union-find';
import { BodyKind, type BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';

/**
 * A split is taken only if no thread gets more than this many times an even share of the step's
 * constraints: beyond it the busiest thread holds the others longer than a split by colour would.
 */
const MAX_IMBALANCE = 1.25;

/**
 * @internal Splits a step's contact constraints between a team's threads by island: the bodies that
 * contacts join (through dynamic bodies only: static and kinematic bodies do not move under contacts)
 * stay on one thread with all their constraints, so that each thread solves its islands through a
 * whole pass with no barrier between colours. Each thread's constraints keep the colour order they
 * have on one thread, and every constraint of a body is on that body's thread, so each body sees the
 * same arithmetic in the same order as on one thread: the same bits.
 *
 * Islands go to the least loaded thread: those with at least half an even share first, then the
 * rest, each group in the order it first appears in the colour order. No island may be split, so a
 * step whose islands cannot be shared evenly (one pile) is not split.
 */
export class IslandSplit {
  /** union-find parents by body slot */
  private parent = new Int32Array(0);
  /** per island root: its constraints */
  private load = new Int32Array(0);
  /** per island root: its thread */
  private threadOf = new Int32Array(0);
  /** by body slot: the split in which it was last in a constraint */
  private stamp = new Int32Array(0);
  private splits = 0;
  /** the island roots, in the order they first appear */
  private roots = new Int32Array(0);
  private rootCount = 0;
  /** the constraints each thread takes */
  private readonly loads: Int32Array;
  /** after a split: where each thread's constraints start in the split order; the last is the count */
  readonly starts: Int32Array;

  constructor(private readonly threads: number) {
    this.loads = new Int32Array(threads);
    this.starts = new Int32Array(threads + 1);
  }

  /**
   * Writes the contact slots of `order[0..count)` to `out` grouped by thread, each group in `order`'s
   * order, and their bounds to `starts`; false (and `out` untouched) if the islands cannot be shared
   * within MAX_IMBALANCE.
   */
  split(
    order: Int32Array,
    count: number,
    contacts: ContactStore,
    bodies: BodyStore,
    out: Int32Array,
  ): boolean {
    const capacity = bodies.capacity;
    if (this.parent.length < capacity) {
      this.parent = new Int32Array(capacity);
      this.load = new Int32Array(capacity);
      this.threadOf = new Int32Array(capacity);
      this.roots = new Int32Array(capacity);
      this.stamp = new Int32Array(capacity);
    }
    const kind = bodies.kind;
    const split = ++this.splits;
    uniteBodies(
      order,
      count,
      contacts.bodyA,
      contacts.bodyB,
      kind,
      this.parent,
      this.load,
      this.stamp,
      split,
    );
    this.rootCount = countLoads(
      order,
      count,
      contacts.bodyA,
      contacts.bodyB,
      kind,
      this.parent,
      this.load,
      this.roots,
    );
    const share = count / this.threads;
    this.loads.fill(0);
    // constraints with no dynamic body (a kinematic body on a static one) move nothing: thread 0's
    this.loads[0] = count - this.rootSum();
    this.assign(share / 2, Number.POSITIVE_INFINITY);
    this.assign(0, share / 2);
    let most = 0;
    for (let t = 0; t < this.threads; t++) most = Math.max(most, this.loads[t]);
    if (most > share * MAX_IMBALANCE) return false;
    const starts = this.starts;
    starts[0] = 0;
    for (let t = 0; t < this.threads; t++) starts[t + 1] = starts[t] + this.loads[t];
    // starts[t] advances while writing: the bounds are set again afterwards
    scatterByThread(
      order,
      count,
      contacts.bodyA,
      contacts.bodyB,
      kind,
      this.parent,
      this.threadOf,
      starts,
      out,
    );
    for (let t = this.threads; t > 0; t--) starts[t] = starts[t - 1];
    starts[0] = 0;
    return true;
  }

  /**
   * After a split: writes `awake[0..count)` to `out` grouped by thread (a dynamic body in a constraint
   * on its island's thread, the others by turns), each group in `awake`'s order, and the groups'
   * bounds to `bounds[at..at + threads]`. Returns false if a kinematic body is in a constraint: the
   * threads read it, so it must be moved between their passes, not during one.
   */
  group(
    awake: Int32Array,
    count: number,
    kind: Uint8Array,
    out: Int32Array,
    bounds: Int32Array,
    at: number,
  ): boolean {
    const next = this.loads;
    next.fill(0);
    this.countGroups(awake, count, kind);
    let start = 0;
    for (let t = 0; t < this.threads; t++) {
      const n = next[t];
      bounds[at + t] = start;
      next[t] = start;
      start += n;
    }
    bounds[at + this.threads] = start;
    this.writeGroups(awake, count, kind, out);
    return !this.movesShared(awake, count, kind);
  }

  /** Whether one of the awake bodies is kinematic and in a constraint of this split. */
  private movesShared(awake: Int32Array, count: number, kind: Uint8Array): boolean {
    for (let i = 0; i < count; i++) {
      const b = awake[i];
      if (kind[b] === BodyKind.KINEMATIC && this.stamp[b] === this.splits) return true;
    }
    return false;
  }

  /** Counts each thread's bodies into `loads`. */
  private countGroups(awake: Int32Array, count: number, kind: Uint8Array): void {
    for (let i = 0; i < count; i++) this.loads[this.threadOfBody(awake, i, kind)]++;
  }

  /** Writes each body at its thread's `loads[t]++` in `out`. */
  private writeGroups(awake: Int32Array, count: number, kind: Uint8Array, out: Int32Array): void {
    for (let i = 0; i < count; i++) out[this.loads[this.threadOfBody(awake, i, kind)]++] = awake[i];
  }

  /** the thread of `awake[i]`: its island's, or for a body in no constraint, one in turn */
  private threadOfBody(awake: Int32Array, i: number, kind: Uint8Array): number {
    const b = awake[i];
    if (kind[b] === BodyKind.DYNAMIC && this.stamp[b] === this.splits)
      return this.threadOf[findRoot(this.parent, b)];
    return i % this.threads;
  }

  private rootSum(): number {
    let sum = 0;
    for (let i = 0; i < this.rootCount; i++) sum += this.load[this.roots[i]];
    return sum;
  }

  /** Gives each island of `from` to below `to` constraints, in order, to the least loaded thread. */
  private assign(from: number, to: number): void {
    const loads = this.loads;
    for (let i = 0; i < this.rootCount; i++) {
      const r = this.roots[i];
      const n = this.load[r];
      if (n < from || n >= to) continue;
      let t = 0;
      for (let u = 1; u < this.threads; u++) if (loads[u] < loads[t]) t = u;
      this.threadOf[r] = t;
      loads[t] += n;
    }
  }
}

// Each long loop below is a function of its own that ends with it (see listAwakeBodies in world/solve.ts).

/** The dynamic body of a constraint that stands for its island, or -1 if it has none. */
function dynamicOf(a: number, b: number, kind: Uint8Array): number {
  return kind[a] === BodyKind.DYNAMIC ? a : kind[b] === BodyKind.DYNAMIC ? b : -1;
}

/**
 * Unites the dynamic bodies of each constraint; a body met for the first time in this split (its
 * stamp) starts as an island of its own, with no constraints counted.
 */
function uniteBodies(
  order: Int32Array,
  count: number,
  bodyA: Int32Array,
  bodyB: Int32Array,
  kind: Uint8Array,
  parent: Int32Array,
  load: Int32Array,
  stamp: Int32Array,
  split: number,
): void {
  for (let i = 0; i < count; i++) {
    const a = bodyA[order[i]];
    const b = bodyB[order[i]];
    if (stamp[a] !== split) {
      stamp[a] = split;
      parent[a] = a;
      load[a] = 0;
    }
    if (stamp[b] !== split) {
      stamp[b] = split;
      parent[b] = b;
      load[b] = 0;
    }
    if (kind[a] === BodyKind.DYNAMIC && kind[b] === BodyKind.DYNAMIC) unionRoots(parent, a, b);
  }
}

/** Counts each island's constraints into `load` by root; lists the roots as first met. Returns how many. */
function countLoads(
  order: Int32Array,
  count: number,
  bodyA: Int32Array,
  bodyB: Int32Array,
  kind: Uint8Array,
  parent: Int32Array,
  load: Int32Array,
  roots: Int32Array,
): number {
  let rootCount = 0;
  for (let i = 0; i < count; i++) {
    const d = dynamicOf(bodyA[order[i]], bodyB[order[i]], kind);
    if (d < 0) continue;
    const r = findRoot(parent, d);
    if (load[r]++ === 0) roots[rootCount++] = r;
  }
  return rootCount;
}

function scatterByThread(
  order: Int32Array,
  count: number,
  bodyA: Int32Array,
  bodyB: Int32Array,
  kind: Uint8Array,
  parent: Int32Array,
  threadOf: Int32Array,
  next: Int32Array,
  out: Int32Array,
): void {
  for (let i = 0; i < count; i++) {
    const d = dynamicOf(bodyA[order[i]], bodyB[order[i]], kind);
    const t = d < 0 ? 0 : threadOf[parent[d]];
    out[next[t]++] = order[i];
  }
}
