import { afterEach, describe, expect, it } from 'vitest';
import { ROOM_DT, type RoomCommand } from '../../examples/server/room';
import { RoomPool, type WorkerFailure } from '../../examples/server/room-pool';
import { roomScene } from '../../examples/server/scene';
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { FulcrumError, stateHash, World } from '../../src/index';
import { plainRoomHash, roomProgram, roomSpec } from '../helpers/room-program';
import { workerScript } from '../helpers/worker-script';

/*
 * The example game server's RoomPool (examples/server): rooms in worker threads give the bits a plain
 * World gives for the same calls on this thread, also after moving to another worker mid-run; a
 * worker that fails rejects what waits on it and says so.
 */

const pools: RoomPool[] = [];

function openPool(workers: number, workerUrl?: URL): RoomPool {
  const pool = new RoomPool(workerUrl ? { workers, workerUrl } : { workers });
  pools.push(pool);
  return pool;
}

afterEach(async () => {
  await Promise.all(pools.splice(0).map((pool) => pool.close()));
});

const STEPS = 150;

describe('RoomPool', () => {
  it('a room moved to another worker mid-run gives the bits of one never moved and of a plain World', async () => {
    const pool = openPool(2);
    await pool.createRoom('moved', roomSpec, 0);
    await pool.createRoom('stays', roomSpec, 0);
    await pool.createRoom('other', { scene: roomScene(8) }, 1);
    let hashAtMove = 0;
    for (let t = 0; t < STEPS; t++) {
      const commands = roomProgram.get(t) ?? [];
      if (t === 45) {
        hashAtMove = await pool.stateHash('moved');
        // one command queued before the move travels with the room; one sent during it follows it
        const before = pool.command('moved', commands[0]);
        const move = pool.moveRoom('moved', 1);
        const during = pool.command('moved', commands[1]);
        await Promise.all([before, move, during]);
        expect(pool.workerOf('moved')).toBe(1);
      } else {
        for (const command of commands) await pool.command('moved', command);
      }
      for (const command of commands) await pool.command('stays', command);
      await pool.step();
    }
    const moved = await pool.stateHash('moved');
    expect(moved).toBe(await pool.stateHash('stays'));
    expect(moved).toBe(plainRoomHash(STEPS));
    // the room moved between those hashes: equal hashes of a world at rest would prove little
    expect(moved).not.toBe(hashAtMove);
    expect(hashAtMove).toBe(plainRoomHash(45));

    // the moved room's snapshot restores here to the same state, and it kept count of its steps
    const { snapshot, steps } = await pool.snapshot('moved');
    expect(steps).toBe(STEPS);
    expect(stateHash(World.restore(snapshot))).toBe(moved);
    const stats = await pool.stats();
    expect(stats[0].rooms.map((r) => r.room)).toEqual(['stays']);
    expect(stats[1].rooms.map((r) => r.room)).toEqual(['other', 'moved']);
    expect(stats[0].rooms[0].step.count).toBe(STEPS);
  });

  it('rooms on the 60 Hz clock step as a plain World does, for as many steps as they took', async () => {
    const pool = openPool(1);
    await pool.createRoom('a', roomSpec);
    await pool.start();
    // wait for some steps, however long they take on this machine
    while ((await pool.stats())[0].rooms[0].steps < 20) await new Promise((r) => setTimeout(r, 20));
    await pool.stop();
    const [stats] = await pool.stats();
    const steps = stats.rooms[0].steps;
    const { world } = buildFulcrumWorld(roomSpec.scene, { enableSleep: false });
    for (let t = 0; t < steps; t++) world.step(ROOM_DT);
    expect(await pool.stateHash('a')).toBe(stateHash(world));
  });

  it('rejects a bad command with a FulcrumError and queues nothing', async () => {
    const pool = openPool(1);
    await pool.createRoom('a', roomSpec);
    const bad: RoomCommand[] = [
      { kind: 'impulse', body: 200, impulse: { x: 1, y: 1 } },
      { kind: 'impulse', body: 1.5, impulse: { x: 1, y: 1 } },
      { kind: 'velocity', body: 3, velocity: { x: Number.NaN, y: 0 } },
      {
        kind: 'spawn',
        body: { type: 'dynamic', position: { x: 0, y: 5 }, shapes: [{ kind: 'circle', radius: -1 }] },
      },
      { kind: 'jump', body: 1 } as unknown as RoomCommand,
    ];
    for (const command of bad) {
      const result = pool.command('a', command);
      await expect(result).rejects.toBeInstanceOf(FulcrumError);
      await expect(result).rejects.toThrow(/command|radius/);
    }
    await pool.step(30);
    const { world } = buildFulcrumWorld(roomSpec.scene, { enableSleep: false });
    for (let t = 0; t < 30; t++) world.step(ROOM_DT);
    expect(await pool.stateHash('a')).toBe(stateHash(world));
    await pool.removeRoom('a');
    await expect(pool.stateHash('a')).rejects.toThrow(/no room "a"/);
    expect((await pool.stats())[0].rooms).toEqual([]);
  });

  describe('reports a worker that fails, and hangs nothing', () => {
    const crashing = () => workerScript('test/server/fixtures/crashing-room-entry.mjs');

    for (const [room, why] of [
      ['exit', /room worker 0 failed: the worker exited with code 7/],
      ['throw', /room worker 0 failed: thrown in the worker/],
    ] as const) {
      it(`when it ${room === 'exit' ? 'exits' : 'throws'}`, async () => {
        const pool = openPool(2, crashing());
        const failures: WorkerFailure[] = [];
        pool.on('failure', (failure) => failures.push(failure));
        await pool.createRoom('a', roomSpec, 0);
        await pool.createRoom('b', roomSpec, 1);
        await pool.step(2);

        await expect(pool.createRoom(room, roomSpec, 0)).rejects.toThrow(why);
        expect(failures.length).toBe(1);
        expect(failures[0].worker).toBe(0);
        expect(failures[0].rooms.sort()).toEqual(['a', room]);
        expect(failures[0].error.message).toMatch(why);
        // the lost room's requests and the pool's, which need every worker, are refused at once
        await expect(pool.stateHash('a')).rejects.toThrow(why);
        await expect(
          pool.command('a', { kind: 'impulse', body: 1, impulse: { x: 0, y: 1 } }),
        ).rejects.toThrow(why);
        await expect(pool.step()).rejects.toThrow(why);
        // the other worker's room goes on, and new rooms go there
        const { world } = buildFulcrumWorld(roomSpec.scene, { enableSleep: false });
        for (let t = 0; t < 2; t++) world.step(ROOM_DT);
        expect(await pool.stateHash('b')).toBe(stateHash(world));
        await pool.createRoom('c', roomSpec);
        expect(pool.workerOf('c')).toBe(1);
      }, 20_000);
    }
  });
});
