/**
 * Rain of mixed shapes (circles, boxes, capsules, regular polygons; density 1) falling from a grid
 * into an open container of static walls. Shapes and jitter come from the seeded PRNG.
 */
import { GRAVITY, regularPolygon } from './common';
import { createRandom } from './random';
import type { Scene, SceneBody, SceneShape } from './types';

const CELL = 1; // grid pitch; every shape fits in a 0.8 m square so jittered neighbours never overlap

function rainShape(kind: number, sides: number): SceneShape {
  switch (kind) {
    case 0:
      return { kind: 'circle', radius: 0.25 };
    case 1:
      return { kind: 'box', halfWidth: 0.25, halfHeight: 0.2 };
    case 2:
      return { kind: 'capsule', p1: { x: -0.2, y: 0 }, p2: { x: 0.2, y: 0 }, radius: 0.15 };
    default:
      return { kind: 'polygon', points: regularPolygon(sides, 0.3) };
  }
}

export function rain({
  count = 1000,
  width = 40,
  seed = 7,
}: {
  count?: number;
  width?: number;
  seed?: number;
} = {}): Scene {
  const random = createRandom(seed);
  const halfWidth = width / 2;
  const wallHeight = 20;
  const container: SceneBody = {
    type: 'static',
    position: { x: 0, y: 0 },
    shapes: [
      { kind: 'box', halfWidth: halfWidth + 1, halfHeight: 0.5, center: { x: 0, y: -0.5 } },
      {
        kind: 'box',
        halfWidth: 0.5,
        halfHeight: wallHeight / 2,
        center: { x: -halfWidth - 0.5, y: wallHeight / 2 },
      },
      {
        kind: 'box',
        halfWidth: 0.5,
        halfHeight: wallHeight / 2,
        center: { x: halfWidth + 0.5, y: wallHeight / 2 },
      },
    ],
    tag: 'container',
  };
  const bodies: SceneBody[] = [container];
  const columns = Math.floor(width / CELL) - 1;
  for (let i = 0; i < count; i++) {
    const column = i % columns;
    const row = Math.floor(i / columns);
    const x = (column - (columns - 1) / 2) * CELL + random.range(-0.1, 0.1);
    const y = 2 + row * CELL + random.range(-0.1, 0.1);
    const shape = rainShape(random.int(4), 3 + random.int(4));
    bodies.push({
      type: 'dynamic',
      position: { x, y },
      angle: random.range(-Math.PI, Math.PI),
      shapes: [shape],
      tag: 'drop',
    });
  }
  const top = 2 + Math.ceil(count / columns) * CELL;
  return {
    name: `rain-${count}`,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: top / 2 }, halfHeight: top / 2 + 2 },
    containment: { lower: { x: -halfWidth - 1, y: -1 }, upper: { x: halfWidth + 1, y: top + 100 } },
  };
}
