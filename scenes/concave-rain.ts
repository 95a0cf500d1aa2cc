/**
 * Rain of concave bodies (five-pointed stars, L's, T's, U's; density 1) into an open container of
 * static walls: each body is the convex pieces `Shape.decompose` cuts its outline into, so every
 * engine builds the same pieces. Outlines and jitter come from the seeded PRNG.
 */
import { Shape } from '../src/index';
import { GRAVITY } from './common';
import { createRandom } from './random';
import type { Scene, SceneBody, SceneShape, V } from './types';

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
    bodies.push({
      type: 'dynamic',
      position: {
        x: (column - (columns - 1) / 2) * CELL + random.range(-0.1, 0.1),
        y: 2 + row * CELL + random.range(-0.1, 0.1),
      },
      angle: random.range(-Math.PI, Math.PI),
      shapes: PIECES[random.int(PIECES.length)],
      tag: 'drop',
    });
  }
  const top = 2 + Math.ceil(count / columns) * CELL;
  return {
    name: `concave-rain-${count}`,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: top / 2 }, halfHeight: top / 2 + 2 },
    containment: { lower: { x: -halfWidth - 1, y: -1 }, upper: { x: halfWidth + 1, y: top + 100 } },
  };
}
