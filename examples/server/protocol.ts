/** The messages between a RoomPool (main thread) and its room workers. */

import type { PackedRoom, RoomCommand, RoomSpec } from './room';
import type { Percentiles } from './samples';

export type Request =
  | { kind: 'create'; room: string; spec: RoomSpec }
  | { kind: 'attach'; room: string; packed: PackedRoom }
  /** takes the room out of the worker at a step boundary and answers it packed */
  | { kind: 'detach'; room: string }
  | { kind: 'remove'; room: string }
  | { kind: 'command'; room: string; command: RoomCommand }
  | { kind: 'hash'; room: string }
  | { kind: 'snapshot'; room: string }
  /** steps every room of the worker `ticks` times, now (the clock must be stopped) */
  | { kind: 'step'; ticks: number }
  | { kind: 'start'; maxCatchUp: number }
  | { kind: 'stop' }
  | { kind: 'stats'; reset: boolean };

export interface RoomStats {
  room: string;
  steps: number;
  /** time of this room's steps, ms (commands applied and the world stepped) */
  step: Percentiles;
}

export interface WorkerStats {
  /** the worker's rooms, in the order it steps them */
  rooms: RoomStats[];
  /** time of a room step, ms, over every room of the worker */
  step: Percentiles;
  /** time of a tick, ms: every room of the worker stepped once */
  tick: Percentiles;
  /** ticks run on the clock */
  ticks: number;
  /** ticks the clock let go because the worker fell further behind than its catch-up limit */
  dropped: number;
}

export interface Message {
  id: number;
  request: Request;
}

export type Reply =
  | { id: number; ok: true; value: unknown }
  | { id: number; ok: false; error: { name: string; message: string } };
