/**
 * The matter.js layer, entry point `fulcrum/matter`: matter's API over Fulcrum, the modules of matter
 * 0.20 that programs use (issue 21; what still differs is in docs/guide/from-matter.md).
 */
import { Bodies } from './bodies';
import { Body } from './body';
import { Bounds } from './bounds';
import { Common } from './common';
import { Composite, World } from './composite';
import { Composites } from './composites';
import { Constraint } from './constraint';
import { Detector, Pairs } from './detector';
import { Engine } from './engine';
import { Events } from './events';
import { Mouse } from './mouse';
import { MouseConstraint } from './mouse-constraint';
import { type MatterPlugin, Plugin } from './plugin';
import { Query } from './query';
import { Render } from './render';
import { Runner } from './runner';
import { Sleeping } from './sleeping';
import { Svg } from './svg';
import { Vector } from './vector';
import { Vertices } from './vertices';

type Fn = (...args: unknown[]) => unknown;

/** The `Matter` namespace: the modules, and `before`/`after` to hook a module function by path. */
export const Matter = {
  name: 'matter-js',
  version: '0.20.0',
  Bodies,
  Body,
  Bounds,
  Common,
  Composite,
  Composites,
  Constraint,
  Detector,
  Engine,
  Events,
  Mouse,
  MouseConstraint,
  Pairs,
  Plugin,
  Query,
  Render,
  Runner,
  Sleeping,
  Svg,
  Vector,
  Vertices,
  World,
  /** Installs plugins (objects, or names registered with Plugin.register) on the Matter namespace, each once. */
  use(...plugins: (MatterPlugin | string)[]): void {
    Plugin.use(Matter as unknown as { used?: string[] }, plugins);
  },
  /** Makes the function at `path` (e.g. 'Engine.update') call `func` first; returns the new function. */
  before(path: string, func: Fn): unknown {
    return Common.chainPathBefore(Matter as unknown as Record<string, unknown>, path, func);
  },
  /** Makes the function at `path` call `func` after it; returns the new function. */
  after(path: string, func: Fn): unknown {
    return Common.chainPathAfter(Matter as unknown as Record<string, unknown>, path, func);
  },
};

export {
  Bodies,
  Body,
  Bounds,
  Common,
  Composite,
  Composites,
  Constraint,
  Detector,
  Engine,
  Events,
  Mouse,
  MouseConstraint,
  Pairs,
  Plugin,
  Query,
  Render,
  Runner,
  Sleeping,
  Svg,
  Vector,
  Vertices,
  World,
};
/** `Matter.use`, `Matter.before` and `Matter.after` as named exports too, for `require('fulcrum/matter')`. */
export const { use, before, after, name, version } = Matter;
export default Matter;
