/**
 * The browser side of `npm run bench -- --browser`: bundles the page, serves it, launches the
 * browser, checks that the page is cross-origin isolated, and runs one engine on one scene per fresh
 * page. The caller (bench/run.ts) loops over engines and scenes as it does for Node processes.
 */
import { fileURLToPath } from 'node:url';
import type { BrowserName } from '../options';
import type { RunResult } from '../result';
import { bundlePage } from './bundle';
import type { PageClock } from './page';
import { servePage } from './server';
import { launch } from './session';

const nodeModules = fileURLToPath(new URL('../../node_modules', import.meta.url));

export interface BrowserBench {
  browser: { name: BrowserName; version: string } & PageClock;
  run(engine: string, scene: string, quick: boolean, timeoutMs: number): Promise<RunResult>;
  transforms(engine: string, scene: string, quick: boolean, steps: number): Promise<string>;
  close(): Promise<void>;
}

export async function startBrowserBench(name: BrowserName): Promise<BrowserBench> {
  const bundle = bundlePage();
  const server = await servePage(bundle.dir, nodeModules);
  const close = async () => {
    await server.close();
    bundle.remove();
  };
  let session: Awaited<ReturnType<typeof launch>>;
  try {
    session = await launch(name);
  } catch (error) {
    await close();
    throw error;
  }
  const shutdown = async () => {
    await session.close();
    await close();
  };
  try {
    const clock = await session.call(server.url, 'clock', [], 30_000);
    if (!clock.crossOriginIsolated) {
      throw new Error(`${name}: the benchmark page is not cross-origin isolated (${clock.userAgent})`);
    }
    return {
      browser: { name, version: session.version, ...clock },
      async run(engine, scene, quick, timeoutMs) {
        try {
          return await session.call(server.url, 'run', [engine, scene, quick], timeoutMs);
        } catch (error) {
          const message = error instanceof Error ? error.message : String(error);
          return { engine, scene, ok: false, stage: 'step', error: message };
        }
      },
      transforms: (engine, scene, quick, steps) =>
        session.call(server.url, 'transforms', [engine, scene, quick, steps], 60_000),
      close: shutdown,
    };
  } catch (error) {
    await shutdown();
    throw error;
  }
}
