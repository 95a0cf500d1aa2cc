import type { Transform, Vec2 } from '../math/vec2';
import { type Geometry, ShapeKind } from './types';

/*
 * Geometry packed into a flat record of doubles, for the narrow phase and bounds: the geometry objects
 * keep each coordinate in its own heap box, and chasing those pointers for every pair of a large pile
 * costs more than the collision test itself. Record layout:
 *   [count, radius, rectangle flag, then per vertex i: x, y, nx, ny]
 * nx, ny is the outward unit normal of the edge from vertex i to vertex i + 1. A circle is one vertex
 * (its centre, no normal); a capsule or segment is a 2-vertex polygon whose edge 0 runs p1 -> p2 and
 * edge 1 back, so polygon routines handle it unchanged. A rectangle (4 vertices, opposite normals
 * opposite, neighbouring normals perpendicular: every box) has the flag set to 1 and, after
 * its vertices, its centre and its half extents along normals 0 and 1, so that the separating axis
 * test of two rectangles takes two axes each instead of every vertex against every edge. A segment
 * then has its sidedness and, if one-sided, its chain neighbours' bounds (see ONE_SIDED).
 */
export enum Pack {
  COUNT = 0,
  RADIUS = 1,
  RECTANGLE = 2,
  VERTICES = 3,
  VERTEX_STRIDE = 4,
  /** VERTICES + VERTEX_STRIDE * MAX_POLYGON_VERTICES, as a number: an enum member must be a constant */
  STRIDE = VERTICES + VERTEX_STRIDE * 8,
  /** A rectangle's centre and its half extents along its normals 0 and 1, from the record's base. */
  RECT_CX = VERTICES + 4 * VERTEX_STRIDE,
  RECT_CY = RECT_CX + 1,
  RECT_H0 = RECT_CX + 2,
  RECT_H1 = RECT_CX + 3,
  /**
   * A segment's sidedness, from the record's base: 1 for a chain's one-sided segment, 0 for a
   * two-sided one. Then, for a one-sided segment, the normals that bound the directions a contact
   * normal may take (from the segment to the other shape) at its first and at its second end: the
   * neighbour's normal where the chain bends away from the front there (a convex corner), the
   * segment's own normal where it is flat or bends toward the front (the neighbour's face owns those
   * contacts), and the segment's direction, backward or forward, at an open end (a free corner).
   */
  ONE_SIDED = VERTICES + 2 * VERTEX_STRIDE,
  LIMIT1_X = ONE_SIDED + 1,
  LIMIT1_Y = ONE_SIDED + 2,
  LIMIT2_X = ONE_SIDED + 3,
  LIMIT2_Y = ONE_SIDED + 4,
}
/**
 * How far a 4-gon's unit normals may be from exactly opposite and perpendicular for it to count as a
 * rectangle: a turned box's normals are off by rounding, and the rectangle routine's result then
 * differs from the every-vertex one by about as much.
 */
const RECTANGLE_TOLERANCE = 1e-12;

/**
 * How far a chain's neighbour normal must lean (the sine of the bend) for the corner to count as
 * convex: a straight run of segments, turned, bends by rounding only.
 */
const CORNER_TOLERANCE = 1e-9;

function packVertex(
  out: Float64Array,
  base: number,
  i: number,
  x: number,
  y: number,
  nx: number,
  ny: number,
) {
  const k = base + Pack.VERTICES + Pack.VERTEX_STRIDE * i;
  out[k] = x;
  out[k + 1] = y;
  out[k + 2] = nx;
  out[k + 3] = ny;
}

function isRectangle(count: number, n: readonly Vec2[]): boolean {
  const tolerance = RECTANGLE_TOLERANCE;
  return (
    count === 4 &&
    Math.abs(n[2].x + n[0].x) < tolerance &&
    Math.abs(n[2].y + n[0].y) < tolerance &&
    Math.abs(n[3].x + n[1].x) < tolerance &&
    Math.abs(n[3].y + n[1].y) < tolerance &&
    Math.abs(n[0].x * n[1].x + n[0].y * n[1].y) < tolerance
  );
}

