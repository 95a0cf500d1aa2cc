import { type Body, Shape, type Vec2, World } from '../../src/index';
import type { Demo } from '../demo';

/** A star of `spikes` points between radii `outer` and `inner`. */
function star(spikes: number, outer: number, inner: number): Vec2[] {
  const points: Vec2[] = [];
  for (let i = 0; i < 2 * spikes; i++) {
    const a = Math.PI / 2 + (Math.PI * i) / spikes;
    const r = i % 2 === 0 ? outer : inner;
    points.push({ x: r * Math.cos(a), y: r * Math.sin(a) });
  }
  return points;
}

/** Outlines on a grid of `cell` metres: letters and blocks, counter-clockwise or not (either works). */
function cells(outline: [number, number][], cell: number): Vec2[] {
  return outline.map(([x, y]) => ({ x: (x - 1) * cell, y: (y - 1.5) * cell }));
}

const SHAPES: Vec2[][] = [
  star(5, 0.55, 0.24),
  star(4, 0.5, 0.2),
  star(7, 0.55, 0.3),
  cells(
    [
      [0, 0],
      [2, 0],
      [2, 1],
      [1, 1],
      [1, 3],
      [0, 3],
    ],
    0.3,
  ), // L
  cells(
    [
      [0, 2],
      [1, 2],
      [1, 0],
      [2, 0],
      [2, 2],
      [3, 2],
      [3, 3],
      [0, 3],
    ],
    0.3,
  ), // T
  cells(
    [
      [0, 0],
      [3, 0],
      [3, 3],
      [2, 3],
      [2, 1],
      [1, 1],
      [1, 3],
      [0, 3],
    ],
    0.3,
  ), // U
  cells(
    [
      [0, 0],
      [1, 0],
      [1, 2],
      [2, 2],
      [2, 3],
      [0, 3],
    ],
    0.3,
  ).map((p) => ({ x: -p.x, y: p.y })), // a mirrored L
  cells(
    [
      [0, 0],
      [3, 0],
      [3, 1],
      [2, 1],
      [2, 2],
      [3, 2],
      [3, 3],
      [0, 3],
      [0, 2],
      [1, 2],
      [1, 1],
      [0, 1],
    ],
    0.3,
  ), // I-beam
];
const COLORS = [0xe0a33a, 0xd9695f, 0x6fb3d9, 0x8fc46a, 0xb58ad9, 0xe3d26f];
const MAX_BODIES = 140;
const SPAWN_EVERY = 12;

export const concaveRainDemo: Demo = {
  id: 'concave-rain',
  title: 'Concave shapes',
  description:
    'Stars, letters and beams, each one body made with Shape.concave (split into convex pieces, mass and inertia exact), rain into a bowl that is a smooth chain. Click to drag one.',
  view: { center: { x: 0, y: 6 }, halfHeight: 8 },
  create: (ctx) => {
    const world = new World();
    // the bowl: a half circle and two lips, listed right to left under it so that it faces inwards
    const bowl: Vec2[] = [{ x: 10, y: 9 }];
    for (let i = 0; i <= 40; i++) {
      const a = -(Math.PI * i) / 40;
      bowl.push({ x: 8 * Math.cos(a), y: 8 + 8 * Math.sin(a) });
    }
    bowl.push({ x: -10, y: 9 });
    world.createBody().createShape(Shape.chain(bowl), { friction: 0.5 });

    // the bowl's stone, drawn under the chain
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        render.setWorldTransform();
        const context = render.context;
        const stone = context.createLinearGradient(0, 9, 0, -2);
        stone.addColorStop(0, '#6b7280');
        stone.addColorStop(1, '#3a3f4a');
        context.fillStyle = stone;
        context.beginPath();
        context.moveTo(11, -2);
        for (const p of bowl) context.lineTo(p.x, p.y);
        context.lineTo(-11, -2);
        context.closePath();
        context.fill();
        render.setScreenTransform();
      }),
    );

    const concaves = SHAPES.map((points) => Shape.concave(points));
    const bodies: Body[] = [];
    let spawned = 0;
    let steps = 0;
    const spawn = () => {
      const kind = spawned % concaves.length;
      const body = world.createBody({
        type: 'dynamic',
        position: { x: ((spawned * 7) % 11) - 5, y: 12 + (spawned < 8 ? spawned * 0.4 : 3) },
        angle: spawned * 0.7,
        angularVelocity: ((spawned % 5) - 2) * 0.8,
      });
      body.createShape(concaves[kind], { density: 1, friction: 0.5 });
      ctx.render.setBodyStyle(body, { color: COLORS[spawned % COLORS.length] });
      bodies.push(body);
      spawned++;
      ctx.setStatus(`${bodies.length} concave bodies, ${world.bodyCount - 1} bodies in all`);
    };
    // a first handful already in the air, then one every SPAWN_EVERY steps
    for (let i = 0; i < 8; i++) spawn();
    ctx.track(
      world.on('postStep', () => {
        steps++;
        if (steps % SPAWN_EVERY === 0 && bodies.length < MAX_BODIES) spawn();
      }),
    );
    return { world, bodies };
  },
};
