/**
 * Game rooms spread over a pool of worker_threads workers, each room a Fulcrum World stepping at 60 Hz
 * in its worker. The pool places rooms, forwards commands, moves rooms between workers (and out of the
 * pool and into it, to travel to another process or machine), gathers step statistics, and reports a worker that fails: every promise waiting on it is rejected and a 'failure'
 * event names the rooms it took with it.
 */
import { EventEmitter } from 'node:events';
import { availableParallelism } from 'node:os';
import { Worker } from 'node:worker_threads';
import { FulcrumError } from '../../src/index';
import type { Message, Reply, Request, WorkerStats } from './protocol';
import type { PackedRoom, RoomCommand, RoomSpec } from './room';

export interface RoomPoolOptions {
  /** workers in the pool; default the machine's cores */
  workers?: number;
  /** the workers' script; default ./worker-entry.mjs (tests give a failing one) */
  workerUrl?: URL;
  /** ticks a worker may run at once to catch up when late; later ones are dropped. Default 3 */
  maxCatchUp?: number;
}

/** What a 'failure' event carries. */
export interface WorkerFailure {
  worker: number;
  error: Error;
  /** the rooms that were in the worker, now lost */
  rooms: string[];
}

interface Pending {
  resolve(value: unknown): void;
  reject(error: Error): void;
}

/** One worker of the pool and the requests it has not answered yet. */
class PoolWorker {
  readonly thread: Worker;
  readonly pending = new Map<number, Pending>();
  failure: Error | undefined;
  #nextId = 0;
  #ending = false;

  constructor(index: number, url: URL, onFailure: (error: Error) => void) {
    this.thread = new Worker(url);
    this.thread.on('message', (reply: Reply) => {
      const pending = this.pending.get(reply.id);
      if (pending === undefined) return;
      this.pending.delete(reply.id);
      if (reply.ok) pending.resolve(reply.value);
      else {
        const { name, message } = reply.error;
        pending.reject(name === 'FulcrumError' ? new FulcrumError(message) : new Error(message));
      }
    });
    const fail = (cause: Error) => {
      if (this.failure !== undefined) return;
      const error = new Error(`room worker ${index} failed: ${cause.message}`, { cause });
      this.failure = error;
      for (const pending of this.pending.values()) pending.reject(error);
      this.pending.clear();
      onFailure(error);
    };
    this.thread.on('error', fail);
    this.thread.on('messageerror', fail);
    this.thread.on('exit', (code) => {
      if (!this.#ending) fail(new Error(`the worker exited with code ${code}`));
    });
  }

  request(request: Request, transfer: ArrayBuffer[] = []): Promise<unknown> {
    if (this.failure !== undefined) return Promise.reject(this.failure);
    const id = this.#nextId++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      const message: Message = { id, request };
      this.thread.postMessage(message, transfer);
    });
  }

  async end(): Promise<void> {
    this.#ending = true;
    await this.thread.terminate();
  }
}

export class RoomPool extends EventEmitter<{ failure: [WorkerFailure] }> {
  readonly #workers: PoolWorker[];
  readonly #maxCatchUp: number;
  /** room id -> the index of its worker */
  readonly #placement = new Map<string, number>();
  /** rooms being moved: their commands wait here, in order, until the move is done */
  readonly #moving = new Map<string, Promise<void>>();
  /** rooms lost with a failed worker, and why */
  readonly #lost = new Map<string, Error>();

  constructor(options: RoomPoolOptions = {}) {
    super();
    const count = options.workers ?? availableParallelism();
    if (!Number.isInteger(count) || count < 1) {
      throw new FulcrumError(`options.workers must be a positive integer, got ${count}`);
    }
    this.#maxCatchUp = options.maxCatchUp ?? 3;
    const url = options.workerUrl ?? new URL('./worker-entry.mjs', import.meta.url);
    this.#workers = [];
    for (let i = 0; i < count; i++) {
      this.#workers.push(new PoolWorker(i, url, (error) => this.#failed(i, error)));
    }
  }

  get workerCount(): number {
    return this.#workers.length;
  }

  /** The worker a room is in. */
  workerOf(room: string): number {
    const worker = this.#placement.get(room);
    if (worker === undefined) throw this.#lost.get(room) ?? new Error(`no room ${JSON.stringify(room)}`);
    return worker;
  }

  /**
   * Makes a room in `worker`, or else in the worker with fewest rooms (the lowest index on a tie).
   * It steps from the worker's next tick on.
   */
  createRoom(room: string, spec: RoomSpec, worker?: number): Promise<void> {
    return this.#place(room, worker, { kind: 'create', room, spec });
  }

  /**
   * Brings in a room packed elsewhere (by `detachRoom` of this or another pool, or `Room.pack` in
   * another process or machine) to `worker`, or else to the worker with fewest rooms. It goes on from
   * where it was packed, with its step count and the commands it had not applied yet, from the
   * worker's next tick on. The bytes are copied: the caller keeps `packed`.
   */
  attachRoom(room: string, packed: PackedRoom, worker?: number): Promise<void> {
    return this.#place(room, worker, { kind: 'attach', room, packed });
  }

