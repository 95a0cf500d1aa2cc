/**
 * Soak test (`npm run soak`, not part of the unit run): a world of N bodies (default 5,000) in a walled
 * bin, where every step destroys a few bodies at random and creates as many above the pile, for an
 * hour of simulated time at 60 Hz (216,000 steps) by default. Every report interval it prints the
 * heap after a full garbage collection and the step time (mean and 99th percentile); at the end it
 * compares the first and last quarters of the run and prints a verdict: flat when the heap grew less
 * than HEAP_GROWTH_LIMIT and the mean step time less than STEP_GROWTH_LIMIT. Exits 1 when not flat.
 *
 *   npm run soak -- --seconds 600 --bodies 5000 --churn 5 --report 60 --seed 1
 *
 * Step times are wall-clock figures of a noisy machine: read them as a trend, not as a benchmark.
 */
import { parseArgs } from 'node:util';
import { type Body, Shape, World } from '../src/index';

const HEAP_GROWTH_LIMIT = 0.1;
const STEP_GROWTH_LIMIT = 0.25;
const DT = 1 / 60;

const { values } = parseArgs({
  options: {
    seconds: { type: 'string', default: '3600' },
    bodies: { type: 'string', default: '5000' },
    churn: { type: 'string', default: '5' },
    report: { type: 'string', default: '60' },
    seed: { type: 'string', default: '1' },
    help: { type: 'boolean', default: false },
  },
});
if (values.help) {
  console.log(
    'npm run soak -- [--seconds 3600] [--bodies 5000] [--churn 5 (bodies replaced per step)] [--report 60] [--seed 1]',
  );
  process.exit(0);
}
const seconds = positive('seconds', values.seconds);
const population = positive('bodies', values.bodies);
const churn = positive('churn', values.churn);
const reportEvery = positive('report', values.report);
let rng = positive('seed', values.seed) >>> 0 || 1;

function positive(name: string, text: string): number {
  const v = Number(text);
  if (!(v > 0) || !Number.isFinite(v)) throw new Error(`--${name} must be a number > 0, got ${text}`);
  return v;
}

/** xorshift32: the same bodies come and go on every run with the same seed */
function random(): number {
  rng ^= rng << 13;
  rng ^= rng >>> 17;
  rng ^= rng << 5;
  return (rng >>> 0) / 0x100000000;
}

const gc = (globalThis as { gc?: () => void }).gc;
if (!gc) throw new Error('run with node --expose-gc (npm run soak does)');

function heapMB(): number {
  gc!();
  return process.memoryUsage().heapUsed / 1e6;
}

// a bin wide enough that the pile stays ~12 m high
const halfWidth = Math.max(20, Math.sqrt(population) * 0.7);
const world = new World();
const bin = world.createBody({ position: { x: 0, y: 0 } });
bin.createShape(Shape.box(halfWidth, 1, { x: 0, y: -1 }));
bin.createShape(Shape.box(1, 40, { x: -halfWidth - 1, y: 39 }));
bin.createShape(Shape.box(1, 40, { x: halfWidth + 1, y: 39 }));

const bodies: Body[] = [];

function spawn(y: number): void {
  const body = world.createBody({
    type: 'dynamic',
    position: { x: (random() * 2 - 1) * (halfWidth - 1), y },
    angle: random() * 6.28,
  });
  const kind = Math.floor(random() * 4);
  const size = 0.2 + random() * 0.3;
  const geometry =
    kind === 0
      ? Shape.box(size, size * (0.5 + random()))
      : kind === 1
        ? Shape.circle(size)
        : kind === 2
          ? Shape.capsule({ x: -size, y: 0 }, { x: size, y: 0 }, size * 0.5)
          : Shape.polygon([
              { x: -size, y: -size },
              { x: size, y: -size * 0.8 },
              { x: size * 0.6, y: size },
              { x: -size * 0.7, y: size * 0.9 },
            ]);
  body.createShape(geometry, { friction: 0.6, restitution: random() * 0.2 });
  bodies.push(body);
}

