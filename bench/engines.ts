/** The engines the benchmark knows, how to load each adapter, and which npm package it measures. */
import type { EngineAdapter } from './adapter';
import { bundledSolverWorker, importBundledFulcrum, importBundledFulcrumMatter } from './bundle';

export interface EngineEntry {
  id: string;
  label: string;
  /** npm package whose version is reported; null for Fulcrum itself */
  pkg: string | null;
  load(): Promise<EngineAdapter>;
}

export const engines: EngineEntry[] = [
  {
    id: 'fulcrum',
    label: 'Fulcrum',
    pkg: null,
    load: async () => new (await importBundledFulcrum()).FulcrumAdapter(),
  },
  {
    id: 'fulcrum-2w',
    label: 'Fulcrum, 2 threads',
    pkg: null,
    load: async () => new (await importBundledFulcrum()).FulcrumAdapter(2, bundledSolverWorker()),
  },
  {
    id: 'box2d3',
    label: 'box2d3-wasm',
    pkg: 'box2d3-wasm',
    load: async () => new (await import('./adapters/box2d3')).Box2dAdapter('compat'),
  },
  {
    id: 'box2d3-simd',
    label: 'box2d3-wasm SIMD',
    pkg: 'box2d3-wasm',
    load: async () => new (await import('./adapters/box2d3')).Box2dAdapter('deluxe'),
  },
  {
    id: 'rapier',
    label: 'rapier2d',
    pkg: '@dimforge/rapier2d-compat',
    load: async () => new (await import('./adapters/rapier')).RapierAdapter(),
  },
  {
    id: 'matter',
    label: 'matter-js',
    pkg: 'matter-js',
    load: async () => new (await import('./adapters/matter')).MatterAdapter(),
  },
  {
    id: 'fulcrum-matter',
    label: 'fulcrum/matter',
    pkg: null,
    load: async () => new (await importBundledFulcrumMatter()).FulcrumMatterAdapter(),
  },
  {
    id: 'planck',
    label: 'planck',
    pkg: 'planck',
    load: async () => new (await import('./adapters/planck')).PlanckAdapter(),
  },
  {
    id: 'p2',
    label: 'p2-es',
    pkg: 'p2-es',
    load: async () => new (await import('./adapters/p2')).P2Adapter(),
  },
];

export function findEngine(id: string): EngineEntry {
  const entry = engines.find((e) => e.id === id);
  if (!entry) throw new Error(`unknown engine '${id}' (known: ${engines.map((e) => e.id).join(', ')})`);
  return entry;
}
