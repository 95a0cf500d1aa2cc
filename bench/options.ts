/** Command-line options of `npm run bench`. */
import { benchmarkScenes, sceneBuilders } from '../scenes/index';
import { engines } from './engines';

export interface BenchOptions {
  quick: boolean;
  engines: string[];
  scenes: string[];
  /** scene to profile; null when not profiling */
  profile: string | null;
  /** times every run is repeated, round after round, before the results are merged (merge-rounds.ts) */
  rounds: number;
  /** run in this headless browser instead of Node (bench/browser/); null: Node */
  browser: BrowserName | null;
}

export const BROWSERS = ['chromium', 'firefox'] as const;
export type BrowserName = (typeof BROWSERS)[number];

const MAX_ROUNDS = 10;

export const USAGE = `usage: npm run bench -- [--quick] [--engines a,b] [--scenes x,y] [--rounds n] [--profile <scene>]
                          [--browser [chromium|firefox]]
  --quick             smaller scenes and fewer steps (under a minute for everything)
  --engines a,b       engines to run (${engines.map((e) => e.id).join(', ')})
  --scenes x,y        scenes to run (default: ${benchmarkScenes.join(', ')};
                      also: ${Object.keys(sceneBuilders)
                        .filter((s) => !benchmarkScenes.includes(s))
                        .join(', ')})
  --rounds n          run everything n times over (1-${MAX_ROUNDS}, default 1), each run in a fresh process,
                      and time by the median of the rounds' medians: a noisy machine's slow spells
                      then fall on different runs each round
  --profile <scene>   CPU-profile Fulcrum (or --engines) on one scene and print the top functions by self time
  --browser [name]    run in headless Chromium (the default: /usr/bin/chromium or CHROMIUM_PATH) or Firefox
                      (/usr/bin/firefox from Debian's firefox-esr, or FIREFOX_PATH) instead of Node: each
                      run in a fresh browser context and page, served cross-origin isolated from
                      127.0.0.1; writes bench/results/browser-<name>[-quick].json and .svg beside Node's
  --help              this text`;

function list(value: string | undefined, flag: string, known: string[]): string[] {
  if (!value) throw new Error(`${flag} needs a comma-separated list`);
  const items = value.split(',').map((s) => s.trim());
  for (const item of items) {
    if (!known.includes(item)) throw new Error(`${flag}: unknown '${item}' (known: ${known.join(', ')})`);
  }
  return items;
}

export function parseOptions(argv: string[]): BenchOptions {
  const options: BenchOptions = {
    quick: false,
    engines: engines.map((e) => e.id),
    scenes: benchmarkScenes,
    profile: null,
    rounds: 1,
    browser: null,
  };
  let enginesGiven = false;
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (arg === '--quick') options.quick = true;
    else if (arg === '--engines') {
      options.engines = list(
        argv[++i],
        arg,
        engines.map((e) => e.id),
      );
      enginesGiven = true;
    } else if (arg === '--scenes') options.scenes = list(argv[++i], arg, Object.keys(sceneBuilders));
    else if (arg === '--profile') {
      options.profile = list(argv[++i], arg, Object.keys(sceneBuilders))[0];
      options.scenes = [options.profile];
    } else if (arg === '--rounds') {
      const value = argv[++i];
      const rounds = Number(value);
      if (!Number.isInteger(rounds) || rounds < 1 || rounds > MAX_ROUNDS) {
        throw new Error(`--rounds: expected a whole number from 1 to ${MAX_ROUNDS}, got '${value}'`);
      }
      options.rounds = rounds;
    } else if (arg === '--browser') {
      const next = argv[i + 1];
      if (next === undefined || next.startsWith('--')) options.browser = 'chromium';
      else if ((BROWSERS as readonly string[]).includes(next)) options.browser = argv[++i] as BrowserName;
      else throw new Error(`--browser: unknown browser '${next}' (known: ${BROWSERS.join(', ')})`);
    } else throw new Error(`unknown option '${arg}'`);
  }
  if (options.profile && options.browser) {
    throw new Error('--profile profiles Node processes; it does not go with --browser');
  }
  if (options.profile && !enginesGiven) options.engines = ['fulcrum'];
  return options;
}

/** the results files' name without extension: results[-quick] for Node, browser-<name>[-quick] */
export function resultsName(options: Pick<BenchOptions, 'quick' | 'browser'>): string {
  const base = options.browser ? `browser-${options.browser}` : 'results';
  return options.quick ? `${base}-quick` : base;
}
