/** The differential tests' two matter namespaces: real matter-js and the layer, typed as the layer. */
import { createRequire } from 'node:module';
import FulcrumMatter from '../../src/matter/index';

export type M = typeof FulcrumMatter;

export const RealMatter = createRequire(import.meta.url)('matter-js') as M;

/** the same matter.js program, run on real matter.js and on the layer */
export const both: [string, M][] = [
  ['matter-js', RealMatter],
  ['fulcrum/matter', FulcrumMatter],
];

/** `updates` updates of 1000/60 ms */
export function run(Matter: M, engine: ReturnType<M['Engine']['create']>, updates: number): void {
  for (let i = 0; i < updates; i++) Matter.Engine.update(engine, 1000 / 60);
}
