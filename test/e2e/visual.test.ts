/**
 * Visual regression: each demo of the gallery, started again paused and stepped by hand to step 60,
 * looks as its stored picture (test/e2e/baselines/<id>.png) does, but for a small share of pixels.
 * Steps taken by hand make the picture the same on every run and machine speed; the tolerance is for
 * anti-aliasing that a different Chromium build may draw a little differently. A change that moves,
 * recolours or hides what a demo shows fails here: look at the picture written beside the stored one
 * under test-results/e2e/visual/, and if the change is wanted, store the new pictures with
 * `UPDATE_VISUALS=1 npx vitest run --config vitest.e2e.config.ts test/e2e/visual.test.ts` (one picture:
 * `-t "<id> at"`). The landing view is stored as the window shows it (landing.png), its thumbnails made
 * again and stepped by its step hook.
 */
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { demos } from '../../examples/registry';
import { type Browser, launchChromium } from './browser';
import {
  drawsItself,
  openDemo,
  openLanding,
  restartPaused,
  runsInWorker,
  stepByHand,
  waitForDrawnStep,
  waitForOwnRenderer,
  waitForWorkerSteps,
} from './gallery-page';
import { decodePng, differingShare } from './png';

const BASELINES = resolve(__dirname, 'baselines');
const ACTUAL = resolve(__dirname, '../../test-results/e2e/visual');
const UPDATE = process.env.UPDATE_VISUALS === '1';
/** the step each picture is taken at */
const STEPS = 60;
/** the share of pixels that may differ (by more than 8 levels in a channel) from the stored picture */
const TOLERANCE = 0.005;

/** Compares a screenshot with the stored picture `name`.png, or stores it with UPDATE_VISUALS=1. */
function compareWithStored(name: string, png: Buffer): void {
  const stored = resolve(BASELINES, `${name}.png`);
  if (UPDATE) {
    writeFileSync(stored, png);
    return;
  }
  if (!existsSync(stored)) {
    writeFileSync(resolve(ACTUAL, `${name}.png`), png);
    throw new Error(`no stored picture of ${name} (${stored}): store one with UPDATE_VISUALS=1`);
  }
  const share = differingShare(decodePng(readFileSync(stored)), decodePng(png));
  if (share > TOLERANCE) writeFileSync(resolve(ACTUAL, `${name}.png`), png);
  expect(share, `share of pixels unlike the stored picture of ${name}`).toBeLessThanOrEqual(TOLERANCE);
}

/**
 * For a demo whose world steps in a worker: waits until the worker has finished the `steps` steps
 * sent and the page has drawn a frame after (a local world's steps are drawn as they are taken).
 */
async function waitForWorkerWorld(page: Page, steps: number): Promise<void> {
  if (!(await runsInWorker(page))) return;
  await waitForWorkerSteps(page, steps);
  await page.evaluate(
    () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))),
  );
}

let browser: Browser;
const url = inject('galleryUrl');

beforeAll(async () => {
  mkdirSync(ACTUAL, { recursive: true });
  if (UPDATE) mkdirSync(BASELINES, { recursive: true });
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
});

describe('every demo looks as stored', () => {
  for (const demo of demos) {
    it(`${demo.id} at step ${STEPS}`, async () => {
      const open = await openDemo(browser.context, url, demo.id);
      try {
        await restartPaused(open.page);
        const ownRenderer = await drawsItself(open.page);
        if (ownRenderer) await waitForOwnRenderer(open.page);
        await stepByHand(open.page, STEPS);
        if (ownRenderer) await waitForDrawnStep(open.page);
        await waitForWorkerWorld(open.page, STEPS);
        // readouts of measured times (.timings) differ from run to run: masked
        const png = await open.page
          .locator('#stage')
          .screenshot({ animations: 'disabled', mask: [open.page.locator('#stage .timings')] });
        compareWithStored(demo.id, png);
        expect(open.errors).toEqual([]);
      } finally {
        await open.close();
      }
    });
  }
});

describe('the landing view looks as stored', () => {
  it(`landing at step ${STEPS}`, async () => {
    const open = await openLanding(browser.context, url);
    try {
      type LandingWindow = Window & {
        gallery: {
          landing: {
            paused: boolean;
            thumbnails(): { made: boolean }[];
            restart(): void;
            advance(steps: number): void;
          };
        };
      };
      // once the cards on screen are known (their thumbnails are made), they start again, paused, and are
      // stepped by the landing view's step hook
      await open.page.waitForFunction(() =>
        (window as unknown as LandingWindow).gallery.landing.thumbnails().some((t) => t.made),
      );
      await open.page.evaluate((steps) => {
        const landing = (window as unknown as LandingWindow).gallery.landing;
        landing.paused = true;
        landing.restart();
        landing.advance(steps);
      }, STEPS);
      compareWithStored('landing', await open.page.screenshot({ animations: 'disabled' }));
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});
