import { describe, expect, it } from 'vitest';
import { PairSet } from '../../../src/broad-phase/pair-set';
import { FulcrumError } from '../../../src/core/errors';

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = Math.imul(s ^ (s >>> 15), 1 | s);
    t ^= t + Math.imul(t ^ (t >>> 7), 61 | t);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const key = (a: number, b: number) => (a < b ? `${a},${b}` : `${b},${a}`);

describe('PairSet', () => {
  it('treats (a, b) and (b, a) as one key', () => {
    const set = new PairSet();
    set.set(3, 9, 42);
    expect(set.get(9, 3)).toBe(42);
    expect(set.has(3, 9)).toBe(true);
    set.set(9, 3, 7);
    expect(set.size).toBe(1);
    expect(set.get(3, 9)).toBe(7);
    expect(set.get(3, 8)).toBe(-1);
    expect(set.delete(9, 3)).toBe(true);
    expect(set.delete(3, 9)).toBe(false);
    expect(set.size).toBe(0);
    set.set(0, 0, 1);
    expect(set.get(0, 0)).toBe(1);
    set.set(2147483647, 2147483646, 5);
    expect(set.get(2147483646, 2147483647)).toBe(5);
  });

  it('rejects negative ids', () => {
    expect(() => new PairSet().set(-1, 2, 0)).toThrow(FulcrumError);
  });

  it('matches a Map under random inserts, updates and deletes (growth and backward shift)', () => {
    for (const [seed, range] of [
      [1, 40],
      [2, 300],
      [3, 5000],
    ]) {
      const random = rng(seed);
      const set = new PairSet(4);
      const ref = new Map<string, number>();
      let mismatches = 0;
      for (let step = 0; step < 30000; step++) {
        const a = Math.floor(random() * range);
        const b = Math.floor(random() * range);
        const op = random();
        if (op < 0.5) {
          const v = Math.floor(random() * 1e6);
          set.set(a, b, v);
          ref.set(key(a, b), v);
        } else if (op < 0.8) {
          if (set.delete(a, b) !== ref.delete(key(a, b))) mismatches++;
        } else if (set.get(a, b) !== (ref.get(key(a, b)) ?? -1)) {
          mismatches++;
        }
        if (set.size !== ref.size) mismatches++;
      }
      expect(mismatches).toBe(0);
      for (const [k, v] of ref) {
        const [a, b] = k.split(',').map(Number);
        expect(set.get(b, a)).toBe(v);
      }
      for (let a = 0; a < Math.min(range, 60); a++) {
        for (let b = 0; b < Math.min(range, 60); b++) expect(set.get(a, b)).toBe(ref.get(key(a, b)) ?? -1);
      }
      set.clear();
      expect(set.size).toBe(0);
      expect(set.get(1, 2)).toBe(-1);
    }
  });
});
