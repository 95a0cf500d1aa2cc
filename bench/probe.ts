/**
 * An engine's transforms after a number of steps, as the hex of their float64 bytes: the same bits
 * from Node and from a browser page mean the same simulation (test/e2e/browser-bench.test.ts).
 */
import { sceneBuilders } from '../scenes/index';
import type { EngineAdapter } from './adapter';
import { initialTransforms } from './quality';

export async function transformsAfter(
  load: () => Promise<EngineAdapter>,
  sceneId: string,
  quick: boolean,
  steps: number,
): Promise<string> {
  const builder = sceneBuilders[sceneId];
  if (!builder) throw new Error(`unknown scene '${sceneId}'`);
  const adapter = await load();
  await adapter.init();
  const scene = builder(quick);
  adapter.build(scene);
  for (let i = 0; i < steps; i++) adapter.step(1 / 60);
  const out = initialTransforms(scene);
  adapter.readTransforms(out);
  adapter.dispose();
  const bytes = new Uint8Array(out.buffer, out.byteOffset, out.byteLength);
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}
