import type { Transform } from '../math/vec2';
import type { ShapeProxy } from './shape-proxy';
import { MAX_POLYGON_VERTICES } from './types';

/**
 * Shared machinery of GJK (distance.ts) and the GJK ray cast (shape-cast.ts). Everything is done in
 * the local frame of shape A, which keeps precision when both shapes are far from the world origin.
 * Their working memory is a GjkMemory the caller owns and passes in.
 */

/** A vertex of the simplex: support points of A and B, the simplex point w and its barycentric weight. */
export class SimplexVertex {
  ax = 0;
  ay = 0;
  bx = 0;
  by = 0;
  wx = 0;
  wy = 0;
  a = 0;
  indexA = 0;
  indexB = 0;
}

export class Simplex {
  readonly v1 = new SimplexVertex();
  readonly v2 = new SimplexVertex();
  readonly v3 = new SimplexVertex();
  count = 0;
}

/** Points of proxy B expressed in the frame of A, filled by `loadRelativeB`. */
export class RelativePoints {
  readonly x = new Float64Array(MAX_POLYGON_VERTICES);
  readonly y = new Float64Array(MAX_POLYGON_VERTICES);
  count = 0;
}

/**
 * The working memory of one GJK call (shapeDistance, shapeCast): written before it is read, so one
 * instance serves any number of calls made one after the other. Its owner passes it in (a world
 * keeps its own), so that calls for different owners share nothing.
 */
export class GjkMemory {
  readonly simplex = new Simplex();
  readonly relB = new RelativePoints();
}

/** Write the points of proxy B, placed by xfB, into `relB` in the frame of A (placed by xfA). */
export function loadRelativeB(
  relB: RelativePoints,
  xfA: Transform,
  proxyB: ShapeProxy,
  xfB: Transform,
): void {
  const ac = xfA.q.c;
  const as = xfA.q.s;
  const bc = xfB.q.c;
  const bs = xfB.q.s;
  // q = qA^T qB, p = qA^T (pB - pA)
  const c = ac * bc + as * bs;
  const s = ac * bs - as * bc;
  const dx = xfB.p.x - xfA.p.x;
  const dy = xfB.p.y - xfA.p.y;
  const px = ac * dx + as * dy;
  const py = -as * dx + ac * dy;
  const n = proxyB.count;
  for (let i = 0; i < n; i++) {
    const x = proxyB.x[i];
    const y = proxyB.y[i];
    relB.x[i] = c * x - s * y + px;
    relB.y[i] = s * x + c * y + py;
  }
  relB.count = n;
}

/** Index of the point furthest along (dx, dy); ties go to the lowest index. */
export function support(xs: Float64Array, ys: Float64Array, count: number, dx: number, dy: number): number {
  let best = 0;
  let bestValue = xs[0] * dx + ys[0] * dy;
  for (let i = 1; i < count; i++) {
    const value = xs[i] * dx + ys[i] * dy;
    if (value > bestValue) {
      best = i;
      bestValue = value;
    }
  }
  return best;
}

function copyVertex(dst: SimplexVertex, src: SimplexVertex): void {
  dst.ax = src.ax;
  dst.ay = src.ay;
  dst.bx = src.bx;
  dst.by = src.by;
  dst.wx = src.wx;
  dst.wy = src.wy;
  dst.a = src.a;
  dst.indexA = src.indexA;
  dst.indexB = src.indexB;
}

export function vertexAt(s: Simplex, i: number): SimplexVertex {
  return i === 0 ? s.v1 : i === 1 ? s.v2 : s.v3;
}

/**
 * Reduce the simplex to the smallest sub-simplex whose hull contains the point closest to the origin
 * and set the barycentric weights of that point. A count of 3 afterwards means the origin is inside.
 * Each region test uses unnormalised barycentric coordinates, so collinear or repeated points
 * fall into an edge or vertex region instead of dividing by zero.
 */
