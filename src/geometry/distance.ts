import type { Transform } from '../math/vec2';
import type { ShapeProxy } from './shape-proxy';
import {
  type GjkMemory,
  loadRelativeB,
  type RelativePoints,
  type Simplex,
  solveSimplex,
  support,
} from './simplex';

/** Result of `shapeDistance`; points are in world coordinates. */
export interface DistanceOutput {
  /** closest point on A */
  pointAX: number;
  pointAY: number;
  /** closest point on B */
  pointBX: number;
  pointBY: number;
  /** unit vector from A to B; (0, 0) when the core shapes touch or overlap */
  normalX: number;
  normalY: number;
  /** distance between the shapes, >= 0 (0 when they overlap) */
  distance: number;
  /** GJK iterations used */
  iterations: number;
}

export function makeDistanceOutput(): DistanceOutput {
  return {
    pointAX: 0,
    pointAY: 0,
    pointBX: 0,
    pointBY: 0,
    normalX: 0,
    normalY: 0,
    distance: 0,
    iterations: 0,
  };
}

/** More than enough for two 8-point hulls; hit only if rounding makes GJK cycle. */
const MAX_ITERATIONS = 30;
/** A search direction shorter than ~1e-15 means the origin is on the simplex (shapes touch). */
const EPSILON_SQ = 1e-30;

/**
 * Closest points between two convex shapes by GJK on their core point clouds.
 * With `useRadii` the result is for the rounded shapes: the points move out to the surfaces and the
 * distance drops by both radii. When the rounded shapes overlap, both points are the midpoint between
 * the two surfaces and the distance is 0. Allocation free: `memory` is its working memory.
 */
export function shapeDistance(
  memory: GjkMemory,
  proxyA: ShapeProxy,
  xfA: Transform,
  proxyB: ShapeProxy,
  xfB: Transform,
  useRadii: boolean,
  out: DistanceOutput,
): DistanceOutput {
  const s = memory.simplex;
  loadRelativeB(memory.relB, xfA, proxyB, xfB);
  out.iterations = runGjk(s, proxyA, memory.relB);

  // witness points and normal in the frame of A
  const v1 = s.v1;
  const v2 = s.v2;
  const v3 = s.v3;
  let pax: number;
  let pay: number;
  let pbx: number;
  let pby: number;
  let nx = 0;
  let ny = 0;
  if (s.count === 1) {
    pax = v1.ax;
    pay = v1.ay;
    pbx = v1.bx;
    pby = v1.by;
    const len = Math.sqrt(v1.wx * v1.wx + v1.wy * v1.wy);
    if (len > 0) {
      nx = v1.wx / len;
      ny = v1.wy / len;
    }
  } else if (s.count === 2) {
    pax = v1.a * v1.ax + v2.a * v2.ax;
    pay = v1.a * v1.ay + v2.a * v2.ay;
    pbx = v1.a * v1.bx + v2.a * v2.bx;
    pby = v1.a * v1.by + v2.a * v2.by;
    // the edge perpendicular is a more accurate direction than the difference of the witness points
    const ex = v2.wx - v1.wx;
    const ey = v2.wy - v1.wy;
    const side = ey * v1.wx - ex * v1.wy;
    const len = Math.sqrt(ex * ex + ey * ey);
    if (side > 0) {
      nx = ey / len;
      ny = -ex / len;
    } else if (side < 0) {
      nx = -ey / len;
      ny = ex / len;
    }
  } else {
    pax = v1.a * v1.ax + v2.a * v2.ax + v3.a * v3.ax;
    pay = v1.a * v1.ay + v2.a * v2.ay + v3.a * v3.ay;
    pbx = pax;
    pby = pay;
  }
  const dx = pbx - pax;
  const dy = pby - pay;
  let distance = s.count === 3 ? 0 : Math.sqrt(dx * dx + dy * dy);

  if (useRadii) {
    const rA = proxyA.radius;
    const rB = proxyB.radius;
    if (distance > rA + rB) {
      distance -= rA + rB;
      pax += rA * nx;
      pay += rA * ny;
      pbx -= rB * nx;
      pby -= rB * ny;
    } else {
      const mx = 0.5 * (pax + rA * nx + pbx - rB * nx);
      const my = 0.5 * (pay + rA * ny + pby - rB * ny);
      pax = mx;
      pay = my;
      pbx = mx;
      pby = my;
      distance = 0;
    }
  }

  const c = xfA.q.c;
  const sn = xfA.q.s;
  out.pointAX = c * pax - sn * pay + xfA.p.x;
  out.pointAY = sn * pax + c * pay + xfA.p.y;
  out.pointBX = c * pbx - sn * pby + xfA.p.x;
  out.pointBY = sn * pbx + c * pby + xfA.p.y;
  out.normalX = c * nx - sn * ny;
  out.normalY = sn * nx + c * ny;
  out.distance = distance;
  return out;
}