/** Writes the packed record of `g` to `out` at `base` (Pack.STRIDE doubles). */
export function packGeometry(g: Geometry, out: Float64Array, base: number): void {
  out[base + Pack.RECTANGLE] = 0;
  if (g.kind === ShapeKind.CIRCLE) {
    out[base + Pack.COUNT] = 1;
    out[base + Pack.RADIUS] = g.radius;
    packVertex(out, base, 0, g.center.x, g.center.y, 0, 0);
    return;
  }
  if (g.kind === ShapeKind.POLYGON) {
    out[base + Pack.COUNT] = g.count;
    out[base + Pack.RADIUS] = g.radius;
    for (let i = 0; i < g.count; i++) {
      packVertex(out, base, i, g.vertices[i].x, g.vertices[i].y, g.normals[i].x, g.normals[i].y);
    }
    if (isRectangle(g.count, g.normals)) {
      const v = g.vertices;
      const n = g.normals;
      const cx = 0.5 * (v[0].x + v[2].x);
      const cy = 0.5 * (v[0].y + v[2].y);
      out[base + Pack.RECTANGLE] = 1;
      out[base + Pack.RECT_CX] = cx;
      out[base + Pack.RECT_CY] = cy;
      out[base + Pack.RECT_H0] = n[0].x * (v[0].x - cx) + n[0].y * (v[0].y - cy);
      out[base + Pack.RECT_H1] = n[1].x * (v[1].x - cx) + n[1].y * (v[1].y - cy);
    }
    return;
  }
  const p1 = g.kind === ShapeKind.CAPSULE ? g.center1 : g.point1;
  const p2 = g.kind === ShapeKind.CAPSULE ? g.center2 : g.point2;
  const ex = p2.x - p1.x;
  const ey = p2.y - p1.y;
  const length = Math.sqrt(ex * ex + ey * ey);
  out[base + Pack.COUNT] = 2;
  out[base + Pack.RADIUS] = g.kind === ShapeKind.CAPSULE ? g.radius : 0;
  const nx = ey / length;
  const ny = -ex / length;
  packVertex(out, base, 0, p1.x, p1.y, nx, ny);
  packVertex(out, base, 1, p2.x, p2.y, -nx, -ny);
  if (g.kind === ShapeKind.CAPSULE) return;
  out[base + Pack.ONE_SIDED] = g.oneSided ? 1 : 0;
  if (!g.oneSided) return;
  const tx = ex / length;
  const ty = ey / length;
  // at the first end: the previous segment's normal if the corner is convex (that normal leans back,
  // against the direction t), else this one's; -t at an open end
  let limitX = -tx;
  let limitY = -ty;
  if (g.ghost1 !== null) {
    const dx = p1.x - g.ghost1.x;
    const dy = p1.y - g.ghost1.y;
    const d = Math.sqrt(dx * dx + dy * dy);
    const convex = (dy * tx - dx * ty) / d < -CORNER_TOLERANCE;
    limitX = convex ? dy / d : nx;
    limitY = convex ? -dx / d : ny;
  }
  out[base + Pack.LIMIT1_X] = limitX;
  out[base + Pack.LIMIT1_Y] = limitY;
  limitX = tx;
  limitY = ty;
  if (g.ghost2 !== null) {
    const dx = g.ghost2.x - p2.x;
    const dy = g.ghost2.y - p2.y;
    const d = Math.sqrt(dx * dx + dy * dy);
    const convex = (dy * tx - dx * ty) / d > CORNER_TOLERANCE;
    limitX = convex ? dy / d : nx;
    limitY = convex ? -dx / d : ny;
  }
  out[base + Pack.LIMIT2_X] = limitX;
  out[base + Pack.LIMIT2_Y] = limitY;
}

/**
 * Distance of the point (x, y), in the body's frame, in front of the one-sided segment packed at
 * `base`: negative behind its line.
 */
export function frontOffset(data: Float64Array, base: number, x: number, y: number): number {
  const k = base + Pack.VERTICES;
  return (x - data[k]) * data[k + 2] + (y - data[k + 1]) * data[k + 3];
}

/** Whether the shape packed at `base` is a chain's one-sided segment. */
export function isOneSided(kind: number, data: Float64Array, base: number): boolean {
  return kind === ShapeKind.SEGMENT && data[base + Pack.ONE_SIDED] === 1;
}

/**
 * Distance of the world point (x, y) in front of the one-sided segment packed at `base` of a body
 * placed at `xf`: negative behind its line (a shape whose centre is there passes through it).
 */
export function frontOffsetAt(data: Float64Array, base: number, xf: Transform, x: number, y: number): number {
  const dx = x - xf.p.x;
  const dy = y - xf.p.y;
  return frontOffset(data, base, xf.q.c * dx + xf.q.s * dy, xf.q.c * dy - xf.q.s * dx);
}
