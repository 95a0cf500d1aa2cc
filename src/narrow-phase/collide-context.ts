import { Pack } from '../geometry/packed';
import { MAX_POLYGON_VERTICES } from '../geometry/types';
import { makeSegmentClosest, type SegmentClosest } from './segment-distance';

/** Core polygon in A's frame (manifold-polygon.ts): vertices, outward unit edge normals, radius. */
export interface WorkPolygon {
  count: number;
  radius: number;
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly nx: Float64Array;
  readonly ny: Float64Array;
}

function makeWorkPolygon(): WorkPolygon {
  const n = MAX_POLYGON_VERTICES;
  return {
    count: 0,
    radius: 0,
    x: new Float64Array(n),
    y: new Float64Array(n),
    nx: new Float64Array(n),
    ny: new Float64Array(n),
  };
}

/**
 * What one collidePacked call reads besides the shapes, what it reports besides the manifold, and the
 * pair routines' working memory. The caller owns it (the narrow phase one per world) and sets the
 * inputs before each call, so no pair's hints leak into another caller's and nothing is allocated per
 * call. The buffers exist because a double passed to, or returned from, a call V8 does not inline is
 * boxed on the heap, and the pair routines run for every pair of every step.
 */
export class CollideContext {
  // --- inputs ---
  /** Points with a separation at or above this speculative distance are dropped. */
  reach = 0;
  /**
   * Which polygon owned the reference face of this pair's previous manifold (0 = A, 1 = B, -1 = none);
   * see manifold-polygon.ts.
   */
  referenceHint = -1;
  /** The pair's separating axis from its previous call (0 = none; see manifold-polygon.ts). */
  axisHint = 0;

  // --- results (set them to 0 and -1 before the call) ---
  /** The axis that separated a polygon pair, 0 when none did or it was not a polygon pair. */
  separatingAxis = 0;
  /**
   * When the pair was found apart: that separation less both radii, a lower bound of the shapes'
   * distance; -1 otherwise (capsule pairs never say).
   */
  separatedDistance = -1;

  // --- working memory of the pair routines ---
  readonly polyA: WorkPolygon = makeWorkPolygon();
  readonly polyB: WorkPolygon = makeWorkPolygon();
  readonly closest: SegmentClosest = makeSegmentClosest();
  /** The segments of a closestBetweenSegments call: p1, p2, q1, q2 (x, y each). */
  readonly segments = new Float64Array(8);
  /** A separation computed by a SAT helper. */
  readonly separation = new Float64Array(1);
  /** B's transform relative to A: cos, sin, x, y. */
  readonly relative = new Float64Array(4);
  /** A polygon manifold in A's frame (layout LocalManifold in manifold-polygon.ts) and its point ids. */
  readonly local = new Float64Array(2 + 3 * 2);
  readonly localIds = new Int32Array(2);
  /** The faces chosen by the polygon SAT (layout FaceInput in manifold-polygon.ts). */
  readonly faces = new Float64Array(13);
  /** Whether the polygon manifold in `local` took its reference face from B. */
  referenceFlip = false;
  /** A capsule point (layout CandidatePoint in manifold-capsule.ts). */
  readonly candidate = new Float64Array(7);
  /** Two packed shapes, for `collide` on geometry objects. */
  readonly packed = new Float64Array(2 * Pack.STRIDE);
}
