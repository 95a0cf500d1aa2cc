import { describe, expect, it } from 'vitest';
import { mergeRounds } from '../../../bench/merge-rounds';
import { parseOptions } from '../../../bench/options';
import type { RunResult } from '../../../bench/result';

function run(engine: string, windowMs: number[], sep: number, escaped: number | null = null): RunResult {
  return {
    engine,
    scene: 'joint-grid',
    ok: true,
    windows: windowMs.length,
    windowMs,
    msPerStep: { median: 0, min: 0, max: 0 },
    quality: {
      seconds: 10,
      settledAt: 1,
      drift: sep / 2,
      jointSeparation: sep,
      maxJointSeparation: sep,
      escaped,
      finite: true,
    },
  };
}

describe('bench rounds', () => {
  it("times by the median of the rounds' medians, and the least and greatest window", () => {
    // round 1 ran slow throughout: its own median (1.3) would misstate the engine, and pooled with the
    // others its windows would pull the median of all nine windows up to 0.9
    const merged = mergeRounds([
      [run('fulcrum', [1.2, 1.3, 1.4], 0.006)],
      [run('fulcrum', [0.7, 0.8, 0.9], 0.006)],
      [run('fulcrum', [0.75, 0.85, 0.95], 0.006)],
    ]);
    expect(merged).toHaveLength(1);
    const m = merged[0];
    // round medians 1.3, 0.8, 0.85: their median is 0.85
    expect(m.msPerStep).toEqual({ median: 0.85, min: 0.7, max: 1.4 });
    expect(m.windows).toBe(9);
    expect(m.rounds).toBe(3);
    expect(m.roundMedians).toEqual([1.3, 0.8, 0.85]);
  });

  it('keeps the worst quality figure of any round, and a failure of any round', () => {
    const failed: RunResult = {
      engine: 'planck',
      scene: 'joint-grid',
      ok: false,
      stage: 'step',
      error: 'NaN',
    };
    const merged = mergeRounds([
      [run('fulcrum', [1], 0.005, 0), run('planck', [2], 0.01)],
      [run('fulcrum', [1], 0.007, 2), failed],
    ]);
    expect(merged[0].quality?.maxJointSeparation).toBe(0.007);
    expect(merged[0].quality?.drift).toBe(0.0035);
    expect(merged[0].quality?.escaped).toBe(2);
    expect(merged[1]).toBe(failed);
  });

  it('refuses rounds whose runs are not in the same order', () => {
    expect(() => mergeRounds([[run('fulcrum', [1], 0)], [run('planck', [1], 0)]])).toThrow(/out of order/);
  });

  it('parses --rounds and rejects counts that are not whole numbers from 1 to 10', () => {
    expect(parseOptions([]).rounds).toBe(1);
    expect(parseOptions(['--rounds', '3']).rounds).toBe(3);
    for (const bad of ['0', '11', '2.5', 'x']) {
      expect(() => parseOptions(['--rounds', bad])).toThrow(`got '${bad}'`);
    }
  });
});
