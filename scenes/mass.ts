/**
 * Area, centroid and mass of scene shapes, so tests can check the stated masses and adapters of
 * engines that take a mass instead of a density (p2) can compute it.
 */
import type { SceneBody, SceneShape, V } from './types';

/** signed area and centroid of a simple polygon (counter-clockwise gives a positive area) */
export function polygonAreaCentroid(points: readonly V[]): { area: number; centroid: V } {
  let twiceArea = 0;
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < points.length; i++) {
    const a = points[i];
    const b = points[(i + 1) % points.length];
    const cross = a.x * b.y - b.x * a.y;
    twiceArea += cross;
    cx += (a.x + b.x) * cross;
    cy += (a.y + b.y) * cross;
  }
  const area = twiceArea / 2;
  return { area, centroid: { x: cx / (6 * area), y: cy / (6 * area) } };
}

function perimeter(points: readonly V[]): number {
  let sum = 0;
  for (let i = 0; i < points.length; i++) {
    const a = points[i];
    const b = points[(i + 1) % points.length];
    sum += Math.hypot(b.x - a.x, b.y - a.y);
  }
  return sum;
}

/** area in m^2; segments have none. Polygons are assumed convex and given counter-clockwise. */
export function shapeArea(shape: SceneShape): number {
  switch (shape.kind) {
    case 'circle':
      return Math.PI * shape.radius * shape.radius;
    case 'box':
      return 4 * shape.halfWidth * shape.halfHeight;
    case 'polygon': {
      const r = shape.radius ?? 0;
      return polygonAreaCentroid(shape.points).area + perimeter(shape.points) * r + Math.PI * r * r;
    }
    case 'capsule': {
      const length = Math.hypot(shape.p2.x - shape.p1.x, shape.p2.y - shape.p1.y);
      return 2 * shape.radius * length + Math.PI * shape.radius * shape.radius;
    }
    case 'segment':
      return 0;
  }
}

/** centroid of a shape in its body's frame */
export function shapeCentroid(shape: SceneShape): V {
  switch (shape.kind) {
    case 'circle':
    case 'box':
      return shape.center ?? { x: 0, y: 0 };
    case 'polygon':
      return polygonAreaCentroid(shape.points).centroid;
    case 'capsule':
    case 'segment':
      return { x: (shape.p1.x + shape.p2.x) / 2, y: (shape.p1.y + shape.p2.y) / 2 };
  }
}

export function shapeMass(shape: SceneShape): number {
  return shapeArea(shape) * (shape.density ?? 1);
}

/** mass in kg of a dynamic body (density times area summed over its shapes) */
export function bodyMass(body: SceneBody): number {
  let mass = 0;
  for (const shape of body.shapes) mass += shapeMass(shape);
  return mass;
}

/** centre of mass of a body in its own frame */
export function bodyCentroid(body: SceneBody): V {
  let mass = 0;
  let x = 0;
  let y = 0;
  for (const shape of body.shapes) {
    const m = shapeMass(shape);
    const c = shapeCentroid(shape);
    mass += m;
    x += m * c.x;
    y += m * c.y;
  }
  return mass > 0 ? { x: x / mass, y: y / mass } : { x: 0, y: 0 };
}
