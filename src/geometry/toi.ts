import { makeTransform, type Transform } from '../math/vec2';
import { makeDistanceOutput, shapeDistance } from './distance';
import type { ShapeProxy } from './shape-proxy';
import { GjkMemory } from './simplex';
import { getSweepTransform, type Sweep, sweepAngularBound } from './sweep';
import { MAX_POLYGON_VERTICES } from './types';

export interface TOIInput {
  proxyA: ShapeProxy;
  sweepA: Sweep;
  proxyB: ShapeProxy;
  sweepB: Sweep;
  /** search [0, maxFraction] of the sweeps */
  maxFraction: number;
}

export type TOIState = 'hit' | 'separated' | 'overlapped' | 'failed';

export interface TOIOutput {
  state: TOIState;
  fraction: number;
  iterations: number;
}

export function makeTOIOutput(): TOIOutput {
  return { state: 'separated', fraction: 0, iterations: 0 };
}

/** In metres; pass the world's slop (scaled by lengthUnitsPerMeter) as `linearSlop`. */
const DEFAULT_LINEAR_SLOP = 0.005;
/** Each iteration costs one GJK call; grazing passes of fast spinning bodies take the most. */
const MAX_ITERATIONS = 50;

/**
 * The working memory of timeOfImpact: written before it is read, so one instance serves any number
 * of calls made one after the other. Its owner passes it in (a world keeps its own).
 */
export class TOIMemory {
  readonly gjk = new GjkMemory();
  readonly xfA = makeTransform();
  readonly xfB = makeTransform();
  readonly distance = makeDistanceOutput();
  // per core point, at the current fraction: projection on n, and |n . perp(u)|, |n . u| where u is
  // the point's offset from its body's centre of mass
  readonly projA = new Float64Array(MAX_POLYGON_VERTICES);
  readonly perpA = new Float64Array(MAX_POLYGON_VERTICES);
  readonly alongA = new Float64Array(MAX_POLYGON_VERTICES);
  readonly projB = new Float64Array(MAX_POLYGON_VERTICES);
  readonly perpB = new Float64Array(MAX_POLYGON_VERTICES);
  readonly alongB = new Float64Array(MAX_POLYGON_VERTICES);
}

/**
 * Time of impact by conservative advancement (Catto, "Continuous Collision", GDC 2013), with a
 * second-order motion bound. At fraction t, GJK gives the surface separation and the normal n from
 * A to B. The separation along any fixed axis bounds the distance from below, so it is enough to
 * bound how far each core point can move along n in the next dt of fraction:
 *   linear part: n . (centre displacement) * dt;
 *   rotation by an angle delta <= w dt (w: angular bound of the nlerp sweep) of an offset u:
 *   |n . (R(delta) - I) u| <= delta |n . perp(u)| + delta^2 / 2 |n . u|.
 * For each pair of core points this gives a concave quadratic lower bound of their separation along
 * n; the smallest root where it reaches `target` is a step that cannot skip the first contact.
 * The second-order term lets the tip of a spinning rod that slides past a surface advance in large
 * steps, where a first-order bound (w times the largest radius) would crawl.
 *
 * Results (fraction in [0, maxFraction]):
 * - 'hit': at `fraction` the surfaces are between target and target + 0.25 linearSlop apart
 *   (fraction 0 when they start in that band). target = linearSlop.
 * - 'overlapped': they start closer than target - 0.25 linearSlop (or overlapping); fraction 0.
 * - 'separated': they never come within target before maxFraction; fraction = maxFraction.
 * - 'failed': out of iterations (grazing motion); fraction is still safe, the shapes are at least
 *   target apart there, so treating it as a hit is conservative.
 */
export function timeOfImpact(
  memory: TOIMemory,
  input: TOIInput,
  out: TOIOutput,
  linearSlop = DEFAULT_LINEAR_SLOP,
): TOIOutput {
  const gjk = memory.gjk;
  const xfA = memory.xfA;
  const xfB = memory.xfB;
  const distance = memory.distance;
  const projA = memory.projA;
  const perpA = memory.perpA;
  const alongA = memory.alongA;
  const projB = memory.projB;
  const perpB = memory.perpB;
  const alongB = memory.alongB;
  const proxyA = input.proxyA;
  const proxyB = input.proxyB;
  const sweepA = input.sweepA;
  const sweepB = input.sweepB;
  const maxFraction = input.maxFraction;
  const target = linearSlop;
  const tolerance = 0.25 * linearSlop;
  const totalRadius = proxyA.radius + proxyB.radius;

  const wA = sweepAngularBound(sweepA);
  const wB = sweepAngularBound(sweepB);
  const dx = sweepA.c2X - sweepA.c1X - (sweepB.c2X - sweepB.c1X);
  const dy = sweepA.c2Y - sweepA.c1Y - (sweepB.c2Y - sweepB.c1Y);

  let t = 0;
  for (let iter = 0; iter < MAX_ITERATIONS; iter++) {
    out.iterations = iter + 1;
    getSweepTransform(sweepA, t, xfA);
    getSweepTransform(sweepB, t, xfB);
    shapeDistance(gjk, proxyA, xfA, proxyB, xfB, false, distance);
    const separation = distance.distance - totalRadius;

    if (separation < target + tolerance) {
      out.state = iter === 0 && separation < target - tolerance ? 'overlapped' : 'hit';
      out.fraction = t;
      return out;
    }

    const nx = distance.normalX;
    const ny = distance.normalY;
    projectPoints(proxyA, xfA, sweepA, nx, ny, projA, perpA, alongA);
    projectPoints(proxyB, xfB, sweepB, nx, ny, projB, perpB, alongB);
    const linear = nx * dx + ny * dy;
    let step = Number.POSITIVE_INFINITY;
    for (let i = 0; i < proxyA.count; i++) {
      for (let j = 0; j < proxyB.count; j++) {
        // c0 - c1 dt - c2 dt^2 bounds this pair's separation minus target
        const c0 = projB[j] - projA[i] - totalRadius - target;
        const c1 = linear + wA * perpA[i] + wB * perpB[j];
        const c2 = 0.5 * (wA * wA * alongA[i] + wB * wB * alongB[j]);
        const den = c1 + Math.sqrt(c1 * c1 + 4 * c2 * c0);
        if (den > 0) {
          step = Math.min(step, (2 * c0) / den);
        }
      }
    }
    t += step;
    if (t >= maxFraction) {
      break; // includes an infinite step: nothing approaches along n
    }
    if (iter === MAX_ITERATIONS - 1) {
      out.state = 'failed';
      out.fraction = t;
      return out;
    }
  }
  out.state = 'separated';
  out.fraction = maxFraction;
  return out;
}

function projectPoints(
  proxy: ShapeProxy,
  xf: Transform,
  sweep: Sweep,
  nx: number,
  ny: number,
  proj: Float64Array,
  perp: Float64Array,
  along: Float64Array,
): void {
  const c = xf.q.c;
  const s = xf.q.s;
  // world centre of mass
  const cx = c * sweep.localCenterX - s * sweep.localCenterY + xf.p.x;
  const cy = s * sweep.localCenterX + c * sweep.localCenterY + xf.p.y;
  for (let i = 0; i < proxy.count; i++) {
    const lx = proxy.x[i] - sweep.localCenterX;
    const ly = proxy.y[i] - sweep.localCenterY;
    const ux = c * lx - s * ly;
    const uy = s * lx + c * ly;
    const un = nx * ux + ny * uy;
    proj[i] = nx * cx + ny * cy + un;
    perp[i] = Math.abs(ny * ux - nx * uy);
    along[i] = Math.abs(un);
  }
}
