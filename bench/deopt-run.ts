/**
 * The child of bench/deopts.ts: builds one scene on Fulcrum (as the benchmark does, sleep off) and
 * steps it, printing a marker line after the steps the report groups by. Run bundled, under
 * `node --trace-deopt`, so that V8's deoptimization lines fall between the markers.
 */
import { sceneBuilders } from '../scenes/index';
import { FulcrumAdapter } from './adapters/fulcrum';

const [scene, stepsArg] = process.argv.slice(2);
const steps = Number(stepsArg);
const adapter = new FulcrumAdapter();
await adapter.init();
adapter.build(sceneBuilders[scene]());
console.log('@@ built');
for (let i = 1; i <= steps; i++) {
  adapter.step(1 / 60);
  if (i === 1 || i === 10 || i === 60 || i === steps) console.log(`@@ step ${i}`);
}
