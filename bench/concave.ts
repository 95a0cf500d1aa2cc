/**
 * What a concave body costs to create: `Shape.concave(points)` alone, and a dynamic body given it
 * (`world.createBody` + `body.createShape`), for outlines of about 64 points. Each figure is the
 * median, and the best, of 50 batches of 200 after a warm-up: on a busy machine the best is the one
 * to read. Run with `npx tsx bench/concave.ts`.
 */
import { Shape, type Vec2, World } from '../src/index';

/** 32 spikes: 32 reflex points, the most pieces a 64-point outline gives */
function star(): Vec2[] {
  return Array.from({ length: 64 }, (_, i) => {
    const a = (2 * Math.PI * i) / 64;
    const r = i % 2 === 0 ? 1 : 0.6;
    return { x: r * Math.cos(a), y: r * Math.sin(a) };
  });
}

/** a gear of 8 teeth, 8 points on each tooth and each gap: 16 reflex points */
function gear(): Vec2[] {
  return Array.from({ length: 64 }, (_, i) => {
    const a = (2 * Math.PI * i) / 64;
    const r = i % 8 < 4 ? 1 : 0.8;
    return { x: r * Math.cos(a), y: r * Math.sin(a) };
  });
}

/** a bar with 15 teeth: 62 points, 30 reflex, all on a grid */
function comb(): Vec2[] {
  const points = [
    { x: 0, y: 0 },
    { x: 9.3, y: 0 },
  ];
  for (let k = 15; k >= 1; k--) {
    points.push(
      { x: 0.6 * k, y: 0.3 },
      { x: 0.6 * k, y: 1.5 },
      { x: 0.6 * k - 0.3, y: 1.5 },
      { x: 0.6 * k - 0.3, y: 0.3 },
    );
  }
  return points;
}

const BATCHES = 50;
const PER_BATCH = 200;

function summary(samples: number[]): string {
  const sorted = samples.slice().sort((a, b) => a - b);
  return `median ${sorted[sorted.length >> 1].toFixed(1)} us, best ${sorted[0].toFixed(1)} us`;
}

for (const [name, outline] of Object.entries({ star: star(), gear: gear(), comb: comb() })) {
  const pieces = Shape.concave(outline).pieces.length;
  const alone: number[] = [];
  const body: number[] = [];
  for (let batch = -5; batch < BATCHES; batch++) {
    let t = performance.now();
    for (let i = 0; i < PER_BATCH; i++) Shape.concave(outline);
    if (batch >= 0) alone.push(((performance.now() - t) * 1000) / PER_BATCH);
    const world = new World();
    t = performance.now();
    for (let i = 0; i < PER_BATCH; i++) {
      const b = world.createBody({
        type: 'dynamic',
        position: { x: 4 * (i % 20), y: 4 * Math.floor(i / 20) },
      });
      b.createShape(Shape.concave(outline));
    }
    if (batch >= 0) body.push(((performance.now() - t) * 1000) / PER_BATCH);
  }
  console.log(`${name}: ${outline.length} points, ${pieces} pieces`);
  console.log(`  Shape.concave:               ${summary(alone)}`);
  console.log(`  body with Shape.concave:     ${summary(body)}`);
}
