/**
 * Fulcrum as its users get it: the benchmark adapter and the engine bundled by esbuild, as tsup
 * bundles dist/. The engine keeps its typed-array layouts in enums, which a bundler writes into the
 * code as numbers; tsx compiles file by file and leaves an enum imported from another file as a
 * property load at every use (see src/store/body-store.ts).
 *
 * esbuild runs as a command, not through its JavaScript API: importing that API into a process
 * under tsx made the engine's steps in it about 20 % slower (pyramid 1.30 -> 1.58 ms).
 */
import { execFileSync } from 'node:child_process';
import { rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const esbuild = createRequire(import.meta.url).resolve('esbuild/bin/esbuild');

/** Bundles the adapter, imports the bundle and removes the file. */
export function importBundledFulcrum(): Promise<typeof import('./adapters/fulcrum')> {
  return importBundled('./adapters/fulcrum.ts');
}

/** The fulcrum/matter adapter, bundled as Fulcrum's is. */
export function importBundledFulcrumMatter(): Promise<typeof import('./adapters/fulcrum-matter')> {
  return importBundled('./adapters/fulcrum-matter.ts');
}

/**
 * The solver workers' script (src/parallel/solver-worker.ts) bundled the same way, for a world with
 * `workers`: written once per process and removed when it exits.
 */
export function bundledSolverWorker(): URL {
  const outfile = bundle('../src/parallel/solver-worker.ts', `fulcrum-bench-solver-${process.pid}.mjs`);
  process.once('exit', () => rmSync(outfile, { force: true }));
  return pathToFileURL(outfile);
}

/** Bundles the file at `relative` (to this one) for Node into the temporary file `name`; returns its path. */
export function bundle(relative: string, name: string): string {
  const outfile = join(tmpdir(), name);
  execFileSync(esbuild, [
    fileURLToPath(new URL(relative, import.meta.url)),
    '--bundle',
    '--format=esm',
    '--platform=node',
    '--target=es2022',
    `--outfile=${outfile}`,
    '--log-level=error',
  ]);
  return outfile;
}

async function importBundled<T>(relative: string): Promise<T> {
  const outfile = bundle(relative, `fulcrum-bench-${process.pid}.mjs`);
  try {
    return await import(pathToFileURL(outfile).href);
  } finally {
    rmSync(outfile, { force: true });
  }
}
