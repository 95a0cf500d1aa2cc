import { createRandom } from '../../scenes/index';
import { type BodyDef, type Geometry, Shape, type ShapeDef, World } from '../../src/index';
import type { Demo } from '../demo';
import { regularPolygon } from '../lib';

export const COUNT = 5000;

/** What the scene needs of a world: a World and a WorkerWorld both take these calls. */
interface Builder {
  createBody(def: BodyDef): { createShape(geometry: Geometry, def?: ShapeDef): unknown };
}

/** The bin, its pegs and COUNT boxes, balls and polygons above it, the same for the same world. */
export function buildStressScene(world: Builder): void {
  const random = createRandom(21);
  const bin = world.createBody({ position: { x: 0, y: 0 } });
  bin.createShape(Shape.box(31, 0.5, { x: 0, y: -0.5 }));
  bin.createShape(Shape.box(0.5, 17, { x: -30.5, y: 16 }));
  bin.createShape(Shape.box(0.5, 17, { x: 30.5, y: 16 }));
  // a few pegs to stir the flow
  for (let i = 0; i < 9; i++) {
    bin.createShape(Shape.circle(0.6, { x: -24 + i * 6, y: 9 + (i % 2) * 2 }));
  }
  const pitch = 0.55;
  const columns = Math.floor(58 / pitch);
  const triangle = regularPolygon(3, 0.25);
  const hexagon = regularPolygon(6, 0.24);
  for (let i = 0; i < COUNT; i++) {
    const x = ((i % columns) - (columns - 1) / 2) * pitch + random.range(-0.04, 0.04);
    const y = 14 + Math.floor(i / columns) * pitch;
    const body = world.createBody({ type: 'dynamic', position: { x, y }, angle: random.range(0, 3) });
    const kind = random.int(4);
    body.createShape(
      kind === 0
        ? Shape.circle(0.22)
        : kind === 1
          ? Shape.box(0.22, 0.18)
          : kind === 2
            ? Shape.polygon(triangle)
            : Shape.polygon(hexagon),
      { friction: 0.5 },
    );
  }
}

export const stressDemo: Demo = {
  id: 'stress',
  title: '5,000 bodies',
  description:
    'Five thousand boxes, balls and polygons pour into a bin. Watch the step time in the readout; bodies that come to rest fall asleep (grey) and cost almost nothing.',
  view: { center: { x: 0, y: 17 }, halfHeight: 19 },
  maxStepsPerFrame: 2,
  create: (ctx) => {
    const world = new World();
    buildStressScene(world);
    ctx.setStatus(`${COUNT.toLocaleString('en')} dynamic bodies`);
    return { world };
  },
};
