import { LINEAR_SLOP, REFERENCE_FACE_TOLERANCE } from '../geometry/constants';
import { Pack } from '../geometry/packed';
import type { Manifold } from '../geometry/types';
import type { Transform } from '../math/vec2';
import type { CollideContext, WorkPolygon } from './collide-context';
import { closestBetweenSegments } from './segment-distance';

/*
 * Polygon contacts (capsules and segments act as 2-vertex rounded polygons here), all computed in
 * A's local frame:
 * 1. SAT on the core polygons: the edge of largest separation on A and on B.
 * 2. Reference face: A's best edge unless B's beats it by REFERENCE_FACE_TOLERANCE; the incident edge
 *    is the other polygon's edge most anti-parallel to the reference normal.
 * 3. Separated cores whose closest features are two vertices: one point along the vertex-vertex line.
 * 4. Otherwise the incident edge is clipped to the reference edge's side planes: up to two points.
 *
 * Point ids (also described in manifold.ts): bits 0-3 incident vertex, bits 4-7 reference edge (or,
 * for a vertex pair, reference vertex), bit 8 set when B owns the reference face, bit 9 vertex pair.
 */

/** Feature id bits. Enums, not consts, for the reason in store/body-store.ts. */
enum IdBit {
  B_REFERENCE = 1 << 8,
  VERTEX_PAIR = 1 << 9,
}

/*
 * The reference hint (CollideContext.referenceHint): which polygon owned the reference face of this
 * pair's previous manifold. Faces under load are nearly parallel and their separations nearly equal;
 * without memory the reference face would swap between the two shapes as they tilt by a milliradian,
 * renaming every point and turning the normal, and a large pile would never come to rest. With memory
 * the owner only changes when the other face is clearly better.
 */
const STICKY_REFERENCE_TOLERANCE = 0.5 * LINEAR_SLOP;

/** The owner bit of a polygon contact id: 1 when B owned the reference face. */
export function referenceOwnerOfId(id: number): number {
  return (id & IdBit.B_REFERENCE) !== 0 ? 1 : 0;
}
/**
 * How much more than the face separation the cores' true distance must be before separated cores get
 * a vertex-pair point: up to this much, a point's separation may be below the true distance.
 */
export const VERTEX_PAIR_MIN_GAP = 0.1 * LINEAR_SLOP;

/*
 * Separating axis memory (speed only, never the result): a pair whose cores were apart by more than
 * the contact limit along one edge normal usually still is a step later. Testing that edge first
 * costs one edge instead of the full two-way SAT; when it still separates, the full SAT would find a
 * separation at least as large and return no points as well. Axis = edge + 1, plus 8 when the edge is
 * B's; 0 = none (CollideContext.axisHint in, separatingAxis out).
 */
enum Axis {
  /** added to B's face index in `separatingAxis` */
  B = 8,
}

/** Smallest signed distance of q's vertices to edge `i` of p (as in maxSeparation), to `out[0]`. */
function edgeSeparation(p: WorkPolygon, i: number, q: WorkPolygon, out: Float64Array): void {
  const nx = p.nx[i];
  const ny = p.ny[i];
  const vx = p.x[i];
  const vy = p.y[i];
  const qx = q.x;
  const qy = q.y;
  let min = Number.POSITIVE_INFINITY;
  for (let j = 0, n = q.count; j < n; j++) {
    const d = nx * (qx[j] - vx) + ny * (qy[j] - vy);
    if (d < min) min = d;
  }
  out[0] = min;
}

/** B's transform relative to A (q = qA^T qB, p = qA^T (pB - pA)): cos, sin, x, y, to `relative`. */
export function setRelative(
  relative: Float64Array,
  ac: number,
  as: number,
  ax: number,
  ay: number,
  bc: number,
  bs: number,
  bx: number,
  by: number,
) {
  relative[0] = ac * bc + as * bs;
  relative[1] = ac * bs - as * bc;
  const dx = bx - ax;
  const dy = by - ay;
  relative[2] = ac * dx + as * dy;
  relative[3] = -as * dx + ac * dy;
}

