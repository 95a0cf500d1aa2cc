import { Room as GameRoom, type RoomCommand } from '../../examples/server/room';
import { roomScene } from '../../examples/server/scene';

/**
 * The poses (x, y, angle of each body, rounded to float32 as a Colyseus physics room's state carries
 * them) of a game room on this thread after `steps` steps, given `commands` before the steps they are
 * listed at: what the room of examples/colyseus must have shown after the same calls.
 */
export function replayPhysicsRoom(
  seed: number,
  steps: number,
  commands: readonly { step: number; command: RoomCommand }[] = [],
): number[] {
  const room = GameRoom.create('replay', { scene: roomScene(seed), settings: { enableSleep: true } });
  for (let i = 0; i < steps; i++) {
    for (const c of commands) if (c.step === i) room.command(c.command);
    room.step();
  }
  const poses: number[] = [];
  for (const body of room.world.bodies) {
    const p = body.position;
    poses.push(Math.fround(p.x), Math.fround(p.y), Math.fround(body.angle));
  }
  return poses;
}
