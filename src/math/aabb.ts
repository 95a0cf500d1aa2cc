import type { Vec2 } from './vec2';

/** Axis-aligned bounding box. */
export interface AABB {
  lowerBound: Vec2;
  upperBound: Vec2;
}

/** @internal Scratch form used inside the engine: four numbers, no nested objects. */
export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/** @internal */
export function makeBounds(): Bounds {
  return { minX: 0, minY: 0, maxX: 0, maxY: 0 };
}