/** A's packed shape as it is (A's frame is its body's frame). */
function loadPolygonA(polyA: WorkPolygon, data: Float64Array, base: number): void {
  const x = polyA.x;
  const y = polyA.y;
  const nx = polyA.nx;
  const ny = polyA.ny;
  const n = data[base + Pack.COUNT];
  polyA.count = n;
  polyA.radius = data[base + Pack.RADIUS];
  for (let i = 0, k = base + Pack.VERTICES; i < n; i++, k += Pack.VERTEX_STRIDE) {
    x[i] = data[k];
    y[i] = data[k + 1];
    nx[i] = data[k + 2];
    ny[i] = data[k + 3];
  }
}

/** B's packed shape moved into A's frame by `relative`. */
function loadPolygonB(polyB: WorkPolygon, relative: Float64Array, data: Float64Array, base: number): void {
  const relC = relative[0];
  const relS = relative[1];
  const relX = relative[2];
  const relY = relative[3];
  const x = polyB.x;
  const y = polyB.y;
  const nx = polyB.nx;
  const ny = polyB.ny;
  const n = data[base + Pack.COUNT];
  polyB.count = n;
  polyB.radius = data[base + Pack.RADIUS];
  for (let i = 0, k = base + Pack.VERTICES; i < n; i++, k += Pack.VERTEX_STRIDE) {
    const vx = data[k];
    const vy = data[k + 1];
    const mx = data[k + 2];
    const my = data[k + 3];
    x[i] = relC * vx - relS * vy + relX;
    y[i] = relS * vx + relC * vy + relY;
    nx[i] = relC * mx - relS * my;
    ny[i] = relS * mx + relC * my;
  }
}

/**
 * Largest over p's edges of the smallest signed distance of q's vertices to that edge. Returns the
 * edge; the separation goes to `out[0]`.
 */
function maxSeparation(p: WorkPolygon, q: WorkPolygon, out: Float64Array): number {
  const px = p.x;
  const py = p.y;
  const pnx = p.nx;
  const pny = p.ny;
  const qx = q.x;
  const qy = q.y;
  const qCount = q.count;
  let best = Number.NEGATIVE_INFINITY;
  let bestEdge = 0;
  for (let i = 0, n = p.count; i < n; i++) {
    const nx = pnx[i];
    const ny = pny[i];
    const vx = px[i];
    const vy = py[i];
    let min = Number.POSITIVE_INFINITY;
    for (let j = 0; j < qCount; j++) {
      const d = nx * (qx[j] - vx) + ny * (qy[j] - vy);
      if (d < min) min = d;
    }
    if (min > best) {
      best = min;
      bestEdge = i;
    }
  }
  out[0] = best;
  return bestEdge;
}

/*
 * The result of collideLoaded in A's frame, turned into the world manifold by writeManifold:
 * the normal from the reference to the incident shape, and per point the point on the incident core,
 * its core separation and id.
 */
enum LocalManifold {
  NX = 0,
  NY = 1,
  POINTS = 2,
}

/** Whether B's face of largest separation is the reference face (step 2 and the reference hint). */
function referenceFromB(referenceHint: number, separationA: number, separationB: number): boolean {
  return referenceHint === 1
    ? !(separationA > separationB + STICKY_REFERENCE_TOLERANCE)
    : referenceHint === 0
      ? separationB > separationA + STICKY_REFERENCE_TOLERANCE
      : separationB > separationA + REFERENCE_FACE_TOLERANCE;
}

