// #region example
import { Shape, World } from 'fulcrum';

function shoot(enableContinuous: boolean) {
  const world = new World({ gravity: { x: 0, y: 0 }, enableContinuous });
  const wall = world.createBody({ position: { x: 5, y: 0 } });
  wall.createShape(Shape.box(0.05, 2)); // a 10 cm wall

  // 300 m/s is 5 m per step at 60 Hz: without continuous collision the ball jumps over the wall.
  const bullet = world.createBody({ type: 'dynamic', linearVelocity: { x: 300, y: 0 } });
  bullet.createShape(Shape.circle(0.1));
  for (let i = 0; i < 10; i++) world.step(1 / 60);
  return bullet.position.x;
}

console.log(shoot(true), shoot(false)); // stopped before the wall (< 5), passed it (> 5)

// #endregion example

// #region bullet
import type { World as FulcrumWorld } from 'fulcrum';

/** Bodies with `bullet: true` also sweep against moving bodies, not just static ones. */
export function fireBullet(world: FulcrumWorld) {
  const bullet = world.createBody({ type: 'dynamic', bullet: true, linearVelocity: { x: 300, y: 0 } });
  bullet.createShape(Shape.circle(0.05));
  return bullet;
}
// #endregion bullet

export { shoot };
