import { describe, expect, it } from 'vitest';
import { DynamicTree, type TreeRayCastVisitor } from '../../../src/broad-phase/dynamic-tree';
import { IntList } from '../../../src/broad-phase/int-list';
import { makeBounds } from '../../../src/math/aabb';

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

function randomBox(random: () => number, world: number, size: number): Box {
  const x = random() * world;
  const y = random() * world;
  return [x, y, x + random() * size, y + random() * size];
}

const overlaps = (a: Box, b: Box) => !(a[0] > b[2] || a[1] > b[3] || a[2] < b[0] || a[3] < b[1]);

function treeQuery(tree: DynamicTree, q: Box): number[] {
  const out = new IntList();
  tree.queryBox(Float64Array.from(q), 0, out);
  return Array.from(out.data.subarray(0, out.length)).sort((a, b) => a - b);
}

function bruteQuery(boxes: Map<number, Box>, q: Box): number[] {
  const ids: number[] = [];
  for (const [id, b] of boxes) if (overlaps(b, q)) ids.push(id);
  return ids.sort((a, b) => a - b);
}

/** Slab test: the entry fraction of origin + t·d into the box, t in [0, maxT], or -1 when it misses. */
function segmentEntry(b: Box, ox: number, oy: number, dx: number, dy: number, maxT: number): number {
  let lo = 0;
  let hi = maxT;
  for (const [o, d, min, max] of [
    [ox, dx, b[0], b[2]],
    [oy, dy, b[1], b[3]],
  ]) {
    if (d === 0) {
      if (o < min || o > max) return -1;
    } else {
      let t1 = (min - o) / d;
      let t2 = (max - o) / d;
      if (t1 > t2) [t1, t2] = [t2, t1];
      lo = Math.max(lo, t1);
      hi = Math.min(hi, t2);
      if (lo > hi) return -1;
    }
  }
  return lo;
}

class Collect implements TreeRayCastVisitor {
  ids: number[] = [];
  rayCastProxy(proxyId: number): number {
    this.ids.push(proxyId);
    return -1;
  }
}

class Closest implements TreeRayCastVisitor {
  best = -1;
  constructor(
    private boxes: Map<number, Box>,
    private ray: [number, number, number, number],
  ) {}
  rayCastProxy(proxyId: number, _userData: number, maxFraction: number): number {
    const [ox, oy, dx, dy] = this.ray;
    const t = segmentEntry(this.boxes.get(proxyId)!, ox, oy, dx, dy, maxFraction);
    if (t < 0) return -1;
    this.best = proxyId;
    return t;
  }
}

