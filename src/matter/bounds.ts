import type { MatterVector } from './vector';

/** matter.js's axis-aligned box, `{ min, max }`. */
export interface MatterBounds {
  min: MatterVector;
  max: MatterVector;
}

/** matter.js's `Bounds`: boxes around vertex lists. A plain, mutable module object. */
export const Bounds = {
  /** The box around `vertices`, or an empty one at the origin without them. */
  create(vertices?: readonly MatterVector[]): MatterBounds {
    const bounds = { min: { x: 0, y: 0 }, max: { x: 0, y: 0 } };
    if (vertices) Bounds.update(bounds, vertices);
    return bounds;
  },

  /** Fits `bounds` to `vertices`, widened on the side it moves by `velocity` if given. */
  update(bounds: MatterBounds, vertices: readonly MatterVector[], velocity?: MatterVector): void {
    let minX = Number.POSITIVE_INFINITY;
    let minY = Number.POSITIVE_INFINITY;
    let maxX = Number.NEGATIVE_INFINITY;
    let maxY = Number.NEGATIVE_INFINITY;
    for (const v of vertices) {
      if (v.x > maxX) maxX = v.x;
      if (v.x < minX) minX = v.x;
      if (v.y > maxY) maxY = v.y;
      if (v.y < minY) minY = v.y;
    }
    if (velocity) {
      if (velocity.x > 0) maxX += velocity.x;
      else minX += velocity.x;
      if (velocity.y > 0) maxY += velocity.y;
      else minY += velocity.y;
    }
    bounds.min.x = minX;
    bounds.min.y = minY;
    bounds.max.x = maxX;
    bounds.max.y = maxY;
  },

  contains(bounds: MatterBounds, point: MatterVector): boolean {
    return (
      point.x >= bounds.min.x && point.x <= bounds.max.x && point.y >= bounds.min.y && point.y <= bounds.max.y
    );
  },

  overlaps(a: MatterBounds, b: MatterBounds): boolean {
    return a.min.x <= b.max.x && a.max.x >= b.min.x && a.max.y >= b.min.y && a.min.y <= b.max.y;
  },

  translate(bounds: MatterBounds, vector: MatterVector): void {
    bounds.min.x += vector.x;
    bounds.max.x += vector.x;
    bounds.min.y += vector.y;
    bounds.max.y += vector.y;
  },

  /** Moves `bounds` so that its min corner is at `position`. */
  shift(bounds: MatterBounds, position: MatterVector): void {
    const dx = bounds.max.x - bounds.min.x;
    const dy = bounds.max.y - bounds.min.y;
    bounds.min.x = position.x;
    bounds.max.x = position.x + dx;
    bounds.min.y = position.y;
    bounds.max.y = position.y + dy;
  },
};
