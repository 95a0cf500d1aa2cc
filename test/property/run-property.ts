import { writeFileSync } from 'node:fs';
import fc from 'fast-check';
import { firstSeed, fuzzing, lastCaseFile, runsPerSeed, seedCount } from './settings';

/**
 * Checks `property` over the configured seeds (settings.ts). Each failure is shrunk by fast-check to
 * a minimal case; the seed, the path to replay it and the shrunk case are printed and the test fails
 * with all of them.
 */
export async function checkProperty<T>(
  name: string,
  arbitrary: fc.Arbitrary<T>,
  predicate: (value: T) => void,
  ciRuns: number,
): Promise<void> {
  const numRuns = runsPerSeed(ciRuns);
  const failures: string[] = [];
  for (let k = 0; k < seedCount; k++) {
    const seed = (firstSeed + k) | 0;
    const started = performance.now();
    let cases = 0;
    const property = fc.asyncProperty(arbitrary, async (value) => {
      // a case that never ends (a hang) is found in this file
      if (lastCaseFile) writeFileSync(lastCaseFile, `${JSON.stringify([value], exactNumbers)}\n`);
      predicate(value);
      if (++cases % 25 === 0) await letRunnerTalk();
    });
    const details = await fc.check(property, { seed, numRuns });
    if (details.failed) {
      const error = details.errorInstance;
      const cause = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
      const shrunk = JSON.stringify(details.counterexample, exactNumbers);
      const message =
        `${name}: seed ${seed}, failed after ${details.numRuns} cases, shrunk ${details.numShrinks} times\n` +
        `${cause}\nshrunk case: ${shrunk}\n` +
        `replay: fc.check(property, { seed: ${seed}, path: '${details.counterexamplePath}', endOnFailure: true })`;
      failures.push(message);
      console.log(message);
    } else if (fuzzing) {
      const seconds = ((performance.now() - started) / 1000).toFixed(1);
      console.log(`${name}: seed ${seed}: ${details.numRuns} cases passed (${seconds} s)`);
    }
  }
  if (failures.length > 0) throw new Error(failures.join('\n\n'));
}

/**
 * Gives the event loop a turn, so that the test runner's worker can talk to the main process: its calls
 * time out ("Timeout calling onTaskUpdate", a failed run) when a test holds the thread for a minute.
 */
export function letRunnerTalk(): Promise<void> {
  return new Promise((resolve) => setImmediate(resolve));
}

/** JSON of the case with every number exact (-0, NaN and the infinities as strings); undefined fields left out */
function exactNumbers(_key: string, value: unknown): unknown {
  if (typeof value !== 'number') return value;
  if (Object.is(value, -0)) return '-0';
  return Number.isFinite(value) ? value : String(value);
}
