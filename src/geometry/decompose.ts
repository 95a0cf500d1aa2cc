import { FulcrumError, fail } from '../core/errors';
import type { Vec2 } from '../math/vec2';
import { LINEAR_SLOP } from './constants';
import { MAX_OUTLINE_POINTS, MAX_POLYGON_VERTICES } from './types';

const SLOP_SQ = LINEAR_SLOP * LINEAR_SLOP;

/** A simple outline split into convex pieces. Both are counter-clockwise lists of the outline's points. */
export interface Decomposition {
  /** the cleaned outline: duplicate and collinear points removed, counter-clockwise */
  outline: Vec2[];
  /** convex pieces, each of 3 to MAX_POLYGON_VERTICES points of `outline` */
  pieces: Vec2[][];
}

/**
 * The outline being cleaned: coordinates, each point's index in the input (for messages) and the
 * input points dropped between it and the next point kept.
 */
interface Outline {
  x: number[];
  y: number[];
  index: number[];
  dropped: number[][];
}

function at(o: Outline, i: number): string {
  return `points[${o.index[i]}] (${o.x[i]}, ${o.y[i]})`;
}

/** Twice the signed area of triangle (a, b, c): > 0 when counter-clockwise. */
function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

function distanceSqToSegment(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax;
  const ey = by - ay;
  const t = Math.min(1, Math.max(0, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)));
  const dx = ax + t * ex - px;
  const dy = ay + t * ey - py;
  return dx * dx + dy * dy;
}

/** Drops point i; the points dropped after it now come after the point before it. */
function dropAt(o: Outline, i: number): void {
  const before = i === 0 ? o.x.length - 1 : i - 1;
  o.dropped[before].push(o.index[i], ...o.dropped[i]);
  o.x.splice(i, 1);
  o.y.splice(i, 1);
  o.index.splice(i, 1);
  o.dropped.splice(i, 1);
}

/** Drops each point closer than LINEAR_SLOP to the point kept before it, around the loop. */
function dropRepeatedPoints(points: readonly Vec2[]): Outline {
  const o: Outline = { x: [], y: [], index: [], dropped: [] };
  for (let i = 0; i < points.length; i++) {
    const p = points[i];
    const k = o.x.length - 1;
    if (k >= 0) {
      const dx = p.x - o.x[k];
      const dy = p.y - o.y[k];
      if (dx * dx + dy * dy < SLOP_SQ) {
        o.dropped[k].push(i);
        continue;
      }
    }
    o.x.push(p.x);
    o.y.push(p.y);
    o.index.push(i);
    o.dropped.push([]);
  }
  // the loop closes: the last points may repeat the first
  while (o.x.length > 1) {
    const k = o.x.length - 1;
    const dx = o.x[k] - o.x[0];
    const dy = o.y[k] - o.y[0];
    if (dx * dx + dy * dy >= SLOP_SQ) break;
    dropAt(o, k);
  }
  return o;
}

/**
 * Drops the points that lie within LINEAR_SLOP of the line through their neighbours (on either side)
 * and between them, as long as every point dropped so far next to them stays within LINEAR_SLOP of
 * the new edge: a gentle curve sampled finely loses points, but never drifts more than LINEAR_SLOP
 * from any point given. A point within LINEAR_SLOP of that line but not between its neighbours is the
 * tip of a spike of no width: the outline turns back on itself there, and that is an error. After a
 * point is dropped the point before it is looked at again, until a whole turn drops nothing.
 */
function dropCollinearPoints(o: Outline, points: readonly Vec2[], argument: string): void {
  let i = 0;
  let unchanged = 0;
  while (o.x.length >= 3 && unchanged < o.x.length) {
    const n = o.x.length;
    const a = i === 0 ? n - 1 : i - 1;
    const c = i === n - 1 ? 0 : i + 1;
    if (isFlat(o, points, a, i, c, argument)) {
      dropAt(o, i);
      i = a < i ? a : a - 1;
      unchanged = 0;
    } else {
      i = c;
      unchanged++;
    }
  }
}

