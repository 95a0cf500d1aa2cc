/**
 * A Colyseus room whose state is a Fulcrum world: examples/server's game room (a World stepping at a
 * fixed 60 Hz, commanded by messages applied at the next step boundary in the order they came) behind
 * Colyseus's matchmaking, transport and state sync. Colyseus spreads rooms over processes and machines
 * (its Redis presence and driver); each room steps its world on its process's event loop.
 *
 * Messages: `command` (a RoomCommand of examples/server/room.ts: impulse, velocity or spawn) answered
 * with `accepted` { id, step } — the command is applied before step `step + 1`, i.e. after `step`
 * steps — or `refused` { id, message } with the FulcrumError's message (nothing queued).
 */
import { type Client, Room } from '@colyseus/core';
import { Encoder } from '@colyseus/schema';
import type { Body } from '../../src/index';
import { FulcrumError } from '../../src/index';
import { Room as GameRoom, ROOM_DT, type RoomCommand } from '../server/room';
import { roomScene } from '../server/scene';
import { BodyView, PhysicsState, ShapeView } from './state';

// a client's first patch carries every body's shapes: about 20 kB for the 200-body scene (8 kB by default)
Encoder.BUFFER_SIZE = 64 * 1024;

export interface PhysicsRoomOptions {
  /** the scene's seed (examples/server/scene.ts): rooms with the same seed are the same room */
  seed?: number;
  /** sleeping, as World's enableSleep (default true) */
  enableSleep?: boolean;
}

/** A command as a client sends it: an id of its choosing, to match the answer. */
export interface CommandMessage {
  id: number;
  command: RoomCommand;
}

function shapeView(body: Body): ShapeView[] {
  return body.shapes.map((shape) => {
    const g = shape.geometry;
    const points: number[] = [];
    if (g.type === 'circle') points.push(g.center.x, g.center.y);
    else if (g.type === 'capsule') points.push(g.center1.x, g.center1.y, g.center2.x, g.center2.y);
    else if (g.type === 'segment') points.push(g.point1.x, g.point1.y, g.point2.x, g.point2.y);
    else for (const v of g.vertices) points.push(v.x, v.y);
    const view = new ShapeView({ kind: g.type, radius: 'radius' in g ? g.radius : 0 });
    view.points.push(...points);
    return view;
  });
}

export class PhysicsRoom extends Room<{ state: PhysicsState }> {
  override state = new PhysicsState();
  /** the game room: world, commands, steps */
  game!: GameRoom;
  /** the world's bodies in command order, as the state lists them */
  readonly #bodies: Body[] = [];

  override onCreate(options: PhysicsRoomOptions = {}): void {
    const seed = Number.isInteger(options.seed) ? (options.seed as number) : 1;
    this.game = GameRoom.create(this.roomId, {
      scene: roomScene(seed),
      settings: { enableSleep: options.enableSleep ?? true },
    });
    this.#follow();
    this.onMessage('command', (client: Client, message: CommandMessage) => {
      const id = typeof message?.id === 'number' ? message.id : -1;
      try {
        this.game.command(message?.command);
      } catch (error) {
        if (!(error instanceof FulcrumError)) throw error;
        client.send('refused', { id, message: error.message });
        return;
      }
      client.send('accepted', { id, step: this.game.steps });
    });
    // Colyseus's fixed step (an accumulator over its clock) calls the world's 60 Hz step
    this.setFixedTimestep(() => {
      this.state.stepMs = this.game.step();
      this.#follow();
    }, 1 / ROOM_DT);
    this.setPatchRate(1000 / 30);
  }

  /** Brings the state up to the world: new bodies' shapes, every body's pose, the step count. */
  #follow(): void {
    const world = this.game.world;
    const bodies = this.#bodies;
    if (world.bodyCount > bodies.length) {
      // a world lists its bodies in the order they were made: the new ones are at the end
      let i = 0;
      for (const body of world.bodies) {
        if (i++ < bodies.length) continue;
        bodies.push(body);
        const p = body.position;
        const view = new BodyView({ x: p.x, y: p.y, angle: body.angle, isStatic: body.type === 'static' });
        view.shapes.push(...shapeView(body));
        this.state.bodies.push(view);
      }
    }
    const views = this.state.bodies;
    for (let i = 0; i < bodies.length; i++) {
      const body = bodies[i];
      const view = views[i];
      const p = body.position;
      view.x = p.x;
      view.y = p.y;
      view.angle = body.angle;
    }
    this.state.step = this.game.steps;
  }
}
