/**
 * Fulcrum through its public API. Settings: Fulcrum's defaults (4 substeps, continuous collision on),
 * sleeping off. Units are already metres, kilograms, seconds, radians, y up: nothing to map.
 * The benchmark loads this file bundled with the engine, as the package ships (bench/bundle.ts).
 */
import { buildFulcrumWorld, type FulcrumScene } from '../../scenes/build-fulcrum';
import type { Scene } from '../../scenes/types';
import type { EngineAdapter } from '../adapter';

export class FulcrumAdapter implements EngineAdapter {
  readonly settings = 'defaults (subSteps 4, continuous on), enableSleep false, bundled by esbuild';
  private built: FulcrumScene | null = null;

  async init(): Promise<void> {}

  build(scene: Scene): void {
    this.built = buildFulcrumWorld(scene, { enableSleep: false });
  }

  step(dt: number): void {
    this.built!.world.step(dt);
  }

  readTransforms(out: Float64Array): void {
    const bodies = this.built!.bodies;
    for (let i = 0; i < bodies.length; i++) {
      const p = bodies[i].position;
      out[3 * i] = p.x;
      out[3 * i + 1] = p.y;
      out[3 * i + 2] = bodies[i].angle;
    }
  }

  dispose(): void {
    this.built = null;
  }
}
