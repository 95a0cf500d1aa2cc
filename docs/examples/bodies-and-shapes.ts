// #region example
import { Shape, World } from 'fulcrum';

const world = new World();

// static (the default): never moves; kinematic: moves at the velocity you set; dynamic: simulated
const ground = world.createBody();
ground.createShape(Shape.segment({ x: -10, y: 0 }, { x: 10, y: 0 })); // segments: static/kinematic only

const box = world.createBody({ type: 'dynamic', position: { x: -2, y: 1 }, angle: 0.3 });
box.createShape(Shape.box(0.5, 0.25), { density: 2 }); // 1 m x 0.5 m, 2 kg/m²: 1 kg

const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 1 } });
ball.createShape(Shape.circle(0.5), { restitution: 0.3 }); // density 1: pi / 4 kg

const pill = world.createBody({ type: 'dynamic', position: { x: 2, y: 1 } });
pill.createShape(Shape.capsule({ x: -0.5, y: 0 }, { x: 0.5, y: 0 }, 0.25));

const wedge = world.createBody({ type: 'dynamic', position: { x: 4, y: 1 } });
// a convex polygon (the convex hull of the points), here with corners rounded by 5 cm
wedge.createShape(
  Shape.polygon(
    [
      { x: -0.5, y: 0 },
      { x: 0.5, y: 0 },
      { x: 0, y: 0.8 },
    ],
    0.05,
  ),
);

const platform = world.createBody({ type: 'kinematic', position: { x: 0, y: 3 } });
platform.createShape(Shape.box(1, 0.1));
platform.setLinearVelocity({ x: 1, y: 0 });

for (let i = 0; i < 60; i++) world.step(1 / 60);
console.log(box.mass, ball.mass, platform.position.x); // 1, 0.785..., 1 (one second at 1 m/s)

// #endregion example

export { ball, box, pill, platform, wedge, world };
