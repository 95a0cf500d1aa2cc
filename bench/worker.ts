/**
 * One engine on one scene, in its own process (bench/measure.ts does the measuring); prints one
 * RESULT line of JSON on stdout.
 * Usage: node --import tsx bench/worker.ts <engine> <scene> [--quick]
 */
import { findEngine } from './engines';
import { measure } from './measure';
import { RESULT_PREFIX } from './result';

async function main(): Promise<void> {
  const [engineId, sceneId] = process.argv.slice(2);
  const result = await measure(engineId, sceneId, process.argv.includes('--quick'), () =>
    findEngine(engineId).load(),
  );
  process.stdout.write(`${RESULT_PREFIX}${JSON.stringify(result)}\n`);
  process.exit(0);
}

main().catch((error) => {
  process.stderr.write(`${error instanceof Error ? error.stack : error}\n`);
  process.exit(1);
});
