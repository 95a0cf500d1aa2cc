import { growI32, growU32 } from '../core/grow';

const COLORS = 32;
const OVERFLOW = COLORS;

/**
 * Orders the contact constraints of a step by graph colour: each constraint takes the lowest colour
 * that neither of its movable bodies has used yet, and constraints are solved colour by colour. This
 * mixes the order in which neighbouring contacts are visited, so the creation order (row by row, left
 * to right) cannot bias a large pile one way: pyramids settle instead of creeping sideways. Bodies
 * that contacts cannot move (static, kinematic) take no colours.
 */
export class GraphColoring {
  private bodyColors = new Uint32Array(0);
  private slots = new Int32Array(0);
  private bodyA = new Int32Array(0);
  private bodyB = new Int32Array(0);
  private colorOf = new Int32Array(0);
  private readonly starts = new Int32Array(COLORS + 1);
  private count = 0;
  /** contact slots in colour order, valid after finish() */
  order = new Int32Array(0);

  begin(bodyCapacity: number, maxCount: number): void {
    if (this.bodyColors.length < bodyCapacity) this.bodyColors = growU32(this.bodyColors, bodyCapacity);
    if (this.slots.length < maxCount) {
      const capacity = Math.max(maxCount, this.slots.length * 2);
      this.slots = growI32(this.slots, capacity);
      this.bodyA = growI32(this.bodyA, capacity);
      this.bodyB = growI32(this.bodyB, capacity);
      this.colorOf = growI32(this.colorOf, capacity);
      this.order = growI32(this.order, capacity);
    }
    this.starts.fill(0);
    this.count = 0;
  }

  /** Adds a contact; a body is -1 when contacts cannot move it. */
  add(slot: number, bodyA: number, bodyB: number): void {
    const colors = this.bodyColors;
    const used = (bodyA >= 0 ? colors[bodyA] : 0) | (bodyB >= 0 ? colors[bodyB] : 0);
    const free = ~used;
    let color = OVERFLOW;
    if (free !== 0) {
      color = 31 - Math.clz32(free & -free);
      const bit = 1 << color;
      if (bodyA >= 0) colors[bodyA] |= bit;
      if (bodyB >= 0) colors[bodyB] |= bit;
    }
    const k = this.count++;
    this.slots[k] = slot;
    this.bodyA[k] = bodyA;
    this.bodyB[k] = bodyB;
    this.colorOf[k] = color;
    this.starts[color]++;
  }

  /** Sorts the contacts by colour, stable within a colour; returns how many there are. */
  finish(): number {
    const starts = this.starts;
    let start = 0;
    for (let c = 0; c <= COLORS; c++) {
      const n = starts[c];
      starts[c] = start;
      start += n;
    }
    const count = this.count;
    for (let k = 0; k < count; k++) this.order[starts[this.colorOf[k]]++] = this.slots[k];
    const colors = this.bodyColors;
    for (let k = 0; k < count; k++) {
      if (this.bodyA[k] >= 0) colors[this.bodyA[k]] = 0;
      if (this.bodyB[k] >= 0) colors[this.bodyB[k]] = 0;
    }
    return count;
  }
}
