/** Runs bench/worker.ts for one engine and one scene in a fresh Node process and parses its result. */
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { RESULT_PREFIX, type RunResult } from './result';

const workerPath = fileURLToPath(new URL('./worker.ts', import.meta.url));

export interface SpawnOptions {
  quick: boolean;
  /** extra Node flags, e.g. --cpu-prof */
  nodeFlags?: string[];
  timeoutMs: number;
}

export function runWorker(engine: string, scene: string, options: SpawnOptions): Promise<RunResult> {
  const args = [...(options.nodeFlags ?? []), '--import', 'tsx', workerPath, engine, scene];
  if (options.quick) args.push('--quick');
  return new Promise((resolve) => {
    const child = spawn(process.execPath, args, { stdio: ['ignore', 'pipe', 'pipe'] });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (chunk) => {
      stdout += chunk;
    });
    child.stderr.on('data', (chunk) => {
      stderr += chunk;
    });
    const timer = setTimeout(() => child.kill(), options.timeoutMs);
    child.on('close', (code, signal) => {
      clearTimeout(timer);
      const line = stdout.split('\n').find((l) => l.startsWith(RESULT_PREFIX));
      if (line) {
        resolve(JSON.parse(line.slice(RESULT_PREFIX.length)) as RunResult);
        return;
      }
      const why = signal
        ? `killed by ${signal} (timeout ${options.timeoutMs / 1000} s?)`
        : `exit code ${code}`;
      const detail = stderr.trim().split('\n').slice(-3).join(' | ');
      resolve({ engine, scene, ok: false, stage: 'step', error: `${why}${detail ? `: ${detail}` : ''}` });
    });
  });
}
