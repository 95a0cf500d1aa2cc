/**
 * Game rooms of a 200-body scene (examples/server/scene.ts: a pyramid and 144 falling boxes and
 * circles, sleep off so every body costs every step) at 60 Hz, on examples/server's RoomPool:
 * - one thread: the rooms stepped in turn on this thread, no workers: ms per room step, percentiles;
 * - the pool's overhead: the same rooms in a pool of 1 and of 2 workers, stepped as fast as they go
 *   one tick per round trip, ms per room step against one thread's;
 * - rooms that fit: the largest count whose rooms all keep 60 Hz on the workers' clocks on 1 and on 2
 *   workers, i.e. every worker's p99 time per 1/60 s tick stays under 16.7 ms and no tick is dropped
 *   (each count measured over 2 s on the clock after 120 ticks of warm-up).
 * Several rounds (the machine is noisy); prints ranges over them and writes bench/results/rooms.json.
 *
 *   npm run bench:rooms -- [--rounds n=2] [--quick]
 */
import { writeFileSync } from 'node:fs';
import { availableParallelism, cpus } from 'node:os';
import { setTimeout as sleep } from 'node:timers/promises';
import { pathToFileURL } from 'node:url';
import { Room, type RoomSpec } from '../examples/server/room';
import { RoomPool } from '../examples/server/room-pool';
import { type Percentiles, Samples } from '../examples/server/samples';
import { roomScene } from '../examples/server/scene';
import { largestThatFits } from './fit-search';

const args = process.argv.slice(2);
const quick = args.includes('--quick');
const roundsAt = args.indexOf('--rounds');
const rounds = roundsAt >= 0 ? Number(args[roundsAt + 1]) : quick ? 1 : 2;
if (!Number.isInteger(rounds) || rounds < 1)
  throw new Error(`--rounds must be a positive integer, got ${rounds}`);

/** one 1/60 s tick, ms */
const BUDGET = 1000 / 60;
/** rooms for the one-thread and overhead runs */
const ROOMS = 8;
/** ticks before measuring: the falling bodies land, the JIT settles */
const WARM = quick ? 60 : 120;
const TICKS = quick ? 120 : 240;
/** time on the clock before and while measuring a count of rooms, ms */
const SETTLE_MS = 300;
const MEASURE_MS = quick ? 1500 : 2000;

const spec = (i: number): RoomSpec => ({ scene: roomScene(i + 1), settings: { enableSleep: false } });

interface OneThread {
  msPerRoomStep: number;
  step: Percentiles;
}

function oneThread(): OneThread {
  const rooms = Array.from({ length: ROOMS }, (_, i) => Room.create(`r${i}`, spec(i)));
  for (let t = 0; t < WARM; t++) for (const room of rooms) room.step();
  const steps = new Samples(ROOMS * TICKS);
  const start = performance.now();
  for (let t = 0; t < TICKS; t++) for (const room of rooms) steps.add(room.step());
  return { msPerRoomStep: (performance.now() - start) / (ROOMS * TICKS), step: steps.percentiles() };
}

async function fill(pool: RoomPool, count: number): Promise<string[]> {
  const rooms = Array.from({ length: count }, (_, i) => `r${i}`);
  for (const [i, room] of rooms.entries()) await pool.createRoom(room, spec(i));
  await pool.step(WARM);
  await pool.stats(true);
  return rooms;
}

async function empty(pool: RoomPool, rooms: string[]): Promise<void> {
  for (const room of rooms) await pool.removeRoom(room);
}

/** ms per room step in the pool, stepped as fast as it goes, one tick per round trip */
async function pooled(pool: RoomPool): Promise<number> {
  const rooms = await fill(pool, ROOMS);
  const start = performance.now();
  for (let t = 0; t < TICKS; t++) await pool.step(1);
  const ms = (performance.now() - start) / (ROOMS * TICKS);
  await empty(pool, rooms);
  return ms;
}

export interface PoolTrial {
  rooms: number;
  keeps60Hz: boolean;
  /** per worker */
  tickP99: number[];
  dropped: number[];
  step: Percentiles[];
}

/** `count` rooms on the workers' 60 Hz clocks */
export async function trial(pool: RoomPool, count: number): Promise<PoolTrial> {
  const rooms = await fill(pool, count);
  await pool.start();
  await sleep(SETTLE_MS);
  await pool.stats(true);
  await sleep(MEASURE_MS);
  const stats = await pool.stats();
  await pool.stop();
  await empty(pool, rooms);
  const tickP99 = stats.map((s) => s.tick.p99);
  const dropped = stats.map((s) => s.dropped);
  return {
    rooms: count,
    keeps60Hz: tickP99.every((p) => p < BUDGET) && dropped.every((d) => d === 0),
    tickP99,
    dropped,
    step: stats.map((s) => s.step),
  };
}

interface RoundResult {
  round: number;
  single: OneThread;
  pool1: number;
  pool2: number;
  fit1: { rooms: number; trials: PoolTrial[] };
  fit2: { rooms: number; trials: PoolTrial[] };
}

