import { describe, expect, it } from 'vitest';
import {
  BroadPhase,
  type BroadPhaseRayCastVisitor,
  type PairFilter,
  type ProxyType,
  proxyKeyId,
  proxyKeyType,
} from '../../../src/broad-phase/broad-phase';
import { IntList } from '../../../src/broad-phase/int-list';
import { PairSet } from '../../../src/broad-phase/pair-set';
import { makeBounds } from '../../../src/math/aabb';

/** One box as the columns BroadPhase.moveProxy reads (entry 0). */
function box(minX: number, minY: number, maxX: number, maxY: number) {
  const column = (v: number) => Float64Array.of(v);
  return { minX: column(minX), minY: column(minY), maxX: column(maxX), maxY: column(maxY) };
}

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = Math.imul(s ^ (s >>> 15), 1 | s);
    t ^= t + Math.imul(t ^ (t >>> 7), 61 | t);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

type Box = [number, number, number, number];

interface Proxy {
  type: ProxyType;
  shapeId: number;
  fat: Box;
}

const MARGIN = 0.1;
const overlaps = (a: Box, b: Box) => !(a[0] > b[2] || a[1] > b[3] || a[2] < b[0] || a[3] < b[1]);
/** A box grown by the margin and reaching twice the displacement (dx, dy) ahead; static: neither. */
const fatten = (b: Box, type: ProxyType, dx = 0, dy = 0): Box => {
  const m = type === 0 ? 0 : MARGIN;
  const ax = type === 0 ? 0 : 2 * dx;
  const ay = type === 0 ? 0 : 2 * dy;
  return [
    b[0] - m + Math.min(ax, 0),
    b[1] - m + Math.min(ay, 0),
    b[2] + m + Math.max(ax, 0),
    b[3] + m + Math.max(ay, 0),
  ];
};
/** Whether a fat box may stay: it holds the tight box and is nowhere more than margin + stretch larger than `next`. */
const keeps = (fat: Box, tight: Box, next: Box, type: ProxyType, dx: number, dy: number): boolean => {
  const slack = type === 0 ? 0 : MARGIN + 2 * Math.abs(dx) + 2 * Math.abs(dy);
  return (
    fat[0] <= tight[0] &&
    fat[1] <= tight[1] &&
    fat[2] >= tight[2] &&
    fat[3] >= tight[3] &&
    fat[0] >= next[0] - slack &&
    fat[1] >= next[1] - slack &&
    fat[2] <= next[2] + slack &&
    fat[3] <= next[3] + slack
  );
};

function pairsOf(list: IntList, from = 0): [number, number][] {
  const pairs: [number, number][] = [];
  for (let i = from; i < list.length; i += 2) pairs.push([list.get(i), list.get(i + 1)]);
  return pairs;
}

const allPairs: PairFilter = { shouldPair: () => true };

/** Refuses the pairs whose shape ids sum to a multiple of 7 (the engine refuses jointed bodies' pairs). */
const someRefused: PairFilter = { shouldPair: (a, b) => (a + b) % 7 !== 0 };

/**
 * Every pair of live proxies that may pair by type, involves a buffered one, overlaps, is not existing
 * and that `filter` allows.
 */
function bruteForcePairs(
  proxies: Map<number, Proxy>,
  moved: Set<number>,
  existing: PairSet,
  filter: PairFilter,
): [number, number][] {
  const entries = [...proxies];
  const pairs: [number, number][] = [];
  for (let i = 0; i < entries.length; i++) {
    for (let j = i + 1; j < entries.length; j++) {
      const [ka, a] = entries[i];
      const [kb, b] = entries[j];
      if (a.type !== 2 && b.type !== 2) continue;
      if (!moved.has(ka) && !moved.has(kb)) continue;
      if (!overlaps(a.fat, b.fat) || existing.has(a.shapeId, b.shapeId)) continue;
      if (!filter.shouldPair(a.shapeId, b.shapeId)) continue;
      pairs.push([Math.min(a.shapeId, b.shapeId), Math.max(a.shapeId, b.shapeId)]);
    }
  }
  return pairs.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
}

