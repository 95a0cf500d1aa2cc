// #region example
import { Shape, stateHash, World } from 'fulcrum';

/** A 40-row pyramid (820 boxes) stepped by two threads, and the same pyramid by one: the same bits. */
export async function pyramidOnTwoThreads(workerUrl?: URL) {
  const two = new World({ workers: 2, workerUrl }); // workerUrl: only if the script is not beside the package's files
  const one = new World();
  const threads = await two.workersReady; // 2 once the worker runs (1 without SharedArrayBuffer)
  for (const world of [two, one]) {
    world.createBody().createShape(Shape.box(30, 0.5));
    for (let row = 0; row < 40; row++) {
      for (let i = 0; i < 40 - row; i++) {
        const x = (i - (40 - row) / 2) * 1.05;
        const box = world.createBody({ type: 'dynamic', position: { x, y: 1 + row } });
        box.createShape(Shape.box(0.5, 0.5));
      }
    }
  }
  for (let i = 0; i < 120; i++) {
    two.step(1 / 60); // returns when both threads are done: nothing else changes for the caller
    one.step(1 / 60);
  }
  const same = stateHash(two) === stateHash(one);
  two.dispose(); // ends the worker; the world would go on, on one thread
  return { threads, same, bodies: two.bodyCount };
}
// #endregion
