import { ROOM_DT, type RoomCommand, type RoomSpec } from '../../examples/server/room';
import { roomScene } from '../../examples/server/scene';
import { buildFulcrumWorld, createSceneBody } from '../../scenes/build-fulcrum';
import type { SceneBody } from '../../scenes/types';
import { type Body, stateHash } from '../../src/index';

/*
 * A game room (examples/server) and the commands its "players" send, for the tests that move the room
 * about (between worker threads, to another process) and compare it with a room that stayed and with
 * a plain World given the same calls on the test's own thread.
 */

export const roomSpec: RoomSpec = { scene: roomScene(7), settings: { enableSleep: false } };

const spawned: SceneBody = {
  type: 'dynamic',
  position: { x: 3, y: 20 },
  linearVelocity: { x: -2, y: 0 },
  shapes: [{ kind: 'circle', radius: 0.7, density: 3 }],
};

/** commands by the step boundary they come before; body 200 is the first spawned one */
export const roomProgram = new Map<number, RoomCommand[]>([
  [10, [{ kind: 'impulse', body: 60, impulse: { x: 8, y: 30 } }]],
  [20, [{ kind: 'spawn', body: spawned }]],
  [30, [{ kind: 'velocity', body: 200, velocity: { x: 4, y: -1 } }]],
  [
    45,
    [
      { kind: 'impulse', body: 120, impulse: { x: -5, y: 2 } },
      { kind: 'spawn', body: { ...spawned, position: { x: -3, y: 18 } } },
    ],
  ],
  [80, [{ kind: 'impulse', body: 201, impulse: { x: 0, y: 40 } }]],
  [110, [{ kind: 'velocity', body: 90, velocity: { x: 0, y: 12 } }]],
]);

/** The room's program for `steps` steps on a plain World on this thread, through Fulcrum's own calls. */
export function plainRoomHash(steps: number): number {
  const { world } = buildFulcrumWorld(roomSpec.scene, { enableSleep: false });
  const bodies: Body[] = [...world.bodies];
  for (let t = 0; t < steps; t++) {
    for (const command of roomProgram.get(t) ?? []) {
      if (command.kind === 'impulse') bodies[command.body].applyLinearImpulse(command.impulse);
      else if (command.kind === 'velocity') bodies[command.body].setLinearVelocity(command.velocity);
      else bodies.push(createSceneBody(world, command.body));
    }
    world.step(ROOM_DT);
  }
  return stateHash(world);
}