// the starting population, in layers above the floor
for (let i = 0; i < population; i++) spawn(2 + (i / (halfWidth * 1.5)) * 1.1);

interface Sample {
  t: number;
  heap: number;
  meanMs: number;
  p99Ms: number;
  awake: number;
  contacts: number;
}
const samples: Sample[] = [];
const steps = Math.round(seconds / DT);
const stepsPerReport = Math.max(1, Math.round(reportEvery / DT));
const times = new Float64Array(stepsPerReport);
let n = 0;

console.log(
  `soak: ${population} bodies, ${churn} replaced per step, ${seconds} s simulated (${steps} steps), seed ${values.seed}`,
);
console.log(`start: heap ${heapMB().toFixed(1)} MB`);
console.log('   t (s)   heap (MB)   step mean (ms)   step p99 (ms)   awake   contacts');
const started = performance.now();
for (let s = 1; s <= steps; s++) {
  for (let k = 0; k < churn; k++) {
    const i = Math.floor(random() * bodies.length);
    world.destroyBody(bodies[i]);
    bodies[i] = bodies[bodies.length - 1];
    bodies.pop();
    spawn(30 + random() * 8);
  }
  const t0 = performance.now();
  world.step(DT);
  times[n++] = performance.now() - t0;
  if (n === stepsPerReport || s === steps) {
    const slice = Array.from(times.subarray(0, n)).sort((a, b) => a - b);
    const sample: Sample = {
      t: s * DT,
      heap: heapMB(),
      meanMs: slice.reduce((a, b) => a + b, 0) / n,
      p99Ms: slice[Math.min(n - 1, Math.floor(n * 0.99))],
      awake: world.awakeBodyCount,
      contacts: world.contactCount,
    };
    samples.push(sample);
    n = 0;
    console.log(
      `${sample.t.toFixed(0).padStart(8)}   ${sample.heap.toFixed(1).padStart(9)}   ${sample.meanMs.toFixed(2).padStart(14)}   ${sample.p99Ms.toFixed(2).padStart(13)}   ${String(sample.awake).padStart(5)}   ${String(sample.contacts).padStart(8)}`,
    );
  }
}
if (world.bodyCount !== population + 1)
  throw new Error(`body count ${world.bodyCount}, expected ${population + 1}`);

const quarter = Math.max(1, Math.floor(samples.length / 4));
const mean = (list: Sample[], f: (s: Sample) => number) => list.reduce((a, s) => a + f(s), 0) / list.length;
const first = samples.slice(0, quarter);
const last = samples.slice(samples.length - quarter);
const heapGrowth = mean(last, (s) => s.heap) / mean(first, (s) => s.heap) - 1;
const stepGrowth = mean(last, (s) => s.meanMs) / mean(first, (s) => s.meanMs) - 1;
const wall = (performance.now() - started) / 1000;
console.log(
  `first quarter: heap ${mean(first, (s) => s.heap).toFixed(1)} MB, step ${mean(first, (s) => s.meanMs).toFixed(2)} ms; ` +
    `last quarter: heap ${mean(last, (s) => s.heap).toFixed(1)} MB, step ${mean(last, (s) => s.meanMs).toFixed(2)} ms`,
);
const flat = heapGrowth < HEAP_GROWTH_LIMIT && stepGrowth < STEP_GROWTH_LIMIT;
console.log(
  `verdict: ${flat ? 'flat' : 'NOT flat'} (heap ${(heapGrowth * 100).toFixed(1)}%, limit ${HEAP_GROWTH_LIMIT * 100}%; ` +
    `step time ${(stepGrowth * 100).toFixed(1)}%, limit ${STEP_GROWTH_LIMIT * 100}%); ${wall.toFixed(0)} s of wall time`,
);
process.exit(flat ? 0 : 1);
