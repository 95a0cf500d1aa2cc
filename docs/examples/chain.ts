// #region example
import { Shape, World } from 'fulcrum';

const world = new World();

// Rolling hills as a chain of 161 points, 0.1 m apart. A chain faces right of the way its points
// run: listed from right to left, this one faces up.
const hills = [];
for (let i = 160; i >= 0; i--) {
  const x = -8 + 0.1 * i;
  hills.push({ x, y: 0.3 * Math.cos(x) });
}
const ground = world.createBody();
const segments = ground.createShape(Shape.chain(hills), { friction: 0.9 }); // one handle per segment

// A ball rolls over 160 seams as over one smooth curve.
const ball = world.createBody({ type: 'dynamic', position: { x: -6, y: 1 } });
ball.createShape(Shape.circle(0.3), { friction: 0.9 });
ball.setLinearVelocity({ x: 4, y: 0 });

// A one-way platform: a box below it jumps up through it and lands on top.
const platform = world.createBody({ position: { x: 12, y: 3 } });
platform.createShape(
  Shape.chain([
    { x: 2, y: 0 },
    { x: -2, y: 0 },
  ]),
);
const jumper = world.createBody({ type: 'dynamic', position: { x: 12, y: 1 } });
jumper.createShape(Shape.box(0.4, 0.4));
jumper.setLinearVelocity({ x: 0, y: 10 });

// A counter-clockwise loop is solid, like a polygon; a clockwise one is a hollow that holds things.
const bowl = world.createBody({ position: { x: 20, y: 0 } });
bowl.createShape(
  Shape.chain(
    [
      { x: -2, y: 2 },
      { x: 2, y: 2 },
      { x: 2, y: -2 },
      { x: -2, y: -2 },
    ],
    { loop: true },
  ),
);
const marble = world.createBody({ type: 'dynamic', position: { x: 20, y: 0 } });
marble.createShape(Shape.circle(0.5));

for (let i = 0; i < 240; i++) world.step(1 / 60);
console.log(segments.length, jumper.position.y, marble.position.y); // 160, 3.4 (on top), -1.5 (inside)

// #endregion example

export { ball, jumper, marble, segments };
