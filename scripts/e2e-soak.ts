/**
 * The end-to-end suite run again and again (`npm run test:e2e:soak -- --runs 20 [--throttle 4]`), as
 * issue 25 asks: a test that fails one run in twenty blocks everyone's work from landing. Each run is
 * a fresh `vitest run --config vitest.e2e.config.ts`; the soak stops at the first failing run, prints
 * its output, and exits 1. `--throttle n` slows every page's CPU n times (E2E_CPU_THROTTLE, see
 * test/e2e/browser.ts). A line per run goes to stdout and to `--log` (appended).
 */
import { spawnSync } from 'node:child_process';
import { appendFileSync } from 'node:fs';
import { parseArgs } from 'node:util';

const { values } = parseArgs({
  options: {
    runs: { type: 'string', default: '20' },
    throttle: { type: 'string', default: '1' },
    log: { type: 'string', default: 'e2e-soak.log' },
  },
});
const runs = Number(values.runs);
const throttle = Number(values.throttle);
if (!Number.isInteger(runs) || runs < 1)
  throw new Error(`--runs must be a positive integer, not ${values.runs}`);
if (!(throttle >= 1)) throw new Error(`--throttle must be 1 or more, not ${values.throttle}`);

function report(line: string): void {
  console.log(line);
  appendFileSync(values.log, `${line}\n`);
}

report(`# ${new Date().toISOString()}: ${runs} runs, CPU throttle ${throttle}`);
for (let i = 1; i <= runs; i++) {
  const start = Date.now();
  const run = spawnSync('npx', ['vitest', 'run', '--config', 'vitest.e2e.config.ts'], {
    env: { ...process.env, E2E_CPU_THROTTLE: String(throttle), NO_COLOR: '1' },
    encoding: 'utf8',
    maxBuffer: 64 * 1024 * 1024,
  });
  const seconds = ((Date.now() - start) / 1000).toFixed(0);
  const output = `${run.stdout}${run.stderr}`;
  const tests = /Tests\s+([^\n]+)/.exec(output)?.[1]?.trim() ?? '?';
  report(`run ${i}/${runs}: ${run.status === 0 ? 'passed' : 'FAILED'} in ${seconds} s (${tests})`);
  if (run.status !== 0) {
    console.log(output);
    process.exit(1);
  }
}
report(`all ${runs} runs passed`);
