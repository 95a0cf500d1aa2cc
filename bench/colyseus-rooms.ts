/**
 * Game rooms of the 200-body scene (examples/server/scene.ts, sleep off) at 60 Hz hosted by Colyseus
 * (examples/colyseus/physics-room.ts: Colyseus's fixed timestep steps the world, the room's schema
 * takes every body's pose after each step), on one process and on two: how many rooms fit, and the
 * step-time percentiles, beside examples/server's RoomPool on 1 and 2 workers measured in the same
 * rounds with the same scene (bench/rooms.ts's trial).
 *
 * Colyseus spreads rooms over processes with its Redis presence and driver, each process a Server that
 * hosts the rooms the matchmaker gives it (by default the process with fewest rooms). Here each
 * process is a Colyseus Server of its own (no Redis on this machine) and the rooms are dealt out in
 * turn, as that default would; the benchmark makes them through each process's matchmaker.
 *
 * A count of rooms keeps 60 Hz when, over the window (2 s after 120 steps of warm-up), every process's
 * p99 of the rooms' work per 1/60 s frame (their fixed-step callbacks due in it) is under
 * 16.7 ms, and no room fell 3 or more steps behind 60 Hz (Colyseus's catch-up runs up to 5 at once,
 * then drops the rest): the counterpart of the pool's "every worker's tick p99 under 16.7 ms, no tick
 * dropped" (the pool catches up 3). With --clients each room has one client (this process, over a
 * WebSocket) and Colyseus encodes and sends its patches at 30 Hz; without, it only tracks the changes.
 * The patches are encoded on Colyseus's patch timer, outside the fixed-step callbacks: the work per
 * frame leaves them out, and they count only as they make rooms fall behind (and in "event loop busy").
 *
 * Each round first runs 8 rooms on one process and then on one pool worker, for the mean cost of a
 * room step side by side: the counts that fit hang on the p99 of a frame's work, which every pause of
 * a busy machine reaches; the means hold better.
 *
 *   npm run bench:colyseus -- [--rounds n=2] [--quick] [--clients] [--no-pool]
 */
import { type ChildProcess, fork } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { availableParallelism, cpus } from 'node:os';
import { setTimeout as sleep } from 'node:timers/promises';
import { fileURLToPath } from 'node:url';
import { Client, type Room as ClientRoom } from '@colyseus/sdk';
import { RoomPool } from '../examples/server/room-pool';
import type { Percentiles } from '../examples/server/samples';
import type { HostRequest, HostWindow } from './colyseus-host';
import { largestThatFits } from './fit-search';
import { type PoolTrial, trial as poolTrial } from './rooms';

const args = process.argv.slice(2);
const quick = args.includes('--quick');
const withClients = args.includes('--clients');
const withPool = !args.includes('--no-pool');
const roundsAt = args.indexOf('--rounds');
const rounds = roundsAt >= 0 ? Number(args[roundsAt + 1]) : quick ? 1 : 2;
if (!Number.isInteger(rounds) || rounds < 1)
  throw new Error(`--rounds must be a positive integer, got ${rounds}`);

/** one 1/60 s tick, ms */
const BUDGET = 1000 / 60;
/** steps each room takes before measuring: the falling bodies land, the JIT settles */
const WARM = quick ? 60 : 120;
const SETTLE_MS = 300;
const MEASURE_MS = quick ? 1500 : 2000;
/** rooms on one core for the side-by-side cost of a room step */
const SAME_ROOMS = 8;
/** the first count tried on one process (later rounds start from the last answer) */
const FIRST_GUESS = 20;

/** One Colyseus process of the benchmark, and its requests in flight. */
class Host {
  readonly child: ChildProcess;
  readonly ready: Promise<number>;
  readonly #pending = new Map<number, { resolve(v: unknown): void; reject(e: Error): void }>();
  #nextId = 0;