const f2 = (x: number) => x.toFixed(2);
const range = (xs: number[], digits = 2) => {
  const lo = Math.min(...xs).toFixed(digits);
  const hi = Math.max(...xs).toFixed(digits);
  return lo === hi ? lo : `${lo}-${hi}`;
};

async function main(): Promise<void> {
  const began = performance.now();
  const pools = [new RoomPool({ workers: 1 }), new RoomPool({ workers: 2 })];
  const results: RoundResult[] = [];
  try {
    for (let round = 1; round <= rounds; round++) {
      const single = oneThread();
      const pool1 = await pooled(pools[0]);
      const pool2 = await pooled(pools[1]);
      // a room step takes longer among many rooms than among 8, and the p99 of a tick catches every
      // pause: start at half the one-thread estimate, or at the last round's answer
      const guess1 = results.at(-1)?.fit1.rooms ?? BUDGET / single.msPerRoomStep / 2;
      const fit1 = await largestThatFits((n) => trial(pools[0], n), guess1);
      const fit2 = await largestThatFits(
        (n) => trial(pools[1], n),
        results.at(-1)?.fit2.rooms ?? 1.8 * Math.max(1, fit1.rooms),
      );
      const best2 = fit2.trials.find((t) => t.rooms === fit2.rooms && t.keeps60Hz);
      results.push({ round, single, pool1, pool2, fit1, fit2 });
      console.log(
        `round ${round}: one thread ${f2(single.msPerRoomStep)} ms/room-step; pool of 1 ${f2(pool1)}, of 2 ${f2(pool2)}; ` +
          `fit ${fit1.rooms} rooms on 1 worker, ${fit2.rooms} on 2 (tick p99 ${best2?.tickP99.map(f2).join(', ')} ms) ` +
          `[${((performance.now() - began) / 1000).toFixed(0)} s]`,
      );
    }
  } finally {
    await Promise.all(pools.map((pool) => pool.close()));
  }

  const best = (fit: { rooms: number; trials: PoolTrial[] }) =>
    fit.trials.find((t) => t.rooms === fit.rooms && t.keeps60Hz);
  const rows: [string, string][] = [
    [
      'rooms at 60 Hz, 1 worker (1 core)',
      range(
        results.map((r) => r.fit1.rooms),
        0,
      ),
    ],
    [
      'rooms at 60 Hz, 2 workers (2 cores)',
      range(
        results.map((r) => r.fit2.rooms),
        0,
      ),
    ],
    ['one thread: ms per room step (mean)', range(results.map((r) => r.single.msPerRoomStep))],
    [
      'one thread: room step p50 / p95 / p99, ms',
      ['p50', 'p95', 'p99'].map((p) => range(results.map((r) => r.single.step[p as 'p50']))).join(' / '),
    ],
    ['pool of 1, stepped flat out: ms per room step', range(results.map((r) => r.pool1))],
    ['pool of 2, stepped flat out: ms per room step', range(results.map((r) => r.pool2))],
    ['pool of 1 against one thread', range(results.map((r) => r.pool1 / r.single.msPerRoomStep))],
    ['pool of 2 against one thread', range(results.map((r) => r.pool2 / r.single.msPerRoomStep))],
  ];
  const atFit = results.flatMap((r) => [best(r.fit1), best(r.fit2)]).filter((t) => t !== undefined);
  for (const p of ['p50', 'p95', 'p99'] as const) {
    rows.push([
      `on the clock at the fitted counts: room step ${p}, ms`,
      range(atFit.flatMap((t) => t.step.map((s) => s[p]))),
    ]);
  }
  rows.push(['on the clock at the fitted counts: tick p99, ms', range(atFit.flatMap((t) => t.tickP99))]);
  const width = Math.max(...rows.map(([k]) => k.length));
  console.log(
    `\n${ROOMS} rooms of 200 bodies (sleep off), ${rounds} round(s), ${cpus().length} cores, Node ${process.version}`,
  );
  for (const [k, v] of rows) console.log(`${k.padEnd(width)}  ${v}`);

  const out = {
    date: new Date().toISOString(),
    machine: { cores: availableParallelism(), cpu: cpus()[0]?.model, node: process.version },
    settings: {
      quick,
      rounds,
      rooms: ROOMS,
      warmTicks: WARM,
      ticks: TICKS,
      measureMs: MEASURE_MS,
      budgetMs: BUDGET,
    },
    summary: Object.fromEntries(rows),
    rounds: results,
  };
  writeFileSync(new URL('./results/rooms.json', import.meta.url), `${JSON.stringify(out, null, 2)}\n`);
  console.log(`\nwrote bench/results/rooms.json in ${((performance.now() - began) / 1000).toFixed(0)} s`);
}

// run as a script (bench/colyseus-rooms.ts imports the pool's trial)
if (import.meta.url === pathToFileURL(process.argv[1]).href) await main();
