import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { afterEach } from 'vitest';
import { WorkerWorld, type WorkerWorldDef } from '../../src/worker/index';

/*
 * A WorkerWorld's worker in the tests runs the TypeScript source itself, compiled by tsx as the
 * tests' own modules are (test/worker/fixtures/source-entry.mjs registers tsx in the worker, then
 * imports src/worker/worker-entry.ts). So the worker runs the very code the tests' World runs, which
 * snapshots require: a snapshot restores only into the build that wrote it, and a bundle of the same
 * source names some classes otherwise. The package's worker, dist/worker-entry.js, shares its chunks
 * with dist/index.js in the same way.
 */

const ROOT = resolve(__dirname, '../..');

/** The URL of a worker script (a path from the repository's root) for a WorkerWorld's `worker.url`. */
export function workerScript(entry = 'test/worker/fixtures/source-entry.mjs'): URL {
  return pathToFileURL(resolve(ROOT, entry));
}

/**
 * For a test file (call at its top level): `open(def)` makes a WorkerWorld on the tests' worker
 * script and `keep(world)` takes one made otherwise; all are terminated after each test.
 */
export function workerWorlds(): {
  open(def?: WorkerWorldDef): Promise<WorkerWorld>;
  keep(world: WorkerWorld): WorkerWorld;
} {
  const opened: WorkerWorld[] = [];
  afterEach(() => {
    for (const world of opened.splice(0)) world.terminate();
  });
  const keep = (world: WorkerWorld) => {
    opened.push(world);
    return world;
  };
  return {
    open: async (def = {}) =>
      keep(await WorkerWorld.create({ ...def, worker: { url: workerScript(), ...def.worker } })),
    keep,
  };
}
