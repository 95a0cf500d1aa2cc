/**
 * Rain of concave bodies (five-pointed stars, L's, T's, U's; density 1) into an open container of
 * static walls: each body is the convex pieces `Shape.decompose` cuts its outline into, so every
 * engine builds the same pieces. Outlines and jitter come from the seeded PRNG.
 */
import { Shape } from '../src/index';
import { rainScene } from './rain';
import { createRandom } from './random';
import type { Scene, SceneShape, V } from './types';

const CELL = 1.2; // grid pitch: every outline fits in a 1 m square

function star(): V[] {
  const points: V[] = [];
  for (let i = 0; i < 10; i++) {
    const a = Math.PI / 2 + (Math.PI * i) / 5;
    const r = i % 2 === 0 ? 0.5 : 0.22;
    points.push({ x: r * Math.cos(a), y: r * Math.sin(a) });
  }
  return points;
}

/** an outline on a grid of 0.3 m cells, centred */
function cells(outline: [number, number][]): V[] {
  return outline.map(([x, y]) => ({ x: (x - 1.5) * 0.3, y: (y - 1.5) * 0.3 }));
}

const OUTLINES: V[][] = [
  star(),
  cells([
    [0, 0],
    [2, 0],
    [2, 1],
    [1, 1],
    [1, 3],
    [0, 3],
  ]),
  cells([
    [0, 2],
    [1, 2],
    [1, 0],
    [2, 0],
    [2, 2],
    [3, 2],
    [3, 3],
    [0, 3],
  ]),
  cells([
    [0, 0],
    [3, 0],
    [3, 3],
    [2, 3],
    [2, 1],
    [1, 1],
    [1, 3],
    [0, 3],
  ]),
];

/** the outline moved so that its area centroid is the origin (scene bodies have their centre of mass there) */
function centred(outline: V[]): V[] {
  let area = 0;
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < outline.length; i++) {
    const a = outline[i];
    const b = outline[(i + 1) % outline.length];
    const cross = a.x * b.y - b.x * a.y;
    area += cross / 2;
    cx += ((a.x + b.x) * cross) / 6;
    cy += ((a.y + b.y) * cross) / 6;
  }
  return outline.map((p) => ({ x: p.x - cx / area, y: p.y - cy / area }));
}

/** each outline's convex pieces, as scene polygons */
const PIECES: SceneShape[][] = OUTLINES.map((outline) =>
  Shape.decompose(centred(outline)).map((piece) => ({
    kind: 'polygon',
    points: piece.vertices.map((v) => ({ x: v.x, y: v.y })),
  })),
);

export function concaveRain({
  count = 500,
  width = 30,
  seed = 11,
}: {
  count?: number;
  width?: number;
  seed?: number;
} = {}): Scene {
  return rainScene(`concave-rain-${count}`, count, width, CELL, createRandom(seed), (random) => {
    const angle = random.range(-Math.PI, Math.PI);
    return { shapes: PIECES[random.int(PIECES.length)], angle };
  });
}
