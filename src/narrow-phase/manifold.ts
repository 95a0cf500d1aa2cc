import { isOneSided, Pack, packGeometry } from '../geometry/packed';
import type { Geometry, Manifold } from '../geometry/types';
import type { Transform } from '../math/vec2';
import type { CollideContext } from './collide-context';
import { collideRoundedSegmentPair } from './manifold-capsule';
import { admitChainNormal, isBehindSegment } from './manifold-chain';
import { collideCirclePolygon, collideCircleRoundedSegment, collideCircles } from './manifold-circle';
import { collidePackedPolygons } from './manifold-polygon';

/*
 * Contact ids (ManifoldPoint.id), stable while the same features touch:
 * - circle against anything: 0 (one point).
 * - capsule-capsule, capsule-segment: 0 and 1 for two points made from B's first and second end
 *   (clipped to A's extent); 2 for a single point between the closest points of the cores.
 * - polygon pairs (capsules and segments against polygons act as 2-vertex polygons):
 *   bits 0-3 the vertex of the incident shape the point came from, bits 4-7 the reference edge,
 *   bit 8 set when the reference face belongs to the function's B argument, bit 9 set for a
 *   vertex-vertex point of separated cores (bits 4-7 then hold the reference vertex).
 * When collidePacked swaps its arguments (see SWAPPED), "A" and "B" above are the swapped ones; a pair of
 * shapes always comes in the same order, so the ids stay stable.
 */

/** A pair routine: both shapes packed in `data` (see packed.ts), at `baseA` and `baseB`. */
type PairFunction = (
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
) => void;

function collideNothing(
  _data: Float64Array,
  _baseA: number,
  _xfA: Transform,
  _baseB: number,
  _xfB: Transform,
  out: Manifold,
  _context: CollideContext,
): void {
  out.pointCount = 0;
}

/** Indexed by kindA * 4 + kindB (ShapeKind: CIRCLE 0, CAPSULE 1, SEGMENT 2, POLYGON 3). */
const PAIRS: readonly PairFunction[] = [
  collideCircles, // circle-circle
  collideCircleRoundedSegment, // circle-capsule
  collideCircleRoundedSegment, // circle-segment
  collideCirclePolygon, // circle-polygon
  collideCircleRoundedSegment, // capsule-circle (swapped)
  collideRoundedSegmentPair, // capsule-capsule
  collideRoundedSegmentPair, // capsule-segment
  collidePackedPolygons, // capsule-polygon
  collideCircleRoundedSegment, // segment-circle (swapped)
  collideRoundedSegmentPair, // segment-capsule (swapped)
  collideNothing, // segment-segment: segments live on static or kinematic bodies only
  collidePackedPolygons, // segment-polygon
  collideCirclePolygon, // polygon-circle (swapped)
  collidePackedPolygons, // polygon-capsule (swapped)
  collidePackedPolygons, // polygon-segment (swapped)
  collidePackedPolygons, // polygon-polygon
];

/** 1 where the pair function takes the shapes in the other order: call it swapped, flip the normal. */
const SWAPPED: readonly number[] = [0, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 1, 0];

/** The manifold of two-sided shapes: the pair routine of the table, in the order it takes them. */
function collideTwoSided(
  pair: number,
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  if (SWAPPED[pair] === 1) {
    PAIRS[pair](data, baseB, xfB, baseA, xfA, out, context);
    out.normalX = -out.normalX;
    out.normalY = -out.normalY;
  } else {
    PAIRS[pair](data, baseA, xfA, baseB, xfB, out, context);
  }
}

/**
 * Contact manifold of the shapes of kinds `kindA` and `kindB` packed in `data` at `baseA` and `baseB`
 * (see packed.ts: the narrow phase passes the shape store's records), placed at `xfA` and `xfB`:
 * world normal from A to B, up to two world points halfway between the surfaces, each with its
 * separation (< 0 overlapping) and feature id. Only points with separation below the speculative
 * distance `context.reach` are kept; the context's hints and results are described in
 * collide-context.ts (set them first). A chain's one-sided segment follows manifold-chain.ts.
 * Allocation free.
 */
export function collidePacked(
  kindA: number,
  kindB: number,
  data: Float64Array,
  baseA: number,
  xfA: Transform,
  baseB: number,
  xfB: Transform,
  out: Manifold,
  context: CollideContext,
): void {
  const pair = kindA * 4 + kindB;
  const chainA = isOneSided(kindA, data, baseA);
  const chainB = isOneSided(kindB, data, baseB);
  if (!chainA && !chainB) {
    collideTwoSided(pair, data, baseA, xfA, baseB, xfB, out, context);
    return;
  }
  const segBase = chainA ? baseA : baseB;
  const segXf = chainA ? xfA : xfB;
  const otherBase = chainA ? baseB : baseA;
  const otherXf = chainA ? xfB : xfA;
  if (isBehindSegment(data, segBase, segXf, otherBase, otherXf, context)) {
    out.pointCount = 0;
    return;
  }
  collideTwoSided(pair, data, baseA, xfA, baseB, xfB, out, context);
  if (out.pointCount > 0) admitChainNormal(data, segBase, segXf, otherBase, otherXf, chainB, out, context);
}

/**
 * collidePacked for geometry objects: packs them first (into `context.packed`), without hints (the
 * memoryless result).
 */
export function collide(
  a: Geometry,
  xfA: Transform,
  b: Geometry,
  xfB: Transform,
  speculativeDistance: number,
  out: Manifold,
  context: CollideContext,
): void {
  const packed = context.packed;
  packGeometry(a, packed, 0);
  packGeometry(b, packed, Pack.STRIDE);
  context.reach = speculativeDistance;
  context.referenceHint = -1;
  context.axisHint = 0;
  collidePacked(a.kind, b.kind, packed, 0, xfA, Pack.STRIDE, xfB, out, context);
}
