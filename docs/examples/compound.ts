// #region example
import { Shape, World } from 'fulcrum';

const world = new World();
const ground = world.createBody();
ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));

// A hammer: one body, two shapes. Each shape adds its own mass; the body's centre of mass and
// inertia come from all of them, and the shapes never collide with each other.
const hammer = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
hammer.createShape(Shape.box(0.05, 0.5, { x: 0, y: 0 }), { density: 10 }); // handle: 1 kg
hammer.createShape(Shape.box(0.2, 0.1, { x: 0, y: 0.6 }), { density: 50 }); // head: 4 kg

console.log(hammer.mass, hammer.worldCenter); // 5 kg, centre of mass 0.48 m above the body's origin

// #endregion example

export { hammer, world };
