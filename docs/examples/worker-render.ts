// #region example
import { Shape } from 'fulcrum';
import { Pointer, Render, Runner } from 'fulcrum/render';
import { WorkerWorld } from 'fulcrum/worker';

// The world steps in a worker; this thread builds it, draws it and drags its bodies.
const world = await WorkerWorld.create();
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

// Render and Pointer as with a World: shapes are known here from the create calls, poses come from
// the state the worker publishes, and a drag moves a mouse joint in the worker by commands.
const render = new Render({
  element: document.getElementById('app')!,
  world,
  view: { center: { x: 0, y: 4 }, halfHeight: 6 },
});
new Pointer({ render });

// The Runner sends each fixed 1/60 s step to the worker and draws every frame at once, blended
// between the last two steps the worker finished: a slow step never holds up a frame.
const runner = new Runner({ world, render });
runner.start();

// #endregion example

export { render, runner, world };
