// #region example
import { Shape, stateHash, World } from 'fulcrum';
import { type WorkerOptions, WorkerWorld } from 'fulcrum/worker';

/** Drops a ball in a world that steps in a worker, and the same ball in a World on this thread. */
export async function dropInAWorker(worker?: WorkerOptions) {
  const remote = await WorkerWorld.create({ gravity: { x: 0, y: -10 }, worker });
  const local = new World({ gravity: { x: 0, y: -10 } });
  for (const world of [remote, local]) {
    const ground = world.createBody();
    ground.createShape(Shape.box(5, 0.5));
  }
  const ball = remote.createBody({ type: 'dynamic', position: { x: 0, y: 5 } });
  ball.createShape(Shape.circle(0.5), { restitution: 0.5 });
  const twin = local.createBody({ type: 'dynamic', position: { x: 0, y: 5 } });
  twin.createShape(Shape.circle(0.5), { restitution: 0.5 });

  let bounces = 0;
  remote.on('contactBegin', () => {
    bounces++; // the step's events, before its promise resolves
  });
  for (let i = 0; i < 120; i++) {
    await remote.step(1 / 60); // the worker steps; this thread could draw meanwhile
    local.step(1 / 60);
  }
  // read at once, without waiting: the state after the last step
  console.log(ball.position, bounces);
  const same = (await remote.stateHash()) === stateHash(local);
  remote.terminate();
  return { y: ball.position.y, twinY: twin.position.y, bounces, same };
}
// #endregion
