import { fork } from 'node:child_process';
import { resolve } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import type { RoomCommand } from '../../examples/server/room';
import { RoomPool } from '../../examples/server/room-pool';
import { plainRoomHash, roomProgram, roomSpec } from '../helpers/room-program';
import type { Arrival, Travel } from './fixtures/room-process';

/*
 * Snapshots travel: a game room of examples/server's RoomPool is taken out of its worker thread at a
 * step boundary, sent as bytes to another process, restored and stepped on there, sent back and
 * brought into another worker of the pool; at every stop its state hash is the hash of the same room
 * that never moved and of a plain World given the same calls on this thread.
 */

const pools: RoomPool[] = [];
afterEach(async () => {
  await Promise.all(pools.splice(0).map((pool) => pool.close()));
});

/** Sends the room to a new process, which steps it to `until` and sends it back. */
function travel(message: Travel): Promise<Arrival> {
  const child = fork(resolve(__dirname, 'fixtures/room-process.ts'), {
    execArgv: ['--import', 'tsx'],
    // the V8 serializer: a snapshot's Uint8Array travels as bytes, not as JSON
    serialization: 'advanced',
  });
  return new Promise((done, failed) => {
    let arrival: Arrival | undefined;
    child.once('message', (m) => {
      arrival = m as Arrival;
    });
    child.once('error', failed);
    child.once('exit', (code) => {
      if (arrival !== undefined) done(arrival);
      else failed(new Error(`the room's process exited with code ${code} and sent nothing back`));
    });
    child.send(message);
  });
}

/** the program's commands from step `from` (inclusive) to `to` (exclusive), as [step, command] */
function commandsBetween(from: number, to: number): [number, RoomCommand][] {
  const list: [number, RoomCommand][] = [];
  for (let t = from; t < to; t++) for (const c of roomProgram.get(t) ?? []) list.push([t, c]);
  return list;
}

describe('a game room travels', () => {
  it('from a worker thread to another process and back to another worker, with the same bits', async () => {
    const pool = new RoomPool({ workers: 2 });
    pools.push(pool);
    await pool.createRoom('travelling', roomSpec, 0);
    await pool.createRoom('stays', roomSpec, 1);
    const LEAVE = 45;
    const BACK = 100;
    const END = 150;
    for (let t = 0; t < LEAVE; t++) {
      for (const c of roomProgram.get(t) ?? []) {
        await pool.command('travelling', c);
        await pool.command('stays', c);
      }
      await pool.step();
    }
    const hashAtLeave = await pool.stateHash('travelling');
    expect(hashAtLeave).toBe(plainRoomHash(LEAVE));

    // the first command of step 45 is queued before the room leaves and travels with it, unapplied
    const [first, ...rest] = roomProgram.get(LEAVE) ?? [];
    await pool.command('travelling', first);
    const packed = await pool.detachRoom('travelling');
    expect(packed.steps).toBe(LEAVE);
    expect(packed.pending).toEqual([first]);
    await expect(pool.stateHash('travelling')).rejects.toThrow(/no room "travelling"/);

    const away = travel({
      packed,
      until: BACK,
      commands: [...rest.map((c): [number, RoomCommand] => [LEAVE, c]), ...commandsBetween(LEAVE + 1, BACK)],
    });
    // meanwhile the room that stayed goes on in the pool
    for (let t = LEAVE; t < BACK; t++) {
      for (const c of roomProgram.get(t) ?? []) await pool.command('stays', c);
      await pool.step();
    }
    const arrival = await away;
    expect(arrival.pid).not.toBe(process.pid);
    expect(arrival.packed.steps).toBe(BACK);
    expect(arrival.hash).toBe(await pool.stateHash('stays'));
    expect(arrival.hash).toBe(plainRoomHash(BACK));
    // the room moved while away: equal hashes of a world at rest would prove little
    expect(arrival.hash).not.toBe(hashAtLeave);

    // back into the pool, in the other worker
    await pool.attachRoom('travelling', arrival.packed, 1);
    expect(pool.workerOf('travelling')).toBe(1);
    for (let t = BACK; t < END; t++) {
      for (const c of roomProgram.get(t) ?? []) {
        await pool.command('travelling', c);
        await pool.command('stays', c);
      }
      await pool.step();
    }
    const final = await pool.stateHash('travelling');
    expect(final).toBe(await pool.stateHash('stays'));
    expect(final).toBe(plainRoomHash(END));
    expect((await pool.snapshot('travelling')).steps).toBe(END);
  });

  it('refuses to bring in a room under a name the pool has', async () => {
    const pool = new RoomPool({ workers: 1 });
    pools.push(pool);
    await pool.createRoom('a', roomSpec);
    const packed = await pool.detachRoom('a');
    await pool.createRoom('a', roomSpec);
    await expect(pool.attachRoom('a', packed)).rejects.toThrow(/room "a" exists already/);
    await pool.attachRoom('b', packed);
    expect(await pool.stateHash('b')).toBe(plainRoomHash(0));
  });
});
