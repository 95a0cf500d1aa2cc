/**
 * The gallery in a real browser: Debian's Chromium, headless, driven by playwright-core against the
 * gallery built by Vite and served on 127.0.0.1 (see global-setup.ts).
 */
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { demos } from '../../examples/registry';
import { type Browser, launchChromium } from './browser';
import {
  drawsItself,
  mouseDrag,
  openDemo,
  restartPaused,
  shootStage,
  stepByHand,
  waitForDrawnStep,
  waitForOwnRenderer,
  waitForSteps,
  worldToPage,
} from './gallery-page';
import { differingShare, inkStats } from './png';

const SCREENSHOTS = resolve(__dirname, '../../test-results/e2e/screenshots');

let browser: Browser;
const url = inject('galleryUrl');

beforeAll(async () => {
  mkdirSync(SCREENSHOTS, { recursive: true });
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
});

interface BodyView {
  x: number;
  y: number;
}

type GalleryWindow = Window & {
  gallery: {
    instance: Record<string, unknown>;
    runner: { stepCount: number; stepMs: number };
  };
};

describe('every demo', () => {
  for (const demo of demos) {
    it(`${demo.id}: opens without errors, draws and moves`, async () => {
      const open = await openDemo(browser.context, url, demo.id);
      try {
        // Every demo is started again, paused, and stepped by hand: the two pictures are then steps 3
        // and 15 of the demo on any machine. Taken as the runner went, a slow machine's first picture
        // could come late enough that a demo which settles had stopped (the slingshot's bird on its
        // spring: 10 pixels changed, in one CI run of three). A demo that draws with its own renderer
        // (PixiJS, p5, Phaser) loads it asynchronously and draws on its own animation frames: the test
        // waits for it to load, and after each batch of steps for it to have drawn the last one.
        await restartPaused(open.page);
        const ownRenderer = await drawsItself(open.page);
        if (ownRenderer) await waitForOwnRenderer(open.page);
        await stepByHand(open.page, 3);
        if (ownRenderer) await waitForDrawnStep(open.page);
        const first = await shootStage(open.page);
        const { ink, colors } = inkStats(first);
        expect(ink, 'share of the canvas that is not background').toBeGreaterThan(0.01);
        expect(colors).toBeGreaterThan(3);
        await stepByHand(open.page, 12);
        if (ownRenderer) await waitForDrawnStep(open.page);
        // kept for a person to look at
        const second = await shootStage(open.page, resolve(SCREENSHOTS, `${demo.id}.png`));
        const changed = differingShare(first, second) * first.width * first.height;
        expect(changed, 'pixels that changed').toBeGreaterThan(50);
        expect(open.errors).toEqual([]);
      } finally {
        await open.close();
      }
    });
  }
});

describe('the gallery', () => {
  it('shows the time per step as a number', async () => {
    const open = await openDemo(browser.context, url, 'pyramid');
    try {
      await open.page.waitForFunction(() => Number(document.getElementById('stat-step')?.textContent) > 0, {
        timeout: 10_000,
      });
      const text = (await open.page.textContent('#stat-step')) ?? '';
      expect(text).toMatch(/^\d+\.\d+$/);
      expect(Number(text)).toBeGreaterThan(0);
      expect(Number(await open.page.textContent('#stat-bodies'))).toBe(211);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('opens the demo the URL names, and switches on a link', async () => {
    const open = await openDemo(browser.context, url, 'golf');
    try {
      expect(await open.page.textContent('#demo-title')).toBe('Golf green');
      await open.page.click('a[data-demo="planets"]');
      await open.page.waitForFunction(
        () => (window as unknown as { gallery: { demo: string } }).gallery.demo === 'planets',
      );
      expect(open.page.url()).toMatch(/#planets$/);
      expect(await open.page.textContent('#demo-title')).toBe('Planets');
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('the routes', () => {
  it('opens the landing view for a hash that names no demo, and a demo for one that does', async () => {
    const open = await openDemo(browser.context, url, 'golf');
    try {
      const view = () =>
        open.page.evaluate(() => {
          const g = (window as unknown as { gallery: { view: string; demo?: string } }).gallery;
          return { view: g.view, demo: g.demo ?? null };
        });
      await open.page.goto(`${url}#no-such-demo`);
      await open.page.waitForFunction(
        () => (window as unknown as { gallery: { view: string } }).gallery.view === 'landing',
      );
      expect(await view()).toEqual({ view: 'landing', demo: null });
      expect(await open.page.locator('#cards .card').count()).toBe(demos.length);
      await open.page.goBack();
      await open.page.waitForFunction(
        () => (window as unknown as { gallery: { demo?: string } }).gallery.demo === 'golf',
      );
      expect(await view()).toEqual({ view: 'demo', demo: 'golf' });
      expect(await open.page.isVisible('#landing')).toBe(false);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('pointer drag', () => {
  /** position of the top box of the pyramid */
  const topBox = (page: import('playwright-core').Page) =>
    page.evaluate(() => {
      const boxes = (window as unknown as GalleryWindow).gallery.instance.boxes as { position: BodyView }[];
      return boxes[boxes.length - 1].position;
    });

  it('drags a box of the pyramid up', async () => {
    const open = await openDemo(browser.context, url, 'pyramid');
    try {
      await waitForSteps(open.page, 60); // let it settle
      const before = await topBox(open.page);
      const from = await worldToPage(open.page, before);
      const to = await worldToPage(open.page, { x: before.x + 2, y: before.y + 3 });
      await mouseDrag(open.page, from, to, 36);
      const after = await topBox(open.page);
      expect(after.y - before.y).toBeGreaterThan(1.5);
      expect(after.x - before.x).toBeGreaterThan(0.8);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('drags right when the page is scrolled and the stage scaled by CSS', async () => {
    const open = await openDemo(browser.context, url, 'pyramid');
    try {
      await open.page.addStyleTag({
        content:
          'body { height: auto; min-height: 2000px; } #stage { flex: none; height: 560px; transform: scale(0.7); transform-origin: 30% 40%; }',
      });
      await open.page.evaluate(() => window.scrollTo(0, 120));
      await waitForSteps(open.page, 60);
      const before = await topBox(open.page);
      const from = await worldToPage(open.page, before);
      const to = await worldToPage(open.page, { x: before.x - 2, y: before.y + 3 });
      await mouseDrag(open.page, from, to, 36);
      const after = await topBox(open.page);
      expect(after.y - before.y).toBeGreaterThan(1.5);
      expect(before.x - after.x).toBeGreaterThan(0.8);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});
