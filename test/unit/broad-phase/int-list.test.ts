import { describe, expect, it } from 'vitest';
import { IntList } from '../../../src/broad-phase/int-list';

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = Math.imul(s ^ (s >>> 15), 1 | s);
    t ^= t + Math.imul(t ^ (t >>> 7), 61 | t);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

describe('IntList', () => {
  it('pushes, grows, reads, writes, pops and clears', () => {
    const list = new IntList(2);
    for (let i = 0; i < 100; i++) list.push(i * 3);
    expect(list.length).toBe(100);
    expect(list.capacity).toBeGreaterThanOrEqual(100);
    expect(list.get(99)).toBe(297);
    list.set(5, -7);
    expect(list.get(5)).toBe(-7);
    expect(list.pop()).toBe(297);
    expect(list.length).toBe(99);
    list.push2(1, 2);
    expect(list.get(99)).toBe(1);
    expect(list.get(100)).toBe(2);
    list.clear();
    expect(list.length).toBe(0);
    list.reserve(1000);
    expect(list.capacity).toBeGreaterThanOrEqual(1000);
  });

  it('sorts like Array.prototype.sort, on random, sorted, reversed and constant inputs', () => {
    const random = rng(1);
    const inputs: number[][] = [[], [5], [2, 1]];
    for (const n of [10, 13, 100, 1000, 5000]) {
      inputs.push(Array.from({ length: n }, () => Math.floor(random() * 2 ** 32) | 0));
      inputs.push(Array.from({ length: n }, () => Math.floor(random() * 8)));
      inputs.push(Array.from({ length: n }, (_, i) => i));
      inputs.push(Array.from({ length: n }, (_, i) => n - i));
      inputs.push(Array.from({ length: n }, () => 7));
    }
    for (const input of inputs) {
      const list = new IntList();
      for (const v of input) list.push(v);
      const capacity = list.capacity;
      list.sort();
      expect(Array.from(list.data.subarray(0, list.length))).toEqual([...input].sort((a, b) => a - b));
      expect(list.capacity).toBe(capacity);
    }
  });

  it('sorts pairs lexicographically from an offset, leaving the prefix alone', () => {
    const random = rng(2);
    for (const n of [0, 1, 7, 50, 2000]) {
      const list = new IntList();
      list.push2(99, 98);
      const pairs: [number, number][] = [];
      for (let i = 0; i < n; i++) {
        const p: [number, number] = [Math.floor(random() * 20), Math.floor(random() * 20)];
        pairs.push(p);
        list.push2(p[0], p[1]);
      }
      list.sortPairs(2);
      pairs.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
      expect(list.get(0)).toBe(99);
      expect(list.get(1)).toBe(98);
      const got: [number, number][] = [];
      for (let i = 2; i < list.length; i += 2) got.push([list.get(i), list.get(i + 1)]);
      expect(got).toEqual(pairs);
    }
  });
});
