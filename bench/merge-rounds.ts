/**
 * Merges the results of several rounds of the same runs (`npm run bench -- --rounds N`). The machines
 * this runs on are shared and noisy: one process's windows can all be 10-50 % slow while another
 * engine's process ran in a quiet spell. Each round runs every engine on every scene once more, in
 * the same order, so a slow spell falls on different runs each round. The merged median is the
 * median of the rounds' own medians: a process that ran slow throughout counts as one round of
 * several, where pooling its windows with the others' would shift the median by a third of them
 * (Fulcrum's chain: rounds 0.058, 0.051, 0.078 ms pooled to 0.065). Least and greatest are over
 * every window. Quality figures take the worst round, and the simulated time the shortest: the
 * engines are deterministic, but a slow engine's run stops at the time budget after fewer windows,
 * so its final figures can differ from round to round. A run that failed in any round is reported
 * as that failure. Cold starts take the median round's figures, each on its own; one that never
 * settled in any round is reported as not settled.
 */
import { type Quality, type RunResult, summarize } from './result';

function worse(a: number | null, b: number | null): number | null {
  return a === null || b === null ? null : Math.max(a, b);
}

function worstQuality(a: Quality, b: Quality): Quality {
  return {
    seconds: Math.min(a.seconds, b.seconds),
    settledAt: a.settledAt,
    drift: Math.max(a.drift, b.drift),
    jointSeparation: worse(a.jointSeparation, b.jointSeparation),
    maxJointSeparation: worse(a.maxJointSeparation, b.maxJointSeparation),
    escaped: worse(a.escaped, b.escaped),
    finite: a.finite && b.finite,
  };
}

/** `rounds[r][i]` is round r's result of run i (every round lists the same runs in the same order) */
export function mergeRounds(rounds: readonly (readonly RunResult[])[]): RunResult[] {
  if (rounds.length === 1) return [...rounds[0]];
  return rounds[0].map((first, i) => {
    const runs = rounds.map((round) => round[i]);
    for (const run of runs) {
      if (run.engine !== first.engine || run.scene !== first.scene) {
        throw new Error(
          `round results out of order: ${run.engine}/${run.scene} at ${first.engine}/${first.scene}`,
        );
      }
    }
    const failed = runs.find((run) => !run.ok || !run.windowMs || !run.quality);
    if (failed) return failed;
    const windowMs = runs.flatMap((run) => run.windowMs!);
    const roundMedians = runs.map((run) => summarize(run.windowMs!).median);
    const all = summarize(windowMs);
    // the cold start of each round is one fresh process: the median round's figures, field by field
    const middle = (values: number[]) => summarize(values).median;
    const colds = runs.map((run) => run.coldStart).filter((c) => c !== undefined);
    const settled = colds.map((c) => c.settledSteps);
    const coldStart =
      colds.length === runs.length
        ? {
            firstStepMs: middle(colds.map((c) => c.firstStepMs)),
            first60Ms: middle(colds.map((c) => c.first60Ms)),
            warmFirst60Ms: middle(colds.map((c) => c.warmFirst60Ms)),
            settledSteps: settled.includes(null) ? null : middle(settled as number[]),
            settledMs: settled.includes(null) ? null : middle(colds.map((c) => c.settledMs as number)),
          }
        : undefined;
    let quality = first.quality!;
    for (const run of runs) quality = worstQuality(quality, run.quality!);
    return {
      ...first,
      windows: windowMs.length,
      windowMs,
      msPerStep: { median: summarize(roundMedians).median, min: all.min, max: all.max },
      rounds: runs.length,
      roundMedians,
      coldStart,
      quality,
    };
  });
}
