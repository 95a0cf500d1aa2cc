/**
 * One engine on one scene, measured: load the engine, run the scene on a throwaway world (its cold
 * start, each step timed) until the engine's compilers have settled, check free fall, build the scene
 * anew, warm up, then time windows of steps. The same code runs in a fresh Node process
 * (bench/worker.ts) and in a fresh browser page (bench/browser/page.ts); only performance.now() and
 * the loader differ.
 *
 * Timer resolution: Node's performance.now() is sub-microsecond; a browser clamps it (Chromium to
 * 5 us in a cross-origin isolated page, 100 us otherwise; Firefox to 20 us isolated), which is why the
 * browser bench serves its page isolated. The steady-state figures time whole windows of steps (10 or
 * 60 steps, 0.5 ms at the very least). The cold start times every step, because its first step and
 * the step where the engine settles are per-step figures; one step of a small scene (the chain, about
 * 0.05 ms) then reads to +-5 us, but the figures built from many steps are sums of consecutive
 * differences of clamped times, which telescope to the time of the whole run of steps within two clamps.
 */
import { freeFall, sceneBuilders } from '../scenes/index';
import type { EngineAdapter } from './adapter';
import {
  allFinite,
  escapedBodies,
  FREE_FALL,
  freeFallPasses,
  initialTransforms,
  jointLocalAnchors,
  maxDisplacement,
  maxJointSeparation,
} from './quality';
import { COLD_STEPS, coldStart, type RunResult, summarize } from './result';

const DT = 1 / 60;
/**
 * Full runs first step a throwaway copy of the scene for up to 600 steps or 1 s of wall time (the JIT
 * warm-up), then simulate 10 s of a fresh copy: 1 s of warm-up, then 9 windows of 1 s. Without the
 * throwaway copy a small scene's windows time V8 compiling the engine: a JavaScript engine's code
 * runs unoptimised, then optimised, deoptimised and optimised again over its first few hundred steps,
 * and the garbage of the build and of unoptimised code is collected meanwhile (the 100-link chain:
 * Fulcrum 0.11-0.15 ms a step cold, 0.06-0.10 warmed; Rapier 0.28-0.34 cold, 0.14-0.20 warmed;
 * box2d3-wasm 0.06 both ways). A game runs for minutes: the warmed figure is the one it sees.
 */
const FULL = { jitSteps: 600, jitMs: 1_000, warmup: 60, window: 60, windows: 9, budgetMs: 60_000 };
/**
 * Quick runs warm up for 300 steps or 0.4 s: with 120 or 0.2 s Fulcrum's 200-box tumbler was still
 * compiling (its steps take 3.8 ms, then 2.9, before they settle at 0.5 after ~90 steps) and came out
 * 0.58x box2d3-wasm against 1.09x in full runs. The whole quick run takes ~40 s.
 */
const QUICK = { jitSteps: 300, jitMs: 400, warmup: 60, window: 10, windows: 3, budgetMs: 2_000 };
const MIN_WINDOWS = 3;