/** The manifold of the loaded polyA and polyB in `local`; returns the point count. */
function collideLoaded(context: CollideContext): number {
  const polyA = context.polyA;
  const polyB = context.polyB;
  const separationOut = context.separation;
  const axisHint = context.axisHint;
  const speculativeDistance = context.reach;
  const limit = speculativeDistance + polyA.radius + polyB.radius;
  if (axisHint !== 0) {
    const edge = (axisHint - 1) & 7;
    const ofB = axisHint > Axis.B;
    const p = ofB ? polyB : polyA;
    if (edge < p.count) {
      edgeSeparation(p, edge, ofB ? polyA : polyB, separationOut);
      if (separationOut[0] >= limit) {
        context.separatingAxis = axisHint;
        context.separatedDistance = separationOut[0] - polyA.radius - polyB.radius;
        return 0;
      }
    }
  }
  const edgeA = maxSeparation(polyA, polyB, separationOut);
  const separationA = separationOut[0];
  if (separationA >= limit) {
    context.separatingAxis = edgeA + 1;
    context.separatedDistance = separationA - polyA.radius - polyB.radius;
    return 0;
  }
  const edgeB = maxSeparation(polyB, polyA, separationOut);
  const separationB = separationOut[0];
  if (separationB >= limit) {
    context.separatingAxis = Axis.B + edgeB + 1;
    context.separatedDistance = separationB - polyA.radius - polyB.radius;
    return 0;
  }

  const flip = referenceFromB(context.referenceHint, separationA, separationB);
  context.referenceFlip = flip;
  const ref = flip ? polyB : polyA;
  const inc = flip ? polyA : polyB;
  const refEdge = flip ? edgeB : edgeA;
  const separation = flip ? separationB : separationA;
  const owner = flip ? IdBit.B_REFERENCE : 0;
  const rRef = ref.radius;
  const rInc = inc.radius;
  const nx = ref.nx[refEdge];
  const ny = ref.ny[refEdge];
  const ref2 = refEdge + 1 === ref.count ? 0 : refEdge + 1;
  const v1x = ref.x[refEdge];
  const v1y = ref.y[refEdge];
  const v2x = ref.x[ref2];
  const v2y = ref.y[ref2];

  const incNx = inc.nx;
  const incNy = inc.ny;
  let inc1 = 0;
  let minDot = Number.POSITIVE_INFINITY;
  for (let i = 0, n = inc.count; i < n; i++) {
    const d = nx * incNx[i] + ny * incNy[i];
    if (d < minDot) {
      minDot = d;
      inc1 = i;
    }
  }
  const inc2 = inc1 + 1 === inc.count ? 0 : inc1 + 1;
  const faces = context.faces;
  faces[FaceInput.NX] = nx;
  faces[FaceInput.NY] = ny;
  faces[FaceInput.V1X] = v1x;
  faces[FaceInput.V1Y] = v1y;
  faces[FaceInput.V2X] = v2x;
  faces[FaceInput.V2Y] = v2y;
  faces[FaceInput.W1X] = inc.x[inc1];
  faces[FaceInput.W1Y] = inc.y[inc1];
  faces[FaceInput.W2X] = inc.x[inc2];
  faces[FaceInput.W2Y] = inc.y[inc2];
  faces[FaceInput.SEPARATION] = separation;
  faces[FaceInput.R_REF] = rRef;
  faces[FaceInput.R_INC] = rInc;
  return contactFromFaces(context, owner, refEdge, ref2, inc1, inc2);
}

/** The inputs of contactFromFaces, in A's frame (CollideContext.faces). */
enum FaceInput {
  NX = 0,
  NY = 1,
  V1X = 2,
  V1Y = 3,
  V2X = 4,
  V2Y = 5,
  W1X = 6,
  W1Y = 7,
  W2X = 8,
  W2Y = 9,
  SEPARATION = 10,
  R_REF = 11,
  R_INC = 12,
}

/**
 * Steps 3 and 4 above, once the faces are chosen (inputs in `faces`): reference edge `refEdge` from
 * v1 to v2 (the next vertex, `ref2`) with outward normal n, incident edge from vertex inc1 (w1) to
 * inc2 (w2), the reference face's SAT separation, both shapes' radii. Writes the points to `local`;
 * returns how many.
 */