/**
 * GJK on the Minkowski difference B - A (A's points from the proxy, B's from `relB`), leaving the
 * simplex of the point closest to the origin in `s`. Returns the iteration count.
 */
function runGjk(s: Simplex, proxyA: ShapeProxy, relB: RelativePoints): number {
  const axs = proxyA.x;
  const ays = proxyA.y;
  const na = proxyA.count;
  const bxs = relB.x;
  const bys = relB.y;
  const nb = relB.count;

  const v0 = s.v1;
  v0.indexA = 0;
  v0.indexB = 0;
  v0.ax = axs[0];
  v0.ay = ays[0];
  v0.bx = bxs[0];
  v0.by = bys[0];
  v0.wx = v0.bx - v0.ax;
  v0.wy = v0.by - v0.ay;
  v0.a = 1;
  s.count = 1;

  let iter = 0;
  while (iter < MAX_ITERATIONS) {
    // remember the vertices before solving, to detect a support point that was already tried
    const saveCount = s.count;
    const sA1 = s.v1.indexA;
    const sB1 = s.v1.indexB;
    const sA2 = s.v2.indexA;
    const sB2 = s.v2.indexB;
    const sA3 = s.v3.indexA;
    const sB3 = s.v3.indexB;

    solveSimplex(s);
    if (s.count === 3) {
      break; // origin inside: the cores overlap
    }

    // search direction: from the simplex toward the origin
    let dx: number;
    let dy: number;
    if (s.count === 1) {
      dx = -s.v1.wx;
      dy = -s.v1.wy;
    } else {
      const ex = s.v2.wx - s.v1.wx;
      const ey = s.v2.wy - s.v1.wy;
      const side = ey * s.v1.wx - ex * s.v1.wy; // cross(e, -w1)
      if (side > 0) {
        dx = -ey;
        dy = ex;
      } else if (side < 0) {
        dx = ey;
        dy = -ex;
      } else {
        break; // origin on the segment: the cores touch
      }
    }
    if (dx * dx + dy * dy < EPSILON_SQ) {
      break;
    }

    const iA = support(axs, ays, na, -dx, -dy);
    const iB = support(bxs, bys, nb, dx, dy);
    iter++;

    if (
      (iA === sA1 && iB === sB1) ||
      (saveCount > 1 && iA === sA2 && iB === sB2) ||
      (saveCount > 2 && iA === sA3 && iB === sB3)
    ) {
      break; // no new vertex: converged
    }
    const wx = bxs[iB] - axs[iA];
    const wy = bys[iB] - ays[iA];
    if (wx * dx + wy * dy <= s.v1.wx * dx + s.v1.wy * dy) {
      break; // no progress toward the origin: the simplex already holds the closest point
    }

    const v = s.count === 1 ? s.v2 : s.v3;
    v.indexA = iA;
    v.indexB = iB;
    v.ax = axs[iA];
    v.ay = ays[iA];
    v.bx = bxs[iB];
    v.by = bys[iB];
    v.wx = wx;
    v.wy = wy;
    s.count++;
  }
  if (iter === MAX_ITERATIONS) {
    solveSimplex(s); // weigh the vertex added last (solving a solved simplex changes nothing)
  }
  return iter;
}