function message(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

function checkFreeFall(adapter: EngineAdapter): number {
  const scene = freeFall();
  adapter.build(scene);
  for (let i = 0; i < FREE_FALL.steps; i++) adapter.step(FREE_FALL.dt);
  const t = initialTransforms(scene);
  adapter.readTransforms(t);
  adapter.dispose();
  return scene.bodies[0].position.y - t[1];
}

/** measures `engine` (loaded by `load`) on `sceneId`; failures come back as a result, not thrown */
export async function measure(
  engine: string,
  sceneId: string,
  quick: boolean,
  load: () => Promise<EngineAdapter>,
): Promise<RunResult> {
  const plan = quick ? QUICK : FULL;
  const base: RunResult = { engine, scene: sceneId, ok: false };
  const builder = sceneBuilders[sceneId];
  if (!builder) throw new Error(`unknown scene '${sceneId}'`);
  const scene = builder(quick);

  const clock = { start: performance.now(), loaded: 0, checked: 0, jitWarmed: 0, built: 0 };
  let adapter: EngineAdapter;
  try {
    adapter = await load();
    await adapter.init();
  } catch (error) {
    return { ...base, stage: 'load', error: message(error) };
  }
  base.settings = adapter.settings;
  clock.loaded = performance.now();

  // the cold start: the engine's first steps ever in this process, on a throwaway copy of the scene,
  // each timed; they also warm the JIT up for the timed run below
  const coldMs: number[] = [];
  let jitSteps = 0;
  try {
    adapter.build(builder(quick));
    await adapter.ready?.();
    const until = performance.now() + plan.jitMs;
    while (jitSteps < COLD_STEPS || (jitSteps < plan.jitSteps && performance.now() < until)) {
      const t0 = performance.now();
      adapter.step(DT);
      coldMs.push(performance.now() - t0);
      jitSteps++;
    }
    adapter.dispose();
  } catch (error) {
    return { ...base, stage: 'step', error: `cold start, after ${jitSteps} steps: ${message(error)}` };
  }
  clock.jitWarmed = performance.now();

  let fall: number;
  try {
    fall = checkFreeFall(adapter);
  } catch (error) {
    return { ...base, stage: 'free-fall', error: message(error) };
  }
  base.freeFall = fall;
  if (!freeFallPasses(fall)) {
    return {
      ...base,
      stage: 'free-fall',
      error: `fell ${fall.toFixed(4)} m, expected ${FREE_FALL.min}..${FREE_FALL.max.toFixed(4)}`,
    };
  }

  clock.checked = performance.now();
  base.jitWarmupSteps = jitSteps;
  clock.jitWarmed = performance.now();
  try {
    adapter.build(scene);
    await adapter.ready?.();
  } catch (error) {
    return { ...base, stage: 'build', error: message(error) };
  }
  base.settings = adapter.settings;
  clock.built = performance.now();
  base.bodies = scene.bodies.length;
  base.joints = scene.joints.length;

  const transforms = initialTransforms(scene);
  const anchors = jointLocalAnchors(scene);
  let worstSeparation = 0;
  const sample = (): void => {
    adapter.readTransforms(transforms);
    if (anchors.length > 0)
      worstSeparation = Math.max(worstSeparation, maxJointSeparation(anchors, transforms));
  };

  const samples: number[] = [];
  let steps = 0;
  try {
    const warmMs: number[] = [];
    const timedStep = (): void => {
      const t0 = performance.now();
      adapter.step(DT);
      warmMs.push(performance.now() - t0);
    };
    for (; steps < plan.warmup; steps++) timedStep();
    sample();
    const settled = transforms.slice();
    const settledAt = steps * DT;
    const started = performance.now();
    for (let w = 0; w < plan.windows; w++) {
      const t0 = performance.now();
      for (let i = 0; i < plan.window; i++) timedStep();
      samples.push((performance.now() - t0) / plan.window);
      steps += plan.window;
      sample();
      if (w + 1 >= MIN_WINDOWS && performance.now() - started > plan.budgetMs) break;
    }
    return {
      ...base,
      ok: true,
      warmupSteps: plan.warmup,
      stepsPerWindow: plan.window,
      windows: samples.length,
      windowMs: samples,
      msPerStep: summarize(samples),
      coldStart: coldStart(coldMs, warmMs),
      setupMs: {
        load: clock.loaded - clock.start,
        jitWarmup: clock.jitWarmed - clock.loaded,
        freeFall: clock.checked - clock.jitWarmed,
        build: clock.built - clock.checked,
      },
      quality: {
        seconds: steps * DT,
        settledAt,
        drift: maxDisplacement(scene, settled, transforms),
        jointSeparation: anchors.length > 0 ? maxJointSeparation(anchors, transforms) : null,
        maxJointSeparation: anchors.length > 0 ? worstSeparation : null,
        escaped: scene.containment ? escapedBodies(scene, transforms) : null,
        finite: allFinite(transforms),
      },
    };
  } catch (error) {
    return { ...base, stage: 'step', error: `after ${steps} steps: ${message(error)}` };
  }
}