function contactFromFaces(
  context: CollideContext,
  owner: number,
  refEdge: number,
  ref2: number,
  inc1: number,
  inc2: number,
): number {
  const faces = context.faces;
  const local = context.local;
  const localIds = context.localIds;
  const nx = faces[FaceInput.NX];
  const ny = faces[FaceInput.NY];
  const v1x = faces[FaceInput.V1X];
  const v1y = faces[FaceInput.V1Y];
  const v2x = faces[FaceInput.V2X];
  const v2y = faces[FaceInput.V2Y];
  const w1x = faces[FaceInput.W1X];
  const w1y = faces[FaceInput.W1Y];
  const w2x = faces[FaceInput.W2X];
  const w2y = faces[FaceInput.W2Y];
  const separation = faces[FaceInput.SEPARATION];
  const rRef = faces[FaceInput.R_REF];
  const rInc = faces[FaceInput.R_INC];
  const speculativeDistance = context.reach;
  local[LocalManifold.NX] = nx;
  local[LocalManifold.NY] = ny;
  if (separation > VERTEX_PAIR_MIN_GAP) {
    // cores apart: when the edges' true distance exceeds the face separation, two vertices are closest
    const segmentPair = context.segments;
    const closest = context.closest;
    segmentPair[0] = v1x;
    segmentPair[1] = v1y;
    segmentPair[2] = v2x;
    segmentPair[3] = v2y;
    segmentPair[4] = w1x;
    segmentPair[5] = w1y;
    segmentPair[6] = w2x;
    segmentPair[7] = w2y;
    closestBetweenSegments(segmentPair, closest);
    const gap = separation + VERTEX_PAIR_MIN_GAP;
    if (closest.distanceSq > gap * gap) {
      const distance = Math.sqrt(closest.distanceSq);
      const ux = (closest.qx - closest.px) / distance;
      const uy = (closest.qy - closest.py) / distance;
      if (!(distance - rRef - rInc < speculativeDistance)) return 0;
      const refVertex = closest.s < 0.5 ? refEdge : ref2;
      const incVertex = closest.t < 0.5 ? inc1 : inc2;
      // the points are written in place: doubles passed to a helper V8 does not inline are boxed
      local[LocalManifold.NX] = ux;
      local[LocalManifold.NY] = uy;
      local[LocalManifold.POINTS] = closest.qx;
      local[LocalManifold.POINTS + 1] = closest.qy;
      local[LocalManifold.POINTS + 2] = distance;
      localIds[0] = IdBit.VERTEX_PAIR | owner | (refVertex << 4) | incVertex;
      return 1;
    }
  }

  // clip the incident edge to the slab 0 <= (p - v1) . t <= length of the reference edge
  const tx = -ny;
  const ty = nx;
  const upper = (v2x - v1x) * tx + (v2y - v1y) * ty;
  const a1 = (w1x - v1x) * tx + (w1y - v1y) * ty;
  const a2 = (w2x - v1x) * tx + (w2y - v1y) * ty;
  const idBase = owner | (refEdge << 4);
  if ((a1 < 0 && a2 < 0) || (a1 > upper && a2 > upper)) {
    // the incident edge misses the slab (only in deep or degenerate overlaps): keep its deeper vertex
    const s1 = (w1x - v1x) * nx + (w1y - v1y) * ny;
    const s2 = (w2x - v1x) * nx + (w2y - v1y) * ny;
    const first = s1 <= s2;
    const s = first ? s1 : s2;
    if (!(s - rRef - rInc < speculativeDistance)) return 0;
    local[LocalManifold.POINTS] = first ? w1x : w2x;
    local[LocalManifold.POINTS + 1] = first ? w1y : w2y;
    local[LocalManifold.POINTS + 2] = s;
    localIds[0] = idBase | (first ? inc1 : inc2);
    return 1;
  }
  let count = 0;
  for (let k = 0; k < 2; k++) {
    const ak = k === 0 ? a1 : a2;
    let x = k === 0 ? w1x : w2x;
    let y = k === 0 ? w1y : w2y;
    const bound = ak < 0 ? 0 : Math.min(ak, upper);
    if (bound !== ak) {
      const w = (bound - a1) / (a2 - a1);
      x = w1x + w * (w2x - w1x);
      y = w1y + w * (w2y - w1y);
    }
    const s = (x - v1x) * nx + (y - v1y) * ny;
    if (s - rRef - rInc < speculativeDistance) {
      const at = LocalManifold.POINTS + 3 * count;
      local[at] = x;
      local[at + 1] = y;
      local[at + 2] = s;
      localIds[count] = idBase | (k === 0 ? inc1 : inc2);
      count++;
    }
  }
  return count;
}

