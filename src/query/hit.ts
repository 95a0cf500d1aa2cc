import type { Body } from '../api/body';
import type { ShapeHandle } from '../api/shape';
import type { Vec2 } from '../math/vec2';

/** The answer of `castRay`, `castRayAll` and `castShape`: a fresh object owned by the caller. */
export interface CastHit {
  shape: ShapeHandle;
  body: Body;
  /** world point where the surfaces meet, on the hit shape */
  point: Vec2;
  /** unit normal of the hit shape's surface at `point`, pointing out of it (toward the caster) */
  normal: Vec2;
  /** fraction of the translation at which the hit happens, in [0, 1] */
  fraction: number;
}

export function makeCastHit(
  shape: ShapeHandle,
  pointX: number,
  pointY: number,
  normalX: number,
  normalY: number,
  fraction: number,
): CastHit {
  return {
    shape,
    body: shape.body,
    point: { x: pointX, y: pointY },
    normal: { x: normalX, y: normalY },
    fraction,
  };
}