/** Whether point i can be dropped from between a and c (see dropCollinearPoints). */
function isFlat(
  o: Outline,
  points: readonly Vec2[],
  a: number,
  i: number,
  c: number,
  argument: string,
): boolean {
  const ax = o.x[a];
  const ay = o.y[a];
  const cx = o.x[c];
  const cy = o.y[c];
  const ex = cx - ax;
  const ey = cy - ay;
  const px = o.x[i] - ax;
  const py = o.y[i] - ay;
  const cross = ex * py - ey * px;
  if (cross * cross > SLOP_SQ * (ex * ex + ey * ey)) return false;
  const along = ex * px + ey * py;
  if (along <= 0 || along >= ex * ex + ey * ey) {
    throw new FulcrumError(
      `${argument}: the outline turns back on itself at ${at(o, i)}: its edges from ${at(o, a)} and to ${at(o, c)} lie on one line and overlap`,
    );
  }
  for (const list of [o.dropped[a], o.dropped[i]]) {
    for (const k of list) {
      if (distanceSqToSegment(points[k].x, points[k].y, ax, ay, cx, cy) > SLOP_SQ) return false;
    }
  }
  return true;
}

/**
 * Throws a FulcrumError naming the points when the outline is not simple with room to spare: two edges
 * that cross, a point within LINEAR_SLOP of another point, or of an edge it is not on. Only pairs of
 * edges whose bounding boxes, grown by LINEAR_SLOP, overlap are looked at: a point within LINEAR_SLOP
 * of an edge is the end of an edge whose box does. Consecutive points are farther apart than
 * LINEAR_SLOP already (dropRepeatedPoints).
 */
function checkSimple(o: Outline, argument: string): void {
  const n = o.x.length;
  const { x, y } = o;
  const minX = new Float64Array(n);
  const minY = new Float64Array(n);
  const maxX = new Float64Array(n);
  const maxY = new Float64Array(n);
  for (let e = 0; e < n; e++) {
    const e1 = e + 1 === n ? 0 : e + 1;
    minX[e] = Math.min(x[e], x[e1]) - LINEAR_SLOP;
    minY[e] = Math.min(y[e], y[e1]) - LINEAR_SLOP;
    maxX[e] = Math.max(x[e], x[e1]) + LINEAR_SLOP;
    maxY[e] = Math.max(y[e], y[e1]) + LINEAR_SLOP;
  }
  for (let i = 0; i < n; i++) {
    const i1 = i + 1 === n ? 0 : i + 1;
    for (let j = i + 1; j < n; j++) {
      if (minX[j] > maxX[i] || minX[i] > maxX[j] || minY[j] > maxY[i] || minY[i] > maxY[j]) continue;
      const j1 = j + 1 === n ? 0 : j + 1;
      if (j !== i1 && j1 !== i) {
        const d1 = orient(x[i], y[i], x[i1], y[i1], x[j], y[j]);
        const d2 = orient(x[i], y[i], x[i1], y[i1], x[j1], y[j1]);
        const d3 = orient(x[j], y[j], x[j1], y[j1], x[i], y[i]);
        const d4 = orient(x[j], y[j], x[j1], y[j1], x[i1], y[i1]);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
          const t = d3 / (d3 - d4);
          const cx = x[i] + t * (x[i1] - x[i]);
          const cy = y[i] + t * (y[i1] - y[i]);
          throw new FulcrumError(
            `${argument}: the edges ${at(o, i)} to ${at(o, i1)} and ${at(o, j)} to ${at(o, j1)} cross at (${cx}, ${cy}): the outline must not cross itself`,
          );
        }
      }
      checkApart(o, i, j, j1, argument);
      checkApart(o, i1, j, j1, argument);
      checkApart(o, j, i, i1, argument);
      checkApart(o, j1, i, i1, argument);
    }
  }
}

/** Throws when point v, not an end of edge e-e1, lies within LINEAR_SLOP of that edge or of an end. */
function checkApart(o: Outline, v: number, e: number, e1: number, argument: string): void {
  if (v === e || v === e1) return;
  const { x, y } = o;
  if (distanceSqToSegment(x[v], y[v], x[e], y[e], x[e1], y[e1]) >= SLOP_SQ) return;
  for (const w of [e, e1]) {
    const dx = x[w] - x[v];
    const dy = y[w] - y[v];
    if (dx * dx + dy * dy < SLOP_SQ) {
      const [first, second] = v < w ? [v, w] : [w, v];
      throw new FulcrumError(
        `${argument}: ${at(o, first)} and ${at(o, second)} are the same point (closer than ${LINEAR_SLOP} m): the outline touches itself there`,
      );
    }
  }
  throw new FulcrumError(
    `${argument}: ${at(o, v)} is closer than ${LINEAR_SLOP} m to the edge ${at(o, e)} to ${at(o, e1)}: the outline touches itself there`,
  );
}

