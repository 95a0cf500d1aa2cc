// #region example
import { Shape, World } from 'fulcrum';

const world = new World();
const ceiling = world.createBody({ position: { x: 0, y: 10 } });
ceiling.createShape(Shape.box(5, 0.1));

// A pendulum: a hinge (revolute joint) at a world anchor, a 1 m arm.
const bob = world.createBody({ type: 'dynamic', position: { x: 1, y: 10 } });
bob.createShape(Shape.circle(0.1));
world.createJoint({ type: 'revolute', bodyA: ceiling, bodyB: bob, anchor: { x: 0, y: 10 } });

// A chain of 20 links: revolute joints forming a tree are solved exactly.
let previous = ceiling;
for (let i = 0; i < 20; i++) {
  const link = world.createBody({ type: 'dynamic', position: { x: 3 + 0.25 * i + 0.125, y: 10 } });
  link.createShape(Shape.capsule({ x: -0.125, y: 0 }, { x: 0.125, y: 0 }, 0.05), { density: 10 });
  world.createJoint({ type: 'revolute', bodyA: previous, bodyB: link, anchor: { x: 3 + 0.25 * i, y: 10 } });
  previous = link;
}

for (let i = 0; i < 600; i++) world.step(1 / 60);
// The arm is still 1 m long, and the bob has the speed its fall gives it: sqrt(2 g (10 - y)).
const arm = Math.hypot(bob.position.x, bob.position.y - 10);
const speed = Math.hypot(bob.linearVelocity.x, bob.linearVelocity.y);
console.log(arm, speed, Math.sqrt(2 * 10 * (10 - bob.position.y))); // 1.0006, 4.4545, 4.4717

// #endregion example

export { arm, bob, speed, world };