  /**
   * Takes a room out of the pool at a step boundary of its worker and answers it packed (snapshot,
   * steps, commands not yet applied), to go on elsewhere: `attachRoom` here or in another pool,
   * `Room.unpack` in another process. Requests to the room made after this call are refused.
   */
  detachRoom(room: string): Promise<PackedRoom> {
    return this.#after(room, async () => {
      const reply = this.#workers[this.workerOf(room)].request({ kind: 'detach', room });
      this.#placement.delete(room);
      return (await reply) as PackedRoom;
    });
  }

  /** Ends a room (after any move of it in progress). */
  async removeRoom(room: string): Promise<void> {
    await this.#after(room, async () => {
      await this.#workers[this.workerOf(room)].request({ kind: 'remove', room });
      this.#placement.delete(room);
    });
  }

  /** Queues a command for the room's next step; commands to a room apply in the order they are sent. */
  command(room: string, command: RoomCommand): Promise<void> {
    return this.#toRoom(room, { kind: 'command', room, command }) as Promise<void>;
  }

  /** The room's Fulcrum state hash, between two of its steps. */
  stateHash(room: string): Promise<number> {
    return this.#toRoom(room, { kind: 'hash', room }) as Promise<number>;
  }

  /** The room's world as snapshot bytes, and the steps it has taken. */
  snapshot(room: string): Promise<{ snapshot: Uint8Array; steps: number }> {
    return this.#toRoom(room, { kind: 'snapshot', room }) as Promise<{ snapshot: Uint8Array; steps: number }>;
  }

  /**
   * Moves a room to worker `to`: packed at a step boundary of its worker (snapshot, steps, commands not
   * yet applied), unpacked in the other, and stepped there from its next tick on. Commands sent while
   * it moves wait and follow it, in order. On the clock, the room misses the ticks the move takes.
   */
  moveRoom(room: string, to: number): Promise<void> {
    const move = this.#after(room, async () => {
      this.#checkWorker(to);
      const from = this.workerOf(room);
      if (from === to) return;
      const packed = (await this.#workers[from].request({ kind: 'detach', room })) as PackedRoom;
      this.#placement.set(room, to);
      await this.#workers[to].request({ kind: 'attach', room, packed }, [
        packed.snapshot.buffer as ArrayBuffer,
      ]);
    });
    const settled = move.then(
      () => undefined,
      () => undefined,
    );
    this.#moving.set(room, settled);
    void settled.then(() => {
      if (this.#moving.get(room) === settled) this.#moving.delete(room);
    });
    return move;
  }

  /**
   * Steps every room `ticks` times now, each worker its rooms in turn (the clocks must be stopped).
   * Refused, stepping nothing, once a worker has failed: its rooms could not keep step with the rest.
   */
  async step(ticks = 1): Promise<void> {
    const failed = this.#workers.find((w) => w.failure !== undefined);
    if (failed !== undefined) throw failed.failure;
    await Promise.all(this.#workers.map((w) => w.request({ kind: 'step', ticks })));
  }

  /** Starts every worker's 60 Hz clock. */
  async start(): Promise<void> {
    await Promise.all(this.#workers.map((w) => w.request({ kind: 'start', maxCatchUp: this.#maxCatchUp })));
  }

  async stop(): Promise<void> {
    await Promise.all(this.#workers.map((w) => w.request({ kind: 'stop' })));
  }

  /** Each worker's rooms and timings; `reset` starts the next figures afresh. */
  stats(reset = false): Promise<WorkerStats[]> {
    return Promise.all(this.#workers.map((w) => w.request({ kind: 'stats', reset }) as Promise<WorkerStats>));
  }

  /** Ends every worker. */
  async close(): Promise<void> {
    await Promise.all(this.#workers.map((w) => w.end()));
  }

  /** a request to the room's worker, sent after any move of the room in progress */
  #toRoom(room: string, request: Request): Promise<unknown> {
    return this.#after(room, () => this.#workers[this.workerOf(room)].request(request));
  }

  /** async, so that a request refused at once (an unknown or lost room) is a rejected promise too */
  async #after<T>(room: string, then: () => Promise<T>): Promise<T> {
    const moving = this.#moving.get(room);
    // not moving: send now, so that requests keep the order they were made in
    return moving === undefined ? then() : moving.then(then);
  }

  /** a room made or brought into `worker` (default the least loaded) by `request` */
  async #place(room: string, worker: number | undefined, request: Request): Promise<void> {
    if (this.#placement.has(room)) throw new Error(`room ${JSON.stringify(room)} exists already`);
    const target = worker ?? this.#leastLoaded();
    this.#checkWorker(target);
    this.#placement.set(room, target);
    this.#lost.delete(room);
    try {
      await this.#workers[target].request(request);
    } catch (error) {
      if (this.#placement.get(room) === target) this.#placement.delete(room);
      throw error;
    }
  }

  #leastLoaded(): number {
    const counts = this.#workers.map(() => 0);
    for (const w of this.#placement.values()) counts[w]++;
    let best = -1;
    for (let i = 0; i < counts.length; i++) {
      if (this.#workers[i].failure === undefined && (best < 0 || counts[i] < counts[best])) best = i;
    }
    if (best < 0) throw new Error('every worker of the pool has failed');
    return best;
  }

  #checkWorker(index: number): void {
    if (!Number.isInteger(index) || index < 0 || index >= this.#workers.length) {
      throw new FulcrumError(`worker must be an integer in [0, ${this.#workers.length - 1}], got ${index}`);
    }
    const failure = this.#workers[index].failure;
    if (failure !== undefined) throw failure;
  }

  #failed(worker: number, error: Error): void {
    const rooms: string[] = [];
    for (const [room, w] of this.#placement) {
      if (w !== worker) continue;
      rooms.push(room);
      this.#placement.delete(room);
      this.#lost.set(room, error);
    }
    this.emit('failure', { worker, error, rooms });
  }
}
