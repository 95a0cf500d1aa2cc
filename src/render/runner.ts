import type { World } from '../api/world';
import { Emitter } from '../core/emitter';
import type { WorkerWorld } from '../worker/worker-world';
import { requireBrowser } from './browser';
import type { AnyWorld } from './draw-source';
import { Interpolator } from './interpolation';
import type { Render } from './render';
import { isWorkerWorld } from './source-of';

export interface RunnerOptions<W extends AnyWorld = World> {
  /** a World, stepped on this thread, or a WorkerWorld, stepped in its worker while frames go on */
  world?: W | null;
  /** drawn after every frame, with interpolation */
  render?: Render<W> | null;
  /** the fixed physics step, seconds (default 1/60) */
  dt?: number;
  /** most steps one frame may take; time beyond that is dropped, so a slow frame cannot snowball */
  maxStepsPerFrame?: number;
  /** simulated seconds per real second (default 1) */
  timeScale?: number;
  /** blend the last two states when drawing (default true) */
  interpolate?: boolean;
  /**
   * a worker world: most steps sent to its worker and not yet finished (default 2); while that many
   * are out, frames send no more, and time beyond the cap is dropped as `maxStepsPerFrame` drops it
   */
  maxStepsInFlight?: number;
}

export interface FrameEvent<W extends AnyWorld = World> {
  runner: Runner<W>;
  /** real seconds since the previous frame (0 for the first) */
  delta: number;
  /** steps taken this frame */
  steps: number;
  /** blend factor the frame is drawn with */
  alpha: number;
}

/** A step: of a worker world, 'beforeStep' when it is sent and 'afterStep' once its worker has finished it. */
export interface StepEvent<W extends AnyWorld = World> {
  runner: Runner<W>;
  world: W;
  dt: number;
}

export interface RunnerEvents<W extends AnyWorld = World> {
  beforeFrame: FrameEvent<W>;
  afterFrame: FrameEvent<W>;
  beforeStep: StepEvent<W>;
  afterStep: StepEvent<W>;
}

/** Longest real time one frame accounts for: a tab in the background does not come back to a storm of steps. */
const MAX_FRAME_SECONDS = 0.25;

/**
 * The browser loop: requestAnimationFrame, a fixed physics step fed from an accumulator with a cap on
 * steps per frame, and an interpolation factor so that drawing is smooth at any refresh rate.
 * Pause, single step and time scale; events before and after each frame and each step.
 *
 * A WorkerWorld steps in its worker: a frame sends the steps its time asks for and draws at once,
 * from the last state the worker published, without waiting for them. The worker works through them
 * at its own pace, one fixed step each; at most `maxStepsInFlight` are out at a time.
 */
export class Runner<W extends AnyWorld = World> {
  world: W | null;
  render: Render<W> | null;
  dt: number;
  maxStepsPerFrame: number;
  maxStepsInFlight: number;
  timeScale: number;
  interpolate: boolean;
  paused = false;
  readonly interpolator = new Interpolator();
  /** steps taken since the runner was made or `resetStats` (a worker world's: finished by its worker) */
  stepCount = 0;
  frameCount = 0;
  /** average milliseconds per world.step over the recent steps (a worker world's: timed in its worker) */
  stepMs = 0;
  /** a worker world's steps sent and not finished yet */
  stepsInFlight = 0;
  /** why the worker world's last step failed (its worker crashed or was ended), if it did; the runner then stops stepping it */
  failure: unknown = null;
  /** frames per second, averaged */
  fps = 0;
  private accumulator = 0;
  private lastTime: number | null = null;
  private handle: number | null = null;
  private readonly emitter = new Emitter<RunnerEvents<W>>();
  private readonly stepTimes = new Float64Array(60);
  private stepTimeIndex = 0;
  private stepTimeCount = 0;

  constructor(options: RunnerOptions<W> = {}) {
    this.world = options.world ?? null;
    this.render = options.render ?? null;
    this.dt = options.dt ?? 1 / 60;
    this.maxStepsPerFrame = options.maxStepsPerFrame ?? 4;
    this.maxStepsInFlight = options.maxStepsInFlight ?? 2;
    this.timeScale = options.timeScale ?? 1;
    this.interpolate = options.interpolate ?? true;
  }

  on<K extends keyof RunnerEvents<W>>(event: K, handler: (e: RunnerEvents<W>[K]) => void): () => void {
    return this.emitter.on(event, handler);
  }

  get running(): boolean {
    return this.handle !== null;
  }

  /** the blend factor of the last frame */
  get alpha(): number {
    return this.interpolator.alpha;
  }

