import type { Bounds } from '../math/aabb';
import type { Transform } from '../math/vec2';
import { CAPSULE, CIRCLE, type Geometry, POLYGON } from './types';

/** Tight world AABB of `g` placed at `xf`, including its radius. */
export function computeShapeBounds(g: Geometry, xf: Transform, out: Bounds): Bounds {
  const { c, s } = xf.q;
  const px = xf.p.x;
  const py = xf.p.y;
  if (g.kind === CIRCLE) {
    const x = c * g.center.x - s * g.center.y + px;
    const y = s * g.center.x + c * g.center.y + py;
    out.minX = x - g.radius;
    out.minY = y - g.radius;
    out.maxX = x + g.radius;
    out.maxY = y + g.radius;
    return out;
  }
  if (g.kind === POLYGON) {
    const v = g.vertices;
    let minX = Number.POSITIVE_INFINITY;
    let minY = Number.POSITIVE_INFINITY;
    let maxX = Number.NEGATIVE_INFINITY;
    let maxY = Number.NEGATIVE_INFINITY;
    for (let i = 0; i < g.count; i++) {
      const x = c * v[i].x - s * v[i].y;
      const y = s * v[i].x + c * v[i].y;
      minX = Math.min(minX, x);
      minY = Math.min(minY, y);
      maxX = Math.max(maxX, x);
      maxY = Math.max(maxY, y);
    }
    out.minX = minX + px - g.radius;
    out.minY = minY + py - g.radius;
    out.maxX = maxX + px + g.radius;
    out.maxY = maxY + py + g.radius;
    return out;
  }
  const a = g.kind === CAPSULE ? g.center1 : g.point1;
  const b = g.kind === CAPSULE ? g.center2 : g.point2;
  const r = g.kind === CAPSULE ? g.radius : 0;
  const ax = c * a.x - s * a.y + px;
  const ay = s * a.x + c * a.y + py;
  const bx = c * b.x - s * b.y + px;
  const by = s * b.x + c * b.y + py;
  out.minX = Math.min(ax, bx) - r;
  out.minY = Math.min(ay, by) - r;
  out.maxX = Math.max(ax, bx) + r;
  out.maxY = Math.max(ay, by) + r;
  return out;
}
