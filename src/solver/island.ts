import { IntList } from '../broad-phase/int-list';
import { growF64, growI32 } from '../core/grow';
import { TIME_TO_SLEEP } from '../core/settings';
import { findRoot, unionRoots } from '../core/union-find';
import { BodyFlag, BodyKind, BodyState, type BodyStore } from '../store/body-store';

/**
 * Sleep by islands. Each step the awake dynamic bodies are grouped (union-find) through touching
 * contacts and joints; an island whose every body has been slow for TIME_TO_SLEEP falls asleep as a
 * whole. A sleeping island is a linked list of bodies so that waking any one wakes them all.
 * @internal
 */
export class Islands {
  private parent = new Int32Array(0);
  private minSleep = new Float64Array(0);
  private islandHead: number[] = [];
  private freeIslands: number[] = [];
  /** bodies put to sleep and woken since the last step's events, as (slot, generation) pairs */
  readonly slept = new IntList();
  readonly woken = new IntList();

  reset(capacity: number, awake: Int32Array, awakeCount: number): void {
    if (this.parent.length < capacity) {
      this.parent = growI32(this.parent, capacity);
      this.minSleep = growF64(this.minSleep, capacity);
    }
    for (let i = 0; i < awakeCount; i++) this.parent[awake[i]] = awake[i];
  }

  /** Joins the islands of two awake dynamic bodies; the smaller slot becomes the root (defined order). */
  union(a: number, b: number): void {
    unionRoots(this.parent, a, b);
  }

  /** Puts to sleep every island whose bodies have all been slow long enough. */
  sleepIslands(bodies: BodyStore, awake: Int32Array, awakeCount: number): void {
    const minSleep = this.minSleep;
    for (let i = 0; i < awakeCount; i++) minSleep[awake[i]] = Number.POSITIVE_INFINITY;
    for (let i = 0; i < awakeCount; i++) {
      const b = awake[i];
      const r = findRoot(this.parent, b);
      const t = (bodies.flags[b] & BodyFlag.ALLOW_SLEEP) !== 0 ? bodies.sleepTime[b] : 0;
      if (t < minSleep[r]) minSleep[r] = t;
    }
    for (let i = 0; i < awakeCount; i++) {
      const b = awake[i];
      const r = findRoot(this.parent, b);
      if (minSleep[r] < TIME_TO_SLEEP) continue;
      // the root has the smallest slot of its island, so it is reached first and names the island
      const island = r === b ? this.newIsland() : bodies.sleepIsland[r];
      this.sleepBody(bodies, b, island);
    }
  }

  /** Puts a given group of awake bodies to sleep as one island. */
  sleepGroup(bodies: BodyStore, members: readonly number[]): void {
    const island = this.newIsland();
    for (const b of members) this.sleepBody(bodies, b, island);
  }

  private newIsland(): number {
    const island = this.freeIslands.length > 0 ? this.freeIslands.pop()! : this.islandHead.length;
    this.islandHead[island] = -1;
    return island;
  }

  private sleepBody(bodies: BodyStore, b: number, island: number): void {
    bodies.flags[b] &= ~BodyFlag.AWAKE;
    bodies.awakeEpoch++;
    bodies.sleepIsland[b] = island;
    bodies.islandNext[b] = this.islandHead[island];
    this.islandHead[island] = b;
    const s = b * BodyState.STRIDE;
    bodies.state[s + BodyState.VX] = 0;
    bodies.state[s + BodyState.VY] = 0;
    bodies.state[s + BodyState.W] = 0;
    this.slept.push2(b, bodies.generation[b] | 0);
  }

  /** Wakes the body and, if it sleeps in an island, the whole island. */
  wake(bodies: BodyStore, b: number): void {
    if (bodies.kind[b] === BodyKind.STATIC) return;
    const island = bodies.sleepIsland[b];
    if (island === -1) {
      if ((bodies.flags[b] & BodyFlag.AWAKE) === 0) this.wakeBody(bodies, b);
      else bodies.sleepTime[b] = 0;
      return;
    }
    let x = this.islandHead[island];
    while (x !== -1) {
      const next = bodies.islandNext[x];
      this.wakeBody(bodies, x);
      x = next;
    }
    this.islandHead[island] = -1;
    this.freeIslands.push(island);
  }

  private wakeBody(bodies: BodyStore, b: number): void {
    bodies.flags[b] |= BodyFlag.AWAKE;
    bodies.awakeEpoch++;
    bodies.sleepTime[b] = 0;
    bodies.sleepIsland[b] = -1;
    bodies.islandNext[b] = -1;
    this.woken.push2(b, bodies.generation[b] | 0);
  }

  /** Removes a body from its sleeping island before it is destroyed or changes type. */
  remove(bodies: BodyStore, b: number): void {
    const island = bodies.sleepIsland[b];
    if (island === -1) return;
    let prev = -1;
    let x = this.islandHead[island];
    while (x !== -1 && x !== b) {
      prev = x;
      x = bodies.islandNext[x];
    }
    if (x === b) {
      if (prev === -1) this.islandHead[island] = bodies.islandNext[b];
      else bodies.islandNext[prev] = bodies.islandNext[b];
    }
    bodies.sleepIsland[b] = -1;
    bodies.islandNext[b] = -1;
    if (this.islandHead[island] === -1) this.freeIslands.push(island);
  }
}