/** A random scene of boxes moving, appearing and disappearing; checks every step against brute force. */
function runScene(seed: number, steps: number, check: boolean): number[] {
  const random = rng(seed);
  const bp = new BroadPhase(MARGIN);
  const proxies = new Map<number, Proxy>();
  const tight = new Map<number, Box>();
  const moved = new Set<number>();
  const existing = new PairSet();
  const out = new IntList();
  const trace: number[] = [];
  let nextShape = 0;
  const create = () => {
    const x = random() * 40;
    const y = random() * 40;
    const b: Box = [x, y, x + 0.2 + random() * 1.5, y + 0.2 + random() * 1.5];
    const r = random();
    const type: ProxyType = r < 0.2 ? 0 : r < 0.3 ? 1 : 2;
    const force = random() < 0.5;
    const shapeId = nextShape++;
    const key = bp.createProxy(b[0], b[1], b[2], b[3], type, shapeId, force);
    expect(proxies.has(key)).toBe(false);
    proxies.set(key, { type, shapeId, fat: fatten(b, type) });
    tight.set(key, b);
    if (type !== 0 || force) moved.add(key);
  };
  for (let i = 0; i < 400; i++) create();
  for (let step = 0; step < steps; step++) {
    for (const [key, p] of [...proxies]) {
      const r = random();
      if (r < 0.02) {
        bp.destroyProxy(key);
        proxies.delete(key);
        tight.delete(key);
        moved.delete(key);
      } else if (r < 0.04) {
        bp.bufferMove(key);
        moved.add(key);
      } else if ((p.type !== 0 && r < 0.5) || r < 0.06) {
        const b = tight.get(key)!;
        const dx = (random() - 0.5) * 0.3;
        const dy = (random() - 0.5) * 0.3;
        const nb: Box = [b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy];
        tight.set(key, nb);
        // the expected displacement: none, or about this move's again
        const ahead = random() < 0.3 ? 0 : 1 + (random() - 0.5) * 0.4;
        const motion = Float64Array.of(ahead * dx, ahead * dy);
        const next = fatten(nb, p.type, motion[0], motion[1]);
        const kept = keeps(p.fat, nb, next, p.type, motion[0], motion[1]);
        expect(bp.moveProxy(key, box(nb[0], nb[1], nb[2], nb[3]), 0, motion)).toBe(!kept);
        if (!kept) {
          p.fat = next;
          moved.add(key);
        }
      }
    }
    for (let i = 0; i < 8; i++) create();
    const expected = check ? bruteForcePairs(proxies, moved, existing, someRefused) : [];
    out.clear();
    out.push2(-7, -8); // updatePairs appends and sorts only what it appends
    bp.updatePairs(existing, someRefused, out);
    expect(out.get(0)).toBe(-7);
    const found = pairsOf(out, 2);
    if (check) expect(found).toEqual(expected);
    moved.clear();
    for (let i = 0; i < out.length; i++) trace.push(out.get(i));
    // Act like the engine, keep new pairs as contacts and drop those whose fat boxes separated, but
    // keep only most of them, so that some pairs are reported again when their proxies next move.
    for (const [a, b] of found) if (random() < 0.7) existing.set(a, b, a);
    const byShape = new Map<number, Proxy>();
    for (const p of proxies.values()) byShape.set(p.shapeId, p);
    for (let s = 0; s < nextShape; s += 1 + Math.floor(random() * 3)) {
      for (let t = s + 1; t < nextShape && t < s + 60; t++) {
        if (!existing.has(s, t)) continue;
        const pa = byShape.get(s);
        const pb = byShape.get(t);
        if (!pa || !pb || !overlaps(pa.fat, pb.fat)) existing.delete(s, t);
      }
    }
    expect(bp.proxyCount).toBe(proxies.size);
    for (const type of [0, 1, 2] as const) bp.getTree(type).validate();
  }
  const bounds = makeBounds();
  for (const [key, p] of proxies) {
    const b = bp.getFatBounds(key, bounds);
    expect([b.minX, b.minY, b.maxX, b.maxY]).toEqual(p.fat);
    expect(bp.getShapeId(key)).toBe(p.shapeId);
    expect(proxyKeyType(key)).toBe(p.type);
  }
  return trace;
}