describe('DynamicTree', () => {
  it('stores boxes and user data, and reports height and area ratio', () => {
    const tree = new DynamicTree(2);
    expect(tree.getHeight()).toBe(-1);
    const a = tree.createProxy(0, 0, 1, 1, 10);
    const b = tree.createProxy(5, 5, 6, 7, 11);
    const c = tree.createProxy(-3, 2, -2, 3, 12);
    tree.validate();
    expect(tree.getUserData(b)).toBe(11);
    expect(tree.getBounds(b, makeBounds())).toEqual({ minX: 5, minY: 5, maxX: 6, maxY: 7 });
    expect([tree.getMinX(c), tree.getMinY(c), tree.getMaxX(c), tree.getMaxY(c)]).toEqual([-3, 2, -2, 3]);
    expect(tree.getHeight()).toBe(2);
    expect(tree.proxyCount).toBe(3);
    expect(tree.getAreaRatio()).toBeGreaterThanOrEqual(1);
    tree.destroyProxy(a);
    tree.destroyProxy(c);
    tree.validate();
    expect(tree.getHeight()).toBe(0);
    expect(() => tree.destroyProxy(a)).toThrow();
    tree.destroyProxy(b);
    tree.validate();
    expect(tree.proxyCount).toBe(0);
  });

  it('answers queries like brute force while moved leaves wait in place, and after they are settled', () => {
    // a tenth moved re-places them one by one, a half rebuilds the tree (see settleMoves)
    for (const share of [0.1, 0.5]) {
      const random = rng(share === 0.1 ? 21 : 22);
      const tree = new DynamicTree();
      const boxes = new Map<number, Box>();
      for (let i = 0; i < 1000; i++) {
        const b = randomBox(random, 60, 3);
        boxes.set(tree.createProxy(b[0], b[1], b[2], b[3], i), b);
      }
      for (let round = 0; round < 4; round++) {
        for (const [id, b] of boxes) {
          if (random() >= share) continue;
          const dx = (random() - 0.5) * 6;
          const dy = (random() - 0.5) * 6;
          const moved: Box = [b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy];
          tree.enlargeProxy(id, Float64Array.from(moved), 0);
          // a leaf moved twice before settling is re-placed once, with its last box
          if (random() < 0.2) tree.enlargeProxy(id, Float64Array.from(moved), 0);
          boxes.set(id, moved);
        }
        // unsettled: the ancestors only grew, so every box is still held by its parent
        tree.validate();
        for (let q = 0; q < 50; q++) {
          const box = randomBox(random, 60, 10);
          expect(treeQuery(tree, box)).toEqual(bruteQuery(boxes, box));
        }
        tree.settleMoves();
        tree.validate();
        for (let q = 0; q < 50; q++) {
          const box = randomBox(random, 60, 10);
          expect(treeQuery(tree, box)).toEqual(bruteQuery(boxes, box));
        }
        for (const [id, b] of boxes) {
          expect([tree.getMinX(id), tree.getMinY(id), tree.getMaxX(id), tree.getMaxY(id)]).toEqual(b);
        }
      }
      // and about as tight as a tree that inserted the final boxes afresh (sum of node perimeters)
      const fresh = new DynamicTree();
      for (const b of boxes.values()) fresh.createProxy(b[0], b[1], b[2], b[3], 0);
      expect(tree.getAreaRatio()).toBeLessThan(1.1 * fresh.getAreaRatio());
    }
  });

  it('a swinging chain is refitted, not rebuilt: queries exact, boxes tight, as good as a rebuild', () => {
    // 100 links in a row that bend into an arc and back, all moving every step: the tree keeps its
    // shape (neighbours stay neighbours) and only its boxes are refitted (see settleMoves)
    const tree = new DynamicTree();
    const boxes = new Map<number, Box>();
    const linkBox = (i: number, bend: number): Box => {
      const a = (bend * i) / 100;
      const x = 10 * Math.sin(a) * (i / 10);
      const y = -10 * (1 - Math.cos(a)) * (i / 10) - i * 0.3;
      return [x - 0.35, y - 0.15, x + 0.35, y + 0.15];
    };
    for (let i = 0; i < 100; i++) {
      const b = linkBox(i, 0);
      boxes.set(tree.createProxy(b[0], b[1], b[2], b[3], i), b);
    }
    tree.rebuild();
    const random = rng(5);
    let rebuilds = 0;
    const rebuild = tree.rebuild.bind(tree);
    tree.rebuild = () => {
      rebuilds++;
      rebuild();
    };
    for (let step = 1; step <= 60; step++) {
      for (const [id] of boxes) {
        const b = linkBox(id, 1.5 * Math.sin(step / 10));
        tree.enlargeProxy(id, Float64Array.from(b), 0);
        boxes.set(id, b);
      }
      tree.settleMoves();
      tree.validate();
      for (const [id, b] of boxes) {
        expect([tree.getMinX(id), tree.getMinY(id), tree.getMaxX(id), tree.getMaxY(id)]).toEqual(b);
      }
      for (let q = 0; q < 10; q++) {
        const x = (random() - 0.5) * 30;
        const y = -random() * 40;
        const box: Box = [x, y, x + random() * 5, y + random() * 5];
        expect(treeQuery(tree, box)).toEqual(bruteQuery(boxes, box));
      }
    }
    expect(rebuilds).toBe(0);
    // the refitted tree is as good as a fresh build of the final boxes (sum of node perimeters)
    const fresh = new DynamicTree();
    for (const b of boxes.values()) fresh.createProxy(b[0], b[1], b[2], b[3], 0);
    fresh.rebuild();
    expect(tree.getAreaRatio()).toBeLessThan(1.1 * fresh.getAreaRatio());
  });

  it('answers queries exactly like brute force through inserts, moves, removals and rebuilds', () => {
    const random = rng(7);
    const tree = new DynamicTree();
    const boxes = new Map<number, Box>();
    const checkQueries = (count: number) => {
      for (let q = 0; q < count; q++) {
        const box = randomBox(random, 100, 15);
        expect(treeQuery(tree, box)).toEqual(bruteQuery(boxes, box));
      }
    };
    for (let i = 0; i < 3000; i++) {
      const b = randomBox(random, 100, random() < 0.05 ? 30 : 3);
      const id = tree.createProxy(b[0], b[1], b[2], b[3], i);
      expect(boxes.has(id)).toBe(false);
      boxes.set(id, b);
    }
    tree.validate();
    checkQueries(200);
    for (let round = 0; round < 5; round++) {
      const ids = [...boxes.keys()];
      for (const id of ids) {
        const r = random();
        if (r < 0.3) {
          const b = boxes.get(id)!;
          const dx = (random() - 0.5) * 4;
          const dy = (random() - 0.5) * 4;
          const moved: Box = [b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy];
          tree.moveProxy(id, Float64Array.from(moved), 0);
          boxes.set(id, moved);
        } else if (r < 0.4) {
          tree.destroyProxy(id);
          boxes.delete(id);
        }
      }
      for (let i = 0; i < 200; i++) {
        const b = randomBox(random, 100, 3);
        boxes.set(tree.createProxy(b[0], b[1], b[2], b[3], -5), b);
      }
      tree.validate();
      expect(tree.proxyCount).toBe(boxes.size);
      checkQueries(100);
      if (round === 2) {
        tree.rebuild();
        tree.validate();
        checkQueries(100);
      }
    }
    for (const [id, b] of boxes) {
      expect([tree.getMinX(id), tree.getMinY(id), tree.getMaxX(id), tree.getMaxY(id)]).toEqual(b);
    }
    for (const id of [...boxes.keys()]) tree.destroyProxy(id);
    tree.validate();
    expect(tree.getHeight()).toBe(-1);
  });

  it('stays balanced under sorted inserts, and under nested boxes that each contain all others', () => {
    const n = 10000;
    const row = new DynamicTree();
    for (let i = 0; i < n; i++) row.createProxy(i, 0, i + 0.9, 1, i);
    row.validate();
    expect(row.getHeight()).toBeLessThan(3 * Math.log2(n));

    const nested = new DynamicTree();
    for (let i = 1; i <= 2000; i++) nested.createProxy(-i, -i, i, i, i);
    nested.validate();
    expect(nested.getHeight()).toBeLessThan(3 * Math.log2(2000));
  });

  it('stays valid after every single insert, move and removal', () => {
    const random = rng(5);
    const tree = new DynamicTree();
    const ids: number[] = [];
    for (let op = 0; op < 1500; op++) {
      const r = random();
      const b = randomBox(random, 30, r < 0.1 ? 20 : 2);
      if (ids.length > 0 && r < 0.3) {
        tree.destroyProxy(ids.splice(Math.floor(random() * ids.length), 1)[0]);
      } else if (ids.length > 0 && r < 0.6) {
        tree.moveProxy(ids[Math.floor(random() * ids.length)], Float64Array.from(b), 0);
      } else {
        ids.push(tree.createProxy(b[0], b[1], b[2], b[3], op));
      }
      tree.validate();
    }
  });

  it('rebuild keeps ids and gives a valid tree of no worse quality', () => {
    const random = rng(3);
    const tree = new DynamicTree();
    const boxes = new Map<number, Box>();
    const user = new Map<number, number>();
    for (let i = 0; i < 2000; i++) {
      const x = (i % 50) * 2;
      const y = Math.floor(i / 50) * 2;
      const b: Box = [x, y, x + 1, y + 1];
      const id = tree.createProxy(b[0], b[1], b[2], b[3], i);
      boxes.set(id, b);
      user.set(id, i);
    }
    const before = tree.getAreaRatio();
    tree.rebuild();
    tree.validate();
    expect(tree.getAreaRatio()).toBeLessThanOrEqual(before * 1.05);
    for (let q = 0; q < 100; q++) {
      const box = randomBox(random, 100, 10);
      expect(treeQuery(tree, box)).toEqual(bruteQuery(boxes, box));
    }
    for (const [id] of boxes)
      expect(tree.getUserData(id)).toBe(boxes.get(id)![0] / 2 + boxes.get(id)![1] * 25);
  });

  it('ray casts visit exactly the boxes the segment touches, and clipping finds the closest', () => {
    const random = rng(11);
    const tree = new DynamicTree();
    const boxes = new Map<number, Box>();
    for (let i = 0; i < 2000; i++) {
      const b = randomBox(random, 100, 4);
      boxes.set(tree.createProxy(b[0], b[1], b[2], b[3], i), b);
    }
    for (let r = 0; r < 300; r++) {
      const ox = random() * 120 - 10;
      const oy = random() * 120 - 10;
      const dx = r % 10 === 0 ? 0 : (random() - 0.5) * 80;
      const dy = (random() - 0.5) * 80;
      const maxT = r % 3 === 0 ? 1 : random();
      const collect = new Collect();
      expect(tree.rayCast(ox, oy, dx, dy, maxT, collect)).toBe(maxT);
      const expected = [...boxes]
        .filter(([, b]) => segmentEntry(b, ox, oy, dx, dy, maxT) >= 0)
        .map(([id]) => id);
      expect(collect.ids.sort((a, b) => a - b)).toEqual(expected.sort((a, b) => a - b));

      const closest = new Closest(boxes, [ox, oy, dx, dy]);
      const fraction = tree.rayCast(ox, oy, dx, dy, maxT, closest);
      let bestT = maxT;
      for (const b of boxes.values()) {
        const t = segmentEntry(b, ox, oy, dx, dy, maxT);
        if (t >= 0 && t < bestT) bestT = t;
      }
      // An origin inside a box gives an entry of 0, which stops the cast.
      expect(fraction).toBe(bestT);
      if (bestT < maxT) expect(segmentEntry(boxes.get(closest.best)!, ox, oy, dx, dy, maxT)).toBe(bestT);
    }
  });

  it('stops a ray cast when the visitor returns 0', () => {
    const tree = new DynamicTree();
    for (let i = 0; i < 10; i++) tree.createProxy(i * 2, -1, i * 2 + 1, 1, i);
    let calls = 0;
    const fraction = tree.rayCast(-1, 0, 30, 0, 1, {
      rayCastProxy: () => {
        calls++;
        return 0;
      },
    });
    expect(fraction).toBe(0);
    expect(calls).toBe(1);
  });

  it('is deterministic: the same operations give the same structure and query order', () => {
    const run = () => {
      const random = rng(99);
      const tree = new DynamicTree();
      const ids: number[] = [];
      for (let i = 0; i < 1500; i++) {
        const b = randomBox(random, 50, 2);
        ids.push(tree.createProxy(b[0], b[1], b[2], b[3], i));
        if (i % 7 === 3) tree.destroyProxy(ids.splice(Math.floor(random() * ids.length), 1)[0]);
        if (i % 5 === 1) {
          const m = randomBox(random, 50, 2);
          tree.moveProxy(ids[Math.floor(random() * ids.length)], Float64Array.from(m), 0);
        }
      }
      const out = new IntList();
      tree.queryBox(Float64Array.of(10, 10, 30, 30), 0, out);
      return [
        ids.join(),
        tree.getHeight(),
        tree.getAreaRatio(),
        Array.from(out.data.subarray(0, out.length)),
      ];
    };
    expect(run()).toEqual(run());
  });
});
