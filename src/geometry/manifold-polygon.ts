import type { Transform } from '../math/vec2';
import { LINEAR_SLOP, REFERENCE_FACE_TOLERANCE } from './constants';
import { closestBetweenSegments, makeSegmentClosest } from './segment-distance';
import { type Capsule, MAX_POLYGON_VERTICES, type Manifold, type Polygon, type Segment } from './types';

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

/** Core polygon in A's frame: vertices, outward unit edge normals, radius. */
interface WorkPolygon {
  count: number;
  radius: number;
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly nx: Float64Array;
  readonly ny: Float64Array;
}

function makeWorkPolygon(): WorkPolygon {
  const n = MAX_POLYGON_VERTICES;
  return {
    count: 0,
    radius: 0,
    x: new Float64Array(n),
    y: new Float64Array(n),
    nx: new Float64Array(n),
    ny: new Float64Array(n),
  };
}

const polyA = makeWorkPolygon();
const polyB = makeWorkPolygon();
const closest = makeSegmentClosest();
const VERTEX_PAIR_BIT = 1 << 9;
const B_REFERENCE_BIT = 1 << 8;

/**
 * Which polygon owned the reference face of this pair's previous manifold (0 = A, 1 = B, -1 = none).
 * Faces under load are nearly parallel and their separations nearly equal; without memory the
 * reference face would swap between the two shapes as they tilt by a milliradian, renaming every
 * point and turning the normal, and a large pile would never come to rest. With memory the owner
 * only changes when the other face is clearly better.
 */
let referenceHint = -1;
const STICKY_REFERENCE_TOLERANCE = 0.5 * LINEAR_SLOP;

/** Sets the reference-face owner of the previous manifold for the next collide call (see above). */
export function setReferenceHint(ownerOfPreviousManifold: number): void {
  referenceHint = ownerOfPreviousManifold;
}

/** The owner bit of a polygon contact id: 1 when B owned the reference face. */
export function referenceOwnerOfId(id: number): number {
  return (id & B_REFERENCE_BIT) !== 0 ? 1 : 0;
}
const VERTEX_PAIR_MIN_GAP = 0.1 * LINEAR_SLOP;

/** Transform of the shape being loaded, relative to A: cos, sin, x, y (set by setIdentity / setRelative). */
const relative = new Float64Array(4);

function setIdentity(): void {
  relative[0] = 1;
  relative[1] = 0;
  relative[2] = 0;
  relative[3] = 0;
}

/** B's transform relative to A: q = qA^T qB, p = qA^T (pB - pA). */
function setRelative(xfA: Transform, xfB: Transform): void {
  const qa = xfA.q;
  const qb = xfB.q;
  relative[0] = qa.c * qb.c + qa.s * qb.s;
  relative[1] = qa.c * qb.s - qa.s * qb.c;
  const dx = xfB.p.x - xfA.p.x;
  const dy = xfB.p.y - xfA.p.y;
  relative[2] = qa.c * dx + qa.s * dy;
  relative[3] = -qa.s * dx + qa.c * dy;
}

function loadPolygon(g: Polygon, out: WorkPolygon): void {
  const relC = relative[0];
  const relS = relative[1];
  const relX = relative[2];
  const relY = relative[3];
  const v = g.vertices;
  const normals = g.normals;
  out.count = g.count;
  out.radius = g.radius;
  for (let i = 0; i < g.count; i++) {
    out.x[i] = relC * v[i].x - relS * v[i].y + relX;
    out.y[i] = relS * v[i].x + relC * v[i].y + relY;
    out.nx[i] = relC * normals[i].x - relS * normals[i].y;
    out.ny[i] = relS * normals[i].x + relC * normals[i].y;
  }
}

