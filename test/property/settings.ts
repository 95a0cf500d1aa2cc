/**
 * How much the property suites run. In the unit run (`npx vitest run`): one fixed seed and a bounded
 * count, so the same cases run every time. `npm run fuzz` (vitest.fuzz.config.ts sets FULCRUM_FUZZ)
 * runs many seeds; the environment can change each figure:
 *   FULCRUM_FUZZ_SEED   first seed (default: 27 in the unit run, the clock in a fuzz run)
 *   FULCRUM_FUZZ_SEEDS  number of seeds, each its own fast-check run (default 1; fuzz 20)
 *   FULCRUM_FUZZ_RUNS   cases per seed (default: the suite's CI count; fuzz 200)
 *   FULCRUM_FUZZ_LAST  a file that each case is written to (as JSON) before it runs: where a run
 *                       hangs, it holds the case that hangs
 *   FULCRUM_FUZZ_TAME=1 keeps away from the failures known in issue 27 (extreme values, joint limits,
 *                       motors and springs, world.events read late, queries and snapshot bytes), so
 *                       that a run looks for other ones
 */
const env = process.env;
export const fuzzing = env.FULCRUM_FUZZ === '1';
export const tame = env.FULCRUM_FUZZ_TAME === '1';

function integer(name: string, fallback: number): number {
  const text = env[name];
  if (text === undefined || text === '') return fallback;
  const value = Number(text);
  if (!Number.isInteger(value)) throw new Error(`${name} must be an integer, got ${text}`);
  return value;
}

export const firstSeed = integer('FULCRUM_FUZZ_SEED', fuzzing ? Date.now() % 0x7fffffff : 27);
export const seedCount = integer('FULCRUM_FUZZ_SEEDS', fuzzing ? 20 : 1);

/** cases per seed: `ciRuns` in the unit run */
export function runsPerSeed(ciRuns: number): number {
  return integer('FULCRUM_FUZZ_RUNS', fuzzing ? 200 : ciRuns);
}

export const lastCaseFile = env.FULCRUM_FUZZ_LAST || undefined;
