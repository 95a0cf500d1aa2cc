/**
 * `npm run bench`: every selected engine on every selected scene, each in a fresh Node process (or,
 * with --browser, a fresh browser page: bench/browser/). Prints the tables, writes
 * bench/results/results[-quick].json and .svg (browser-<name>[-quick] for a browser). See options.ts
 * for flags.
 */
import { mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, platform, release } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { type BrowserBench, startBrowserBench } from './browser/run-browser';
import { findEngine } from './engines';
import { mergeRounds } from './merge-rounds';
import { type BenchOptions, parseOptions, resultsName, USAGE } from './options';
import { topSelfTimes } from './profile';
import { type RayCastBenchResult, rayCastBenchText, runRayCastBench } from './raycast';
import { type EngineInfo, formatReport, qualityText } from './report';
import type { RunResult } from './result';
import { runWorker } from './spawn-worker';
import { svgChart } from './svg-chart';

const root = fileURLToPath(new URL('..', import.meta.url));
const resultsDir = join(root, 'bench', 'results');
const profilesDir = join(resultsDir, 'profiles');

function version(pkg: string | null): string {
  const path = pkg ? join(root, 'node_modules', pkg, 'package.json') : join(root, 'package.json');
  return (JSON.parse(readFileSync(path, 'utf8')) as { version: string }).version;
}

function engineInfo(id: string): EngineInfo {
  const entry = findEngine(id);
  return { id, label: entry.label, version: version(entry.pkg) };
}

function progress(text: string): void {
  if (process.stdout.isTTY) process.stdout.write(`\r\x1b[K${text}`);
  else process.stdout.write(`${text}\n`);
}

type RunOne = (engine: string, scene: string, timeoutMs: number) => Promise<RunResult>;

async function runAll(options: BenchOptions, engines: EngineInfo[], runOne: RunOne): Promise<RunResult[]> {
  const rounds: RunResult[][] = [];
  const unavailable = new Map<string, RunResult>();
  const total = options.rounds * engines.length * options.scenes.length;
  let done = 0;
  const started = performance.now();
  for (let round = 1; round <= options.rounds; round++) {
    const results: RunResult[] = [];
    for (const scene of options.scenes) {
      for (const engine of engines) {
        done++;
        const skipped = unavailable.get(engine.id);
        if (skipped) {
          results.push({ ...skipped, scene });
          continue;
        }
        const elapsed = ((performance.now() - started) / 1000).toFixed(0);
        const of = options.rounds > 1 ? ` round ${round}/${options.rounds}` : '';
        progress(`[${done}/${total}] ${elapsed} s${of}  ${engine.label} on ${scene} ...`);
        const result = await runOne(engine.id, scene, options.quick ? 60_000 : 600_000);
        if (result.stage === 'load' || result.stage === 'free-fall') unavailable.set(engine.id, result);
        results.push(result);
      }
    }
    rounds.push(results);
  }
  progress(`${total} runs in ${((performance.now() - started) / 1000).toFixed(0)} s\n`);
  return mergeRounds(rounds);
}

async function profile(options: BenchOptions, engines: EngineInfo[]): Promise<void> {
  const scene = options.profile!;
  for (const engine of engines) {
    // one directory per run: the tsx loader thread writes a profile of its own beside the main one
    const dir = join(profilesDir, `${engine.id}-${scene}-${new Date().toISOString().replace(/[:.]/g, '-')}`);
    mkdirSync(dir, { recursive: true });
    progress(`profiling ${engine.label} on ${scene} ...`);
    const flags = ['--cpu-prof', `--cpu-prof-dir=${dir}`];
    const result = await runWorker(engine.id, scene, {
      quick: options.quick,
      nodeFlags: flags,
      timeoutMs: 600_000,
    });
    progress('\n');
    if (!result.ok) {
      console.log(`${engine.label} on ${scene}: ${result.stage}: ${result.error}`);
      continue;
    }
    const path = mainThreadProfile(dir);
    console.log(
      `${engine.label} on ${scene}: ${result.msPerStep!.median.toFixed(2)} ms per step, ${qualityText(result)}`,
    );
    console.log(`profile: ${path} (open in Chrome DevTools > Performance, or speedscope)`);
    console.log('top functions by self time (whole process: load, build and stepping):');
    for (const f of topSelfTimes(path, 25)) {
      console.log(
        `  ${f.ms.toFixed(1).padStart(9)} ms  ${(100 * f.share).toFixed(1).padStart(5)}%  ${f.name}`,
      );
    }
  }
}

