/**
 * One game room's physics: a Fulcrum World stepping at a fixed 60 Hz, commanded by messages that are
 * applied at the start of the room's next step, in the order they came. A room can be packed up at a
 * step boundary (snapshot, step count, commands not yet applied) and unpacked elsewhere to go on with
 * the same bits.
 */

import { buildFulcrumWorld, createSceneBody } from '../../scenes/build-fulcrum';
import type { Scene, SceneBody, V } from '../../scenes/types';
import { type Body, FulcrumError, World } from '../../src/index';
import { Samples } from './samples';

/** The rooms' fixed step: 60 Hz. */
export const ROOM_DT = 1 / 60;

/** World settings a room may set (the rest are Fulcrum's defaults). */
export interface RoomSettings {
  enableSleep?: boolean;
  subSteps?: number;
}

/** What a room is made from: plain data, so it can be posted to a worker. */
export interface RoomSpec {
  scene: Scene;
  settings?: RoomSettings;
}

/**
 * A command to a room. Bodies are named by index: the scene's bodies in order, then the spawned ones
 * in the order they were spawned.
 */
export type RoomCommand =
  | { kind: 'impulse'; body: number; impulse: V }
  | { kind: 'velocity'; body: number; velocity: V }
  | { kind: 'spawn'; body: SceneBody };

/** A room packed up to move: everything needed to go on with the same bits. */
export interface PackedRoom {
  snapshot: Uint8Array;
  steps: number;
  pending: RoomCommand[];
}

/** step times kept per room for its statistics: the last 10 s at 60 Hz */
const STEP_SAMPLES = 600;

function finiteVector(argument: string, v: V): void {
  if (typeof v !== 'object' || v === null || !Number.isFinite(v.x) || !Number.isFinite(v.y)) {
    throw new FulcrumError(`${argument} must be a vector of finite numbers, got ${JSON.stringify(v)}`);
  }
}

export class Room {
  readonly id: string;
  readonly stepTimes = new Samples(STEP_SAMPLES);
  #world: World;
  /** the world's bodies by command index */
  readonly #bodies: Body[];
  #pending: RoomCommand[];
  #spawnsPending = 0;
  #steps: number;

  private constructor(id: string, world: World, steps: number, pending: RoomCommand[]) {
    this.id = id;
    this.#world = world;
    // a new world lists its bodies in the order they were made, a restored one in the same order
    this.#bodies = [...world.bodies];
    this.#steps = steps;
    this.#pending = [];
    for (const command of pending) this.command(command);
  }

  static create(id: string, spec: RoomSpec): Room {
    const { world } = buildFulcrumWorld(spec.scene, { ...spec.settings });
    return new Room(id, world, 0, []);
  }

  static unpack(id: string, packed: PackedRoom): Room {
    return new Room(id, World.restore(packed.snapshot), packed.steps, packed.pending);
  }

  get world(): World {
    return this.#world;
  }

  /** steps taken since the room was made (a moved room keeps counting) */
  get steps(): number {
    return this.#steps;
  }

  /** Queues a command for the next step; bad input throws a FulcrumError and queues nothing. */
  command(command: RoomCommand): void {
    switch (command?.kind) {
      case 'impulse':
      case 'velocity': {
        const count = this.#bodies.length + this.#spawnsPending;
        if (!Number.isInteger(command.body) || command.body < 0 || command.body >= count) {
          throw new FulcrumError(
            `command.body must be an integer in [0, ${count - 1}], got ${JSON.stringify(command.body)}`,
          );
        }
        finiteVector(
          `command.${command.kind}`,
          command.kind === 'impulse' ? command.impulse : command.velocity,
        );
        break;
      }
      case 'spawn':
        // made once in a world of its own, so that a bad body fails here and not inside a step
        buildFulcrumWorld({
          name: 'spawn check',
          gravity: { x: 0, y: 0 },
          bodies: [command.body],
          joints: [],
        });
        this.#spawnsPending++;
        break;
      default:
        throw new FulcrumError(
          `command.kind must be 'impulse', 'velocity' or 'spawn', got ${JSON.stringify(command)}`,
        );
    }
    this.#pending.push(structuredClone(command));
  }

  /** Applies the queued commands in order, then steps the world by 1/60 s; answers the time it took, ms. */
  step(): number {
    const start = performance.now();
    for (const command of this.#pending) {
      if (command.kind === 'impulse') this.#bodies[command.body].applyLinearImpulse(command.impulse);
      else if (command.kind === 'velocity') this.#bodies[command.body].setLinearVelocity(command.velocity);
      else this.#bodies.push(createSceneBody(this.#world, command.body));
    }
    this.#pending.length = 0;
    this.#spawnsPending = 0;
    this.#world.step(ROOM_DT);
    this.#steps++;
    const ms = performance.now() - start;
    this.stepTimes.add(ms);
    return ms;
  }

  /** The room at this step boundary, to unpack elsewhere; this room should be dropped after. */
  pack(): PackedRoom {
    return { snapshot: this.#world.snapshot(), steps: this.#steps, pending: this.#pending.slice() };
  }
}
