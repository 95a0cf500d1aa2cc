import { type Geometry, MAX_POLYGON_VERTICES, ShapeKind } from './types';

/**
 * A shape as GJK sees it: the convex hull of up to 8 core points (local frame of the body)
 * inflated by `radius`. Preallocated: fill it with `makeProxy` and reuse it.
 */
export interface ShapeProxy {
  readonly x: Float64Array;
  readonly y: Float64Array;
  count: number;
  radius: number;
}

export function makeShapeProxy(): ShapeProxy {
  return {
    x: new Float64Array(MAX_POLYGON_VERTICES),
    y: new Float64Array(MAX_POLYGON_VERTICES),
    count: 0,
    radius: 0,
  };
}

/** Fill `out` from a shape's geometry: circle 1 point, capsule and segment 2, polygon its vertices. */
export function makeProxy(g: Geometry, out: ShapeProxy): ShapeProxy {
  if (g.kind === ShapeKind.CIRCLE) {
    out.x[0] = g.center.x;
    out.y[0] = g.center.y;
    out.count = 1;
    out.radius = g.radius;
  } else if (g.kind === ShapeKind.CAPSULE) {
    out.x[0] = g.center1.x;
    out.y[0] = g.center1.y;
    out.x[1] = g.center2.x;
    out.y[1] = g.center2.y;
    out.count = 2;
    out.radius = g.radius;
  } else if (g.kind === ShapeKind.SEGMENT) {
    out.x[0] = g.point1.x;
    out.y[0] = g.point1.y;
    out.x[1] = g.point2.x;
    out.y[1] = g.point2.y;
    out.count = 2;
    out.radius = 0;
  } else {
    const n = g.count;
    for (let i = 0; i < n; i++) {
      out.x[i] = g.vertices[i].x;
      out.y[i] = g.vertices[i].y;
    }
    out.count = n;
    out.radius = g.radius;
  }
  return out;
}