/**
 * The edge of largest separation of a rectangle whose normals 0 and 1 put the other shape's centre at
 * d0 and d1 from its own, the two reaching reach0 and reach1 towards each other along them (edges 2
 * and 3 are the opposite sides), the first of equals as in maxSeparation; the separation goes to
 * `out[0]`.
 */
function bestRectangleEdge(
  d0: number,
  d1: number,
  reach0: number,
  reach1: number,
  out: Float64Array,
): number {
  let edge = 0;
  let best = d0 - reach0;
  if (d1 - reach1 > best) {
    edge = 1;
    best = d1 - reach1;
  }
  if (-d0 - reach0 > best) {
    edge = 2;
    best = -d0 - reach0;
  }
  if (-d1 - reach1 > best) {
    edge = 3;
    best = -d1 - reach1;
  }
  out[0] = best;
  return edge;
}

/**
 * collideLoaded for two packed rectangles (see packed.ts), read straight from their records with B
 * placed by `relative`. The SAT takes each rectangle's two axes: an edge's separation is the centres'
 * offset along its normal, less its own half extent and the other rectangle's extent along it, which
 * is the smallest vertex distance maxSeparation finds by trying every vertex. Faces, ids and points
 * then follow as there. Returns the point count (points in `local`).
 */
function collideRectangles(
  context: CollideContext,
  data: Float64Array,
  baseA: number,
  baseB: number,
): number {
  const relative = context.relative;
  const separationOut = context.separation;
  const speculativeDistance = context.reach;
  const rc = relative[0];
  const rs = relative[1];
  const rx = relative[2];
  const ry = relative[3];
  const radiusA = data[baseA + Pack.RADIUS];
  const radiusB = data[baseB + Pack.RADIUS];
  const limit = speculativeDistance + radiusA + radiusB;
  const vA = baseA + Pack.VERTICES;
  const vB = baseB + Pack.VERTICES;
  // normals 0 and 1 of each (2 and 3 are their exact opposites), B's turned into A's frame
  const n0x = data[vA + 2];
  const n0y = data[vA + 3];
  const n1x = data[vA + Pack.VERTEX_STRIDE + 2];
  const n1y = data[vA + Pack.VERTEX_STRIDE + 3];
  const p0x = data[vB + 2];
  const p0y = data[vB + 3];
  const p1x = data[vB + Pack.VERTEX_STRIDE + 2];
  const p1y = data[vB + Pack.VERTEX_STRIDE + 3];
  const m0x = rc * p0x - rs * p0y;
  const m0y = rs * p0x + rc * p0y;
  const m1x = rc * p1x - rs * p1y;
  const m1y = rs * p1x + rc * p1y;
  const bx = data[baseB + Pack.RECT_CX];
  const by = data[baseB + Pack.RECT_CY];
  const dx = rc * bx - rs * by + rx - data[baseA + Pack.RECT_CX];
  const dy = rs * bx + rc * by + ry - data[baseA + Pack.RECT_CY];
  const hA0 = data[baseA + Pack.RECT_H0];
  const hA1 = data[baseA + Pack.RECT_H1];
  const hB0 = data[baseB + Pack.RECT_H0];
  const hB1 = data[baseB + Pack.RECT_H1];
  const c00 = Math.abs(n0x * m0x + n0y * m0y);
  const c01 = Math.abs(n0x * m1x + n0y * m1y);
  const c10 = Math.abs(n1x * m0x + n1y * m0y);
  const c11 = Math.abs(n1x * m1x + n1y * m1y);

  // A's edges i and i + 2 lie on one axis, where B reaches the same extent either way
  const dA0 = n0x * dx + n0y * dy;
  const dA1 = n1x * dx + n1y * dy;
  const reachA0 = hA0 + hB0 * c00 + hB1 * c01;
  const reachA1 = hA1 + hB0 * c10 + hB1 * c11;
  const edgeA = bestRectangleEdge(dA0, dA1, reachA0, reachA1, separationOut);
  const separationA = separationOut[0];
  if (separationA >= limit) {
    context.separatingAxis = edgeA + 1;
    context.separatedDistance = separationA - radiusA - radiusB;
    return 0;
  }
  const dB0 = -(m0x * dx + m0y * dy);
  const dB1 = -(m1x * dx + m1y * dy);
  const reachB0 = hB0 + hA0 * c00 + hA1 * c10;
  const reachB1 = hB1 + hA0 * c01 + hA1 * c11;
  const edgeB = bestRectangleEdge(dB0, dB1, reachB0, reachB1, separationOut);
  const separationB = separationOut[0];
  if (separationB >= limit) {
    context.separatingAxis = Axis.B + edgeB + 1;
    context.separatedDistance = separationB - radiusA - radiusB;
    return 0;
  }

  const flip = referenceFromB(context.referenceHint, separationA, separationB);
  context.referenceFlip = flip;
  const refEdge = flip ? edgeB : edgeA;
  const ref2 = (refEdge + 1) & 3;
  const r1 = (flip ? vB : vA) + refEdge * Pack.VERTEX_STRIDE;
  const r2 = (flip ? vB : vA) + ref2 * Pack.VERTEX_STRIDE;
  let v1x = data[r1];
  let v1y = data[r1 + 1];
  let v2x = data[r2];
  let v2y = data[r2 + 1];
  let nx = data[r1 + 2];
  let ny = data[r1 + 3];
  // the incident rectangle's normals 0 and 1 in A's frame
  let i0x = m0x;
  let i0y = m0y;
  let i1x = m1x;
  let i1y = m1y;
  if (flip) {
    const ux = nx;
    const uy = ny;
    nx = rc * ux - rs * uy;
    ny = rs * ux + rc * uy;
    const x1 = v1x;
    const y1 = v1y;
    v1x = rc * x1 - rs * y1 + rx;
    v1y = rs * x1 + rc * y1 + ry;
    const x2 = v2x;
    const y2 = v2y;
    v2x = rc * x2 - rs * y2 + rx;
    v2y = rs * x2 + rc * y2 + ry;
    i0x = n0x;
    i0y = n0y;
    i1x = n1x;
    i1y = n1y;
  }
  // the incident edge: the normal most against n, the first of equals as in collideLoaded
  const dot0 = nx * i0x + ny * i0y;
  const dot1 = nx * i1x + ny * i1y;
  let inc1 = 0;
  let minDot = dot0;
  if (dot1 < minDot) {
    inc1 = 1;
    minDot = dot1;
  }
  if (-dot0 < minDot) {
    inc1 = 2;
    minDot = -dot0;
  }
  if (-dot1 < minDot) inc1 = 3;
  const inc2 = (inc1 + 1) & 3;
  const w1 = (flip ? vA : vB) + inc1 * Pack.VERTEX_STRIDE;
  const w2 = (flip ? vA : vB) + inc2 * Pack.VERTEX_STRIDE;
  let w1x = data[w1];
  let w1y = data[w1 + 1];
  let w2x = data[w2];
  let w2y = data[w2 + 1];
  if (!flip) {
    const x1 = w1x;
    const y1 = w1y;
    w1x = rc * x1 - rs * y1 + rx;
    w1y = rs * x1 + rc * y1 + ry;
    const x2 = w2x;
    const y2 = w2y;
    w2x = rc * x2 - rs * y2 + rx;
    w2y = rs * x2 + rc * y2 + ry;
  }
  const faces = context.faces;
  faces[FaceInput.NX] = nx;
  faces[FaceInput.NY] = ny;
  faces[FaceInput.V1X] = v1x;
  faces[FaceInput.V1Y] = v1y;
  faces[FaceInput.V2X] = v2x;
  faces[FaceInput.V2Y] = v2y;
  faces[FaceInput.W1X] = w1x;
  faces[FaceInput.W1Y] = w1y;
  faces[FaceInput.W2X] = w2x;
  faces[FaceInput.W2Y] = w2y;
  faces[FaceInput.SEPARATION] = flip ? separationB : separationA;
  faces[FaceInput.R_REF] = flip ? radiusB : radiusA;
  faces[FaceInput.R_INC] = flip ? radiusA : radiusB;
  return contactFromFaces(context, flip ? IdBit.B_REFERENCE : 0, refEdge, ref2, inc1, inc2);
}

