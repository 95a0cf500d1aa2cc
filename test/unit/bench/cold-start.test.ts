import { describe, expect, it } from 'vitest';
import { coldStart } from '../../../bench/result';

describe('bench cold start', () => {
  it('first step, first 60, and settled where the rest of the cold run is within 10 % of the warmed', () => {
    // 200 steps: the warmed run takes 1 ms each; the cold one 50 ms, then 3 ms for 39 steps, then 1.05 ms
    const warm = Array.from({ length: 200 }, () => 1);
    const cold = [50, ...Array.from({ length: 39 }, () => 3), ...Array.from({ length: 160 }, () => 1.05)];
    const c = coldStart(cold, warm);
    expect(c.firstStepMs).toBe(50);
    expect(c.first60Ms).toBeCloseTo((50 + 39 * 3 + 20 * 1.05) / 60, 12);
    expect(c.warmFirst60Ms).toBe(1);
    // from step 40 on the cold steps take 1.05 ms: within 10 %; from step 30, 10 steps of 3 ms push
    // the rest to (30 + 160 * 1.05) / 170 = 1.165
    expect(c.settledSteps).toBe(40);
    expect(c.settledMs).toBeCloseTo(50 + 39 * 3, 9);
  });

  it('one slow block late in the run (a collection) does not undo the settling', () => {
    const warm = Array.from({ length: 300 }, () => 1);
    const cold = Array.from({ length: 300 }, (_, i) => (i < 20 ? 5 : i >= 200 && i < 210 ? 2 : 1));
    expect(coldStart(cold, warm).settledSteps).toBe(20);
  });

  it('never settled: null', () => {
    const warm = Array.from({ length: 100 }, () => 1);
    const cold = Array.from({ length: 100 }, () => 2);
    const c = coldStart(cold, warm);
    expect(c.settledSteps).toBeNull();
    expect(c.settledMs).toBeNull();
  });
});
