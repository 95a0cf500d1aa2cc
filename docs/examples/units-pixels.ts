// #region example
import { Shape, World } from 'fulcrum';

// A world in pixels: 50 px to the metre. Gravity, positions and sizes are all in pixels, and the
// engine's tolerances (contact margins, sleep speed, speed limits) scale by lengthUnitsPerMeter.
const PX = 50;
const world = new World({ gravity: { x: 0, y: -10 * PX }, lengthUnitsPerMeter: PX });

const ground = world.createBody({ position: { x: 0, y: -0.5 * PX } });
ground.createShape(Shape.box(10 * PX, 0.5 * PX));

const crate = world.createBody({ type: 'dynamic', position: { x: 0, y: 3 * PX } });
// density is per square world unit: 1 kg/m² is 1 / PX² kg per square pixel
crate.createShape(Shape.box(0.5 * PX, 0.5 * PX), { density: 1 / (PX * PX) });

for (let i = 0; i < 120; i++) world.step(1 / 60);
console.log(crate.position.y, crate.mass); // 25 px (half a metre), 1 kg

// #endregion example

export { crate, PX };
