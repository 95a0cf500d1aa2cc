import type { Geometry } from './types';

function sq(x: number): number {
  return x * x;
}

/**
 * Largest distance from (cx, cy) to any point of the shape: with the angular speed it bounds how fast
 * a point of the body can move (sleep test).
 */
export function maxExtentFrom(g: Geometry, cx: number, cy: number): number {
  switch (g.type) {
    case 'circle':
      return Math.sqrt(sq(g.center.x - cx) + sq(g.center.y - cy)) + g.radius;
    case 'capsule':
      return (
        Math.max(
          Math.sqrt(sq(g.center1.x - cx) + sq(g.center1.y - cy)),
          Math.sqrt(sq(g.center2.x - cx) + sq(g.center2.y - cy)),
        ) + g.radius
      );
    case 'segment':
      return Math.max(
        Math.sqrt(sq(g.point1.x - cx) + sq(g.point1.y - cy)),
        Math.sqrt(sq(g.point2.x - cx) + sq(g.point2.y - cy)),
      );
    case 'polygon': {
      let m = 0;
      for (let i = 0; i < g.count; i++) {
        const v = g.vertices[i];
        m = Math.max(m, sq(v.x - cx) + sq(v.y - cy));
      }
      return Math.sqrt(m) + g.radius;
    }
  }
}

/**
 * Smallest half-thickness of the shape: a body moving less than this per step cannot pass through
 * anything, so it needs no continuous collision.
 */
export function minExtent(g: Geometry): number {
  switch (g.type) {
    case 'circle':
    case 'capsule':
      return g.radius;
    case 'segment':
      return 0;
    case 'polygon': {
      let m = Number.POSITIVE_INFINITY;
      for (let i = 0; i < g.count; i++) {
        const v = g.vertices[i];
        const n = g.normals[i];
        m = Math.min(m, (v.x - g.centroid.x) * n.x + (v.y - g.centroid.y) * n.y);
      }
      return m + g.radius;
    }
  }
}

/**
 * Largest distance from the shape's own centroid to any point of it (a circle's radius, a capsule's
 * half length plus radius): its size, which the contact limit compares (see world/contact-limit.ts).
 */
export function centroidExtent(g: Geometry): number {
  switch (g.type) {
    case 'circle':
      return g.radius;
    case 'capsule':
      return maxExtentFrom(g, 0.5 * (g.center1.x + g.center2.x), 0.5 * (g.center1.y + g.center2.y));
    case 'segment':
      return maxExtentFrom(g, 0.5 * (g.point1.x + g.point2.x), 0.5 * (g.point1.y + g.point2.y));
    case 'polygon':
      return maxExtentFrom(g, g.centroid.x, g.centroid.y);
  }
}
