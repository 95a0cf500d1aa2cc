// Independent reference computations for the geometry tests (no engine code beyond the data types).

import type { Geometry } from '../../../src/geometry/types';
import type { Transform } from '../../../src/math/vec2';

export function xf(x: number, y: number, angle: number): Transform {
  return { p: { x, y }, q: { c: Math.cos(angle), s: Math.sin(angle) } };
}

/** Core points of a shape in world coordinates and its radius. */
export function worldCore(g: Geometry, t: Transform): { points: { x: number; y: number }[]; radius: number } {
  const local =
    g.type === 'circle'
      ? [g.center]
      : g.type === 'capsule'
        ? [g.center1, g.center2]
        : g.type === 'segment'
          ? [g.point1, g.point2]
          : g.vertices;
  const points = local.map((p) => ({
    x: t.q.c * p.x - t.q.s * p.y + t.p.x,
    y: t.q.s * p.x + t.q.c * p.y + t.p.y,
  }));
  return { points, radius: g.type === 'segment' ? 0 : g.radius };
}

function support(core: Core, ux: number, uy: number): number {
  let best = Number.NEGATIVE_INFINITY;
  for (const p of core.points) best = Math.max(best, p.x * ux + p.y * uy);
  return best + core.radius;
}

/**
 * Signed distance of two convex shapes (negative: penetration depth) as the largest gap between their
 * support functions over all directions, by dense sampling then repeated zooming on the best angle.
 */
export function signedDistance(a: Geometry, xfA: Transform, b: Geometry, xfB: Transform): number {
  return coreDistance(worldCore(a, xfA), worldCore(b, xfB));
}

/** Signed distance from the world point (x, y) to the shape (negative inside). */
export function pointDistance(g: Geometry, t: Transform, x: number, y: number): number {
  return coreDistance(worldCore(g, t), { points: [{ x, y }], radius: 0 });
}

type Core = { points: { x: number; y: number }[]; radius: number };

function coreDistance(ca: Core, cb: Core): number {
  const gap = (angle: number): number => {
    const ux = Math.cos(angle);
    const uy = Math.sin(angle);
    return -support(cb, -ux, -uy) - support(ca, ux, uy);
  };
  const coarse = 1440;
  let step = (2 * Math.PI) / coarse;
  const candidates: number[] = [];
  const values: number[] = [];
  for (let i = 0; i < coarse; i++) {
    candidates.push(i * step);
    values.push(gap(i * step));
  }
  // refine the best few peaks (the function can have several local maxima)
  const peaks = candidates
    .map((_, i) => i)
    .filter((i) => values[i] >= values[(i + 1) % coarse] && values[i] >= values[(i + coarse - 1) % coarse]);
  const order = peaks.sort((i, j) => values[j] - values[i]);
  let best = Number.NEGATIVE_INFINITY;
  for (const start of order.slice(0, 4)) {
    let center = candidates[start];
    let value = values[start];
    step = (2 * Math.PI) / coarse;
    for (let round = 0; round < 12; round++) {
      const from = center - 2 * step;
      const sub = (4 * step) / 40;
      for (let k = 0; k <= 40; k++) {
        const angle = from + k * sub;
        const v = gap(angle);
        if (v > value) {
          value = v;
          center = angle;
        }
      }
      step = sub;
    }
    best = Math.max(best, value);
  }
  return best;
}

/** Deterministic pseudo-random numbers for reproducible tests. */
export function random(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
