import { growI32, growU32 } from '../core/grow';

/** @internal */
export const COLORS = 32;
const OVERFLOW = COLORS;

/**
 * Orders the contact constraints of a step by graph colour: each constraint takes the lowest colour
 * that neither of its movable bodies has used yet, and constraints are solved colour by colour.
 * Bodies that contacts cannot move (static, kinematic) take no colours.
 *
 * The contacts are coloured in an order shuffled anew every step. Gauss-Seidel favours what it
 * solves first, and any fixed order repeats the same favour for every body of a regular pile: a box
 * whose left support always came before its right one was pushed the same way as all its row, and
 * a base-40 pyramid leaned 6 mm to one side within a quarter second (the creation order, colour by
 * colour), then crept 2 mm for seconds. A fixed random order still creeps 1.1-1.3 mm; an order new
 * every step lets the favours cancel: 0.3 mm. The shuffle is integer arithmetic seeded by the
 * colouring's own step count, so it is deterministic and a restored snapshot continues it.
 *
 * The hinge batch orders its hinges with a colouring of its own, unshuffled (HingeBatch.orderByColor).
 * @internal
 */
export class GraphColoring {
  private bodyColors = new Uint32Array(0);
  private slots = new Int32Array(0);
  private bodyA = new Int32Array(0);
  private bodyB = new Int32Array(0);
  private colorOf = new Int32Array(0);
  /** the order in which the contacts take their colours */
  private shuffled = new Int32Array(0);
  private readonly starts = new Int32Array(COLORS + 1);
  private count = 0;
  /** steps coloured so far: the seed of each step's shuffle */
  private round = 0;
  /** contact slots in colour order, valid after finish() */
  order = new Int32Array(0);

  /** Where colour `c`'s contacts end in `order` (after finish(); colour COLORS is the overflow's). */
  colorEnd(c: number): number {
    return this.starts[c];
  }

  begin(bodyCapacity: number, maxCount: number): void {
    if (this.bodyColors.length < bodyCapacity) this.bodyColors = growU32(this.bodyColors, bodyCapacity);
    if (this.slots.length < maxCount) {
      const capacity = Math.max(maxCount, this.slots.length * 2);
      this.slots = growI32(this.slots, capacity);
      this.bodyA = growI32(this.bodyA, capacity);
      this.bodyB = growI32(this.bodyB, capacity);
      this.colorOf = growI32(this.colorOf, capacity);
      this.shuffled = growI32(this.shuffled, capacity);
      this.order = growI32(this.order, capacity);
    }
    this.starts.fill(0);
    this.count = 0;
  }

  /** Adds a contact; a body is -1 when contacts cannot move it. */
  add(slot: number, bodyA: number, bodyB: number): void {
    const k = this.count++;
    this.slots[k] = slot;
    this.bodyA[k] = bodyA;
    this.bodyB[k] = bodyB;
  }

  /**
   * Colours the contacts in a shuffled order (in the order they were added, when `shuffled` is false)
   * and sorts them by colour, in the order they were added within a colour (no two of a colour share
   * a body that contacts move, so that order changes nothing but the memory access pattern; the
   * overflow's contacts, which may share bodies, keep that order too). Returns how many there are.
   */
  finish(shuffled = true): number {
    const count = this.count;
    if (shuffled) this.shuffle(count);
    else for (let i = 0; i < count; i++) this.shuffled[i] = i;
    this.assign(count);
    const starts = this.starts;
    let start = 0;
    for (let c = 0; c <= COLORS; c++) {
      const n = starts[c];
      starts[c] = start;
      start += n;
    }
    this.scatter(count);
    this.clearBodies(count);
    return count;
  }

  // Each long loop below is a method of its own (see listAwakeBodies in solver.ts).

  /** Gives each contact, in shuffled order, the lowest colour its bodies have not taken; counts per colour. */
  private assign(count: number): void {
    const colors = this.bodyColors;
    const starts = this.starts;
    for (let i = 0; i < count; i++) {
      const k = this.shuffled[i];
      const a = this.bodyA[k];
      const b = this.bodyB[k];
      const free = ~((a >= 0 ? colors[a] : 0) | (b >= 0 ? colors[b] : 0));
      let color = OVERFLOW;
      if (free !== 0) {
        color = 31 - Math.clz32(free & -free);
        const bit = 1 << color;
        if (a >= 0) colors[a] |= bit;
        if (b >= 0) colors[b] |= bit;
      }
      this.colorOf[k] = color;
      starts[color]++;
    }
  }

  /** Writes the slots to `order` by colour, in the order they were added within a colour. */
  private scatter(count: number): void {
    const starts = this.starts;
    for (let k = 0; k < count; k++) this.order[starts[this.colorOf[k]]++] = this.slots[k];
  }

  private clearBodies(count: number): void {
    const colors = this.bodyColors;
    for (let k = 0; k < count; k++) {
      if (this.bodyA[k] >= 0) colors[this.bodyA[k]] = 0;
      if (this.bodyB[k] >= 0) colors[this.bodyB[k]] = 0;
    }
  }

  /** `shuffled` = 0 .. count - 1 in Fisher-Yates order, driven by an integer hash of the round. */
  private shuffle(count: number): void {
    const shuffled = this.shuffled;
    for (let i = 0; i < count; i++) shuffled[i] = i;
    let state = Math.imul(++this.round, 0x9e3779b9) | 0;
    for (let i = count - 1; i > 0; i--) {
      state = (state + 0x6d2b79f5) | 0;
      let h = Math.imul(state ^ (state >>> 15), state | 1);
      h ^= h + Math.imul(h ^ (h >>> 7), h | 61);
      // j in 0 .. i: a 32-bit fraction (exact) times i + 1, floored; the product stays below i + 1
      // at any size (its shortfall, over 2^-32 (i + 1), beats half an ulp). An integer `%` cost
      // 27 ns a contact, most of the shuffle.
      const j = Math.floor((((h ^ (h >>> 14)) >>> 0) / 4294967296) * (i + 1));
      const t = shuffled[i];
      shuffled[i] = shuffled[j];
      shuffled[j] = t;
    }
  }
}
