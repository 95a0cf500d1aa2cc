/**
 * The benchmark's engines as the browser page loads them: the same adapters as bench/engines.ts, each
 * imported on demand, so that the page bundle (bench/browser/bundle.ts splits it by engine) loads only
 * the engine it measures. The page is bundled by esbuild whole, so Fulcrum needs no separate bundling
 * step here to get its enums written in as numbers.
 */
import type { EngineAdapter } from '../adapter';

export const browserEngines: Record<string, () => Promise<EngineAdapter>> = {
  fulcrum: async () => new (await import('../adapters/fulcrum')).FulcrumAdapter(),
  // the chunk this runs in is served beside solver-worker.js (bench/browser/bundle.ts)
  'fulcrum-2w': async () =>
    new (await import('../adapters/fulcrum')).FulcrumAdapter(
      2,
      new URL('./solver-worker.js', import.meta.url),
    ),
  box2d3: async () => new (await import('../adapters/box2d3')).Box2dAdapter('compat'),
  'box2d3-simd': async () => new (await import('../adapters/box2d3')).Box2dAdapter('deluxe'),
  rapier: async () => new (await import('../adapters/rapier')).RapierAdapter(),
  matter: async () => new (await import('../adapters/matter')).MatterAdapter(),
  'fulcrum-matter': async () => new (await import('../adapters/fulcrum-matter')).FulcrumMatterAdapter(),
  planck: async () => new (await import('../adapters/planck')).PlanckAdapter(),
  p2: async () => new (await import('../adapters/p2')).P2Adapter(),
};
