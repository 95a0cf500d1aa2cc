/** World-space outlines of scene shapes and a separating-axis overlap test, for scene checks. */
import type { SceneBody, SceneShape, V } from '../../../scenes/types';

/** corners of a box or polygon shape of `body`, in world space, counter-clockwise */
export function worldPolygon(body: SceneBody, shape: SceneShape): V[] {
  let local: V[];
  if (shape.kind === 'box') {
    const c = shape.center ?? { x: 0, y: 0 };
    const a = shape.angle ?? 0;
    const [cos, sin] = [Math.cos(a), Math.sin(a)];
    const corners = [
      { x: -shape.halfWidth, y: -shape.halfHeight },
      { x: shape.halfWidth, y: -shape.halfHeight },
      { x: shape.halfWidth, y: shape.halfHeight },
      { x: -shape.halfWidth, y: shape.halfHeight },
    ];
    local = corners.map((p) => ({ x: c.x + cos * p.x - sin * p.y, y: c.y + sin * p.x + cos * p.y }));
  } else if (shape.kind === 'polygon') {
    local = shape.points;
  } else {
    throw new Error(`not a polygon: ${shape.kind}`);
  }
  const a = body.angle ?? 0;
  const [cos, sin] = [Math.cos(a), Math.sin(a)];
  return local.map((p) => ({
    x: body.position.x + cos * p.x - sin * p.y,
    y: body.position.y + sin * p.x + cos * p.y,
  }));
}

/** depth of overlap of two convex polygons (<= 0 when they are apart or only touch) */
export function overlapDepth(a: V[], b: V[]): number {
  let depth = Number.POSITIVE_INFINITY;
  for (const poly of [a, b]) {
    for (let i = 0; i < poly.length; i++) {
      const p = poly[i];
      const q = poly[(i + 1) % poly.length];
      const length = Math.hypot(q.x - p.x, q.y - p.y);
      const n = { x: (q.y - p.y) / length, y: -(q.x - p.x) / length };
      const project = (s: V[]) => s.map((v) => v.x * n.x + v.y * n.y);
      const pa = project(a);
      const pb = project(b);
      const overlap = Math.min(Math.max(...pa), Math.max(...pb)) - Math.max(Math.min(...pa), Math.min(...pb));
      depth = Math.min(depth, overlap);
    }
  }
  return depth;
}
