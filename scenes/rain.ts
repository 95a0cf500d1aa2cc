/**
 * Rain of mixed shapes (circles, boxes, capsules, regular polygons; density 1) falling from a grid
 * into an open container of static walls. Shapes and jitter come from the seeded PRNG.
 */
import { GRAVITY, regularPolygon } from './common';
import { createRandom, type Random } from './random';
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

/** What a rain scene drops at each grid cell: the body's shapes and its angle, drawn from `random`. */
export type RainDrop = (random: Random) => { shapes: SceneShape[]; angle: number };

/**
 * A rain scene: an open container of static walls `width` wide and `count` dynamic bodies (tag
 * 'drop') on a grid of `cell` metres above it, each jittered by up to 0.1 m and made by `drop`.
 */
export function rainScene(
  name: string,
  count: number,
  width: number,
  cell: number,
  random: Random,
  drop: RainDrop,
): Scene {
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
  const columns = Math.floor(width / cell) - 1;
  for (let i = 0; i < count; i++) {
    const column = i % columns;
    const row = Math.floor(i / columns);
    const x = (column - (columns - 1) / 2) * cell + random.range(-0.1, 0.1);
    const y = 2 + row * cell + random.range(-0.1, 0.1);
    const { shapes, angle } = drop(random);
    bodies.push({ type: 'dynamic', position: { x, y }, angle, shapes, tag: 'drop' });
  }
  const top = 2 + Math.ceil(count / columns) * cell;
  return {
    name,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: top / 2 }, halfHeight: top / 2 + 2 },
    containment: { lower: { x: -halfWidth - 1, y: -1 }, upper: { x: halfWidth + 1, y: top + 100 } },
  };
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
  return rainScene(`rain-${count}`, count, width, CELL, createRandom(seed), (random) => {
    const shape = rainShape(random.int(4), 3 + random.int(4));
    return { shapes: [shape], angle: random.range(-Math.PI, Math.PI) };
  });
}
