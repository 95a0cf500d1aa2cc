import type { Bounds } from '../math/aabb';
import type { Transform } from '../math/vec2';
import { Pack, packGeometry } from './packed';
import type { Geometry } from './types';

/**
 * Tight world AABB of the packed shape at `base` (see packed.ts) placed at rotation (c, s) and
 * position (px, py): its vertices' box grown by its radius. Circles, capsules, segments and polygons
 * alike.
 * @internal
 */
export function packedBounds(data: Float64Array, base: number, xf: Transform, out: Bounds): void {
  const c = xf.q.c;
  const s = xf.q.s;
  const px = xf.p.x;
  const py = xf.p.y;
  let minX = Number.POSITIVE_INFINITY;
  let minY = Number.POSITIVE_INFINITY;
  let maxX = Number.NEGATIVE_INFINITY;
  let maxY = Number.NEGATIVE_INFINITY;
  const n = data[base + Pack.COUNT];
  for (let i = 0, k = base + Pack.VERTICES; i < n; i++, k += Pack.VERTEX_STRIDE) {
    const vx = data[k];
    const vy = data[k + 1];
    const x = c * vx - s * vy;
    const y = s * vx + c * vy;
    minX = Math.min(minX, x);
    minY = Math.min(minY, y);
    maxX = Math.max(maxX, x);
    maxY = Math.max(maxY, y);
  }
  const r = data[base + Pack.RADIUS];
  out.minX = minX + px - r;
  out.minY = minY + py - r;
  out.maxX = maxX + px + r;
  out.maxY = maxY + py + r;
}

/**
 * @internal Tight world AABB of `g` placed at `xf`, including its radius; `packed` (Pack.STRIDE
 * numbers) is the caller's scratch for the packed shape.
 */
export function computeShapeBounds(g: Geometry, xf: Transform, out: Bounds, packed: Float64Array): Bounds {
  packGeometry(g, packed, 0);
  packedBounds(packed, 0, xf, out);
  return out;
}