/** Writes `count` points of `local` to the world manifold (points halfway between the surfaces). */
function writeManifold(
  context: CollideContext,
  xf: Transform,
  count: number,
  data: Float64Array,
  baseA: number,
  baseB: number,
  out: Manifold,
): void {
  out.pointCount = count;
  if (count === 0) return;
  const radiusA = data[baseA + Pack.RADIUS];
  const radiusB = data[baseB + Pack.RADIUS];
  const c = xf.q.c;
  const s = xf.q.s;
  const px = xf.p.x;
  const py = xf.p.y;
  const local = context.local;
  const nx = local[LocalManifold.NX];
  const ny = local[LocalManifold.NY];
  const flip = context.referenceFlip;
  const sign = flip ? -1 : 1;
  out.normalX = sign * (c * nx - s * ny);
  out.normalY = sign * (s * nx + c * ny);
  const rRef = flip ? radiusB : radiusA;
  const rInc = flip ? radiusA : radiusB;
  for (let i = 0; i < count; i++) {
    const k = LocalManifold.POINTS + 3 * i;
    const coreSeparation = local[k + 2];
    // halfway between the reference surface (x - (s - rRef) n) and the incident surface (x - rInc n)
    const shift = 0.5 * (rRef - rInc - coreSeparation);
    const mx = local[k] + shift * nx;
    const my = local[k + 1] + shift * ny;
    const point = out.points[i];
    point.x = c * mx - s * my + px;
    point.y = s * mx + c * my + py;
    point.separation = coreSeparation - rRef - rInc;
    point.id = context.localIds[i];
  }
}

/**
 * The manifold of two packed polygon-like shapes (polygons, capsules, segments; see packed.ts), both
 * records in `data`, A placed at `xfA` and B at `xfB`; hints in and results out through `context`.
 */
export function collidePackedPolygons(
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  const ac = xfA.q.c;
  const as = xfA.q.s;
  const ax = xfA.p.x;
  const ay = xfA.p.y;
  setRelative(context.relative, ac, as, ax, ay, xfB.q.c, xfB.q.s, xfB.p.x, xfB.p.y);
  let count: number;
  if (data[baseA + Pack.RECTANGLE] === 1 && data[baseB + Pack.RECTANGLE] === 1) {
    count = collideRectangles(context, data, baseA, baseB);
  } else {
    loadPolygonA(context.polyA, data, baseA);
    loadPolygonB(context.polyB, context.relative, data, baseB);
    count = collideLoaded(context);
  }
  writeManifold(context, xfA, count, data, baseA, baseB, out);
}
