// #region example
import { Shape, World } from 'fulcrum';

const world = new World(); // enableSleep is true by default
const ground = world.createBody();
ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));

const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
box.createShape(Shape.box(0.5, 0.5));

let sleptAt = -1;
let step = 0;
world.on('sleep', () => {
  sleptAt = step;
});
for (; step < 120; step++) world.step(1 / 60);
console.log(sleptAt, box.isAwake, world.awakeBodyCount); // 30: half a second at rest; false, 0

// Any force, impulse or setter wakes a body.
box.applyLinearImpulse({ x: 0, y: 5 });
console.log(box.isAwake); // true

// #endregion example

export { box, sleptAt };
