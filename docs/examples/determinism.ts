// #region example
import { Shape, stateHash, World } from 'fulcrum';

function pile(): World {
  const world = new World();
  const ground = world.createBody();
  ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));
  for (let i = 0; i < 30; i++) {
    const body = world.createBody({ type: 'dynamic', position: { x: (i % 5) * 0.3, y: 1 + i } });
    body.createShape(i % 2 ? Shape.circle(0.3) : Shape.box(0.3, 0.2));
  }
  return world;
}

// Same calls, same bits.
const a = pile();
const b = pile();
for (let i = 0; i < 120; i++) {
  a.step(1 / 60);
  b.step(1 / 60);
}
console.log(stateHash(a) === stateHash(b)); // true

// A snapshot restores to a world that steps bit-identically from there.
const bytes = a.snapshot();
const c = World.restore(bytes);
for (let i = 0; i < 120; i++) {
  a.step(1 / 60);
  c.step(1 / 60);
}
console.log(bytes.length, stateHash(a) === stateHash(c)); // 75779 (bytes), true

// #endregion example

export { a, b, bytes, c };
