import { sortIntPairs, sortInts } from './int-sort';

/**
 * A growable list of int32 values backed by an Int32Array: the engine's scratch list.
 * Reading `data` directly is allowed in hot loops (valid entries are `data[0, length)`); the array is
 * replaced when the list grows, so re-read it after any push.
 * @internal
 */
export class IntList {
  data: Int32Array;
  length = 0;

  constructor(capacity = 16) {
    this.data = new Int32Array(Math.max(1, capacity));
  }

  get capacity(): number {
    return this.data.length;
  }

  push(value: number): void {
    if (this.length === this.data.length) this.grow(this.length + 1);
    this.data[this.length++] = value;
  }

  /** Appends two values (a pair) with one capacity check. */
  push2(a: number, b: number): void {
    if (this.length + 2 > this.data.length) this.grow(this.length + 2);
    this.data[this.length++] = a;
    this.data[this.length++] = b;
  }

  /** Removes and returns the last value; the list must not be empty. */
  pop(): number {
    return this.data[--this.length];
  }

  /** `index` must be in [0, length): not checked, for speed. */
  get(index: number): number {
    return this.data[index];
  }

  /** `index` must be in [0, length): not checked, for speed. */
  set(index: number, value: number): void {
    this.data[index] = value;
  }

  clear(): void {
    this.length = 0;
  }

  /** Ensures room for `capacity` values without further growth. */
  reserve(capacity: number): void {
    if (capacity > this.data.length) this.grow(capacity);
  }

  /** Sorts the values ascending, in place. */
  sort(): void {
    sortInts(this.data, 0, this.length);
  }

  /**
   * Treats `data[from, length)` as pairs (a, b) and sorts them by a, then b, in place.
   * `from` and `length - from` must be even.
   */
  sortPairs(from = 0): void {
    sortIntPairs(this.data, from >> 1, this.length >> 1);
  }

  private grow(minCapacity: number): void {
    let capacity = this.data.length * 2;
    while (capacity < minCapacity) capacity *= 2;
    const data = new Int32Array(capacity);
    data.set(this.data.subarray(0, this.length));
    this.data = data;
  }
}
