/**
 * Where V8 throws Fulcrum's compiled code away in a world's first steps: each scene is built and
 * stepped in fresh `node --trace-deopt` processes, and every deoptimization is counted by function,
 * bytecode offset and reason. A site that deoptimizes again and again in one process is a
 * deoptimization loop (its function runs in the interpreter every time); the report lists those
 * first. The JIT compiles concurrently, so runs differ: the figures are a diagnosis, not a test.
 *
 *   npm run bench:deopts -- [--scenes pyramid,rain] [--steps 300] [--runs 3]
 */
import { execFileSync } from 'node:child_process';
import { rmSync } from 'node:fs';
import { parseArgs } from 'node:util';
import { benchmarkScenes } from '../scenes/index';
import { bundle } from './bundle';

const { values } = parseArgs({
  options: {
    scenes: { type: 'string', default: benchmarkScenes.join(',') },
    steps: { type: 'string', default: '300' },
    runs: { type: 'string', default: '3' },
  },
});
const steps = Number(values.steps);
const runs = Number(values.runs);
const script = bundle('./deopt-run.ts', `fulcrum-deopts-${process.pid}.mjs`);
/** the part of the run after each marker line of deopt-run.ts */
const PHASE_AFTER: Record<string, string> = {
  '@@ built': 'step 1',
  '@@ step 1': 'steps 2-10',
  '@@ step 10': 'steps 11-60',
};
const BAILOUT = /reason: ([^)]*)\).*?JSFunction (\S*) .*?bytecode offset (\d+)/;

try {
  console.log('deoptimizations by site: count in each run, when, function@bytecode offset, reason');
  for (const scene of values.scenes.split(',')) {
    const sites = new Map<string, number[]>();
    for (let run = 0; run < runs; run++) {
      const trace = execFileSync(process.execPath, ['--trace-deopt', script, scene, String(steps)], {
        encoding: 'utf8',
        maxBuffer: 1 << 28,
      });
      let phase = 'build';
      for (const line of trace.split('\n')) {
        if (line.startsWith('@@ ')) {
          phase = PHASE_AFTER[line] ?? `steps 61-${steps}`;
          continue;
        }
        const match = BAILOUT.exec(line);
        if (match === null) continue;
        const [, reason, fn, offset] = match;
        const key = `${phase.padEnd(15)} ${`${fn || '(anonymous)'}@${offset}`.padEnd(32)} ${reason}`;
        const counts = sites.get(key) ?? new Array<number>(runs).fill(0);
        counts[run]++;
        sites.set(key, counts);
      }
    }
    const rows = [...sites].sort((a, b) => Math.max(...b[1]) - Math.max(...a[1]));
    const loops = rows.filter(([, counts]) => Math.max(...counts) >= 3).length;
    console.log(`\n${scene}: ${rows.length} sites, ${loops} deoptimizing 3+ times in one run`);
    for (const [key, counts] of rows) console.log(`  ${counts.join('/').padStart(9)}  ${key}`);
  }
} finally {
  rmSync(script, { force: true });
}
