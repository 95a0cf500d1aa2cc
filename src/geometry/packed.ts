import { CAPSULE, CIRCLE, type Geometry, MAX_POLYGON_VERTICES, POLYGON } from './types';

/*
 * Geometry packed into a flat record of doubles, for the narrow phase and bounds: the geometry objects
 * keep each coordinate in its own heap box, and chasing those pointers for every pair of a large pile
 * costs more than the collision test itself. Record layout:
 *   [count, radius, then per vertex i: x, y, nx, ny]
 * nx, ny is the outward unit normal of the edge from vertex i to vertex i + 1. A circle is one vertex
 * (its centre, no normal); a capsule or segment is a 2-vertex polygon whose edge 0 runs p1 -> p2 and
 * edge 1 back, so polygon routines handle it unchanged.
 */
export const PACK_COUNT = 0;
export const PACK_RADIUS = 1;
export const PACK_VERTICES = 2;
export const PACK_VERTEX_STRIDE = 4;
export const PACK_STRIDE = PACK_VERTICES + PACK_VERTEX_STRIDE * MAX_POLYGON_VERTICES;

function packVertex(
  out: Float64Array,
  base: number,
  i: number,
  x: number,
  y: number,
  nx: number,
  ny: number,
) {
  const k = base + PACK_VERTICES + PACK_VERTEX_STRIDE * i;
  out[k] = x;
  out[k + 1] = y;
  out[k + 2] = nx;
  out[k + 3] = ny;
}

/** Writes the packed record of `g` to `out` at `base` (PACK_STRIDE doubles). */
export function packGeometry(g: Geometry, out: Float64Array, base: number): void {
  if (g.kind === CIRCLE) {
    out[base + PACK_COUNT] = 1;
    out[base + PACK_RADIUS] = g.radius;
    packVertex(out, base, 0, g.center.x, g.center.y, 0, 0);
    return;
  }
  if (g.kind === POLYGON) {
    out[base + PACK_COUNT] = g.count;
    out[base + PACK_RADIUS] = g.radius;
    for (let i = 0; i < g.count; i++) {
      packVertex(out, base, i, g.vertices[i].x, g.vertices[i].y, g.normals[i].x, g.normals[i].y);
    }
    return;
  }
  const p1 = g.kind === CAPSULE ? g.center1 : g.point1;
  const p2 = g.kind === CAPSULE ? g.center2 : g.point2;
  const ex = p2.x - p1.x;
  const ey = p2.y - p1.y;
  const length = Math.sqrt(ex * ex + ey * ey);
  out[base + PACK_COUNT] = 2;
  out[base + PACK_RADIUS] = g.kind === CAPSULE ? g.radius : 0;
  packVertex(out, base, 0, p1.x, p1.y, ey / length, -ex / length);
  packVertex(out, base, 1, p2.x, p2.y, -ey / length, ex / length);
}
