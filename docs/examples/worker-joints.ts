// #region example
import { Shape } from 'fulcrum';
import { type WorkerOptions, WorkerWorld } from 'fulcrum/worker';

/** A bob hangs from a hinge in a worker; its joint's reads, then the bob scaled up. */
export async function hangInAWorker(worker?: WorkerOptions) {
  const world = await WorkerWorld.create({ gravity: { x: 0, y: -10 }, worker });
  const pivot = world.createBody({ position: { x: 0, y: 0 } });
  const bob = world.createBody({ type: 'dynamic', position: { x: 0, y: -1 } });
  bob.createShape(Shape.circle(0.25), { density: 4 });
  const hinge = world.createJoint({ type: 'revolute', bodyA: pivot, bodyB: bob, anchor: { x: 0, y: 0 } });
  for (let i = 0; i < 60; i++) await world.step(1 / 60);
  // the joint's reads are of the last step, synchronous like the bodies'
  const before = { mass: bob.mass, force: hinge.getReactionForce(), angle: hinge.angle };

  bob.scale(2); // a command, as on World: applied in the worker at the next step
  for (let i = 0; i < 60; i++) await world.step(1 / 60);
  const after = { mass: bob.mass, force: hinge.getReactionForce(), geometry: bob.shapes[0].geometry };
  console.log(before.force.y, after.force.y); // the hinge holds the bob's weight: m g
  world.terminate();
  return { before, after };
}
// #endregion
