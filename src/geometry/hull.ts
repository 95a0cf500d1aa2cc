import { fail } from '../core/errors';
import type { Vec2 } from '../math/vec2';
import { LINEAR_SLOP } from './constants';
import { MAX_POLYGON_VERTICES } from './types';

const WELD_DISTANCE_SQ = LINEAR_SLOP * LINEAR_SLOP;

/** Drops points closer than LINEAR_SLOP to a point kept before them. */
function weld(points: readonly Vec2[]): Vec2[] {
  const kept: Vec2[] = [];
  for (const p of points) {
    let duplicate = false;
    for (const q of kept) {
      const dx = p.x - q.x;
      const dy = p.y - q.y;
      if (dx * dx + dy * dy < WELD_DISTANCE_SQ) {
        duplicate = true;
        break;
      }
    }
    if (!duplicate) kept.push({ x: p.x, y: p.y });
  }
  return kept;
}

/** Gift wrapping: from the leftmost point, repeatedly take the point with every other point on its left. */
function wrap(points: readonly Vec2[]): Vec2[] | null {
  const n = points.length;
  let start = 0;
  for (let i = 1; i < n; i++) {
    const p = points[i];
    const s = points[start];
    if (p.x < s.x || (p.x === s.x && p.y < s.y)) start = i;
  }
  const hull: Vec2[] = [];
  let current = start;
  do {
    // rounding on nearly collinear points could in theory cycle; a hull never has more than n vertices
    if (hull.length === n) return null;
    const c = points[current];
    hull.push(c);
    let next = current === 0 ? 1 : 0;
    for (let j = 0; j < n; j++) {
      if (j === current || j === next) continue;
      const ex = points[next].x - c.x;
      const ey = points[next].y - c.y;
      const jx = points[j].x - c.x;
      const jy = points[j].y - c.y;
      const side = ex * jy - ey * jx;
      // j right of current->next, or collinear and farther: j replaces next (collinear middles are skipped)
      if (side < 0 || (side === 0 && jx * jx + jy * jy > ex * ex + ey * ey)) next = j;
    }
    current = next;
  } while (current !== start);
  return hull;
}

/** Removes vertices that are not convex by at least LINEAR_SLOP (collinear or slightly reflex). */
function removeFlatVertices(hull: Vec2[]): void {
  let removed = true;
  while (removed && hull.length >= 3) {
    removed = false;
    for (let i = 0; i < hull.length; i++) {
      const prev = hull[i === 0 ? hull.length - 1 : i - 1];
      const next = hull[i === hull.length - 1 ? 0 : i + 1];
      const p = hull[i];
      const ex = next.x - prev.x;
      const ey = next.y - prev.y;
      // distance of p to the right of prev->next (the outside of a counter-clockwise polygon)
      const distance = (ey * (p.x - prev.x) - ex * (p.y - prev.y)) / Math.sqrt(ex * ex + ey * ey);
      if (distance <= LINEAR_SLOP) {
        hull.splice(i, 1);
        removed = true;
        break;
      }
    }
  }
}

/**
 * Throws a FulcrumError naming the first point that lies deeper than LINEAR_SLOP inside the hull: the
 * points are then not a convex outline, and their hull would be a larger shape than the one drawn
 * (an L of area 1.75 would weigh as its hull of area 2.875). Points the hull drops for being repeated
 * or collinear lie within LINEAR_SLOP of its edges and pass.
 */
function checkOnHull(points: readonly Vec2[], hull: readonly Vec2[], argument: string): void {
  for (let i = 0; i < points.length; i++) {
    const p = points[i];
    // inside a convex polygon, the distance to its boundary is the least distance to an edge's line
    let depth = Number.POSITIVE_INFINITY;
    for (let k = 0; k < hull.length; k++) {
      const a = hull[k];
      const b = hull[k + 1 === hull.length ? 0 : k + 1];
      const ex = b.x - a.x;
      const ey = b.y - a.y;
      depth = Math.min(depth, (ex * (p.y - a.y) - ey * (p.x - a.x)) / Math.sqrt(ex * ex + ey * ey));
    }
    if (depth > LINEAR_SLOP) {
      fail(
        `${argument}[${i}]`,
        p,
        `on the convex hull of ${argument} (it lies ${depth} m inside: the outline is concave, and ` +
          `Shape.concave(${argument}) splits a concave outline into convex pieces)`,
      );
    }
  }
}

/**
 * Convex hull of finite points, counter-clockwise, with points closer than LINEAR_SLOP welded and
 * collinear points removed. Throws FulcrumError naming `argument` when the hull is degenerate.
 */
export function convexHull(points: readonly Vec2[], argument: string): Vec2[] {
  const welded = weld(points);
  if (welded.length < 3) {
    fail(argument, points, `at least 3 points more than ${LINEAR_SLOP} m apart`);
  }
  const hull = wrap(welded);
  if (hull !== null) removeFlatVertices(hull);
  if (hull === null || hull.length < 3) {
    fail(argument, points, `points that are not all collinear (within ${LINEAR_SLOP} m)`);
  }
  return hull;
}

/**
 * The vertices of a convex polygon through `points`: their convex hull (see convexHull). Throws
 * FulcrumError naming `argument` when the hull is degenerate, when a point lies inside it (a concave
 * outline) or when it has more than MAX_POLYGON_VERTICES vertices.
 */
export function computeHull(points: readonly Vec2[], argument: string): Vec2[] {
  const hull = convexHull(points, argument);
  checkOnHull(points, hull, argument);
  if (hull.length > MAX_POLYGON_VERTICES) {
    fail(
      argument,
      points,
      `points whose convex hull has at most ${MAX_POLYGON_VERTICES} vertices (it has ${hull.length}; ` +
        `Shape.concave(${argument}) splits a longer outline into pieces)`,
    );
  }
  return hull;
}