/** the profile of the thread that ran bench/worker.ts */
function mainThreadProfile(dir: string): string {
  const files = readdirSync(dir).map((f) => join(dir, f));
  const main = files.find((f) => readFileSync(f, 'utf8').includes('bench/worker.ts'));
  if (!main) throw new Error(`no profile of bench/worker.ts in ${dir}`);
  return main;
}

async function main(): Promise<void> {
  if (process.argv.includes('--help')) {
    console.log(USAGE);
    return;
  }
  let options: BenchOptions;
  try {
    options = parseOptions(process.argv.slice(2));
  } catch (error) {
    console.error(error instanceof Error ? error.message : error);
    console.error(USAGE);
    process.exit(2);
  }
  const engines = options.engines.map(engineInfo);
  if (options.profile) {
    await profile(options, engines);
    return;
  }
  let browser: BrowserBench | null = null;
  let results: RunResult[];
  if (options.browser) {
    progress(`starting ${options.browser} ...`);
    browser = await startBrowserBench(options.browser);
    const bench = browser;
    try {
      results = await runAll(options, engines, (engine, scene, timeoutMs) =>
        bench.run(engine, scene, options.quick, timeoutMs),
      );
    } finally {
      await bench.close();
    }
  } else {
    results = await runAll(options, engines, (engine, scene, timeoutMs) =>
      runWorker(engine, scene, { quick: options.quick, timeoutMs }),
    );
  }
  console.log('');
  console.log(formatReport(engines, options.scenes, results, options.rounds, browser ? 'page' : 'process'));
  // Fulcrum-only query timing (issue 4), in this process: a few seconds
  let raycast: RayCastBenchResult | null = null;
  if (options.engines.includes('fulcrum') && !browser) {
    raycast = runRayCastBench(options.quick ? 3 : 5);
    console.log(`\n${rayCastBenchText(raycast)}`);
  }

  const machine = {
    cpu: cpus()[0]?.model ?? 'unknown',
    cores: cpus().length,
    os: `${platform()} ${release()}`,
  };
  mkdirSync(resultsDir, { recursive: true });
  const json = join(resultsDir, `${resultsName(options)}.json`);
  const svg = join(resultsDir, `${resultsName(options)}.svg`);
  const date = new Date().toISOString();
  const runtime = browser
    ? `${browser.browser.name === 'chromium' ? 'Chromium' : 'Firefox'} ${browser.browser.version}`
    : `Node ${process.version}`;
  writeFileSync(
    json,
    `${JSON.stringify({ date, quick: options.quick, rounds: options.rounds, node: process.version, browser: browser?.browser, machine, engines, scenes: options.scenes, results, raycast }, null, 2)}\n`,
  );
  const of = `${options.quick ? ' (quick)' : ''}${options.rounds > 1 ? `, median of ${options.rounds} rounds` : ''}`;
  const title = `Fulcrum vs peers, ms per step${of}: ${machine.cpu}, ${runtime}, ${date.slice(0, 10)}`;
  writeFileSync(svg, svgChart(engines, options.scenes, results, title));
  console.log(`\nwrote ${json}\nwrote ${svg}`);
  console.log(`machine: ${machine.cpu}, ${machine.cores} cores, ${machine.os}, ${runtime}`);
  if (browser) {
    const b = browser.browser;
    console.log(
      `${b.userAgent}; cross-origin isolated: ${b.crossOriginIsolated}, performance.now() steps of ${(b.timerResolutionMs * 1000).toFixed(1)} us`,
    );
  }
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
