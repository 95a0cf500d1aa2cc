/**
 * What a gallery program is: an ordinary matter.js program, written against matter's API and given
 * the `Matter` namespace to use, so the same code runs on Fulcrum (`fulcrum/matter`) and on matter.js.
 */

import type { MatterEngine } from '../../../src/matter/engine';
import type Matter from '../../../src/matter/index';
import type { MatterMouseConstraint } from '../../../src/matter/mouse-constraint';
import type { MatterRender } from '../../../src/matter/render';
import type { MatterRunner } from '../../../src/matter/runner';

/** matter's namespace, as `import Matter from 'matter-js'` gives it (typed by the layer's declarations). */
export type MatterNamespace = typeof Matter;

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
