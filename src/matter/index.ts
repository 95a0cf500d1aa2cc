/**
 * The matter.js layer (issue 21, in progress): matter's API over Fulcrum. So far the modules below;
 * Detector, Pairs,
 * Svg and Plugin are still to come, and the layer has no package entry point until they do.
 */
import { Bodies } from './bodies';
import { Body } from './body';
import { Bounds } from './bounds';
import { Common } from './common';
import { Composite, World } from './composite';
import { Composites } from './composites';
import { Constraint } from './constraint';
import { Engine } from './engine';
import { Events } from './events';
import { Mouse } from './mouse';
import { MouseConstraint } from './mouse-constraint';
import { Query } from './query';
import { Render } from './render';
import { Runner } from './runner';
import { Sleeping } from './sleeping';
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
  Engine,
  Events,
  Mouse,
  MouseConstraint,
  Query,
  Render,
  Runner,
  Sleeping,
  Vector,
  Vertices,
  World,
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
  Engine,
  Events,
  Mouse,
  MouseConstraint,
  Query,
  Render,
  Runner,
  Sleeping,
  Vector,
  Vertices,
  World,
};
export default Matter;