  constructor() {
    this.child = fork(fileURLToPath(new URL('./colyseus-host.ts', import.meta.url)), {
      execArgv: ['--import', 'tsx'],
    });
    this.ready = new Promise((ready, failed) => {
      this.child.on(
        'message',
        (m: { ready?: number; id?: number; ok?: boolean; value?: unknown; message?: string }) => {
          if (m.ready !== undefined) return ready(m.ready);
          const pending = this.#pending.get(m.id ?? -1);
          if (pending === undefined) return;
          this.#pending.delete(m.id ?? -1);
          if (m.ok) pending.resolve(m.value);
          else pending.reject(new Error(m.message));
        },
      );
      this.child.on('exit', (code) => {
        const error = new Error(`a Colyseus process exited with code ${code}`);
        failed(error);
        for (const pending of this.#pending.values()) pending.reject(error);
      });
    });
  }

  request<T>(request: HostRequest): Promise<T> {
    const id = this.#nextId++;
    return new Promise((resolve, reject) => {
      this.#pending.set(id, { resolve: resolve as (v: unknown) => void, reject });
      this.child.send({ id, request });
    });
  }

  end(): void {
    this.child.disconnect();
  }
}

interface ColyseusTrial {
  keeps60Hz: boolean;
  /** per process */
  windows: HostWindow[];
  /** the fewest steps a room took in the window, and what 60 Hz gives */
  fewestSteps: number;
  expected: number;
}

/** `count` rooms dealt out in turn over `hosts`, measured over one window */
async function colyseusTrial(hosts: Host[], count: number): Promise<ColyseusTrial> {
  const seeds: number[][] = hosts.map(() => []);
  for (let i = 0; i < count; i++) seeds[i % hosts.length].push(i + 1);
  const ids = await Promise.all(
    hosts.map((h, i) => h.request<string[]>({ kind: 'create', seeds: seeds[i] })),
  );
  const clients: ClientRoom[] = [];
  try {
    if (withClients) {
      const ports = await Promise.all(hosts.map((h) => h.ready));
      for (const [h, list] of ids.entries()) {
        for (const id of list) clients.push(await new Client(`http://127.0.0.1:${ports[h]}`).joinById(id));
      }
    }
    // warm-up by the rooms' own clocks: every room WARM steps (however long an overloaded process takes)
    for (;;) {
      const steps = (await Promise.all(hosts.map((h) => h.request<number[]>({ kind: 'steps' })))).flat();
      if (Math.min(...steps) >= WARM) break;
      await sleep(100);
    }
    await sleep(SETTLE_MS);
    const windows = await Promise.all(
      hosts.map((h) => h.request<HostWindow>({ kind: 'measure', ms: MEASURE_MS })),
    );
    const fewestSteps = Math.min(...windows.flatMap((w) => w.steps));
    const expected = windows[0].expected;
    return {
      keeps60Hz: fewestSteps > expected - 3 && windows.every((w) => w.frame.p99 < BUDGET),
      windows,
      fewestSteps,
      expected,
    };
  } finally {
    await Promise.all(clients.map((c) => c.leave()));
    await Promise.all(hosts.map((h) => h.request({ kind: 'clear' })));
  }
}

type Fit<T> = { rooms: number; trials: (T & { rooms: number })[] };

interface RoundResult {
  round: number;
  /** SAME_ROOMS rooms on one core, Colyseus then the pool: the cost of a room step, side by side */
  same: { colyseus: ColyseusTrial; pool?: PoolTrial };
  colyseus1: Fit<ColyseusTrial>;
  colyseus2: Fit<ColyseusTrial>;
  pool1?: Fit<PoolTrial>;
  pool2?: Fit<PoolTrial>;
}

const best = <T extends { keeps60Hz: boolean }>(fit: Fit<T> | undefined) =>
  fit?.trials.find((t) => t.rooms === fit.rooms && t.keeps60Hz);
const f2 = (x: number) => x.toFixed(2);
const range = (xs: number[], digits = 2) => {
  if (xs.length === 0) return '-';
  const lo = Math.min(...xs).toFixed(digits);
  const hi = Math.max(...xs).toFixed(digits);
  return lo === hi ? lo : `${lo}-${hi}`;
};
const pcts = (list: Percentiles[]) =>
  (['p50', 'p95', 'p99'] as const).map((p) => range(list.map((s) => s[p]))).join(' / ');

async function main(): Promise<void> {
  const began = performance.now();
  const hosts = [new Host(), new Host()];
  const pools = withPool ? [new RoomPool({ workers: 1 }), new RoomPool({ workers: 2 })] : [];
  const results: RoundResult[] = [];
  try {
    await Promise.all(hosts.map((h) => h.ready));
    for (let round = 1; round <= rounds; round++) {
      const last = results.at(-1);
      const same = {
        colyseus: await colyseusTrial(hosts.slice(0, 1), SAME_ROOMS),
        pool: withPool ? await poolTrial(pools[0], SAME_ROOMS) : undefined,
      };
      const colyseus1 = await largestThatFits(
        (n) => colyseusTrial(hosts.slice(0, 1), n),
        last?.colyseus1.rooms ?? FIRST_GUESS,
      );
      const colyseus2 = await largestThatFits(
        (n) => colyseusTrial(hosts, n),
        last?.colyseus2.rooms ?? 1.8 * Math.max(1, colyseus1.rooms),
      );
      const result: RoundResult = { round, same, colyseus1, colyseus2 };
      if (withPool) {
        result.pool1 = await largestThatFits(
          (n) => poolTrial(pools[0], n),
          last?.pool1?.rooms ?? colyseus1.rooms,
        );
        result.pool2 = await largestThatFits(
          (n) => poolTrial(pools[1], n),
          last?.pool2?.rooms ?? 1.8 * Math.max(1, result.pool1.rooms),
        );
      }
      results.push(result);
      const c2 = best(colyseus2);
      console.log(
        `round ${round}: Colyseus ${colyseus1.rooms} rooms on 1 process, ${colyseus2.rooms} on 2 ` +
          `(work per 1/60 s p99 ${c2?.windows.map((w) => f2(w.frame.p99)).join(', ')} ms)` +
          (withPool ? `; RoomPool ${result.pool1?.rooms} on 1 worker, ${result.pool2?.rooms} on 2` : '') +
          ` [${((performance.now() - began) / 1000).toFixed(0)} s]`,
      );
    }
  } finally {
    for (const h of hosts) h.end();
    await Promise.all(pools.map((pool) => pool.close()));
  }

  const atFit = results.flatMap((r) => [best(r.colyseus1), best(r.colyseus2)]).filter((t) => t !== undefined);
  // a process without rooms (1 room over 2) has no figures
  const windows = atFit.flatMap((t) => t.windows).filter((w) => w.roomTick.count > 0);
  const sameTick = results.map((r) => r.same.colyseus.windows[0].roomTick.mean);
  const samePool = results.map((r) => r.same.pool?.step[0].mean ?? 0);
  const rows: [string, string][] = [
    [
      'Colyseus: rooms at 60 Hz, 1 process (1 core)',
      range(
        results.map((r) => r.colyseus1.rooms),
        0,
      ),
    ],
    [
      'Colyseus: rooms at 60 Hz, 2 processes (2 cores)',
      range(
        results.map((r) => r.colyseus2.rooms),
        0,
      ),
    ],
    // the mean cost of a room step is less at the mercy of the machine's pauses than the fitted counts
    [
      `${SAME_ROOMS} rooms, 1 process: Colyseus world step mean, ms`,
      range(results.map((r) => r.same.colyseus.windows[0].worldStep.mean)),
    ],
    [`${SAME_ROOMS} rooms, 1 process: Colyseus room tick mean (world step and schema), ms`, range(sameTick)],
    [
      `${SAME_ROOMS} rooms, 1 process: 1/60 s over the room tick mean`,
      range(
        sameTick.map((t) => BUDGET / t),
        0,
      ),
    ],
    ['Colyseus at the fitted counts: world step p50 / p95 / p99, ms', pcts(windows.map((w) => w.worldStep))],
    ['Colyseus at the fitted counts: room tick p50 / p95 / p99, ms', pcts(windows.map((w) => w.roomTick))],
    ['Colyseus at the fitted counts: work per 1/60 s p99, ms', range(windows.map((w) => w.frame.p99))],
    ['Colyseus at the fitted counts: event-loop delay p99, ms', range(windows.map((w) => w.loopDelay.p99))],
    ['Colyseus at the fitted counts: event loop busy', range(windows.map((w) => w.utilization))],
  ];
  if (withPool) {
    const poolFit = results.flatMap((r) => [best(r.pool1), best(r.pool2)]).filter((t) => t !== undefined);
    rows.push(
      [`${SAME_ROOMS} rooms, 1 worker: RoomPool room step mean, ms`, range(samePool)],
      [
        `${SAME_ROOMS} rooms, 1 worker: 1/60 s over the room step mean`,
        range(
          samePool.map((t) => BUDGET / t),
          0,
        ),
      ],
      [
        `${SAME_ROOMS} rooms: Colyseus room tick over RoomPool room step, same round`,
        range(sameTick.map((t, i) => t / samePool[i])),
      ],
      [
        'RoomPool: rooms at 60 Hz, 1 worker',
        range(
          results.map((r) => r.pool1?.rooms ?? 0),
          0,
        ),
      ],
      [
        'RoomPool: rooms at 60 Hz, 2 workers',
        range(
          results.map((r) => r.pool2?.rooms ?? 0),
          0,
        ),
      ],
      [
        'RoomPool at the fitted counts: room step p50 / p95 / p99, ms',
        pcts(poolFit.flatMap((t) => t.step).filter((p) => p.count > 0)),
      ],
      [
        'RoomPool at the fitted counts: worker tick p99, ms',
        range(poolFit.flatMap((t) => t.tickP99.filter((_, w) => t.step[w].count > 0))),
      ],
    );
  }
  const width = Math.max(...rows.map(([k]) => k.length));
  console.log(
    `\nrooms of 200 bodies (sleep off), ${withClients ? 'one client a room' : 'no clients'}, ${rounds} round(s), ` +
      `${cpus().length} cores, Node ${process.version}`,
  );
  for (const [k, v] of rows) console.log(`${k.padEnd(width)}  ${v}`);
  const out = {
    date: new Date().toISOString(),
    machine: { cores: availableParallelism(), cpu: cpus()[0]?.model, node: process.version },
    settings: {
      quick,
      rounds,
      clients: withClients,
      warmSteps: WARM,
      measureMs: MEASURE_MS,
      budgetMs: BUDGET,
    },
    summary: Object.fromEntries(rows),
    rounds: results,
  };
  const file = `colyseus-rooms${withClients ? '-clients' : ''}.json`;
  writeFileSync(new URL(`./results/${file}`, import.meta.url), `${JSON.stringify(out, null, 2)}\n`);
  console.log(`\nwrote bench/results/${file} in ${((performance.now() - began) / 1000).toFixed(0)} s`);
}

await main();
