/**
 * The worker's side of a RoomPool: its rooms, stepped in turn on a fixed 60 Hz clock in the order they
 * came to the worker, and the answers to the pool's requests. A request is handled between two ticks,
 * so commands, moves and snapshots happen at step boundaries.
 */
import { stateHash } from '../../src/index';
import type { Message, Reply, Request, WorkerStats } from './protocol';
import { ROOM_DT, Room } from './room';
import { Samples } from './samples';

/** tick times kept for the statistics: the last 10 s */
const TICK_SAMPLES = 600;
/** room step times kept for the worker's statistics, over all its rooms */
const STEP_SAMPLES = 16384;

/** A fixed-rate timer: runs the ticks due since it started, at most `maxCatchUp` at once. */
class Clock {
  readonly #period: number;
  readonly #tick: () => void;
  #maxCatchUp = 1;
  #origin = 0;
  #done = 0;
  #timer: ReturnType<typeof setTimeout> | undefined;
  ticks = 0;
  dropped = 0;

  constructor(period: number, tick: () => void) {
    this.#period = period;
    this.#tick = tick;
  }

  get running(): boolean {
    return this.#timer !== undefined;
  }

  start(maxCatchUp: number): void {
    if (this.running) return;
    this.#maxCatchUp = maxCatchUp;
    this.#origin = performance.now();
    this.#done = 0;
    this.#schedule();
  }

  stop(): void {
    clearTimeout(this.#timer);
    this.#timer = undefined;
  }

  #schedule(): void {
    const wait = this.#origin + (this.#done + 1) * this.#period * 1000 - performance.now();
    this.#timer = setTimeout(() => this.#run(), Math.max(0, wait));
  }

  #run(): void {
    const due = Math.floor((performance.now() - this.#origin) / (this.#period * 1000));
    if (due - this.#done > this.#maxCatchUp) {
      // too far behind: run the latest few and let the rest go, rather than fall ever further behind
      this.dropped += due - this.#done - this.#maxCatchUp;
      this.#done = due - this.#maxCatchUp;
    }
    while (this.#done < due) {
      this.#tick();
      this.#done++;
      this.ticks++;
    }
    this.#schedule();
  }
}

export class RoomWorker {
  /** in the order they came to this worker: the order they are stepped in */
  readonly #rooms = new Map<string, Room>();
  readonly #tickTimes = new Samples(TICK_SAMPLES);
  readonly #stepTimes = new Samples(STEP_SAMPLES);
  readonly #clock = new Clock(ROOM_DT, () => this.tick());

  tick(): void {
    const start = performance.now();
    for (const room of this.#rooms.values()) this.#stepTimes.add(room.step());
    this.#tickTimes.add(performance.now() - start);
  }

  handle(request: Request): { value: unknown; transfer?: ArrayBuffer[] } {
    switch (request.kind) {
      case 'create':
        this.#add(Room.create(request.room, request.spec));
        return { value: undefined };
      case 'attach':
        this.#add(Room.unpack(request.room, request.packed));
        return { value: undefined };
      case 'detach': {
        const packed = this.#room(request.room).pack();
        this.#rooms.delete(request.room);
        return { value: packed, transfer: [packed.snapshot.buffer as ArrayBuffer] };
      }
      case 'remove':
        this.#room(request.room);
        this.#rooms.delete(request.room);
        return { value: undefined };
      case 'command':
        this.#room(request.room).command(request.command);
        return { value: undefined };
      case 'hash':
        return { value: stateHash(this.#room(request.room).world) };
      case 'snapshot': {
        const room = this.#room(request.room);
        const snapshot = room.world.snapshot();
        return { value: { snapshot, steps: room.steps }, transfer: [snapshot.buffer as ArrayBuffer] };
      }
      case 'step':
        if (this.#clock.running) throw new Error('step: the clock is running; stop it first');
        for (let t = 0; t < request.ticks; t++) this.tick();
        return { value: undefined };
      case 'start':
        this.#clock.start(request.maxCatchUp);
        return { value: undefined };
      case 'stop':
        this.#clock.stop();
        return { value: undefined };
      case 'stats':
        return { value: this.#stats(request.reset) };
    }
  }

  #add(room: Room): void {
    if (this.#rooms.has(room.id))
      throw new Error(`room ${JSON.stringify(room.id)} is already in this worker`);
    this.#rooms.set(room.id, room);
  }

  #room(id: string): Room {
    const room = this.#rooms.get(id);
    if (room === undefined) throw new Error(`no room ${JSON.stringify(id)} in this worker`);
    return room;
  }

  #stats(reset: boolean): WorkerStats {
    const stats: WorkerStats = {
      rooms: [...this.#rooms.values()].map((room) => ({
        room: room.id,
        steps: room.steps,
        step: room.stepTimes.percentiles(),
      })),
      step: this.#stepTimes.percentiles(),
      tick: this.#tickTimes.percentiles(),
      ticks: this.#clock.ticks,
      dropped: this.#clock.dropped,
    };
    if (reset) {
      this.#tickTimes.clear();
      this.#stepTimes.clear();
      for (const room of this.#rooms.values()) room.stepTimes.clear();
      this.#clock.ticks = 0;
      this.#clock.dropped = 0;
    }
    return stats;
  }
}

/** The worker's end of its channel to the pool: its parentPort. */
export interface RoomPort {
  on(event: 'message', listener: (message: Message) => void): void;
  postMessage(reply: Reply, transfer: ArrayBuffer[]): void;
}

/** Serves a RoomWorker on `port`. */
export function serveRooms(port: RoomPort): void {
  const worker = new RoomWorker();
  port.on('message', ({ id, request }: Message) => {
    let reply: Reply;
    let transfer: ArrayBuffer[] = [];
    try {
      const answer = worker.handle(request);
      reply = { id, ok: true, value: answer.value };
      transfer = answer.transfer ?? [];
    } catch (error) {
      const e = error instanceof Error ? error : new Error(String(error));
      reply = { id, ok: false, error: { name: e.name, message: e.message } };
    }
    port.postMessage(reply, transfer);
  });
}
