/**
 * Engine-neutral quality figures computed from body transforms (x, y, angle per body, metres, y up):
 * drift of settled bodies, joint separation, escaped bodies, and the free-fall unit check.
 */
import type { Scene, V } from '../scenes/types';
import { localPoint } from './adapter';

/** the scene's own transforms, the starting content of every transform buffer */
export function initialTransforms(scene: Scene): Float64Array {
  const out = new Float64Array(3 * scene.bodies.length);
  scene.bodies.forEach((b, i) => {
    out[3 * i] = b.position.x;
    out[3 * i + 1] = b.position.y;
    out[3 * i + 2] = b.angle ?? 0;
  });
  return out;
}

/** largest distance any dynamic body moved between two transform snapshots, metres */
export function maxDisplacement(scene: Scene, from: Float64Array, to: Float64Array): number {
  let max = 0;
  scene.bodies.forEach((b, i) => {
    if (b.type !== 'dynamic') return;
    max = Math.max(max, Math.hypot(to[3 * i] - from[3 * i], to[3 * i + 1] - from[3 * i + 1]));
  });
  return max;
}

/** joint anchors in each body's frame, from the scene's initial layout */
export function jointLocalAnchors(scene: Scene): Array<{ a: number; b: number; localA: V; localB: V }> {
  return scene.joints.map((j) => {
    const anchorA = j.type === 'distance' ? j.anchorA : j.anchor;
    const anchorB = j.type === 'distance' ? j.anchorB : j.anchor;
    return {
      a: j.bodyA,
      b: j.bodyB,
      localA: localPoint(scene.bodies[j.bodyA], anchorA),
      localB: localPoint(scene.bodies[j.bodyB], anchorB),
    };
  });
}

function worldPoint(t: Float64Array, i: number, p: V): V {
  const c = Math.cos(t[3 * i + 2]);
  const s = Math.sin(t[3 * i + 2]);
  return { x: t[3 * i] + c * p.x - s * p.y, y: t[3 * i + 1] + s * p.x + c * p.y };
}

/** largest distance between the two world anchors of any revolute joint, metres */
export function maxJointSeparation(anchors: ReturnType<typeof jointLocalAnchors>, t: Float64Array): number {
  let max = 0;
  for (const j of anchors) {
    const a = worldPoint(t, j.a, j.localA);
    const b = worldPoint(t, j.b, j.localB);
    max = Math.max(max, Math.hypot(b.x - a.x, b.y - a.y));
  }
  return max;
}

/** dynamic bodies whose origin is outside the scene's containment box */
export function escapedBodies(scene: Scene, t: Float64Array): number {
  const box = scene.containment;
  if (!box) return 0;
  let count = 0;
  scene.bodies.forEach((b, i) => {
    if (b.type !== 'dynamic') return;
    const x = t[3 * i];
    const y = t[3 * i + 1];
    if (!(x >= box.lower.x && x <= box.upper.x && y >= box.lower.y && y <= box.upper.y)) count++;
  });
  return count;
}

export function allFinite(t: Float64Array): boolean {
  for (let i = 0; i < t.length; i++) if (!Number.isFinite(t[i])) return false;
  return true;
}

/**
 * Free fall from rest for 60 steps of 1/60 s with g = 10. The exact fall is 5.000 m; semi-implicit
 * Euler at dt = 1/60 gives 5.0833 m; an engine that substeps n times gives 5 (1 + 1 / (60 n)), e.g.
 * 5.021 m for Box2D's 4 substeps. Any correct integrator lands in [5.000, 5.0833]; the check accepts
 * that range widened by 1% on each side, which still catches any unit or time-scale error.
 */
export const FREE_FALL = { steps: 60, dt: 1 / 60, min: 5.0 * 0.99, max: ((5 * 61) / 60) * 1.01 };

export function freeFallPasses(fall: number): boolean {
  return fall >= FREE_FALL.min && fall <= FREE_FALL.max;
}