/** A segment as a 2-vertex polygon: edge 0 runs p1->p2, edge 1 back, with opposite normals. */
function loadSegment(
  p1x: number,
  p1y: number,
  p2x: number,
  p2y: number,
  radius: number,
  out: WorkPolygon,
): void {
  const relC = relative[0];
  const relS = relative[1];
  const relX = relative[2];
  const relY = relative[3];
  const x1 = relC * p1x - relS * p1y + relX;
  const y1 = relS * p1x + relC * p1y + relY;
  const x2 = relC * p2x - relS * p2y + relX;
  const y2 = relS * p2x + relC * p2y + relY;
  const ex = x2 - x1;
  const ey = y2 - y1;
  const length = Math.sqrt(ex * ex + ey * ey);
  out.count = 2;
  out.radius = radius;
  out.x[0] = x1;
  out.y[0] = y1;
  out.x[1] = x2;
  out.y[1] = y2;
  out.nx[0] = ey / length;
  out.ny[0] = -ex / length;
  out.nx[1] = -ey / length;
  out.ny[1] = ex / length;
}

let bestEdge = 0;

/** Largest over p's edges of the smallest signed distance of q's vertices to that edge; edge in bestEdge. */
function maxSeparation(p: WorkPolygon, q: WorkPolygon): number {
  let best = Number.NEGATIVE_INFINITY;
  bestEdge = 0;
  for (let i = 0; i < p.count; i++) {
    const nx = p.nx[i];
    const ny = p.ny[i];
    const vx = p.x[i];
    const vy = p.y[i];
    let min = Number.POSITIVE_INFINITY;
    for (let j = 0; j < q.count; j++) {
      const d = nx * (q.x[j] - vx) + ny * (q.y[j] - vy);
      if (d < min) min = d;
    }
    if (min > best) {
      best = min;
      bestEdge = i;
    }
  }
  return best;
}

/** Writes point `index` from a point on the incident core, given n (reference to incident, A's frame). */
function writePoint(
  xfA: Transform,
  out: Manifold,
  index: number,
  x: number,
  y: number,
  nx: number,
  ny: number,
  coreSeparation: number,
  referenceRadius: number,
  incidentRadius: number,
  id: number,
): void {
  // halfway between the reference surface (x - (s - rRef) n) and the incident surface (x - rInc n)
  const shift = 0.5 * (referenceRadius - incidentRadius - coreSeparation);
  const mx = x + shift * nx;
  const my = y + shift * ny;
  const { c, s } = xfA.q;
  const point = out.points[index];
  point.x = c * mx - s * my + xfA.p.x;
  point.y = s * mx + c * my + xfA.p.y;
  point.separation = coreSeparation - referenceRadius - incidentRadius;
  point.id = id;
}

function setNormal(xfA: Transform, nx: number, ny: number, flip: boolean, out: Manifold): void {
  const { c, s } = xfA.q;
  const sign = flip ? -1 : 1;
  out.normalX = sign * (c * nx - s * ny);
  out.normalY = sign * (s * nx + c * ny);
}