/** Counter-clockwise: reversed when the shoelace area is negative. */
function makeCounterClockwise(o: Outline): void {
  const n = o.x.length;
  let area = 0;
  for (let i = 1; i + 1 < n; i++) area += orient(o.x[0], o.y[0], o.x[i], o.y[i], o.x[i + 1], o.y[i + 1]);
  if (area < 0) {
    o.x.reverse();
    o.y.reverse();
    o.index.reverse();
  }
}

/** A piece's corner b (edges a->b, b->c) as a merge would leave it. */
enum Corner {
  /** convex and not flat: kept */
  SHARP,
  /** on the line a-c to rounding, going on: the corner is dropped from the piece */
  STRAIGHT,
  /** reflex, or convex but within LINEAR_SLOP of the line a-c: the merge is refused */
  REFUSED,
}

/** |sin| of the turn below which a corner counts as straight: rounding of points on one line. */
const STRAIGHT_SINE = 1e-12;

/**
 * Classifies corner b. Sharp: turning left, by a right angle or more, or with b farther than
 * LINEAR_SLOP from the line a-c (the rule Shape.polygon keeps hull vertices by). Straight: b on that
 * line to rounding and between a and c, as where the floor of a U meets its arms. A merge never leaves
 * a flat corner, as two nearly collinear edges of one polygon would clip a contact to one of them (a
 * triangle that ear clipping had to cut thin, where the outline itself is thin, may still hold one).
 */
function classifyCorner(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): Corner {
  const e1x = bx - ax;
  const e1y = by - ay;
  const e2x = cx - bx;
  const e2y = cy - by;
  const cross = e1x * e2y - e1y * e2x;
  const dot = e1x * e2x + e1y * e2y;
  if (
    dot > 0 &&
    cross * cross <= STRAIGHT_SINE * STRAIGHT_SINE * (e1x * e1x + e1y * e1y) * (e2x * e2x + e2y * e2y)
  ) {
    return Corner.STRAIGHT;
  }
  if (cross <= 0) return Corner.REFUSED;
  if (dot <= 0) return Corner.SHARP;
  const ex = cx - ax;
  const ey = cy - ay;
  return cross * cross > SLOP_SQ * (ex * ex + ey * ey) ? Corner.SHARP : Corner.REFUSED;
}

function noConvexSplit(argument: string): never {
  throw new FulcrumError(
    `${argument}: the outline could not be split into convex pieces (rounding: it nearly touches itself)`,
  );
}

/**
 * Ear clipping of a counter-clockwise simple outline, fattest ear first: an ear is a convex point whose
 * triangle with its neighbours holds no reflex point (inside or on its edges); of all ears the one whose
 * triangle has the largest area relative to the square of its longest edge is cut off (the first such
 * point on a tie). Clipping an ear changes only its neighbours' ear status. Fills `triangles` with
 * point index triples, counter-clockwise, the tip in the middle: triangle k (but the last) leaves the
 * diagonal from its first point to its third, which triangle `partner[k]` has on its other side.
 */
function triangulate(
  x: readonly number[],
  y: readonly number[],
  triangles: Int32Array,
  partner: Int32Array,
  argument: string,
): void {
  const n = x.length;
  const prev = new Int32Array(n);
  const next = new Int32Array(n);
  /** the triangle across edge i -> next[i] once it is a diagonal, else -1 */
  const across = new Int32Array(n).fill(-1);
  const removed = new Uint8Array(n);
  const isReflex = new Uint8Array(n);
  const reflex: number[] = [];
  const quality = new Float64Array(n); // -1: not an ear
  for (let i = 0; i < n; i++) {
    prev[i] = i === 0 ? n - 1 : i - 1;
    next[i] = i === n - 1 ? 0 : i + 1;
  }
  for (let i = 0; i < n; i++) {
    if (orient(x[prev[i]], y[prev[i]], x[i], y[i], x[next[i]], y[next[i]]) <= 0) {
      isReflex[i] = 1;
      reflex.push(i);
    }
  }
  for (let i = 0; i < n; i++) quality[i] = earQuality(x, y, prev[i], i, next[i], isReflex, reflex);

  for (let k = 0, left = n; left > 3; k++, left--) {
    let tip = -1;
    for (let i = 0; i < n; i++) {
      if (removed[i] === 0 && quality[i] >= 0 && (tip === -1 || quality[i] > quality[tip])) tip = i;
    }
    if (tip === -1) noConvexSplit(argument);
    const a = prev[tip];
    const c = next[tip];
    recordTriangle(triangles, partner, across, k, a, tip, c);
    removed[tip] = 1;
    next[a] = c;
    prev[c] = a;
    across[a] = k;
    for (const v of [a, c]) {
      if (isReflex[v] === 1 && orient(x[prev[v]], y[prev[v]], x[v], y[v], x[next[v]], y[next[v]]) > 0) {
        isReflex[v] = 0;
        reflex.splice(reflex.indexOf(v), 1);
      }
      quality[v] = earQuality(x, y, prev[v], v, next[v], isReflex, reflex);
    }
  }
  let last = 0;
  while (removed[last] === 1) last++;
  const a = prev[last];
  const c = next[last];
  if (orient(x[a], y[a], x[last], y[last], x[c], y[c]) <= 0) noConvexSplit(argument);
  recordTriangle(triangles, partner, across, n - 3, a, last, c);
  // the last triangle's third edge, c -> a, may be a diagonal too
  if (across[c] >= 0) partner[across[c]] = n - 3;
}

