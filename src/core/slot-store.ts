import { growU8, growU32 } from './grow';

/**
 * Base of the column stores (bodies, shapes, joints): slots reused through a free list, with a
 * generation per slot so that a handle can tell its object was destroyed. Subclasses own the
 * typed-array columns and grow and reset them.
 * @internal
 */
export abstract class SlotStore {
  capacity = 0;
  /** one past the highest slot ever used */
  slotCount = 0;
  liveCount = 0;
  generation = new Uint32Array(0);
  alive = new Uint8Array(0);
  private freeSlots: number[] = [];

  allocate(): number {
    let slot: number;
    if (this.freeSlots.length > 0) {
      // last freed, first reused: the order is defined by the call history alone
      slot = this.freeSlots.pop()!;
    } else {
      if (this.slotCount === this.capacity) this.growTo(Math.max(16, this.capacity * 2));
      slot = this.slotCount++;
    }
    this.alive[slot] = 1;
    this.liveCount++;
    this.resetSlot(slot);
    return slot;
  }

  /**
   * Makes room for `count` more allocations at once, at the capacity that allocating them one by one
   * would reach: a world's first step creates all its contacts, which grew the columns ten times.
   */
  reserve(count: number): void {
    const needed = this.slotCount + count - this.freeSlots.length;
    if (needed <= this.capacity) return;
    let capacity = this.capacity;
    while (capacity < needed) capacity = Math.max(16, capacity * 2);
    this.growTo(capacity);
  }

  private growTo(capacity: number): void {
    this.generation = growU32(this.generation, capacity);
    this.alive = growU8(this.alive, capacity);
    this.growColumns(capacity);
    this.capacity = capacity;
  }

  free(slot: number): void {
    this.alive[slot] = 0;
    this.generation[slot]++;
    this.liveCount--;
    this.resetSlot(slot);
    this.freeSlots.push(slot);
  }

  protected abstract growColumns(capacity: number): void;
  protected abstract resetSlot(slot: number): void;
}