/** The manifold of the loaded polyA and polyB. */
function collideLoaded(xfA: Transform, speculativeDistance: number, out: Manifold): void {
  out.pointCount = 0;
  const limit = speculativeDistance + polyA.radius + polyB.radius;
  const separationA = maxSeparation(polyA, polyB);
  if (separationA >= limit) return;
  const edgeA = bestEdge;
  const separationB = maxSeparation(polyB, polyA);
  if (separationB >= limit) return;
  const edgeB = bestEdge;

  const flip =
    referenceHint === 1
      ? !(separationA > separationB + STICKY_REFERENCE_TOLERANCE)
      : referenceHint === 0
        ? separationB > separationA + STICKY_REFERENCE_TOLERANCE
        : separationB > separationA + REFERENCE_FACE_TOLERANCE;
  const ref = flip ? polyB : polyA;
  const inc = flip ? polyA : polyB;
  const refEdge = flip ? edgeB : edgeA;
  const separation = flip ? separationB : separationA;
  const owner = flip ? B_REFERENCE_BIT : 0;
  const nx = ref.nx[refEdge];
  const ny = ref.ny[refEdge];
  const ref2 = refEdge + 1 === ref.count ? 0 : refEdge + 1;
  const v1x = ref.x[refEdge];
  const v1y = ref.y[refEdge];
  const v2x = ref.x[ref2];
  const v2y = ref.y[ref2];

  let inc1 = 0;
  let minDot = Number.POSITIVE_INFINITY;
  for (let i = 0; i < inc.count; i++) {
    const d = nx * inc.nx[i] + ny * inc.ny[i];
    if (d < minDot) {
      minDot = d;
      inc1 = i;
    }
  }
  const inc2 = inc1 + 1 === inc.count ? 0 : inc1 + 1;
  const w1x = inc.x[inc1];
  const w1y = inc.y[inc1];
  const w2x = inc.x[inc2];
  const w2y = inc.y[inc2];

  if (separation > VERTEX_PAIR_MIN_GAP) {
    // cores apart: when the edges' true distance exceeds the face separation, two vertices are closest
    closestBetweenSegments(v1x, v1y, v2x, v2y, w1x, w1y, w2x, w2y, closest);
    const gap = separation + VERTEX_PAIR_MIN_GAP;
    if (closest.distanceSq > gap * gap) {
      const distance = Math.sqrt(closest.distanceSq);
      const ux = (closest.qx - closest.px) / distance;
      const uy = (closest.qy - closest.py) / distance;
      if (!(distance - ref.radius - inc.radius < speculativeDistance)) return;
      const refVertex = closest.s < 0.5 ? refEdge : ref2;
      const incVertex = closest.t < 0.5 ? inc1 : inc2;
      setNormal(xfA, ux, uy, flip, out);
      const id = VERTEX_PAIR_BIT | owner | (refVertex << 4) | incVertex;
      writePoint(xfA, out, 0, closest.qx, closest.qy, ux, uy, distance, ref.radius, inc.radius, id);
      out.pointCount = 1;
      return;
    }
  }

  // clip the incident edge to the slab 0 <= (p - v1) . t <= length of the reference edge
  const tx = -ny;
  const ty = nx;
  const upper = (v2x - v1x) * tx + (v2y - v1y) * ty;
  const a1 = (w1x - v1x) * tx + (w1y - v1y) * ty;
  const a2 = (w2x - v1x) * tx + (w2y - v1y) * ty;
  setNormal(xfA, nx, ny, flip, out);
  const idBase = owner | (refEdge << 4);
  if ((a1 < 0 && a2 < 0) || (a1 > upper && a2 > upper)) {
    // the incident edge misses the slab (only in deep or degenerate overlaps): keep its deeper vertex
    const s1 = (w1x - v1x) * nx + (w1y - v1y) * ny;
    const s2 = (w2x - v1x) * nx + (w2y - v1y) * ny;
    const first = s1 <= s2;
    const s = first ? s1 : s2;
    if (!(s - ref.radius - inc.radius < speculativeDistance)) return;
    const x = first ? w1x : w2x;
    const y = first ? w1y : w2y;
    writePoint(xfA, out, 0, x, y, nx, ny, s, ref.radius, inc.radius, idBase | (first ? inc1 : inc2));
    out.pointCount = 1;
    return;
  }
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
    if (s - ref.radius - inc.radius < speculativeDistance) {
      const id = idBase | (k === 0 ? inc1 : inc2);
      writePoint(xfA, out, out.pointCount, x, y, nx, ny, s, ref.radius, inc.radius, id);
      out.pointCount += 1;
    }
  }
}

export function collidePolygons(
  a: Polygon,
  xfA: Transform,
  b: Polygon,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  setIdentity();
  loadPolygon(a, polyA);
  setRelative(xfA, xfB);
  loadPolygon(b, polyB);
  collideLoaded(xfA, speculativeDistance, out);
}

export function collideCapsulePolygon(
  a: Capsule,
  xfA: Transform,
  b: Polygon,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  setIdentity();
  loadSegment(a.center1.x, a.center1.y, a.center2.x, a.center2.y, a.radius, polyA);
  setRelative(xfA, xfB);
  loadPolygon(b, polyB);
  collideLoaded(xfA, speculativeDistance, out);
}

export function collideSegmentPolygon(
  a: Segment,
  xfA: Transform,
  b: Polygon,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  setIdentity();
  loadSegment(a.point1.x, a.point1.y, a.point2.x, a.point2.y, 0, polyA);
  setRelative(xfA, xfB);
  loadPolygon(b, polyB);
  collideLoaded(xfA, speculativeDistance, out);
}
