import { describe, expect, it } from 'vitest';
import { buildNetwork, NETWORK_KINDS, runNetwork } from '../helpers/joint-networks';
import { letRunnerTalk } from './run-property';
import { firstSeed, fuzzing } from './settings';

/**
 * Issue 27's random joint networks (test/helpers/joint-networks.ts): 20-50 bodies joined by joints with
 * limits, motors and springs, in trees and in loops, with contacts and 1000:1 masses. None may reach NaN
 * and no body may come near the speed limit. The unit run steps seed 0 of each kind for 4 s; `npm run
 * fuzz` steps FULCRUM_FUZZ_NETWORK_SEEDS (default 200) seeds of each kind from FULCRUM_FUZZ_SEED (the
 * fuzz run's first seed; 0 here) for FULCRUM_FUZZ_NETWORK_STEPS (default 600, 10 s).
 */
const env = process.env;
const seeds = fuzzing ? Number(env.FULCRUM_FUZZ_NETWORK_SEEDS ?? 200) : 1;
const steps = fuzzing ? Number(env.FULCRUM_FUZZ_NETWORK_STEPS ?? 600) : 240;
const first = fuzzing && env.FULCRUM_FUZZ_SEED !== undefined ? firstSeed : 0;

describe('random joint networks', () => {
  for (const kind of NETWORK_KINDS) {
    it(`${kind}: ${seeds} seed${seeds > 1 ? 's' : ''} x ${steps} steps stay finite and below the speed limit`, async () => {
      const failures: string[] = [];
      let fastest = 0;
      for (let seed = first; seed < first + seeds; seed++) {
        const run = runNetwork(buildNetwork(kind, seed), steps);
        fastest = Math.max(fastest, run.maxSpeed);
        if (run.nanStep >= 0 || run.atClamp > 0)
          failures.push(`seed ${seed}: NaN at step ${run.nanStep}, ${run.atClamp} bodies at the speed limit`);
        await letRunnerTalk();
      }
      if (fuzzing)
        console.log(
          `${kind}: ${seeds} seeds, ${failures.length} failed, fastest body ${fastest.toFixed(1)} m/s`,
        );
      expect(failures).toEqual([]);
    });
  }
});
