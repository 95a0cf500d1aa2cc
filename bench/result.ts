/** What a benchmark child process reports for one engine and one scene. */
export interface Timing {
  median: number;
  min: number;
  max: number;
}

export interface Quality {
  /** simulated time at the end of the run, seconds */
  seconds: number;
  /** simulated time of the reference snapshot for drift (end of warm-up), seconds */
  settledAt: number;
  /** largest displacement of a dynamic body from its settled position (at settledAt), metres */
  drift: number;
  /** largest distance between the two anchors of a joint at the end, metres (null: no joints) */
  jointSeparation: number | null;
  /** the largest joint separation seen at the end of warm-up and of each window, metres (null: no joints) */
  maxJointSeparation: number | null;
  /** dynamic bodies outside the scene's containment box at the end (null: no containment) */
  escaped: number | null;
  /** false if any transform became NaN or infinite */
  finite: boolean;
}

/** An engine's first steps in a fresh process (its JIT cold), against the same steps warmed. */
export interface ColdStart {
  /** the very first step, ms */
  firstStepMs: number;
  /** mean of the first 60 steps, ms */
  first60Ms: number;
  /** mean of the same 60 steps of the scene once the engine is warmed, ms */
  warmFirst60Ms: number;
  /** steps (and their wall time, ms) until the cold steps stay within 10 % of the warmed ones */
  settledSteps: number | null;
  settledMs: number | null;
}

export interface RunResult {
  engine: string;
  scene: string;
  ok: boolean;
  /** where it failed: the engine could not load, failed the free-fall check, or threw */
  stage?: 'load' | 'free-fall' | 'build' | 'step';
  error?: string;
  settings?: string;
  freeFall?: number;
  bodies?: number;
  joints?: number;
  /** steps of the throwaway copy of the scene run first, while the engine's JIT compiles it */
  jitWarmupSteps?: number;
  warmupSteps?: number;
  stepsPerWindow?: number;
  windows?: number;
  /** ms per step of each timed window, in order (of every round, when merged: see merge-rounds.ts) */
  windowMs?: number[];
  msPerStep?: Timing;
  coldStart?: ColdStart;
  /** rounds merged into this result, and the median of each round's windows */
  rounds?: number;
  roundMedians?: number[];
  /** wall time of loading the engine, the cold run (the JIT warm-up), the free-fall check and building the scene, ms */
  setupMs?: { load: number; jitWarmup: number; freeFall: number; build: number };
  quality?: Quality;
}

export const RESULT_PREFIX = 'RESULT ';

/** ms per step as printed: three significant digits at least (the chain's 0.05-0.07 ms would all read 0.06) */
export function formatMs(ms: number): string {
  return ms.toFixed(ms < 1 ? 3 : 2);
}

/** median, least and greatest of window timings */
export function summarize(samples: readonly number[]): Timing {
  const sorted = [...samples].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  const median = sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
  return { median, min: sorted[0], max: sorted[sorted.length - 1] };
}

/** the cold start's "first 60 steps": the cold run takes at least this many */
export const COLD_STEPS = 60;
/** the cold steps are compared with the warmed run's from every 10th step on, over at least 60 steps */
const SETTLE_BLOCK = 10;
const SETTLE_REST = 60;

/**
 * The cold start against the warmed run of the same scene, step for step (the same simulation, so
 * the same work): the first step, the mean of the first 60, and how long until the cold steps stay
 * within 10 % of the warmed ones (null if they never do within the cold run).
 */
export function coldStart(cold: readonly number[], warm: readonly number[]): ColdStart {
  const mean = (list: readonly number[], from: number, to: number) => {
    let sum = 0;
    for (let i = from; i < to; i++) sum += list[i];
    return sum / (to - from);
  };
  // the first block from which the rest of the cold run takes within 10 % of the same steps warmed
  // (a sum over the rest, so that one slow block of timer noise or a collection does not count as
  // not settled); the rest is at least SETTLE_REST steps long
  const length = Math.min(cold.length, warm.length);
  let settled: number | null = null;
  for (let from = 0; from + SETTLE_REST <= length; from += SETTLE_BLOCK) {
    if (mean(cold, from, length) <= 1.1 * mean(warm, from, length)) {
      settled = from;
      break;
    }
  }
  const n = Math.min(COLD_STEPS, cold.length);
  return {
    firstStepMs: cold[0],
    first60Ms: mean(cold, 0, n),
    warmFirst60Ms: mean(warm, 0, Math.min(n, warm.length)),
    settledSteps: settled,
    settledMs: settled === null ? null : cold.slice(0, settled).reduce((a, b) => a + b, 0),
  };
}
