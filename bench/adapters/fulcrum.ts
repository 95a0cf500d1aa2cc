/**
 * Fulcrum through its public API. Settings: Fulcrum's defaults (4 substeps, continuous collision on),
 * sleeping off. Units are already metres, kilograms, seconds, radians, y up: nothing to map.
 * The benchmark loads this file bundled with the engine, as the package ships (bench/bundle.ts).
 */
import { buildFulcrumWorld, type FulcrumScene } from '../../scenes/build-fulcrum';
import type { Scene } from '../../scenes/types';
import type { EngineAdapter } from '../adapter';

export class FulcrumAdapter implements EngineAdapter {
  readonly settings: string;
  private built: FulcrumScene | null = null;

  /** `workers` > 1: `new World({ workers })`, its workers running the script at `workerUrl` */
  constructor(
    private readonly workers = 1,
    private readonly workerUrl?: URL,
  ) {
    const threads = workers > 1 ? `, workers ${workers}` : '';
    this.settings = `defaults (subSteps 4, continuous on)${threads}, enableSleep false, bundled by esbuild`;
  }

  async init(): Promise<void> {}

  build(scene: Scene): void {
    this.dispose();
    const def = this.workers > 1 ? { workers: this.workers, workerUrl: this.workerUrl } : {};
    this.built = buildFulcrumWorld(scene, { enableSleep: false, ...def });
  }

  /** waits until the world's workers run (a team starts asynchronously) */
  async ready(): Promise<void> {
    if (this.built === null || this.workers === 1) return;
    const threads = await this.built.world.workersReady;
    if (threads !== this.workers) throw new Error(`${threads} threads started, not ${this.workers}`);
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
    this.built?.world.dispose();
    this.built = null;
  }
}
