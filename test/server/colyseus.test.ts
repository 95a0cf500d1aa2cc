import { Client, type Room as ClientRoom } from '@colyseus/sdk';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { CommandMessage } from '../../examples/colyseus/physics-room';
import { startPhysicsServer } from '../../examples/colyseus/server';
import type { PhysicsState } from '../../examples/colyseus/state';
import type { SceneBody } from '../../scenes/types';
import { replayPhysicsRoom as replay } from '../helpers/physics-room-replay';

/*
 * The Colyseus example (examples/colyseus): a room whose state is a Fulcrum world. What its clients
 * receive is the world a plain game room on this thread reaches after the same steps and commands,
 * to the last bit of the float32 the state carries; bad commands are refused with the FulcrumError's
 * message and change nothing. The waits are for messages; what is checked does not depend on when
 * they came.
 */

type Server = Awaited<ReturnType<typeof startPhysicsServer>>['server'];
let server: Server;
let endpoint: string;

beforeAll(async () => {
  const started = await startPhysicsServer(0, '127.0.0.1');
  server = started.server;
  endpoint = `http://127.0.0.1:${started.port}`;
});

afterAll(async () => {
  await server.gracefullyShutdown(false);
});

/** the first state the room sends (after a change) that satisfies `test`, copied out */
function stateWhere(room: ClientRoom<PhysicsState>, test: (state: PhysicsState) => boolean) {
  return new Promise<{ step: number; poses: number[]; count: number }>((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('no such state within 20 s')), 20_000);
    const look = (state: PhysicsState) => {
      if (!test(state)) return;
      clearTimeout(timer);
      room.onStateChange.remove(look);
      const poses: number[] = [];
      for (const body of state.bodies) poses.push(body.x, body.y, body.angle);
      resolve({ step: state.step, poses, count: state.bodies.length });
    };
    room.onStateChange(look);
  });
}

/** the next answer to command `id` */
function answer(room: ClientRoom<PhysicsState>, id: number) {
  return new Promise<{ kind: 'accepted'; step: number } | { kind: 'refused'; message: string }>((resolve) => {
    room.onMessage('accepted', (m: { id: number; step: number }) => {
      if (m.id === id) resolve({ kind: 'accepted', step: m.step });
    });
    room.onMessage('refused', (m: { id: number; message: string }) => {
      if (m.id === id) resolve({ kind: 'refused', message: m.message });
    });
  });
}

const ball: SceneBody = {
  type: 'dynamic',
  position: { x: -2, y: 18 },
  linearVelocity: { x: 3, y: 0 },
  shapes: [{ kind: 'circle', radius: 0.6, density: 2 }],
};

describe('a Colyseus room whose state is a Fulcrum world', () => {
  it('sends its clients the world a plain game room reaches after the same steps and commands', async () => {
    const client = new Client(endpoint);
    const room = await client.joinOrCreate<PhysicsState>('physics', { seed: 3 });
    try {
      const first = await stateWhere(room, (s) => s.step >= 30);
      expect(first.count).toBe(200);
      expect(first.poses).toEqual(replay(3, first.step));

      // a second client in the same room sees the same world
      const other = await new Client(endpoint).joinById<PhysicsState>(room.roomId);
      const seen = await stateWhere(other, (s) => s.step > first.step);
      expect(seen.poses).toEqual(replay(3, seen.step));
      await other.leave();

      // a spawned ball and an impulse, applied at the step boundary the room answers with
      const spawn: CommandMessage = { id: 1, command: { kind: 'spawn', body: ball } };
      const kick: CommandMessage = {
        id: 2,
        command: { kind: 'impulse', body: 40, impulse: { x: 0, y: 25 } },
      };
      const spawned = answer(room, 1);
      const kicked = answer(room, 2);
      room.send('command', spawn);
      room.send('command', kick);
      const a = await spawned;
      const b = await kicked;
      if (a.kind !== 'accepted' || b.kind !== 'accepted') throw new Error('a command was refused');
      expect(b.step).toBeGreaterThanOrEqual(a.step);
      const after = await stateWhere(room, (s) => s.step >= b.step + 30);
      expect(after.count).toBe(201);
      const commands = [
        { step: a.step, command: spawn.command },
        { step: b.step, command: kick.command },
      ];
      expect(after.poses).toEqual(replay(3, after.step, commands));
      // the ball moved as a body does: it fell from 18 m and went right
      const [bx, by] = after.poses.slice(3 * 200, 3 * 200 + 2);
      expect(by).toBeLessThan(18);
      expect(bx).toBeGreaterThan(-2);
    } finally {
      await room.leave();
    }
  });

  it('refuses a bad command with the FulcrumError that names it, and queues nothing', async () => {
    const room = await new Client(endpoint).joinOrCreate<PhysicsState>('physics', { seed: 5 });
    try {
      const bad: CommandMessage = {
        id: 7,
        command: { kind: 'velocity', body: 10, velocity: { x: Number.NaN, y: 0 } },
      };
      const outOfRange: CommandMessage = {
        id: 8,
        command: { kind: 'impulse', body: 999, impulse: { x: 1, y: 0 } },
      };
      const first = answer(room, 7);
      const second = answer(room, 8);
      room.send('command', bad);
      room.send('command', outOfRange);
      const refusedNaN = await first;
      const refusedIndex = await second;
      expect(refusedNaN.kind).toBe('refused');
      expect(refusedNaN.kind === 'refused' && refusedNaN.message).toMatch(/command\.velocity/);
      expect(refusedIndex.kind === 'refused' && refusedIndex.message).toMatch(/command\.body .*999/);
      const later = await stateWhere(room, (s) => s.step >= 20);
      expect(later.count).toBe(200);
      expect(later.poses).toEqual(replay(5, later.step));
    } finally {
      await room.leave();
    }
  });
});