describe('BroadPhase', () => {
  it('encodes the tree and id in the key and fattens non-static boxes', () => {
    const bp = new BroadPhase(0.5);
    const s = bp.createProxy(0, 0, 1, 1, 0, 10, false);
    const k = bp.createProxy(0, 0, 1, 1, 1, 11, false);
    const d = bp.createProxy(0, 0, 1, 1, 2, 12, false);
    expect([proxyKeyType(s), proxyKeyType(k), proxyKeyType(d)]).toEqual([0, 1, 2]);
    expect(proxyKeyId(d)).toBe(d >> 2);
    expect(bp.getFatBounds(s, makeBounds())).toEqual({ minX: 0, minY: 0, maxX: 1, maxY: 1 });
    expect(bp.getFatBounds(d, makeBounds())).toEqual({ minX: -0.5, minY: -0.5, maxX: 1.5, maxY: 1.5 });
    expect(bp.moveCount).toBe(2);
    expect(bp.placeProxy(d, box(0.3, 0.3, 1.3, 1.3), 0)).toBe(false);
    expect(bp.placeProxy(d, box(0.6, 0, 1.6, 1), 0)).toBe(true);
    expect(bp.moveCount).toBe(2);
    const out = new IntList();
    bp.updatePairs(new PairSet(), allPairs, out);
    expect(pairsOf(out)).toEqual([
      [10, 12],
      [11, 12],
    ]);
    expect(bp.moveCount).toBe(0);
    out.clear();
    bp.updatePairs(new PairSet(), allPairs, out);
    expect(out.length).toBe(0);
  });

  it('reaches twice the displacement ahead of a moving box, and shrinks back when it stops', () => {
    const bp = new BroadPhase(0.1);
    const key = bp.createProxy(0, 0, 1, 1, 2, 1, false);
    const bounds = makeBounds();
    const motion = Float64Array.of(0.15, 0);
    // a box moving 0.15 a step to the right: leaves the unstretched fat box (margin 0.1) at once,
    // then gets one reaching 0.1 + 0.3 ahead, and leaves that only every third step
    const moves: boolean[] = [];
    for (let step = 1; step <= 7; step++) {
      const x = 0.15 * step;
      moves.push(bp.moveProxy(key, box(x, 0, x + 1, 1), 0, motion));
      if (step === 1) {
        const b = bp.getFatBounds(key, bounds);
        expect(b.minX).toBeCloseTo(0.15 - 0.1, 12);
        expect(b.maxX).toBeCloseTo(1.15 + 0.1 + 0.3, 12);
        expect([b.minY, b.maxY]).toEqual([-0.1, 1.1]);
      }
    }
    expect(moves).toEqual([true, false, false, true, false, false, true]);
    // at rest where it is: the box stretched ahead is more than the margin larger than needed, and
    // shrinks to the tight box grown by the margin
    expect(bp.placeProxy(key, box(1.05, 0, 2.05, 1), 0)).toBe(true);
    const b = bp.getFatBounds(key, bounds);
    expect(b.minX).toBeCloseTo(0.95, 12);
    expect(b.maxX).toBeCloseTo(2.15, 12);
    expect(bp.placeProxy(key, box(1.05, 0, 2.05, 1), 0)).toBe(false);
  });

  it('forgets a buffered proxy that is destroyed', () => {
    const bp = new BroadPhase(0.1);
    const a = bp.createProxy(0, 0, 1, 1, 2, 1, false);
    const b = bp.createProxy(0, 0, 1, 1, 2, 2, false);
    bp.createProxy(0, 0, 1, 1, 0, 3, false);
    bp.destroyProxy(b);
    const out = new IntList();
    bp.updatePairs(new PairSet(), allPairs, out);
    expect(pairsOf(out)).toEqual([[1, 3]]);
    bp.destroyProxy(a);
    expect(bp.proxyCount).toBe(1);
  });

  it('reports exactly the brute-force pairs of moving, appearing and vanishing boxes, sorted', () => {
    runScene(1, 25, true);
    runScene(2, 10, true);
  });

  it('is deterministic: the same operations give identical outputs', () => {
    expect(runScene(5, 15, false)).toEqual(runScene(5, 15, false));
  });

  it('stops searching at its budget of overlaps and searches the rest, in order, at the next updates', () => {
    // 300 dynamic boxes on one spot: each search finds all 300 boxes, 90,000 in all, over the
    // budget of max(65,536, 256 per proxy = 76,800)
    const bp = new BroadPhase(0.1);
    for (let i = 0; i < 300; i++) bp.createProxy(0, 0, 1, 1, 2, i, false);
    expect(bp.searchBudget).toBe(256 * 300);
    const existing = new PairSet();
    const out = new IntList();
    const found = new Set<number>();
    const deferred: number[] = [];
    for (let update = 0; update < 3; update++) {
      out.clear();
      bp.updatePairs(existing, allPairs, out);
      expect(bp.examinedCount).toBeLessThan(bp.searchBudget + 300);
      deferred.push(bp.deferredCount);
      for (const [a, b] of pairsOf(out)) {
        const pair = a * 300 + b;
        expect(found.has(pair)).toBe(false);
        found.add(pair);
        existing.set(a, b, 0);
      }
    }
    // the first update searched the first 256 proxies (each reporting its pairs with the ones before
    // it), and the second the other 44: every pair once, none after
    expect(deferred).toEqual([44, 0, 0]);
    expect(found.size).toBe((300 * 299) / 2);
    expect(bp.moveCount).toBe(0);
  });

  it('queries selected trees and casts rays through all of them', () => {
    const bp = new BroadPhase(0.1);
    const keys: number[] = [];
    for (let i = 0; i < 9; i++)
      keys.push(bp.createProxy(i * 3, 0, i * 3 + 1, 1, (i % 3) as ProxyType, 100 + i, false));
    const out = new IntList();
    bp.query(-1, -1, 100, 2, 0b101, out);
    expect(Array.from(out.data.subarray(0, out.length)).sort()).toEqual([100, 102, 103, 105, 106, 108]);
    out.clear();
    bp.query(2.95, 0, 3.5, 1, 0b111, out);
    expect(Array.from(out.data.subarray(0, out.length))).toEqual([101]);

    const seen: [number, number][] = [];
    const visitor: BroadPhaseRayCastVisitor = {
      rayCastProxy(key, shapeId, maxFraction) {
        seen.push([key, shapeId]);
        return shapeId === 104 ? 0.5 : maxFraction;
      },
    };
    expect(bp.rayCast(-5, 0.5, 40, 0, 1, visitor)).toBe(0.5);
    for (const [key, shapeId] of seen) expect(keys.indexOf(key)).toBe(shapeId - 100);
    expect(seen.map(([, s]) => s)).toContain(104);
    bp.rebuild();
    bp.getTree(0).validate();
  });
});