/** Triangle k = (a, b, c); the triangles across its edges a->b and b->c, if any, have it as partner. */
function recordTriangle(
  triangles: Int32Array,
  partner: Int32Array,
  across: Int32Array,
  k: number,
  a: number,
  b: number,
  c: number,
): void {
  triangles[3 * k] = a;
  triangles[3 * k + 1] = b;
  triangles[3 * k + 2] = c;
  if (across[a] >= 0) partner[across[a]] = k;
  if (across[b] >= 0) partner[across[b]] = k;
}

/** The ear quality of point b between a and c (see triangulate), or -1 when b is not an ear. */
function earQuality(
  x: readonly number[],
  y: readonly number[],
  a: number,
  b: number,
  c: number,
  isReflex: Uint8Array,
  reflex: readonly number[],
): number {
  if (isReflex[b] === 1) return -1;
  const minX = Math.min(x[a], x[b], x[c]);
  const maxX = Math.max(x[a], x[b], x[c]);
  const minY = Math.min(y[a], y[b], y[c]);
  const maxY = Math.max(y[a], y[b], y[c]);
  for (const r of reflex) {
    const rx = x[r];
    const ry = y[r];
    if (
      rx >= minX &&
      rx <= maxX &&
      ry >= minY &&
      ry <= maxY &&
      r !== a &&
      r !== c &&
      orient(x[a], y[a], x[b], y[b], x[r], y[r]) >= 0 &&
      orient(x[b], y[b], x[c], y[c], x[r], y[r]) >= 0 &&
      orient(x[c], y[c], x[a], y[a], x[r], y[r]) >= 0
    ) {
      return -1;
    }
  }
  const ab = (x[b] - x[a]) * (x[b] - x[a]) + (y[b] - y[a]) * (y[b] - y[a]);
  const bc = (x[c] - x[b]) * (x[c] - x[b]) + (y[c] - y[b]) * (y[c] - y[b]);
  const ca = (x[a] - x[c]) * (x[a] - x[c]) + (y[a] - y[c]) * (y[a] - y[c]);
  return orient(x[a], y[a], x[b], y[b], x[c], y[c]) / Math.max(ab, bc, ca);
}

/**
 * Hertel–Mehlhorn: each diagonal of the triangulation, in the order the ears were cut, is removed when
 * the piece it joins keeps every corner sharp or straight at both of its ends (classifyCorner; a
 * straight corner leaves the piece). What is left are diagonals that each keep a reflex point of the
 * outline from turning flat or reflex, at most two per reflex point: at most 2r + 1 pieces for r
 * reflex points (Hertel and Mehlhorn 1983). Pieces are lists of point indices, counter-clockwise, in
 * the order of the triangle each grew from.
 */
function mergeTriangles(
  x: readonly number[],
  y: readonly number[],
  triangles: Int32Array,
  partner: Int32Array,
): number[][] {
  const count = triangles.length / 3;
  const parent = new Int32Array(count);
  const pieces: (number[] | null)[] = [];
  for (let t = 0; t < count; t++) {
    parent[t] = t;
    pieces.push([triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]]);
  }
  const find = (t: number): number => {
    while (parent[t] !== t) {
      parent[t] = parent[parent[t]];
      t = parent[t];
    }
    return t;
  };
  for (let t = 0; t + 1 < count; t++) {
    // the diagonal a-c that cutting ear t left: piece p holds c -> a, piece q a -> c
    const a = triangles[3 * t];
    const c = triangles[3 * t + 2];
    const p = find(t);
    const q = find(partner[t]);
    const merged = mergedOutline(x, y, pieces[p]!, pieces[q]!, a, c);
    if (merged !== null) {
      parent[q] = p;
      pieces[p] = merged;
      pieces[q] = null;
    }
  }
  const result: number[][] = [];
  for (const piece of pieces) if (piece !== null) result.push(piece);
  return result;
}

