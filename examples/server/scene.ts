/**
 * The scene of one game room: a ground, a pyramid of 55 boxes, and 144 boxes and circles falling onto
 * it from seeded places: 200 bodies. Different seeds give different rooms.
 */
import { dynamicBody, GRAVITY, groundBody } from '../../scenes/common';
import { createRandom } from '../../scenes/random';
import type { Scene, SceneBody } from '../../scenes/types';

const PYRAMID_BASE = 10;
const FALLING = 144;

export function roomScene(seed = 1): Scene {
  const random = createRandom(seed);
  const bodies: SceneBody[] = [groundBody(20)];
  for (let row = 0; row < PYRAMID_BASE; row++) {
    const count = PYRAMID_BASE - row;
    for (let i = 0; i < count; i++) {
      const x = (i - (count - 1) / 2) * 1;
      bodies.push(dynamicBody({ x, y: 0.5 + row }, { kind: 'box', halfWidth: 0.5, halfHeight: 0.5 }, 'box'));
    }
  }
  // 12 columns of 12, 1.5 m apart, from 12 m up: they land on the pyramid and the ground around it
  for (let i = 0; i < FALLING; i++) {
    const x = -8.25 + (i % 12) * 1.5 + random.range(-0.2, 0.2);
    const y = 12 + Math.floor(i / 12) * 1.5;
    const shape =
      i % 2 === 0
        ? { kind: 'box' as const, halfWidth: 0.4, halfHeight: 0.4 }
        : { kind: 'circle' as const, radius: 0.4 };
    bodies.push(dynamicBody({ x, y }, shape, 'falling', random.range(-1, 1)));
  }
  return {
    name: `room-${seed}`,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: 8 }, halfHeight: 12 },
  };
}
