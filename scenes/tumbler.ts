/**
 * Tumbler: a kinematic square drum (four 1 m thick walls on one body) turning at 0.25 rad/s
 * around its centre, with small dynamic boxes (0.4 m, density 1) tumbling inside.
 */
import { GRAVITY } from './common';
import type { Scene, SceneBody, SceneShape } from './types';

const INNER_HALF = 7.5; // inner half-size of the drum, metres
const WALL_HALF = 0.5;
const BOX_HALF = 0.2;
const PITCH = 0.5;

export function tumbler({
  count = 500,
  angularVelocity = 0.25,
}: {
  count?: number;
  angularVelocity?: number;
} = {}): Scene {
  const center = { x: 0, y: 10 };
  const offset = INNER_HALF + WALL_HALF;
  const length = INNER_HALF + 2 * WALL_HALF;
  const walls: SceneShape[] = [
    { kind: 'box', halfWidth: WALL_HALF, halfHeight: length, center: { x: -offset, y: 0 } },
    { kind: 'box', halfWidth: WALL_HALF, halfHeight: length, center: { x: offset, y: 0 } },
    { kind: 'box', halfWidth: length, halfHeight: WALL_HALF, center: { x: 0, y: -offset } },
    { kind: 'box', halfWidth: length, halfHeight: WALL_HALF, center: { x: 0, y: offset } },
  ];
  const bodies: SceneBody[] = [
    { type: 'kinematic', position: center, angularVelocity, shapes: walls, tag: 'drum' },
  ];
  const columns = Math.floor((2 * INNER_HALF - 1) / PITCH);
  for (let i = 0; i < count; i++) {
    const x = center.x + ((i % columns) - (columns - 1) / 2) * PITCH;
    const y = center.y - INNER_HALF + 0.5 + Math.floor(i / columns) * PITCH;
    bodies.push({
      type: 'dynamic',
      position: { x, y },
      shapes: [{ kind: 'box', halfWidth: BOX_HALF, halfHeight: BOX_HALF }],
      tag: 'box',
    });
  }
  const reach = length * Math.SQRT2 + 0.1; // the turning drum never leaves this square
  return {
    name: `tumbler-${count}`,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center, halfHeight: reach },
    containment: {
      lower: { x: center.x - reach, y: center.y - reach },
      upper: { x: center.x + reach, y: center.y + reach },
    },
  };
}
