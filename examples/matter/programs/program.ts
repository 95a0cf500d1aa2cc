/**
 * What a gallery program is: an ordinary matter.js program, written against matter's API and given
 * the `Matter` namespace to use, so the same code runs on Fulcrum (`fulcrum/matter`) and on matter.js.
 */

import type { MatterEngine } from '../../../src/matter/engine';
import type Matter from '../../../src/matter/index';
import type { MatterMouseConstraint } from '../../../src/matter/mouse-constraint';
import type { MatterRender } from '../../../src/matter/render';
import type { MatterRunner } from '../../../src/matter/runner';

type Layer = typeof Matter;

/** Any nested object given in part, as matter's options are (`render: { fillStyle }`, `collisionFilter: { group }`). */
type InPart<T> = T extends (...args: never[]) => unknown
  ? T
  : T extends object
    ? { [K in keyof T]?: InPart<T[K]> }
    : T;
type TakingPartialOptions<F> = F extends (...args: infer A) => infer R
  ? (...args: { [I in keyof A]: InPart<A[I]> }) => R
  : never;
type Lenient<M> = { [K in keyof M]: TakingPartialOptions<M[K]> };

/**
 * matter's namespace, as `import Matter from 'matter-js'` gives it, typed by the layer's declarations
 * with the options matter documents as partial taken in part, and `Mouse.create` taking any element:
 * the layer's own declarations ask for whole `render` and `collisionFilter` objects and a narrower
 * element type than a canvas. Once they accept these, this is `typeof Matter`.
 */
export type MatterNamespace = Omit<
  Layer,
  'Bodies' | 'Composites' | 'Constraint' | 'MouseConstraint' | 'Mouse'
> & {
  Bodies: Lenient<Layer['Bodies']>;
  Composites: Lenient<Layer['Composites']>;
  Constraint: Lenient<Layer['Constraint']>;
  MouseConstraint: Lenient<Layer['MouseConstraint']>;
  Mouse: Omit<Layer['Mouse'], 'create'> & {
    create(element?: HTMLElement | null): ReturnType<Layer['Mouse']['create']>;
  };
};

export interface ProgramOptions {
  /** where `Render.create` puts its canvas */
  element: HTMLElement;
  width: number;
  height: number;
}

/** What a program hands back: the usual trio, the mouse constraint, and anything else worth reading. */
export interface RunningProgram {
  engine: MatterEngine;
  render: MatterRender;
  runner: MatterRunner;
  mouseConstraint?: MatterMouseConstraint;
  [extra: string]: unknown;
}

export interface MatterProgram {
  id: string;
  title: string;
  /** one line, in plain words */
  description: string;
  run(Matter: MatterNamespace, options: ProgramOptions): RunningProgram;
}
