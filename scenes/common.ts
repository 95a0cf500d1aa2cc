/** Small helpers shared by the scene builders. */
import type { SceneBody, SceneShape, V } from './types';

export const GRAVITY: V = { x: 0, y: -10 };

/** a static ground box whose top face is at y = top, centred on x = centerX */
export function groundBody(halfWidth: number, top = 0, centerX = 0): SceneBody {
  return {
    type: 'static',
    position: { x: centerX, y: top - 0.5 },
    shapes: [{ kind: 'box', halfWidth, halfHeight: 0.5 }],
    tag: 'ground',
  };
}

export function dynamicBody(position: V, shape: SceneShape, tag?: string, angle?: number): SceneBody {
  const body: SceneBody = { type: 'dynamic', position, shapes: [shape] };
  if (angle !== undefined) body.angle = angle;
  if (tag !== undefined) body.tag = tag;
  return body;
}

/** vertices of a regular polygon centred on the origin, counter-clockwise, first vertex at `phase` */
export function regularPolygon(sides: number, radius: number, phase = Math.PI / 2): V[] {
  const points: V[] = [];
  for (let i = 0; i < sides; i++) {
    const a = phase + (2 * Math.PI * i) / sides;
    points.push({ x: radius * Math.cos(a), y: radius * Math.sin(a) });
  }
  return points;
}
