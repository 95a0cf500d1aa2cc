/**
 * The script of the browser benchmark's page (bundled by bench/browser/bundle.ts, served by
 * bench/browser/server.ts). It puts `fulcrumBench` on the page's global object; the runner
 * (bench/browser/session.ts) calls it in a fresh page for every run. Measuring is bench/measure.ts,
 * the code Node's runs use.
 */
import type { EngineAdapter } from '../adapter';
import { measure } from '../measure';
import { transformsAfter } from '../probe';
import type { RunResult } from '../result';
import { browserEngines } from './engines';

/** what the page can tell about its clock */
export interface PageClock {
  /** true when the page is cross-origin isolated (COOP and COEP), so the browser's clamp is finest */
  crossOriginIsolated: boolean;
  /** the smallest step performance.now() was seen to take, ms */
  timerResolutionMs: number;
  userAgent: string;
}

export interface BenchPage {
  clock(): PageClock;
  /** bench/measure.ts on one engine and one scene */
  run(engine: string, scene: string, quick: boolean): Promise<RunResult>;
  /** the engine's transforms (x, y, angle per body, as in EngineAdapter) after `steps` steps of 1/60 s, as hex of their float64 bytes (bench/probe.ts) */
  transforms(engine: string, scene: string, quick: boolean, steps: number): Promise<string>;
}

function loader(engine: string): () => Promise<EngineAdapter> {
  const load = browserEngines[engine];
  if (!load) throw new Error(`unknown engine '${engine}'`);
  return load;
}

function timerResolutionMs(): number {
  let least = Number.POSITIVE_INFINITY;
  let last = performance.now();
  for (let changes = 0; changes < 200; ) {
    const now = performance.now();
    if (now !== last) {
      least = Math.min(least, now - last);
      last = now;
      changes++;
    }
  }
  // the clamp's steps are whole microseconds or more; the rounding drops the float's noise (0.019999...)
  return Math.round(least * 1e6) / 1e6;
}

const page: BenchPage = {
  clock: () => ({
    crossOriginIsolated: globalThis.crossOriginIsolated === true,
    timerResolutionMs: timerResolutionMs(),
    userAgent: navigator.userAgent,
  }),
  run: (engine, scene, quick) => measure(engine, scene, quick, loader(engine)),
  transforms: (engine, scene, quick, steps) => transformsAfter(loader(engine), scene, quick, steps),
};

(globalThis as unknown as { fulcrumBench: BenchPage }).fulcrumBench = page;
