import { describe, expect, it } from 'vitest';
import { FulcrumError } from '../../../src/core/errors';
import { Shape } from '../../../src/geometry/shapes';
import type { Polygon } from '../../../src/geometry/types';

type V = { x: number; y: number };

/** Shoelace area, signed: > 0 counter-clockwise. */
function signedArea(p: readonly V[]): number {
  let a = 0;
  for (let i = 0; i < p.length; i++) {
    const q = p[(i + 1) % p.length];
    a += p[i].x * q.y - q.x * p[i].y;
  }
  return a / 2;
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

/**
 * Every corner turns left, and none is flat: farther than 0.005 m from the line of its neighbours or
 * turning by a right angle or more (the rule Shape.polygon keeps a hull's corners by).
 */
function expectConvex(piece: Polygon): void {
  const v = piece.vertices;
  expect(piece.count).toBeGreaterThanOrEqual(3);
  expect(piece.count).toBeLessThanOrEqual(8);
  for (let i = 0; i < piece.count; i++) {
    const a = v[i];
    const b = v[(i + 1) % piece.count];
    const c = v[(i + 2) % piece.count];
    const cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
    const dot = (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y);
    expect(cross).toBeGreaterThan(0);
    if (dot > 0) expect(cross / Math.hypot(c.x - a.x, c.y - a.y)).toBeGreaterThan(0.005);
  }
}

const L = [
  { x: 0, y: 0 },
  { x: 2, y: 0 },
  { x: 2, y: 0.5 },
  { x: 0.5, y: 0.5 },
  { x: 0.5, y: 2 },
  { x: 0, y: 2 },
];

function ring(n: number, radius: number): V[] {
  return Array.from({ length: n }, (_, i) => ({
    x: radius * Math.cos((2 * Math.PI * i) / n),
    y: radius * Math.sin((2 * Math.PI * i) / n),
  }));
}

describe('Shape.decompose', () => {
  it('splits an L into two convex pieces of area 1.75, whichever its winding', () => {
    for (const outline of [L, L.slice().reverse()]) {
      const pieces = Shape.decompose(outline);
      expect(pieces.length).toBe(2); // one reflex corner: two pieces
      for (const piece of pieces) expectConvex(piece);
      const area = pieces.reduce((sum, piece) => sum + signedArea(piece.vertices), 0);
      expect(area).toBeCloseTo(1.75, 14);
      // the pieces' corners are the outline's points and every point is used
      for (const piece of pieces) for (const v of piece.vertices) expect(L).toContainEqual(v);
      for (const p of L)
        expect(pieces.some((piece) => piece.vertices.some((v) => v.x === p.x && v.y === p.y))).toBe(true);
    }
  });

  it('gives a convex outline of up to 8 points as one piece, and a longer one in ceil((n - 2) / 6) pieces', () => {
    expect(Shape.decompose(ring(8, 1)).map((p) => p.count)).toEqual([8]);
    expect(Shape.decompose(ring(3, 1)).map((p) => p.count)).toEqual([3]);
    for (const n of [9, 14, 15, 30]) {
      const pieces = Shape.decompose(ring(n, 1));
      expect(pieces.length).toBe(Math.ceil((n - 2) / 6));
      for (const piece of pieces) expectConvex(piece);
      const area = pieces.reduce((sum, piece) => sum + signedArea(piece.vertices), 0);
      expect(Math.abs(area - signedArea(ring(n, 1)))).toBeLessThan(1e-14);
    }
  });

  it('axis-aligned outlines: a T in 2 pieces, a U in 3, a comb of 15 teeth in 16, no piece with a straight corner', () => {
    const t = [
      { x: -2, y: 1 },
      { x: -0.5, y: 1 },
      { x: -0.5, y: -1 },
      { x: 0.5, y: -1 },
      { x: 0.5, y: 1 },
      { x: 2, y: 1 },
      { x: 2, y: 2 },
      { x: -2, y: 2 },
    ];
    const u = [
      { x: -1.5, y: 0 },
      { x: 1.5, y: 0 },
      { x: 1.5, y: 2 },
      { x: 1, y: 2 },
      { x: 1, y: 0.5 },
      { x: -1, y: 0.5 },
      { x: -1, y: 2 },
      { x: -1.5, y: 2 },
    ];
    // a bar 9.3 m by 0.3 m with 15 teeth 0.3 m wide and 1.2 m tall on top
    const comb = [
      { x: 0, y: 0 },
      { x: 9.3, y: 0 },
    ];
    for (let k = 15; k >= 1; k--) {
      comb.push(
        { x: 0.6 * k, y: 0.3 },
        { x: 0.6 * k, y: 1.5 },
        { x: 0.6 * k - 0.3, y: 1.5 },
        { x: 0.6 * k - 0.3, y: 0.3 },
      );
    }
    for (const [outline, count] of [
      [t, 2],
      [u, 3],
      [comb, 16],
    ] as const) {
      const pieces = Shape.decompose(outline);
      expect(pieces.length).toBe(count);
      for (const piece of pieces) expectConvex(piece);
      const area = pieces.reduce((sum, piece) => sum + signedArea(piece.vertices), 0);
      expect(Math.abs(area - signedArea(outline))).toBeLessThan(1e-12);
    }
  });

  it('cleans the outline: repeated points, points on the line of their neighbours, near-zero edges', () => {
    const messy = [
      { x: 0, y: 0 },
      { x: 1, y: 0 }, // on the bottom edge
      { x: 1.0001, y: 0.002 }, // 2 mm from the point before: dropped, and 2 mm from the edge
      { x: 2, y: 0 },
      { x: 2, y: 0.5 },
      { x: 2, y: 0.5 }, // repeated
      { x: 1.25, y: 0.5 }, // on the edge (2, 0.5)-(0.5, 0.5)
      { x: 0.5, y: 0.5 },
      { x: 0.5, y: 2 },
      { x: 0.003, y: 2.001 }, // kept: (0, 2), 3 mm after it, is dropped
      { x: 0, y: 2 },
      { x: 0, y: 0.001 }, // 1 mm from (0, 0), the first point: dropped
    ];
    const concave = Shape.concave(messy);
    expect(concave.outline.map((p) => [p.x, p.y])).toEqual([
      [0, 0],
      [2, 0],
      [2, 0.5],
      [0.5, 0.5],
      [0.5, 2],
      [0.003, 2.001],
    ]);
    expect(concave.pieces.length).toBe(2);
  });

  it('refuses a self-intersecting outline, naming the edges that cross and where', () => {
    const bowtie = [
      { x: 0, y: 0 },
      { x: 2, y: 2 },
      { x: 2, y: 0 },
      { x: 0, y: 2 },
    ];
    const message = messageOf(() => Shape.decompose(bowtie));
    expect(message).toContain('points[0] (0, 0) to points[1] (2, 2)');
    expect(message).toContain('points[2] (2, 0) to points[3] (0, 2)');
    expect(message).toContain('cross at (1, 1)');
  });

  it('refuses an outline that touches itself: a point repeated, a point on another edge', () => {
    const figureEight = [
      { x: 0, y: 0 },
      { x: 1, y: 0 },
      { x: 1, y: 1 },
      { x: 2, y: 1 },
      { x: 2, y: 2 },
      { x: 1, y: 2 },
      { x: 1.001, y: 1 }, // 1 mm from points[2]
      { x: 0, y: 1 },
    ];
    const repeated = messageOf(() => Shape.concave(figureEight));
    expect(repeated).toContain('points[2] (1, 1) and points[6] (1.001, 1) are the same point');
    const onEdge = [
      { x: 0, y: 0 },
      { x: 2, y: 0 },
      { x: 2, y: 2 },
      { x: 1, y: 0.002 }, // 2 mm above the edge points[0]-points[1]
      { x: 0, y: 2 },
    ];
    const touching = messageOf(() => Shape.concave(onEdge));
    expect(touching).toContain(
      'points[3] (1, 0.002) is closer than 0.005 m to the edge points[0] (0, 0) to points[1] (2, 0)',
    );
  });

  it('refuses degenerate outlines: too few points, all on one line, a spike of no width', () => {
    expect(
      messageOf(() =>
        Shape.decompose([
          { x: 0, y: 0 },
          { x: 1, y: 0 },
        ]),
      ),
    ).toContain('3 to 1024 points, got 2');
    expect(messageOf(() => Shape.decompose(ring(1025, 10)))).toContain('got 1025 points');
    expect(
      messageOf(() =>
        Shape.decompose([
          { x: 0, y: 0 },
          { x: 0.001, y: 0.001 },
          { x: 0.002, y: 0 },
        ]),
      ),
    ).toContain('at least 3 points more than 0.005 m apart');
    const spike = [
      { x: 0, y: 0 },
      { x: 2, y: 0 },
      { x: 2, y: 1 },
      { x: 3, y: 1 }, // out along y = 1 ...
      { x: 2.5, y: 1 }, // ... and back
      { x: 0, y: 1 },
    ];
    const message = messageOf(() => Shape.decompose(spike));
    expect(message).toContain('turns back on itself at points[3] (3, 1)');
  });

  it('refuses bad points with the usual FulcrumError naming the element', () => {
    expect(messageOf(() => Shape.concave('L' as never))).toContain('points must be an array');
    expect(
      messageOf(() =>
        Shape.concave([
          { x: 0, y: 0 },
          { x: 1, y: Number.NaN },
          { x: 0, y: 1 },
        ]),
      ),
    ).toContain('points[1]');
    const sparse = [
      { x: 0, y: 0 },
      { x: 1, y: 0 },
      { x: 0, y: 1 },
    ];
    delete (sparse as unknown[])[1];
    expect(messageOf(() => Shape.decompose(sparse))).toContain('points[1]');
  });

  it('Shape.concave is frozen: the outline counter-clockwise, the pieces polygons', () => {
    const concave = Shape.concave(L.slice().reverse());
    expect(concave.type).toBe('concave');
    expect(
      Object.isFrozen(concave) && Object.isFrozen(concave.outline) && Object.isFrozen(concave.pieces),
    ).toBe(true);
    expect(Object.isFrozen(concave.outline[0])).toBe(true);
    expect(signedArea(concave.outline)).toBeCloseTo(1.75, 14);
    for (const piece of concave.pieces) expect(piece.type).toBe('polygon');
  });

  it('Shape.polygon refuses the L and points to Shape.concave; a 9-point outline too', () => {
    expect(messageOf(() => Shape.polygon(L))).toContain('Shape.concave(points)');
    expect(messageOf(() => Shape.polygon(ring(9, 1)))).toContain('Shape.concave(points)');
  });
});
