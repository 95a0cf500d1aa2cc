import { growF64, growI32 } from '../core/grow';
import { IndexBound } from '../core/index-bound';

/** depth of a body that no chain of supports links to a body contacts cannot move */
export const UNSUPPORTED = 0x3fffffff;

/**
 * Which body rests on which. Each contact `i` of a step is a support when `lower[i]` names the body
 * under the other one (0 for body A, 1 for body B, -1 for a contact that supports nothing). A moving
 * body's depth is the fewest supports between it and a body that contacts cannot move (static,
 * kinematic: depth 0), counted upwards; its carried mass is the heaviest of its own mass and the
 * masses carried by the bodies resting on it one level up, so the heaviest body that rests on it
 * directly or through others.
 *
 * Depths are shortest distances and carried masses maxima: both are the same for any order of the
 * contacts, so the step stays deterministic whatever order the colouring's shuffle gave them.
 * @internal
 */
export class LoadPaths {
  /** per body slot, for the moving bodies of the last analysed contacts */
  depth = new Int32Array(0);
  /** per body slot: the heaviest mass among the body and the bodies resting on it */
  carried = new Float64Array(0);
  /** the largest depth of a supported body */
  maxDepth = 0;
  /** per body slot: the bodies resting on it are above[start .. start + count) */
  private count = new Int32Array(0);
  private start = new Int32Array(0);
  private above = new Int32Array(0);
  /** the supported moving bodies in breadth-first order, so by nondecreasing depth */
  private queue = new Int32Array(0);
  private queued = 0;

  /**
   * Finds the depth and carried mass of the bodies of the contacts `ids[3 i]` (A), `ids[3 i + 1]`
   * (B) for i in 0 .. n - 1, given which body of each is the lower one and the bodies' inverse masses
   * (0 for a body contacts cannot move).
   */
  analyze(ids: Int32Array, lower: Int8Array, n: number, invMass: Float64Array, bodyCapacity: number): void {
    if (this.depth.length < bodyCapacity) {
      this.depth = growI32(this.depth, bodyCapacity);
      this.carried = growF64(this.carried, bodyCapacity);
      this.count = growI32(this.count, bodyCapacity);
      this.start = growI32(this.start, bodyCapacity);
      this.queue = growI32(this.queue, bodyCapacity);
    }
    if (this.above.length < n) this.above = growI32(this.above, 2 * n);
    this.clear(ids, n);
    this.queued = this.countSupports(ids, lower, n, invMass);
    this.placeRuns(ids, n);
    this.linkSupports(ids, lower, n, invMass);
    this.measureDepths();
    this.carryMasses(invMass);
  }

  // Each loop below is a method of its own (see listAwakeBodies in solver.ts).

  private clear(ids: Int32Array, n: number): void {
    const depth = this.depth;
    const count = this.count;
    const start = this.start;
    for (let k = 0, m = (2 * n) & IndexBound.MAX; k < m; k++) {
      const x = ids[(k >> 1) * 3 + (k & 1)] & IndexBound.MAX;
      depth[x] = UNSUPPORTED;
      count[x] = 0;
      start[x] = -1;
    }
  }

  /**
   * Counts the moving bodies resting on each moving body and queues the moving bodies resting on a
   * fixed one, at depth 1. Returns the queue's length.
   */
  private countSupports(ids: Int32Array, lower: Int8Array, n: number, invMass: Float64Array): number {
    const depth = this.depth;
    const count = this.count;
    const queue = this.queue;
    let tail = 0;
    for (let i = 0, m = n & IndexBound.MAX; i < m; i++) {
      const side = lower[i];
      if (side < 0) continue;
      const l = ids[i * 3 + side] & IndexBound.MAX;
      const u = ids[i * 3 + 1 - side] & IndexBound.MAX;
      if (invMass[u] === 0) continue;
      if (invMass[l] > 0) count[l]++;
      else if (depth[u] !== 1) {
        depth[u] = 1;
        queue[tail++] = u;
      }
    }
    return tail;
  }

  /** Gives each body its run of `above`, in the order the bodies first appear. */
  private placeRuns(ids: Int32Array, n: number): void {
    const count = this.count;
    const start = this.start;
    let offset = 0;
    for (let k = 0, m = (2 * n) & IndexBound.MAX; k < m; k++) {
      const x = ids[(k >> 1) * 3 + (k & 1)] & IndexBound.MAX;
      if (start[x] !== -1) continue;
      start[x] = offset;
      offset += count[x];
      // counted again as the run is filled
      count[x] = 0;
    }
  }

  private linkSupports(ids: Int32Array, lower: Int8Array, n: number, invMass: Float64Array): void {
    const count = this.count;
    const start = this.start;
    const above = this.above;
    for (let i = 0, m = n & IndexBound.MAX; i < m; i++) {
      const side = lower[i];
      if (side < 0) continue;
      const l = ids[i * 3 + side] & IndexBound.MAX;
      const u = ids[i * 3 + 1 - side] & IndexBound.MAX;
      if (invMass[u] > 0 && invMass[l] > 0) above[start[l] + count[l]++] = u;
    }
  }

  /** Breadth-first upwards from the bodies of depth 1. */
  private measureDepths(): void {
    const depth = this.depth;
    const count = this.count;
    const start = this.start;
    const above = this.above;
    const queue = this.queue;
    let tail = this.queued;
    let maxDepth = tail > 0 ? 1 : 0;
    for (let head = 0; head < tail; head++) {
      const x = queue[head];
      const next = depth[x] + 1;
      for (let k = start[x], end = k + count[x]; k < end; k++) {
        const y = above[k];
        if (depth[y] === UNSUPPORTED) {
          depth[y] = next;
          maxDepth = next;
          queue[tail++] = y;
        }
      }
    }
    this.maxDepth = maxDepth;
    this.queued = tail;
  }

  /** From the deepest bodies down: each carries its own mass or the heaviest one resting on it carries. */
  private carryMasses(invMass: Float64Array): void {
    const depth = this.depth;
    const count = this.count;
    const start = this.start;
    const above = this.above;
    const queue = this.queue;
    const carried = this.carried;
    for (let q = this.queued - 1; q >= 0; q--) {
      const x = queue[q];
      const up = depth[x] + 1;
      let heaviest = 1 / invMass[x];
      for (let k = start[x], end = k + count[x]; k < end; k++) {
        const y = above[k];
        if (depth[y] === up && carried[y] > heaviest) heaviest = carried[y];
      }
      carried[x] = heaviest;
    }
  }
}
