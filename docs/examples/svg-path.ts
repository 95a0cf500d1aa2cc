// #region example
import { parseSvgPath, Shape, World } from 'fulcrum';

// A drawing at 50 px to the metre, y down as in every SVG: a valley 2 m deep and a crate.
const PX = 50;
const valley = 'M0 100 H100 Q200 200 300 100 H400';
const crateOutline = 'M-20 -10 h40 v20 h-40 z';

// scale turns pixels into metres and flipY turns the drawing upright (the world's y points up);
// tolerance is in the path's units: the curve's chords stray at most 1 px (2 cm) from it
const options = { scale: 1 / PX, flipY: true, tolerance: 1 };
const [terrain] = parseSvgPath(valley, options); // open: from (0, -2) to (8, -2), the bottom at (4, -3)
const [crate] = parseSvgPath(crateOutline, options); // closed: 4 corners, 0.8 m by 0.4 m
console.log(terrain.closed, terrain.points.length, crate.closed, crate.points);

const world = new World();

// An open outline is a terrain: a chain, smooth over the seams between its chords. A chain faces
// right of the way its points run, and this one was drawn left to right: reversed, it faces up.
const ground = world.createBody();
ground.createShape(Shape.chain([...terrain.points].reverse()));

// A closed convex outline of up to 8 points is a polygon.
const box = world.createBody({ type: 'dynamic', position: { x: 4, y: -1 } });
box.createShape(Shape.polygon(crate.points));

for (let i = 0; i < 180; i++) world.step(1 / 60);
console.log(box.position); // at rest at the bottom of the valley, on two chords: about (4, -2.75)

// #endregion example

export { box, crate, terrain };
