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
  msPerStep?: Timing;
  /** wall time of loading the engine, the free-fall check, the JIT warm-up and building the scene, ms */
  setupMs?: { load: number; freeFall: number; jitWarmup: number; build: number };
  quality?: Quality;
}

export const RESULT_PREFIX = 'RESULT ';
