import { FulcrumError } from '../core/errors';

/** An enum, not a const, for the reason in store/body-store.ts. */
enum Slot {
  EMPTY = -1,
}

/**
 * Hash map from an unordered pair of non-negative int32 ids to an int32 value (a contact index).
 * Open addressing with linear probing in typed arrays; deletion shifts later entries back instead of
 * leaving tombstones, so lookups never slow down with churn. The load factor stays at most 1/2.
 * Layout depends only on the sequence of operations, never on addresses or time.
 * @internal
 */
export class PairSet {
  private keysLo: Int32Array;
  private keysHi: Int32Array;
  private values: Int32Array;
  private mask: number;
  private count = 0;

  constructor(expectedSize = 16) {
    let capacity = 16;
    while (capacity < expectedSize * 2) capacity *= 2;
    this.keysLo = new Int32Array(capacity).fill(Slot.EMPTY);
    this.keysHi = new Int32Array(capacity);
    this.values = new Int32Array(capacity);
    this.mask = capacity - 1;
  }

  get size(): number {
    return this.count;
  }

  /** The value stored for {a, b}, or -1 if absent. */
  get(a: number, b: number): number {
    const lo = Math.min(a, b);
    const hi = Math.max(a, b);
    const keysLo = this.keysLo;
    const mask = this.mask;
    let i = hashPair(lo, hi) & mask;
    for (;;) {
      const k = keysLo[i];
      if (k === Slot.EMPTY) return -1;
      if (k === lo && this.keysHi[i] === hi) return this.values[i];
      i = (i + 1) & mask;
    }
  }

  has(a: number, b: number): boolean {
    return this.get(a, b) !== -1;
  }

  /** Inserts or replaces the value for {a, b}. Ids must be non-negative int32; -1 as a value reads as absent. */
  set(a: number, b: number, value: number): void {
    if ((a | b) < 0) throw new FulcrumError(`PairSet ids must be non-negative, got (${a}, ${b})`);
    if ((this.count + 1) * 2 > this.keysLo.length) this.rehash(this.keysLo.length * 2);
    const lo = Math.min(a, b);
    const hi = Math.max(a, b);
    const keysLo = this.keysLo;
    const mask = this.mask;
    let i = hashPair(lo, hi) & mask;
    for (;;) {
      const k = keysLo[i];
      if (k === Slot.EMPTY) {
        keysLo[i] = lo;
        this.keysHi[i] = hi;
        this.values[i] = value;
        this.count++;
        return;
      }
      if (k === lo && this.keysHi[i] === hi) {
        this.values[i] = value;
        return;
      }
      i = (i + 1) & mask;
    }
  }

  /** Removes {a, b}; returns whether it was present. */
  delete(a: number, b: number): boolean {
    const lo = Math.min(a, b);
    const hi = Math.max(a, b);
    const keysLo = this.keysLo;
    const keysHi = this.keysHi;
    const values = this.values;
    const mask = this.mask;
    let i = hashPair(lo, hi) & mask;
    for (;;) {
      const k = keysLo[i];
      if (k === Slot.EMPTY) return false;
      if (k === lo && keysHi[i] === hi) break;
      i = (i + 1) & mask;
    }
    // Backward shift: pull each later entry of the probe run into the hole unless its home slot lies
    // cyclically after the hole (moving it would put it before its home and make it unreachable).
    let j = i;
    for (;;) {
      j = (j + 1) & mask;
      const kl = keysLo[j];
      if (kl === Slot.EMPTY) break;
      const home = hashPair(kl, keysHi[j]) & mask;
      if (((j - home) & mask) >= ((j - i) & mask)) {
        keysLo[i] = kl;
        keysHi[i] = keysHi[j];
        values[i] = values[j];
        i = j;
      }
    }
    keysLo[i] = Slot.EMPTY;
    this.count--;
    return true;
  }

  clear(): void {
    if (this.count === 0) return;
    this.keysLo.fill(Slot.EMPTY);
    this.count = 0;
  }

  private rehash(capacity: number): void {
    const oldLo = this.keysLo;
    const oldHi = this.keysHi;
    const oldValues = this.values;
    const keysLo = new Int32Array(capacity).fill(Slot.EMPTY);
    const keysHi = new Int32Array(capacity);
    const values = new Int32Array(capacity);
    const mask = capacity - 1;
    for (let s = 0; s < oldLo.length; s++) {
      const lo = oldLo[s];
      if (lo === Slot.EMPTY) continue;
      const hi = oldHi[s];
      let i = hashPair(lo, hi) & mask;
      while (keysLo[i] !== Slot.EMPTY) i = (i + 1) & mask;
      keysLo[i] = lo;
      keysHi[i] = hi;
      values[i] = oldValues[s];
    }
    this.keysLo = keysLo;
    this.keysHi = keysHi;
    this.values = values;
    this.mask = mask;
  }
}

/** Mixes two ints into 32 well-spread bits (multiply-xorshift finaliser); only imul, xor and shifts. */
function hashPair(lo: number, hi: number): number {
  let h = Math.imul(lo, 0x9e3779b1) ^ hi;
  h = Math.imul(h ^ (h >>> 16), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return h ^ (h >>> 16);
}
