import { makeTransform, type Transform } from '../math/vec2';
import { makeShapeProxy, type ShapeProxy } from './shape-proxy';
import {
  type GjkMemory,
  loadRelativeB,
  type Simplex,
  type SimplexVertex,
  solveSimplex,
  support,
  vertexAt,
} from './simplex';

/** Shape B, placed by transformB, moves by the world translation against shape A (placed by transformA). */
export interface ShapeCastInput {
  proxyA: ShapeProxy;
  transformA: Transform;
  proxyB: ShapeProxy;
  transformB: Transform;
  translationX: number;
  translationY: number;
  /** the cast stops at this fraction of the translation, in [0, 1] */
  maxFraction: number;
}

export interface ShapeCastOutput {
  hit: boolean;
  /** fraction of the translation at which the surfaces first touch */
  fraction: number;
  /** world contact point, on the surface of A */
  pointX: number;
  pointY: number;
  /** world unit normal of A's surface at the contact (from A toward B); (0, 0) on an initial overlap */
  normalX: number;
  normalY: number;
  iterations: number;
}

export function makeShapeCastInput(): ShapeCastInput {
  return {
    proxyA: makeShapeProxy(),
    transformA: makeTransform(),
    proxyB: makeShapeProxy(),
    transformB: makeTransform(),
    translationX: 0,
    translationY: 0,
    maxFraction: 1,
  };
}

export function makeShapeCastOutput(): ShapeCastOutput {
  return { hit: false, fraction: 0, pointX: 0, pointY: 0, normalX: 0, normalY: 0, iterations: 0 };
}

const MAX_ITERATIONS = 32;
/** contact is accepted within this distance, times (1 + radii + translation length) */
const TOLERANCE = 1e-10;

/**
 * Linear cast of B against A: the GJK ray cast of van den Bergen (2004). B moved by lambda * r
 * touches A when lambda * r lies in the Minkowski difference C = A - B inflated by both radii.
 * The ray point x = lambda * r only moves forward, each time up to a plane that supports the
 * inflated C, so the fraction is approached from below and is exact for flat faces.
 *
 * Rule for shapes that already overlap or touch at the start: hit, fraction 0, normal (0, 0), point
 * halfway between the closest core points. Allocation free: `memory` is its working memory.
 */