/**
 * Pieces pv (holding edge c -> a) and qv (holding a -> c) as one, without their straight corners at a
 * and c; null when a corner at a or c would not be sharp or straight, or when a piece lost a or c to
 * an earlier merge (a straight corner dropped).
 */
function mergedOutline(
  x: readonly number[],
  y: readonly number[],
  pv: readonly number[],
  qv: readonly number[],
  a: number,
  c: number,
): number[] | null {
  const pa = pv.indexOf(a);
  const qc = qv.indexOf(c);
  if (
    pa < 0 ||
    qc < 0 ||
    pv[(pa + pv.length - 1) % pv.length] !== c ||
    qv[(qc + qv.length - 1) % qv.length] !== a
  ) {
    return null;
  }
  // p from a round to c, then q after c round to the point before a
  const merged: number[] = [];
  for (let k = 0; k < pv.length; k++) merged.push(pv[(pa + k) % pv.length]);
  for (let k = 1; k + 1 < qv.length; k++) merged.push(qv[(qc + k) % qv.length]);
  const ci = pv.length - 1;
  const atC = corner(x, y, merged, ci);
  const atA = corner(x, y, merged, 0);
  if (atC === Corner.REFUSED || atA === Corner.REFUSED) return null;
  if (atC === Corner.STRAIGHT) merged.splice(ci, 1);
  if (atA === Corner.STRAIGHT) merged.splice(0, 1);
  return merged.length >= 3 ? merged : null;
}

function corner(x: readonly number[], y: readonly number[], piece: readonly number[], i: number): Corner {
  const a = piece[i === 0 ? piece.length - 1 : i - 1];
  const b = piece[i];
  const c = piece[i + 1 === piece.length ? 0 : i + 1];
  return classifyCorner(x[a], y[a], x[b], y[b], x[c], y[c]);
}

/**
 * Splits a convex piece of k > MAX_POLYGON_VERTICES points into ceil((k - 2) / 6) pieces (the fewest
 * of at most 8 points) by chords from its first point: each chord leaves whole pieces' worth of
 * points on one side, about half of them, so the chords run across the piece rather than cut slivers
 * off its edge.
 */
function splitLargePiece(piece: readonly number[], out: number[][]): void {
  const k = piece.length;
  if (k <= MAX_POLYGON_VERTICES) {
    out.push(piece.slice());
    return;
  }
  const spare = MAX_POLYGON_VERTICES - 2; // points a piece adds beyond its first two
  const total = Math.floor((k - 3) / spare) + 1; // ceil((k - 2) / spare)
  const j = spare * Math.floor(total / 2) + 1;
  splitLargePiece(piece.slice(0, j + 1), out);
  splitLargePiece([piece[0], ...piece.slice(j)], out);
}

/**
 * Cleans a simple outline (either winding) and splits it into convex pieces of at most
 * MAX_POLYGON_VERTICES points, every piece's points being points of the outline. The points are
 * finite and in range (the caller checked them). Throws a FulcrumError naming `argument` and the
 * points at fault when the outline is degenerate or not simple.
 */
export function decomposeOutline(points: readonly Vec2[], argument: string): Decomposition {
  if (points.length < 3 || points.length > MAX_OUTLINE_POINTS) {
    throw new FulcrumError(
      `${argument} must be an array of 3 to ${MAX_OUTLINE_POINTS} points, got ${points.length} points`,
    );
  }
  const o = dropRepeatedPoints(points);
  if (o.x.length >= 3) dropCollinearPoints(o, points, argument);
  if (o.x.length < 3) {
    fail(
      argument,
      points,
      `an outline of at least 3 points more than ${LINEAR_SLOP} m apart and off one line`,
    );
  }
  checkSimple(o, argument);
  makeCounterClockwise(o);
  const { x, y } = o;
  const outline = x.map((px, i) => ({ x: px, y: y[i] }));
  const triangles = new Int32Array(3 * (x.length - 2));
  const partner = new Int32Array(x.length - 2);
  triangulate(x, y, triangles, partner, argument);
  const pieces: number[][] = [];
  for (const piece of mergeTriangles(x, y, triangles, partner)) splitLargePiece(piece, pieces);
  return { outline, pieces: pieces.map((piece) => piece.map((i) => outline[i])) };
}
