import { Common } from './common';
import { Engine, type MatterEngine } from './engine';
import { Events } from './events';

/** A matter.js runner: steps an engine by a fixed `delta` as the frames come. */
export interface MatterRunner {
  delta: number;
  frameDelta: number | null;
  frameDeltaSmoothing: boolean;
  frameDeltaSnapping: boolean;
  frameDeltaHistory: number[];
  frameDeltaHistorySize: number;
  frameRequestId: number | null;
  timeBuffer: number;
  timeLastTick: number | null;
  maxUpdates: number | null;
  maxFrameTime: number;
  lastUpdatesDeferred: number;
  enabled: boolean;
  fps: number;
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
}

/** Frame gaps longer than this (ms) are a pause (a hidden tab), not time to simulate. */
const MAX_FRAME_DELTA = 1000 / 15;
/** The buffer must hold this many updates' time before one runs: frames that jitter do not beat. */
const BUFFER_MARGIN = 1.5;

type FrameCallback = (time: number) => void;

function nextFrame(callback: FrameCallback): number {
  if (typeof requestAnimationFrame === 'function') return requestAnimationFrame(callback);
  return setTimeout(() => callback(Common.now()), 1000 / 60) as unknown as number;
}

function cancelFrame(id: number): void {
  if (typeof cancelAnimationFrame === 'function') cancelAnimationFrame(id);
  else clearTimeout(id);
}

/**
 * matter.js's `Runner` (0.20): each frame adds the frame's time (smoothed over the recent frames and
 * snapped to a whole rate) to a buffer, and runs `Engine.update(engine, runner.delta)` while the
 * buffer holds 1.5 updates, at most `maxUpdates` (default: as many as fit in `maxFrameTime`) a frame.
 * A plain, mutable module object.
 */
export const Runner = {
  create(options: Partial<MatterRunner> = {}): MatterRunner {
    return Common.extend(
      {
        delta: 1000 / 60,
        frameDelta: null,
        frameDeltaSmoothing: true,
        frameDeltaSnapping: true,
        frameDeltaHistory: [],
        frameDeltaHistorySize: 100,
        frameRequestId: null,
        timeBuffer: 0,
        timeLastTick: null,
        maxUpdates: null,
        maxFrameTime: 1000 / 30,
        lastUpdatesDeferred: 0,
        enabled: true,
        fps: 0,
        events: null,
      },
      options,
    ) as unknown as MatterRunner;
  },

  /** Runs `engine` on every animation frame (a timer outside a browser); `Runner.run(engine)` makes a runner. */
  run(runnerOrEngine: MatterRunner | MatterEngine, maybeEngine?: MatterEngine): MatterRunner {
    const runner = maybeEngine ? (runnerOrEngine as MatterRunner) : Runner.create();
    const engine = maybeEngine ?? (runnerOrEngine as MatterEngine);
    runner.timeBuffer = 1000 / 60;
    const frame = (time: number) => {
      runner.frameRequestId = nextFrame(frame);
      if (time && runner.enabled) Runner.tick(runner, engine, time);
    };
    frame(0);
    return runner;
  },

  /** One frame at `time` (ms): the updates its time buys, with matter's runner events. */
  tick(runner: MatterRunner, engine: MatterEngine, time: number): void {
    const delta = runner.delta;
    let frameDelta = time - (runner.timeLastTick ?? 0);
    if (!frameDelta || !runner.timeLastTick || frameDelta > Math.max(MAX_FRAME_DELTA, runner.maxFrameTime)) {
      frameDelta = runner.frameDelta || 1000 / 60;
    }
    if (runner.frameDeltaSmoothing) {
      runner.frameDeltaHistory.push(frameDelta);
      runner.frameDeltaHistory = runner.frameDeltaHistory.slice(-runner.frameDeltaHistorySize);
      // the mean of the recent frames less the first and last tenth of them, in the order they came
      // (matter 0.20 takes its window from the history as it came, not sorted; so does this)
      const history = runner.frameDeltaHistory;
      const kept = history.slice(Math.trunc(history.length * 0.1), Math.trunc(history.length * 0.9));
      if (kept.length > 0) frameDelta = kept.reduce((sum, d) => sum + d, 0) / kept.length;
    }
    if (runner.frameDeltaSnapping) frameDelta = 1000 / Math.round(1000 / frameDelta);
    runner.frameDelta = frameDelta;
    runner.timeLastTick = time;
    runner.timeBuffer = Common.clamp(runner.timeBuffer + frameDelta, 0, frameDelta + delta * BUFFER_MARGIN);
    runner.lastUpdatesDeferred = 0;
    const maxUpdates = runner.maxUpdates || Math.ceil(runner.maxFrameTime / delta);
    const event = { timestamp: engine.timing.timestamp };
    Events.trigger(runner, 'beforeTick', event);
    Events.trigger(runner, 'tick', event);
    const started = Common.now();
    let updates = 0;
    while (delta > 0 && runner.timeBuffer >= delta * BUFFER_MARGIN) {
      Events.trigger(runner, 'beforeUpdate', event);
      Engine.update(engine, delta);
      Events.trigger(runner, 'afterUpdate', event);
      runner.timeBuffer -= delta;
      updates++;
      const elapsed = Common.now() - started;
      if (updates >= maxUpdates || elapsed + elapsed / updates > runner.maxFrameTime) {
        runner.lastUpdatesDeferred = Math.round(Math.max(0, runner.timeBuffer / delta - BUFFER_MARGIN));
        break;
      }
    }
    engine.timing.lastUpdatesPerFrame = updates;
    Events.trigger(runner, 'afterTick', event);
  },

  /** Stops the frames of `Runner.run`. */
  stop(runner: MatterRunner): void {
    if (runner.frameRequestId !== null) cancelFrame(runner.frameRequestId);
    runner.frameRequestId = null;
  },

  /** The same as `Runner.run`. */
  start(runner: MatterRunner, engine: MatterEngine): MatterRunner {
    return Runner.run(runner, engine);
  },
};
