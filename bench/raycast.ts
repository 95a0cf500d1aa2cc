/**
 * Fulcrum-only query benchmark: 10,000 closest-hit ray casts (`world.castRay`) in a world of 5,000
 * bodies (static, kinematic and dynamic; circles, boxes, capsules, polygons) spread over a 300 m
 * square, after a few steps. Run by `npm run bench` after the engine comparison, or alone with
 * `npx tsx bench/raycast.ts`.
 */
import { createRandom } from '../scenes/random';
import { Shape, World } from '../src/index';

export interface RayCastBenchResult {
  bodies: number;
  rays: number;
  hits: number;
  /** total time of the timed batch of rays, median of the batches */
  ms: number;
}

const BODIES = 5000;
const RAYS = 10_000;

function buildWorld(): World {
  const random = createRandom(2024);
  const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
  for (let i = 0; i < BODIES; i++) {
    const kind = random.int(10);
    const type = kind < 3 ? 'static' : kind < 4 ? 'kinematic' : 'dynamic';
    const body = world.createBody({
      type,
      position: { x: random.range(-150, 150), y: random.range(-150, 150) },
      angle: random.range(-3, 3),
      linearVelocity: type === 'static' ? { x: 0, y: 0 } : { x: random.range(-1, 1), y: random.range(-1, 1) },
    });
    const size = random.range(0.2, 1);
    switch (random.int(4)) {
      case 0:
        body.createShape(Shape.circle(size));
        break;
      case 1:
        body.createShape(Shape.box(size, 0.5 * size));
        break;
      case 2:
        body.createShape(Shape.capsule({ x: -size, y: 0 }, { x: size, y: 0 }, 0.3 * size));
        break;
      default:
        body.createShape(
          Shape.polygon([
            { x: size, y: 0 },
            { x: 0, y: size },
            { x: -size, y: 0.2 * size },
            { x: -0.5 * size, y: -size },
          ]),
        );
    }
  }
  for (let i = 0; i < 3; i++) world.step(1 / 60);
  return world;
}

export function runRayCastBench(batches = 5): RayCastBenchResult {
  const world = buildWorld();
  const random = createRandom(7);
  const rays = new Float64Array(4 * RAYS);
  for (let i = 0; i < RAYS; i++) {
    const a = random.range(0, 2 * Math.PI);
    const length = random.range(1, 40);
    rays[4 * i] = random.range(-150, 150);
    rays[4 * i + 1] = random.range(-150, 150);
    rays[4 * i + 2] = length * Math.cos(a);
    rays[4 * i + 3] = length * Math.sin(a);
  }
  const origin = { x: 0, y: 0 };
  const translation = { x: 0, y: 0 };
  const times: number[] = [];
  let hits = 0;
  // the first batch warms up the JIT and is not counted
  for (let batch = 0; batch <= batches; batch++) {
    hits = 0;
    const t0 = performance.now();
    for (let i = 0; i < RAYS; i++) {
      origin.x = rays[4 * i];
      origin.y = rays[4 * i + 1];
      translation.x = rays[4 * i + 2];
      translation.y = rays[4 * i + 3];
      if (world.castRay(origin, translation) !== null) hits++;
    }
    if (batch > 0) times.push(performance.now() - t0);
  }
  times.sort((x, y) => x - y);
  return { bodies: BODIES, rays: RAYS, hits, ms: times[times.length >> 1] };
}

export function rayCastBenchText(r: RayCastBenchResult): string {
  return `queries: ${r.rays.toLocaleString('en-US')} castRay in a ${r.bodies.toLocaleString('en-US')}-body world: ${r.ms.toFixed(1)} ms (${((1000 * r.ms) / r.rays).toFixed(2)} us per ray, ${r.hits} hits; Fulcrum only)`;
}

if (process.argv[1] && import.meta.url.endsWith(process.argv[1].replace(/\\/g, '/'))) {
  console.log(rayCastBenchText(runRayCastBench()));
}
