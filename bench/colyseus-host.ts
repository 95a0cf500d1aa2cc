/**
 * One process of the Colyseus rooms benchmark (bench/colyseus-rooms.ts): a Colyseus server with the
 * physics room of examples/colyseus (a Fulcrum game room stepped at 60 Hz by Colyseus's fixed
 * timestep, each body's pose written into the room's schema after each step). The benchmark makes and
 * ends rooms through Colyseus's matchmaker and asks for the figures of a window of time over IPC.
 */

import { monitorEventLoopDelay, performance } from 'node:perf_hooks';
import { setTimeout as sleep } from 'node:timers/promises';
import { matchMaker, type Room } from '@colyseus/core';
import { PhysicsRoom, type PhysicsRoomOptions } from '../examples/colyseus/physics-room';
import { startPhysicsServer } from '../examples/colyseus/server';
import { type Percentiles, Samples } from '../examples/server/samples';

/** samples kept per figure: 60 rooms x 60 Hz x 4 s */
const SAMPLES = 16384;
/** the time of each room's fixed-step callback (the world's step and the schema's update), ms */
const roomTicks = new Samples(SAMPLES);
/** the time of each world step alone (commands applied, world.step), ms */
const worldSteps = new Samples(SAMPLES);
/** 1/60 s frame of wall time (from the time origin) -> the time of the rooms' steps due in it, ms */
const frameWork = new Map<number, number>();
const FRAME_MS = 1000 / 60;

/** The example's room, its fixed-step callback timed, kept while it has no client. */
class TimedPhysicsRoom extends PhysicsRoom {
  override onCreate(options: PhysicsRoomOptions = {}): void {
    // rooms without clients would be disposed after the seat reservation time
    this.autoDispose = false;
    super.onCreate(options);
  }

  /** when the room's first step ran: step k is due k frames later */
  #origin = -1;

  override setFixedTimestep(...[step, ...rest]: Parameters<Room['setFixedTimestep']>): void {
    super.setFixedTimestep(
      (ctx) => {
        const start = performance.now();
        step(ctx);
        const ms = performance.now() - start;
        roomTicks.add(ms);
        // a late room's catch-up steps count in the frames they were due in, as a RoomPool worker's
        // catch-up ticks are timed one by one
        if (this.#origin < 0) this.#origin = start - ctx.tick * FRAME_MS;
        const frame = Math.floor((this.#origin + ctx.tick * FRAME_MS) / FRAME_MS);
        frameWork.set(frame, (frameWork.get(frame) ?? 0) + ms);
        worldSteps.add(this.state.stepMs);
      },
      ...rest,
    );
  }
}

export type HostRequest =
  /** makes rooms of the 200-body scene (sleep off) with these seeds, answers their ids */
  | { kind: 'create'; seeds: number[] }
  /** ends every room */
  | { kind: 'clear' }
  /** every room's step count */
  | { kind: 'steps' }
  /** the figures of the next `ms` milliseconds */
  | { kind: 'measure'; ms: number };

export interface HostWindow {
  /** steps each room took in the window */
  steps: number[];
  /** the steps a room at 60 Hz takes in the window */
  expected: number;
  /** each room's fixed-step callback, ms */
  roomTick: Percentiles;
  /** each world step alone, ms */
  worldStep: Percentiles;
  /**
   * the time of the rooms' callbacks due in each 1/60 s of the window, ms: the work the process has
   * to do per frame, the counterpart of a RoomPool worker's tick (every room of the worker stepped once)
   */
  frame: Percentiles;
  /** how late the event loop ran a timer, ms (perf_hooks' event-loop delay) */
  loopDelay: { p50: number; p99: number; max: number };
  /** the share of the window the event loop was busy */
  utilization: number;
}

const { server, port } = await startPhysicsServer(0, '127.0.0.1');
server.define('timed-physics', TimedPhysicsRoom);
const rooms: TimedPhysicsRoom[] = [];

async function handle(request: HostRequest): Promise<unknown> {
  switch (request.kind) {
    case 'create': {
      const ids: string[] = [];
      for (const seed of request.seeds) {
        const { roomId } = await matchMaker.createRoom('timed-physics', { seed, enableSleep: false });
        rooms.push(matchMaker.getLocalRoomById(roomId) as TimedPhysicsRoom);
        ids.push(roomId);
      }
      return ids;
    }
    case 'clear':
      await Promise.all(rooms.splice(0).map((room) => room.disconnect()));
      return undefined;
    case 'steps':
      return rooms.map((room) => room.game.steps);
    case 'measure': {
      const before = rooms.map((room) => room.game.steps);
      roomTicks.clear();
      worldSteps.clear();
      frameWork.clear();
      const first = Math.ceil(performance.now() / FRAME_MS);
      const delay = monitorEventLoopDelay({ resolution: 5 });
      delay.enable();
      const busy = performance.eventLoopUtilization();
      await sleep(request.ms);
      const utilization = performance.eventLoopUtilization(busy).utilization;
      delay.disable();
      const frames = new Samples(Math.ceil(request.ms / FRAME_MS) + 1);
      for (let f = first; f < Math.floor(performance.now() / FRAME_MS); f++)
        frames.add(frameWork.get(f) ?? 0);
      const window: HostWindow = {
        steps: rooms.map((room, i) => room.game.steps - before[i]),
        expected: (request.ms / 1000) * 60,
        roomTick: roomTicks.percentiles(),
        worldStep: worldSteps.percentiles(),
        frame: frames.percentiles(),
        loopDelay: {
          p50: delay.percentile(50) / 1e6,
          p99: delay.percentile(99) / 1e6,
          max: delay.max / 1e6,
        },
        utilization,
      };
      return window;
    }
  }
}

process.on('message', async ({ id, request }: { id: number; request: HostRequest }) => {
  try {
    process.send?.({ id, ok: true, value: await handle(request) });
  } catch (error) {
    process.send?.({ id, ok: false, message: (error as Error).stack ?? String(error) });
  }
});
process.on('disconnect', () => process.exit(0));
process.send?.({ ready: port });
