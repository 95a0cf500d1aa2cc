/**
 * The interface every benchmarked engine implements. Each adapter maps its engine's units and
 * conventions at its edge: scenes come in metres, kilograms, seconds, radians with y up, and
 * transforms go out in the same units, so timing and quality code is shared by all engines.
 */
import type { Scene, V } from '../scenes/types';

export interface EngineAdapter {
  /** the engine's default quality settings as used here, for the results file */
  readonly settings: string;
  /** loads the engine (WASM modules are instantiated here, outside any timing) */
  init(): Promise<void>;
  /** builds `scene` in a fresh world with sleeping off; replaces any previous world */
  build(scene: Scene): void;
  /** resolves once the world just built can step at full speed (its threads started), if it needs to wait */
  ready?(): Promise<void>;
  /** advances the world by dt seconds */
  step(dt: number): void;
  /**
   * Writes x, y (metres, y up) and angle (radians, counter-clockwise) of the origin of every scene
   * body, in scene order, to out[3i], out[3i + 1], out[3i + 2]. The buffer starts out holding the
   * scene's own transforms, so a body the engine does not represent (a shapeless static anchor in
   * matter-js) may be left alone.
   */
  readTransforms(out: Float64Array): void;
  /** frees the world (and any WASM memory it holds) */
  dispose(): void;
}

export function unsupportedJoint(engine: string, type: string): never {
  throw new Error(`${engine} adapter: '${type}' joints are not mapped`);
}

/** world point `p` in the frame of a body at `position` turned by `angle` */
export function localPoint(body: { position: V; angle?: number }, p: V): V {
  const angle = body.angle ?? 0;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const dx = p.x - body.position.x;
  const dy = p.y - body.position.y;
  return { x: c * dx + s * dy, y: -s * dx + c * dy };
}
