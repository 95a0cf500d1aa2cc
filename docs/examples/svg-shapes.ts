// #region example
import { svgShapes, World } from 'fulcrum';

const world = new World();
// hills drawn left to right and a crate, in pixels at 50 px to the metre, y down
const [hills, crate] = svgShapes('M0 300 C100 250 200 350 400 300 M140 200 h40 v40 h-40 z', {
  scale: 1 / 50,
  flipY: true,
});
const ground = world.createBody();
const segments = ground.createShape(hills); // a chain, facing up: one handle per segment
const box = world.createBody({ type: 'dynamic' });
const pieces = box.createShape(crate); // a concave shape (here one convex piece): one handle per piece

for (let i = 0; i < 180; i++) world.step(1 / 60); // it lands on a corner, tumbles once and comes to rest

// #endregion example

export { box, hills, pieces, segments };