export function shapeCast(memory: GjkMemory, input: ShapeCastInput, out: ShapeCastOutput): ShapeCastOutput {
  const proxyA = input.proxyA;
  const xfA = input.transformA;
  const relB = memory.relB;
  loadRelativeB(relB, xfA, input.proxyB, input.transformB);
  const axs = proxyA.x;
  const ays = proxyA.y;
  const na = proxyA.count;
  const bxs = relB.x;
  const bys = relB.y;
  const nb = relB.count;

  // translation in A's frame
  const qc = xfA.q.c;
  const qs = xfA.q.s;
  const rx = qc * input.translationX + qs * input.translationY;
  const ry = -qs * input.translationX + qc * input.translationY;
  const radius = proxyA.radius + input.proxyB.radius;
  const tolerance = TOLERANCE * (1 + radius + Math.sqrt(rx * rx + ry * ry));
  const maxFraction = input.maxFraction;

  const s = memory.simplex;
  setVertex(s.v1, axs, ays, support(axs, ays, na, -rx, -ry), bxs, bys, support(bxs, bys, nb, rx, ry));
  s.count = 1;

  let lambda = 0;
  let nx = 0;
  let ny = 0;
  // last direction from C toward x and its length
  let ux = 0;
  let uy = 0;
  let dist = 0;
  let iter = 0;
  for (;;) {
    // simplex points relative to the ray point x
    const xx = lambda * rx;
    const xy = lambda * ry;
    for (let i = 0; i < s.count; i++) {
      const v = vertexAt(s, i);
      v.wx = v.ax - v.bx - xx;
      v.wy = v.ay - v.by - xy;
    }
    solveSimplex(s);
    if (s.count === 3) {
      break; // x is inside the core of C
    }
    // u points from the closest point of C toward x
    ux = -s.v1.a * s.v1.wx;
    uy = -s.v1.a * s.v1.wy;
    if (s.count === 2) {
      ux -= s.v2.a * s.v2.wx;
      uy -= s.v2.a * s.v2.wy;
    }
    dist = Math.sqrt(ux * ux + uy * uy);
    if (dist - radius <= tolerance || iter === MAX_ITERATIONS) {
      break;
    }

    const iA = support(axs, ays, na, ux, uy);
    const iB = support(bxs, bys, nb, -ux, -uy);
    const px = axs[iA] - bxs[iB];
    const py = ays[iA] - bys[iB];
    const known = hasVertex(s, iA, iB);
    // how far x is in front of the supporting plane of the inflated C, times |u|
    const gap = ux * (xx - px) + uy * (xy - py) - radius * dist;
    if (gap > 0) {
      const ur = ux * rx + uy * ry;
      if (ur >= 0) {
        return miss(out, maxFraction, iter);
      }
      lambda -= gap / ur;
      if (lambda > maxFraction) {
        return miss(out, maxFraction, iter);
      }
      nx = ux;
      ny = uy;
    } else if (known) {
      break; // no advance and no new point: converged to rounding
    }
    if (!known) {
      setVertex(vertexAt(s, s.count), axs, ays, iA, bxs, bys, iB);
      s.count++;
    }
    iter++;
  }

  // closest point on the core of A
  let pax = 0;
  let pay = 0;
  let pbx = 0;
  let pby = 0;
  for (let i = 0; i < s.count; i++) {
    const v = vertexAt(s, i);
    pax += v.a * v.ax;
    pay += v.a * v.ay;
    pbx += v.a * v.bx;
    pby += v.a * v.by;
  }
  let lx: number;
  let ly: number;
  if (lambda === 0) {
    lx = 0.5 * (pax + pbx);
    ly = 0.5 * (pay + pby);
    nx = 0;
    ny = 0;
  } else {
    if (s.count < 3 && dist > 0.5 * radius && dist > tolerance) {
      // rounded contact: the final direction is exact, the last plane's normal lags one step behind
      nx = ux;
      ny = uy;
    }
    const len = Math.sqrt(nx * nx + ny * ny);
    nx /= len;
    ny /= len;
    lx = pax + proxyA.radius * nx;
    ly = pay + proxyA.radius * ny;
  }
  out.hit = true;
  out.fraction = lambda;
  out.pointX = qc * lx - qs * ly + xfA.p.x;
  out.pointY = qs * lx + qc * ly + xfA.p.y;
  out.normalX = qc * nx - qs * ny;
  out.normalY = qs * nx + qc * ny;
  out.iterations = iter;
  return out;
}

function setVertex(
  v: SimplexVertex,
  axs: Float64Array,
  ays: Float64Array,
  iA: number,
  bxs: Float64Array,
  bys: Float64Array,
  iB: number,
): void {
  v.indexA = iA;
  v.indexB = iB;
  v.ax = axs[iA];
  v.ay = ays[iA];
  v.bx = bxs[iB];
  v.by = bys[iB];
}

function hasVertex(s: Simplex, iA: number, iB: number): boolean {
  for (let i = 0; i < s.count; i++) {
    const v = vertexAt(s, i);
    if (v.indexA === iA && v.indexB === iB) {
      return true;
    }
  }
  return false;
}

/** A miss reports the whole allowed motion as free: fraction = maxFraction. */
function miss(out: ShapeCastOutput, maxFraction: number, iter: number): ShapeCastOutput {
  out.hit = false;
  out.fraction = maxFraction;
  out.pointX = 0;
  out.pointY = 0;
  out.normalX = 0;
  out.normalY = 0;
  out.iterations = iter;
  return out;
}
