// #region example
import { Shape, World } from 'fulcrum';

const world = new World();
const ground = world.createBody();
ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));

// An L, 2 m by 2 m with arms 0.5 m thick (either winding). Shape.concave splits the outline into
// convex pieces; createShape attaches them all to one body and returns one handle per piece.
const outline = [
  { x: 0, y: 0 },
  { x: 2, y: 0 },
  { x: 2, y: 0.5 },
  { x: 0.5, y: 0.5 },
  { x: 0.5, y: 2 },
  { x: 0, y: 2 },
];
const l = world.createBody({ type: 'dynamic', position: { x: -3, y: 0.5 } });
const pieces = l.createShape(Shape.concave(outline), { density: 2 });
console.log(pieces.length, l.mass); // 2 pieces, 3.5 kg: the L's 1.75 m², not its hull's 2.875 m²

// Shape.polygon refuses a concave outline rather than fill its corner in
let refusal = '';
try {
  Shape.polygon(outline);
} catch (error) {
  refusal = (error as Error).message; // "points[3] must be on the convex hull of points (...Shape.concave...)"
}

// Shape.decompose gives the pieces alone, to attach with options of your own: a static cup whose
// floor grips and whose walls are slippery
const cup = world.createBody({ position: { x: 2, y: 0 } });
const cupPieces = Shape.decompose([
  { x: -1.5, y: 0 },
  { x: 1.5, y: 0 },
  { x: 1.5, y: 2 },
  { x: 1, y: 2 },
  { x: 1, y: 0.5 },
  { x: -1, y: 0.5 },
  { x: -1, y: 2 },
  { x: -1.5, y: 2 },
]);
for (const piece of cupPieces) {
  const isFloor = piece.vertices.every((v) => v.y <= 0.5);
  cup.createShape(piece, { friction: isFloor ? 0.9 : 0.1 });
}
const ball = world.createBody({ type: 'dynamic', position: { x: 2.3, y: 3 } });
ball.createShape(Shape.circle(0.4));

for (let i = 0; i < 180; i++) world.step(1 / 60);

// #endregion example

export { ball, cup, cupPieces, l, pieces, refusal };
