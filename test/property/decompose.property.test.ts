/**
 * Shape.concave on random simple outlines (star-shaped ones, and ones grown by a random walk of
 * inserted points), each checked from outside the code: pieces convex with at most 8 vertices and not
 * overlapping (separating axis test, touching allowed), inside the outline, their areas adding up to
 * the outline's, every point of the cleaned outline a corner of some piece, the cleaned outline within
 * 0.005 m of every point given, and a bounded number of pieces. Outlines made to cross or touch
 * themselves are refused with a FulcrumError that says where. 500 outlines in the unit run (200 of
 * each refusal); `npm run fuzz` runs 20 seeds of 200 each (settings.ts).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { FulcrumError, type Polygon, Shape } from '../../src/index';
import { checkProperty } from './run-property';

type V = { x: number; y: number };

const SLOP = 0.005;
/** Generated outlines keep at least this much room between a point and any other point or edge. */
const ROOM = 2.2 * SLOP;

function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function cross(o: V, a: V, b: V): number {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

function signedArea(p: readonly V[]): number {
  let a = 0;
  for (let i = 0; i < p.length; i++) {
    const q = p[(i + 1) % p.length];
    a += p[i].x * q.y - q.x * p[i].y;
  }
  return a / 2;
}

function distanceToSegment(p: V, a: V, b: V): number {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const t = Math.min(1, Math.max(0, ((p.x - a.x) * ex + (p.y - a.y) * ey) / (ex * ex + ey * ey)));
  return Math.hypot(a.x + t * ex - p.x, a.y + t * ey - p.y);
}

function segmentsCross(a: V, b: V, c: V, d: V): boolean {
  const d1 = cross(a, b, c);
  const d2 = cross(a, b, d);
  const d3 = cross(c, d, a);
  const d4 = cross(c, d, b);
  return d1 * d2 < 0 && d3 * d4 < 0;
}

/** Simple, with at least `room` between any point and any other point or edge it is not on. */
function isRoomy(p: readonly V[], room: number): boolean {
  const n = p.length;
  for (let i = 0; i < n; i++) {
    for (let e = 0; e < n; e++) {
      const e1 = (e + 1) % n;
      if (i === e || i === e1) continue;
      if (distanceToSegment(p[i], p[e], p[e1]) < room) return false;
      const i1 = (i + 1) % n;
      if (e !== i1 && e1 !== i && segmentsCross(p[i], p[i1], p[e], p[e1])) return false;
    }
  }
  return true;
}

/** isRoomy for an outline that was roomy before point k was put in: only what touches k is new. */
function roomyAround(p: readonly V[], k: number, room: number): boolean {
  const n = p.length;
  const before = (k + n - 1) % n;
  const after = (k + 1) % n;
  for (let e = 0; e < n; e++) {
    const e1 = (e + 1) % n;
    if (e !== k && e1 !== k && distanceToSegment(p[k], p[e], p[e1]) < room) return false;
    for (const [a, b] of [
      [before, k],
      [k, after],
    ]) {
      if (e !== a && e !== b && distanceToSegment(p[e], p[a], p[b]) < room) return false;
      if (e !== a && e !== b && e1 !== a && e1 !== b && segmentsCross(p[a], p[b], p[e], p[e1])) return false;
    }
  }
  return true;
}

/** A star-shaped outline: n sorted angles, each at its own radius, around a random centre and size. */
function starOutline(n: number, rnd: () => number): V[] {
  for (;;) {
    const angles = Array.from({ length: n }, () => 2 * Math.PI * rnd()).sort((a, b) => a - b);
    const scale = 0.3 + 3 * rnd();
    const cx = 10 * rnd() - 5;
    const cy = 10 * rnd() - 5;
    const p = angles.map((a) => {
      const r = scale * (0.15 + rnd());
      return { x: cx + r * Math.cos(a), y: cy + r * Math.sin(a) };
    });
    if (isRoomy(p, ROOM) && signedArea(p) > 0) return p;
  }
}

/**
 * A random walk of outlines: from a triangle, again and again a point is put on a random edge and
 * pushed in or out along its normal, kept only when the outline stays simple with room to spare.
 */
function grownOutline(n: number, rnd: () => number): V[] {
  const p: V[] = [
    { x: 0, y: 0 },
    { x: 2, y: 0 },
    { x: 1, y: 1.7 },
  ];
  while (p.length < n) {
    const i = Math.floor(rnd() * p.length);
    const a = p[i];
    const b = p[(i + 1) % p.length];
    const t = 0.2 + 0.6 * rnd();
    const push = (rnd() - 0.45) * 0.9; // out a little more often than in
    const q = {
      x: a.x + t * (b.x - a.x) + push * (b.y - a.y),
      y: a.y + t * (b.y - a.y) - push * (b.x - a.x),
    };
    p.splice(i + 1, 0, q);
    if (!roomyAround(p, i + 1, ROOM)) p.splice(i + 1, 1);
  }
  check(isRoomy(p, ROOM), 'the grown outline is simple with room to spare');
  return p;
}

function insideOutline(p: V, outline: readonly V[]): boolean {
  let inside = false;
  for (let i = 0, j = outline.length - 1; i < outline.length; j = i++) {
    const a = outline[i];
    const b = outline[j];
    if (a.y > p.y !== b.y > p.y && p.x < ((b.x - a.x) * (p.y - a.y)) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

/** Separating axis test of two convex polygons, touching allowed (within `tolerance`). */
function overlap(a: Polygon, b: Polygon, tolerance: number): boolean {
  const box = (p: Polygon) => {
    const xs = p.vertices.map((v) => v.x);
    const ys = p.vertices.map((v) => v.y);
    return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
  };
  const [ax0, ay0, ax1, ay1] = box(a);
  const [bx0, by0, bx1, by1] = box(b);
  if (ax0 >= bx1 - tolerance || bx0 >= ax1 - tolerance || ay0 >= by1 - tolerance || by0 >= ay1 - tolerance) {
    return false; // the x or the y axis separates them
  }
  for (const [p, q] of [
    [a, b],
    [b, a],
  ]) {
    for (let i = 0; i < p.count; i++) {
      const u = p.vertices[i];
      const v = p.vertices[(i + 1) % p.count];
      const nx = v.y - u.y;
      const ny = u.x - v.x;
      const len = Math.hypot(nx, ny);
      const edge = (u.x * nx + u.y * ny) / len;
      let least = Number.POSITIVE_INFINITY;
      for (const w of q.vertices) least = Math.min(least, (w.x * nx + w.y * ny) / len);
      if (least >= edge - tolerance) return false;
    }
  }
  return true;
}

const same = (a: V, b: V) => a.x === b.x && a.y === b.y;

/** Counts of the pieces found, for the bound 2r + 1 that Hertel-Mehlhorn gives without the 8-vertex cap. */
const stats = { outlines: 0, beyondTwoRPlusOne: 0, maxPieceVertices: 0 };

/** A plain check (expect() costs microseconds, and this runs millions of times). */
function check(ok: boolean, what: string): void {
  if (!ok) throw new Error(what);
}

function distanceToOutline(p: V, outline: readonly V[]): number {
  let d = Number.POSITIVE_INFINITY;
  for (let i = 0; i < outline.length; i++) {
    d = Math.min(d, distanceToSegment(p, outline[i], outline[(i + 1) % outline.length]));
  }
  return d;
}

function checkDecomposition(input: V[]): void {
  const concave = Shape.concave(input);
  const outline = concave.outline;
  const n = outline.length;
  stats.outlines++;
  // the cleaned outline: points given, in their order (either way round), counter-clockwise, and
  // within 0.005 m of every point given
  const at = outline.map((p) => input.findIndex((q) => same(p, q)));
  check(
    at.every((i) => i >= 0),
    'every point of the outline is a point given',
  );
  const forward = at.filter((i, k) => i > at[(k + n - 1) % n]).length;
  check(forward === n - 1 || forward === 1, 'the outline keeps the order of the points given');
  check(signedArea(outline) > 0, 'the outline is counter-clockwise');
  for (const p of input) {
    check(distanceToOutline(p, outline) <= SLOP + 1e-12, `(${p.x}, ${p.y}) is within 0.005 m of the outline`);
  }

  const pieces = concave.pieces;
  let extent = 0;
  for (const p of outline) extent = Math.max(extent, Math.abs(p.x), Math.abs(p.y));
  let area = 0;
  for (const [index, piece] of pieces.entries()) {
    check(piece.count >= 3 && piece.count <= 8, `piece ${index} has 3 to 8 vertices (${piece.count})`);
    stats.maxPieceVertices = Math.max(stats.maxPieceVertices, piece.count);
    for (let i = 0; i < piece.count; i++) {
      const a = piece.vertices[i];
      const b = piece.vertices[(i + 1) % piece.count];
      const c = piece.vertices[(i + 2) % piece.count];
      check(cross(a, b, c) > 0, `piece ${index} turns left at every corner`);
      const k = outline.findIndex((p) => same(p, a));
      check(k >= 0, `the corners of piece ${index} are points of the outline`);
      // an edge is an edge of the outline, or runs inside it (or along it, over a straight corner)
      if (!same(outline[(k + 1) % n], b)) {
        const middle = { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
        check(
          insideOutline(middle, outline) || distanceToOutline(middle, outline) < 1e-9 * Math.max(1, extent),
          `edge ${i} of piece ${index} is inside the outline`,
        );
      }
    }
    check(insideOutline(piece.centroid, outline), `piece ${index} is inside the outline`);
    area += signedArea(piece.vertices);
  }
  const outlineArea = signedArea(outline);
  check(
    Math.abs(area - outlineArea) <= 1e-9 * outlineArea,
    `the pieces' area ${area} is the outline's ${outlineArea}`,
  );
  for (const p of outline) {
    check(
      pieces.some((piece) => piece.vertices.some((v) => same(v, p))),
      `(${p.x}, ${p.y}) is a corner of a piece`,
    );
  }
  for (let i = 0; i < pieces.length; i++) {
    for (let j = i + 1; j < pieces.length; j++) {
      check(
        !overlap(pieces[i], pieces[j], 1e-12 * Math.max(1, extent)),
        `pieces ${i} and ${j} do not overlap`,
      );
    }
  }

  let reflex = 0;
  for (let i = 0; i < n; i++) {
    if (cross(outline[(i + n - 1) % n], outline[i], outline[(i + 1) % n]) < 0) reflex++;
  }
  // Hertel-Mehlhorn's 2r + 1 (here 4r + 1), and the cap of 8 vertices: a convex piece of k > 8 corners
  // is split in ceil((k - 2) / 6), which adds at most (n - 3) / 6 pieces over the whole outline
  const cap = Math.floor((n - 3) / 6);
  check(
    pieces.length <= 4 * reflex + 1 + cap,
    `${pieces.length} pieces for ${reflex} reflex points of ${n} (at most ${4 * reflex + 1 + cap})`,
  );
  if (pieces.length > 2 * reflex + 1 + cap) stats.beyondTwoRPlusOne++;

  // the same call, the same pieces
  check(
    JSON.stringify(Shape.concave(input)) === JSON.stringify(concave),
    'the same call gives the same pieces',
  );
}

const outlineCase = fc.record({
  grown: fc.boolean(),
  n: fc.integer({ min: 3, max: 64 }),
  seed: fc.integer(),
  clockwise: fc.boolean(),
});

function makeOutline(c: { grown: boolean; n: number; seed: number; clockwise: boolean }): V[] {
  const rnd = mulberry32(c.seed);
  const p = c.grown ? grownOutline(c.n, rnd) : starOutline(c.n, rnd);
  return c.clockwise ? p.reverse() : p;
}

function messageOf(call: () => unknown): string {
  try {
    call();
  } catch (e) {
    expect(e).toBeInstanceOf(FulcrumError);
    return (e as Error).message;
  }
  throw new Error('expected a FulcrumError');
}

describe('Shape.concave on random simple outlines', () => {
  it('splits outlines of 3 to 64 points into convex, disjoint pieces that make up the outline', async () => {
    await checkProperty('decompose', outlineCase, (c) => checkDecomposition(makeOutline(c)), 500);
    console.log(
      `decompose: ${stats.outlines} outlines, ${stats.beyondTwoRPlusOne} with more pieces than 2r + 1 + floor((n - 3) / 6), ` +
        `largest piece ${stats.maxPieceVertices} vertices`,
    );
  });

  it('refuses an outline with a section turned round (edges that cross), naming the edges and the crossing', async () => {
    const turned = fc.record({
      n: fc.integer({ min: 4, max: 40 }),
      seed: fc.integer(),
      start: fc.nat(),
      length: fc.nat(),
    });
    await checkProperty(
      'decompose: crossing',
      turned,
      ({ n, seed, start, length }) => {
        // points in convex position, well apart; a run of 2 to n - 2 of them reversed
        const rnd = mulberry32(seed);
        const p = Array.from({ length: n }, (_, i) => {
          const a = (2 * Math.PI * (i + 0.2 + 0.6 * rnd())) / n;
          return { x: 2 * Math.cos(a), y: Math.sin(a) };
        });
        const s = start % n;
        const len = 2 + (length % (n - 3));
        const run = Array.from({ length: len }, (_, k) => p[(s + k) % n]).reverse();
        for (let k = 0; k < len; k++) p[(s + k) % n] = run[k];
        const message = messageOf(() => Shape.decompose(p));
        const m =
          /edges points\[(\d+)\].* to points\[(\d+)\].* and points\[(\d+)\].* to points\[(\d+)\].* cross at \((.*), (.*)\)/.exec(
            message,
          );
        expect(m, message).not.toBeNull();
        const [i, i1, j, j1] = m!.slice(1, 5).map(Number);
        const x = { x: Number(m![5]), y: Number(m![6]) };
        expect(segmentsCross(p[i], p[i1], p[j], p[j1])).toBe(true);
        expect(distanceToSegment(x, p[i], p[i1])).toBeLessThan(1e-9);
        expect(distanceToSegment(x, p[j], p[j1])).toBeLessThan(1e-9);
      },
      200,
    );
  });

  it('refuses an outline with a point moved onto another, naming the point', async () => {
    await checkProperty(
      'decompose: repeated point',
      fc.record({ c: outlineCase, i: fc.nat(), j: fc.nat() }),
      ({ c, i, j }) => {
        const p = makeOutline({ ...c, n: Math.max(c.n, 5) });
        const n = p.length;
        const a = i % n;
        const b = (a + 2 + (j % (n - 3))) % n; // not a's neighbour
        p[b] = { x: p[a].x, y: p[a].y };
        const message = messageOf(() => Shape.concave(p));
        expect(message.includes(`points[${a}]`) || message.includes(`points[${b}]`), message).toBe(true);
        if (message.includes('same point'))
          expect(message).toMatch(new RegExp(`points\\[(${a}|${b})\\].*points\\[(${a}|${b})\\]`));
      },
      200,
    );
  });
});
