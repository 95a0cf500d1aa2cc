/** One 1 kg box dropped from rest at y = 10 m with no ground: the reference for unit checks. */
import { GRAVITY } from './common';
import type { Scene } from './types';

export function freeFall(): Scene {
  return {
    name: 'free-fall',
    gravity: GRAVITY,
    bodies: [
      {
        type: 'dynamic',
        position: { x: 0, y: 10 },
        shapes: [{ kind: 'box', halfWidth: 0.5, halfHeight: 0.5 }],
        tag: 'box',
      },
    ],
    joints: [],
    view: { center: { x: 0, y: 5 }, halfHeight: 7 },
  };
}
