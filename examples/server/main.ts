/**
 * The example game server's physics, without the networking: rooms of 200 bodies at 60 Hz spread over
 * a pool of worker threads (one per core), poked by "players", one room moved to another worker
 * half-way, then each worker's rooms and step times printed.
 *
 *   npm run demo:server -- [rooms=8] [seconds=4]
 */
import { setTimeout as sleep } from 'node:timers/promises';
import { createRandom } from '../../scenes/random';
import { RoomPool } from './room-pool';
import { roomScene } from './scene';

const rooms = Number(process.argv[2] ?? 8);
const seconds = Number(process.argv[3] ?? 4);
const pool = new RoomPool();
pool.on('failure', ({ worker, error, rooms }) => {
  console.error(`worker ${worker} failed (${error.message}); lost rooms ${rooms.join(', ')}`);
});

const ids = Array.from({ length: rooms }, (_, i) => `room-${i}`);
for (const [i, id] of ids.entries()) await pool.createRoom(id, { scene: roomScene(i + 1) });
console.log(
  `${rooms} rooms on ${pool.workerCount} workers: ${ids.map((id) => `${id}@${pool.workerOf(id)}`).join(' ')}`,
);
await pool.start();

// players: every 100 ms a kick to a body of one room, now and then a new ball
const random = createRandom(42);
const started = performance.now();
let moved = false;
while (performance.now() - started < seconds * 1000) {
  await sleep(100);
  const room = ids[random.int(ids.length)];
  await pool.command(room, {
    kind: 'impulse',
    body: 1 + random.int(199),
    impulse: { x: random.range(-20, 20), y: random.range(0, 40) },
  });
  if (random.int(5) === 0) {
    await pool.command(room, {
      kind: 'spawn',
      body: {
        type: 'dynamic',
        position: { x: random.range(-8, 8), y: 25 },
        shapes: [{ kind: 'circle', radius: 0.5 }],
      },
    });
  }
  if (!moved && performance.now() - started > (seconds * 1000) / 2 && pool.workerCount > 1) {
    const to = (pool.workerOf(ids[0]) + 1) % pool.workerCount;
    await pool.moveRoom(ids[0], to);
    console.log(`moved ${ids[0]} to worker ${to}`);
    moved = true;
  }
}
await pool.stop();

const stats = await pool.stats();
const f = (x: number) => x.toFixed(2).padStart(6);
for (const [w, s] of stats.entries()) {
  console.log(
    `\nworker ${w}: ${s.ticks} ticks, ${s.dropped} dropped; tick p50 ${f(s.tick.p50)} p99 ${f(s.tick.p99)} max ${f(s.tick.max)} ms`,
  );
  for (const r of s.rooms) {
    const hash = (await pool.stateHash(r.room)).toString(16).padStart(8, '0');
    console.log(
      `  ${r.room.padEnd(8)} ${String(r.steps).padStart(5)} steps  step p50 ${f(r.step.p50)} p95 ${f(r.step.p95)} p99 ${f(r.step.p99)} ms  hash ${hash}`,
    );
  }
}
await pool.close();
