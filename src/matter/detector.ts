import type { MatterBody } from './body';
import { Bounds } from './bounds';
import { canCollide } from './mouse-constraint';
import { Query } from './query';

/** A matter.js detector: a list of bodies to test against one another. */
export interface MatterDetector {
  bodies: MatterBody[];
  pairs: unknown;
}

/**
 * matter.js's `Detector`, for programs that test collisions themselves (the engine collides with
 * Fulcrum's own broad and narrow phase). A plain, mutable module object.
 */
export const Detector = {
  create(options: Partial<MatterDetector> = {}): MatterDetector {
    return { bodies: [], pairs: null, ...options };
  },

  setBodies(detector: MatterDetector, bodies: MatterBody[]): void {
    detector.bodies = bodies.slice();
  },

  clear(detector: MatterDetector): void {
    detector.bodies = [];
  },

  /** Whether two collision filters let their bodies meet: same non-zero group decides, else category against mask both ways. */
  canCollide,

  /** The collisions among the detector's bodies: one record per overlapping pair whose filters allow it. */
  collisions(detector: MatterDetector): ReturnType<typeof Query.collides> {
    const out: ReturnType<typeof Query.collides> = [];
    const bodies = detector.bodies;
    for (let i = 0; i < bodies.length; i++) {
      for (let j = i + 1; j < bodies.length; j++) {
        const a = bodies[i];
        const b = bodies[j];
        if ((a.isStatic || a.isSleeping) && (b.isStatic || b.isSleeping)) continue;
        if (!canCollide(a.collisionFilter, b.collisionFilter) || !Bounds.overlaps(a.bounds, b.bounds))
          continue;
        out.push(...Query.collides(b, [a]));
      }
    }
    return out;
  },
};

/** matter.js's `Pairs`: the collision pairs' table and list an engine keeps. */
export const Pairs = {
  create(options: Record<string, unknown> = {}) {
    return { table: {}, list: [], collisionStart: [], collisionActive: [], collisionEnd: [], ...options };
  },

  clear(pairs: {
    table: Record<string, unknown>;
    list: unknown[];
    collisionStart: unknown[];
    collisionActive: unknown[];
    collisionEnd: unknown[];
  }) {
    pairs.table = {};
    pairs.list.length = 0;
    pairs.collisionStart.length = 0;
    pairs.collisionActive.length = 0;
    pairs.collisionEnd.length = 0;
    return pairs;
  },
};
