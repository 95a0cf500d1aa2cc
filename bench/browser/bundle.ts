/**
 * Bundles the benchmark page (page.ts) with esbuild into a temporary directory, split into chunks so
 * that a page loads only the engine it measures. Run as a command, as bench/bundle.ts does.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const esbuild = createRequire(import.meta.url).resolve('esbuild/bin/esbuild');

export interface PageBundle {
  /** holds page.js, solver-worker.js and their chunks */
  dir: string;
  remove(): void;
}

export function bundlePage(): PageBundle {
  const dir = mkdtempSync(join(tmpdir(), 'fulcrum-browser-bench-'));
  execFileSync(esbuild, [
    fileURLToPath(new URL('./page.ts', import.meta.url)),
    // the script of the workers of Fulcrum's two-thread world (fulcrum-2w), served beside the page
    fileURLToPath(new URL('../../src/parallel/solver-worker.ts', import.meta.url)),
    '--bundle',
    '--splitting',
    '--format=esm',
    '--platform=browser',
    '--target=es2022',
    `--outdir=${dir}`,
    // both at the top of the directory, though their sources live apart
    '--entry-names=[name]',
    '--log-level=error',
  ]);
  return { dir, remove: () => rmSync(dir, { recursive: true, force: true }) };
}