export function solveSimplex(s: Simplex): void {
  if (s.count === 1) {
    s.v1.a = 1;
  } else if (s.count === 2) {
    solve2(s);
  } else if (s.count === 3) {
    solve3(s);
  }
}

function solve2(s: Simplex): void {
  const w1 = s.v1;
  const w2 = s.v2;
  const ex = w2.wx - w1.wx;
  const ey = w2.wy - w1.wy;
  // weight of w2 is -w1.e, weight of w1 is w2.e (both times |e|^2)
  const d2 = -(w1.wx * ex + w1.wy * ey);
  if (d2 <= 0) {
    w1.a = 1;
    s.count = 1;
    return;
  }
  const d1 = w2.wx * ex + w2.wy * ey;
  if (d1 <= 0) {
    copyVertex(w1, w2);
    w1.a = 1;
    s.count = 1;
    return;
  }
  const inv = 1 / (d1 + d2);
  w1.a = d1 * inv;
  w2.a = d2 * inv;
  s.count = 2;
}

function solve3(s: Simplex): void {
  const w1 = s.v1;
  const w2 = s.v2;
  const w3 = s.v3;
  const x1 = w1.wx;
  const y1 = w1.wy;
  const x2 = w2.wx;
  const y2 = w2.wy;
  const x3 = w3.wx;
  const y3 = w3.wy;

  // edge weights: dIJ_I is the weight of vertex I on edge IJ
  const e12x = x2 - x1;
  const e12y = y2 - y1;
  const d12_1 = x2 * e12x + y2 * e12y;
  const d12_2 = -(x1 * e12x + y1 * e12y);
  const e13x = x3 - x1;
  const e13y = y3 - y1;
  const d13_1 = x3 * e13x + y3 * e13y;
  const d13_3 = -(x1 * e13x + y1 * e13y);
  const e23x = x3 - x2;
  const e23y = y3 - y2;
  const d23_2 = x3 * e23x + y3 * e23y;
  const d23_3 = -(x2 * e23x + y2 * e23y);

  // triangle weights: signed sub-areas, signed by the triangle's orientation
  const n123 = e12x * e13y - e12y * e13x;
  const d123_1 = n123 * (x2 * y3 - y2 * x3);
  const d123_2 = n123 * (x3 * y1 - y3 * x1);
  const d123_3 = n123 * (x1 * y2 - y1 * x2);

  if (d12_2 <= 0 && d13_3 <= 0) {
    w1.a = 1;
    s.count = 1;
  } else if (d12_1 > 0 && d12_2 > 0 && d123_3 <= 0) {
    const inv = 1 / (d12_1 + d12_2);
    w1.a = d12_1 * inv;
    w2.a = d12_2 * inv;
    s.count = 2;
  } else if (d13_1 > 0 && d13_3 > 0 && d123_2 <= 0) {
    const inv = 1 / (d13_1 + d13_3);
    w1.a = d13_1 * inv;
    w3.a = d13_3 * inv;
    copyVertex(w2, w3);
    s.count = 2;
  } else if (d12_1 <= 0 && d23_3 <= 0) {
    copyVertex(w1, w2);
    w1.a = 1;
    s.count = 1;
  } else if (d13_1 <= 0 && d23_2 <= 0) {
    copyVertex(w1, w3);
    w1.a = 1;
    s.count = 1;
  } else if (d23_2 > 0 && d23_3 > 0 && d123_1 <= 0) {
    const inv = 1 / (d23_2 + d23_3);
    w2.a = d23_2 * inv;
    w3.a = d23_3 * inv;
    copyVertex(w1, w3);
    s.count = 2;
  } else {
    const sum = d123_1 + d123_2 + d123_3;
    // sum > 0 here unless rounding put the origin on a degenerate triangle; then it is inside anyway
    const inv = sum > 0 ? 1 / sum : 0;
    w1.a = sum > 0 ? d123_1 * inv : 1 / 3;
    w2.a = sum > 0 ? d123_2 * inv : 1 / 3;
    w3.a = sum > 0 ? d123_3 * inv : 1 / 3;
    s.count = 3;
  }
}
