// #region example
import { Shape, World } from 'fulcrum';

const world = new World();
const ground = world.createBody();
ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 })); // top at y = 0
for (let i = 0; i < 5; i++) {
  const crate = world.createBody({ type: 'dynamic', position: { x: 2 * i - 4, y: 0.5 } });
  crate.createShape(Shape.box(0.5, 0.5));
}

// The closest hit along a ray from (0, 10) straight down 20 m: the top of the middle crate.
const hit = world.castRay({ x: 0, y: 10 }, { x: 0, y: -20 });
console.log(hit?.point, hit?.normal, hit?.fraction); // { x: 0, y: 1 }, { x: 0, y: 1 }, 0.45

// Every hit along a ray from the left, sorted by distance: five crates.
const all = world.castRayAll({ x: -10, y: 0.5 }, { x: 20, y: 0 });

// Shapes whose bounding boxes overlap a box, and shapes under a point.
const inBox = world.queryAABB({ lowerBound: { x: -2.6, y: 0.1 }, upperBound: { x: 2.6, y: 2 } });
const underPoint = world.queryPoint({ x: 2.2, y: 0.7 });

// A swept shape: where would a circle of radius 0.25 dropped from (1, 5) first touch something?
const cast = world.castShape(Shape.circle(0.25), { position: { x: 1, y: 5 }, angle: 0 }, { x: 0, y: -10 });
console.log(all.length, inBox.length, underPoint.length, cast?.point); // 5, 3, 1, { x: 1, y: 0 }

// #endregion example

export { all, cast, hit, inBox, underPoint };