  /** Runs a frame on every animation frame (browser only: in Node, call step() or tick(now) instead). */
  start(): void {
    requireBrowser('Runner.start()', 'requestAnimationFrame');
    if (this.handle !== null) return;
    this.lastTime = null;
    const loop = (time: number) => {
      this.handle = requestAnimationFrame(loop);
      this.tick(time);
    };
    this.handle = requestAnimationFrame(loop);
  }

  stop(): void {
    if (this.handle !== null) cancelAnimationFrame(this.handle);
    this.handle = null;
    this.lastTime = null;
  }

  /** Swaps in another world (a reset): forgets the accumulated time and the previous state. */
  setWorld(world: W | null): void {
    this.world = world;
    if (this.render) this.render.world = world;
    this.accumulator = 0;
    this.stepsInFlight = 0;
    this.failure = null;
    this.interpolator.reset();
    this.resetStats();
  }

  resetStats(): void {
    this.stepCount = 0;
    this.stepTimeCount = 0;
    this.stepTimeIndex = 0;
    this.stepMs = 0;
  }

  /** Takes exactly one step (also while paused) and draws the result. */
  step(): void {
    this.stepWorld();
    this.accumulator = 0;
    this.interpolator.alpha = 1;
    this.render?.draw(this.interpolate ? this.interpolator : null);
  }

  /**
   * One frame at time `now` (milliseconds, as requestAnimationFrame gives): steps as the elapsed
   * time asks, then draws. `start` calls it; tests may call it directly.
   */
  tick(now: number): void {
    const delta =
      this.lastTime === null ? 0 : Math.min(MAX_FRAME_SECONDS, Math.max(0, (now - this.lastTime) / 1000));
    this.lastTime = now;
    if (delta > 0) {
      // exponential average of the frame rate (output only)
      const fps = 1 / delta;
      this.fps = this.fps === 0 ? fps : this.fps * 0.9 + fps * 0.1;
    }
    const frame: FrameEvent<W> = { runner: this, delta, steps: 0, alpha: this.interpolator.alpha };
    this.emitter.emit('beforeFrame', frame);
    let steps = 0;
    const world = this.world;
    if (!this.paused && world && this.failure === null) {
      const remote = isWorkerWorld(world);
      this.accumulator += delta * this.timeScale;
      while (
        this.accumulator >= this.dt &&
        steps < this.maxStepsPerFrame &&
        (!remote || this.stepsInFlight < this.maxStepsInFlight)
      ) {
        this.stepWorld();
        this.accumulator -= this.dt;
        steps++;
      }
      // over the cap: drop the backlog but keep the fraction of a step
      if (this.accumulator >= this.dt) this.accumulator %= this.dt;
      // a worker world shows its last finished step; the steps still out put the frame's time beyond it
      const behind = remote ? this.stepsInFlight : 0;
      this.interpolator.alpha = this.interpolate ? Math.min(1, behind + this.accumulator / this.dt) : 1;
    } else {
      this.interpolator.alpha = 1;
    }
    this.frameCount++;
    frame.steps = steps;
    frame.alpha = this.interpolator.alpha;
    this.render?.draw(this.interpolate ? this.interpolator : null);
    this.emitter.emit('afterFrame', frame);
  }

  private stepWorld(): void {
    const world = this.world;
    if (!world) return;
    const e: StepEvent<W> = { runner: this, world, dt: this.dt };
    this.emitter.emit('beforeStep', e);
    if (isWorkerWorld(world)) {
      this.sendStep(world, e);
      return;
    }
    if (this.interpolate) this.interpolator.capture(world);
    const t0 = performance.now();
    world.step(this.dt);
    this.recordStepTime(performance.now() - t0);
    this.stepCount++;
    this.emitter.emit('afterStep', e);
  }

  /** Sends a step to a worker world; its end is counted when it comes, if the world is still this runner's. */
  private sendStep(world: WorkerWorld, e: StepEvent<W>): void {
    if (this.failure !== null) return;
    this.stepsInFlight++;
    world.step(this.dt).then(
      () => {
        if (this.world !== e.world) return;
        this.stepsInFlight--;
        this.recordStepTime(world.lastStepMs);
        this.stepCount++;
        this.emitter.emit('afterStep', e);
      },
      (error: unknown) => {
        // a world swapped out (and terminated) meanwhile is none of this runner's business
        if (this.world !== e.world) return;
        this.stepsInFlight--;
        this.failure = error;
      },
    );
  }

  private recordStepTime(ms: number): void {
    const n = this.stepTimes.length;
    this.stepTimes[this.stepTimeIndex] = ms;
    this.stepTimeIndex = (this.stepTimeIndex + 1) % n;
    if (this.stepTimeCount < n) this.stepTimeCount++;
    let sum = 0;
    for (let i = 0; i < this.stepTimeCount; i++) sum += this.stepTimes[i];
    this.stepMs = sum / this.stepTimeCount;
  }
}
