// #region example
import { Shape, World } from 'fulcrum';
import { Pointer, Render, Runner } from 'fulcrum/render';

const world = new World();
const ground = world.createBody();
ground.createShape(Shape.box(8, 0.5, { x: 0, y: -0.5 }));
for (let row = 0; row < 8; row++) {
  for (let i = 0; i < 8 - row; i++) {
    const box = world.createBody({
      type: 'dynamic',
      position: { x: (i - (7 - row) / 2) * 1.05, y: 0.5 + row },
    });
    box.createShape(Shape.box(0.5, 0.5));
  }
}

// The Render makes a canvas that fills #app (or pass `canvas`), and looks at `view`: the world point
// at the centre and the distance from there to the top edge, in metres. The wheel zooms, a drag on
// empty space pans, a drag on a body pulls it (Pointer).
const render = new Render({
  element: document.getElementById('app')!,
  world,
  view: { center: { x: 0, y: 4 }, halfHeight: 6 },
});
new Pointer({ render });

// The Runner steps the world at a fixed 1/60 s whatever the display's rate, and draws every frame
// between the last two steps.
const runner = new Runner({ world, render });
runner.start();

// #endregion example

export { render, runner, world };
