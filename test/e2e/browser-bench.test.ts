/**
 * The browser benchmark (`npm run bench -- --browser`) in headless Chromium, briefly: Fulcrum is
 * deterministic, so Fulcrum in the page must give the same bits as Fulcrum in Node for the same
 * steps, and a quick run measured in the page must have the shape of Node's, with the same quality
 * figures (the quick plan always runs the same number of steps). No timing is asserted.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type BrowserBench, startBrowserBench } from '../../bench/browser/run-browser';
import { findEngine } from '../../bench/engines';
import { measure } from '../../bench/measure';
import { transformsAfter } from '../../bench/probe';

const loadFulcrum = () => findEngine('fulcrum').load();
let bench: BrowserBench;

beforeAll(async () => {
  bench = await startBrowserBench('chromium');
});

afterAll(async () => {
  await bench?.close();
});

describe('browser bench in Chromium', () => {
  it('serves the page cross-origin isolated, so performance.now() steps by 5 us, not 100', () => {
    expect(bench.browser.name).toBe('chromium');
    expect(bench.browser.version).toMatch(/^\d+\.\d+/);
    expect(bench.browser.crossOriginIsolated).toBe(true);
    expect(bench.browser.timerResolutionMs).toBeLessThanOrEqual(0.005);
  });

  it("Fulcrum's transforms after 120 steps of the chain and the pyramid are Node's, bit for bit", async () => {
    for (const scene of ['chain', 'pyramid']) {
      const page = await bench.transforms('fulcrum', scene, true, 120);
      const node = await transformsAfter(loadFulcrum, scene, true, 120);
      expect(page.length).toBeGreaterThan(0);
      expect(page).toBe(node);
    }
  });

  it("a quick run in the page: every figure of Node's, and the same quality to the bit", async () => {
    const page = await bench.run('fulcrum', 'chain', true, 60_000);
    const node = await measure('fulcrum', 'chain', true, loadFulcrum);
    expect(page.ok, page.error).toBe(true);
    expect(Object.keys(page).sort()).toEqual(Object.keys(node).sort());
    expect(page.windows).toBe(node.windows);
    expect(page.windowMs).toHaveLength(node.windows!);
    expect(page.msPerStep!.median).toBeGreaterThan(0);
    expect(page.coldStart!.firstStepMs).toBeGreaterThan(0);
    expect(page.coldStart!.first60Ms).toBeGreaterThan(0);
    expect(page.freeFall).toBe(node.freeFall);
    expect(page.quality).toEqual(node.quality);
  });
});
