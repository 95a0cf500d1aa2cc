import type { Transform } from '../math/vec2';
import { collideCapsuleSegment, collideCapsules } from './manifold-capsule';
import {
  collideCircleCapsule,
  collideCirclePolygon,
  collideCircleSegment,
  collideCircles,
} from './manifold-circle';
import { clearCollideHints, collidePolygonLike } from './manifold-polygon';
import type { Geometry, Manifold } from './types';

export { collideCapsuleSegment, collideCapsules } from './manifold-capsule';
export {
  collideCircleCapsule,
  collideCirclePackedPolygon,
  collideCirclePolygon,
  collideCircleSegment,
  collideCircles,
} from './manifold-circle';
export { collidePolygonLike } from './manifold-polygon';

/*
 * Contact ids (ManifoldPoint.id), stable while the same features touch:
 * - circle against anything: 0 (one point).
 * - capsule-capsule, capsule-segment: 0 and 1 for two points made from B's first and second end
 *   (clipped to A's extent); 2 for a single point between the closest points of the cores.
 * - polygon pairs (capsules and segments against polygons act as 2-vertex polygons):
 *   bits 0-3 the vertex of the incident shape the point came from, bits 4-7 the reference edge,
 *   bit 8 set when the reference face belongs to the function's B argument, bit 9 set for a
 *   vertex-vertex point of separated cores (bits 4-7 then hold the reference vertex).
 * When collide() swaps its arguments (see SWAPPED), "A" and "B" above are the swapped ones; a pair of
 * shapes always comes in the same order, so the ids stay stable.
 */

type PairFunction = (
  a: Geometry,
  xfA: Transform,
  b: Geometry,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
) => void;

function collideNothing(
  _a: Geometry,
  _xfA: Transform,
  _b: Geometry,
  _xfB: Transform,
  _speculativeDistance: number,
  out: Manifold,
): void {
  out.pointCount = 0;
}

/** Indexed by kindA * 4 + kindB (CIRCLE 0, CAPSULE 1, SEGMENT 2, POLYGON 3). */
const PAIRS: readonly PairFunction[] = [
  collideCircles as PairFunction, // circle-circle
  collideCircleCapsule as PairFunction, // circle-capsule
  collideCircleSegment as PairFunction, // circle-segment
  collideCirclePolygon as PairFunction, // circle-polygon
  collideCircleCapsule as PairFunction, // capsule-circle (swapped)
  collideCapsules as PairFunction, // capsule-capsule
  collideCapsuleSegment as PairFunction, // capsule-segment
  collidePolygonLike as PairFunction, // capsule-polygon
  collideCircleSegment as PairFunction, // segment-circle (swapped)
  collideCapsuleSegment as PairFunction, // segment-capsule (swapped)
  collideNothing, // segment-segment: segments live on static or kinematic bodies only
  collidePolygonLike as PairFunction, // segment-polygon
  collideCirclePolygon as PairFunction, // polygon-circle (swapped)
  collidePolygonLike as PairFunction, // polygon-capsule (swapped)
  collidePolygonLike as PairFunction, // polygon-segment (swapped)
  collidePolygonLike as PairFunction, // polygon-polygon
];

/** 1 where the pair function takes the shapes in the other order: call it swapped, flip the normal. */
const SWAPPED: readonly number[] = [0, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 1, 0];

/**
 * Contact manifold of shape `a` at `xfA` and shape `b` at `xfB`: world normal from A to B, up to two
 * world points halfway between the surfaces, each with its separation (< 0 overlapping) and feature
 * id. Only points with separation < speculativeDistance are kept. Allocation free.
 */
export function collide(
  a: Geometry,
  xfA: Transform,
  b: Geometry,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
): void {
  const pair = a.kind * 4 + b.kind;
  if (SWAPPED[pair] === 1) {
    PAIRS[pair](b, xfB, a, xfA, speculativeDistance, out);
    out.normalX = -out.normalX;
    out.normalY = -out.normalY;
  } else {
    PAIRS[pair](a, xfA, b, xfB, speculativeDistance, out);
  }
  clearCollideHints();
}
