/**
 * The gallery as a visitor meets it: the landing view of cards with live thumbnails, a card opening its
 * demo, the Show code panel, and a layout without overlaps from a phone to a laptop.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { cards } from '../../examples/cards';
import { demos } from '../../examples/registry';
import { type Browser, launchChromium } from './browser';
import { openDemo, openLanding } from './gallery-page';
import { measureLayout } from './layout';

const EXAMPLES = resolve(__dirname, '../../examples');

let browser: Browser;
const url = inject('galleryUrl');

beforeAll(async () => {
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
});

interface ThumbnailState {
  id: string;
  kind: 'live' | 'still' | 'picture';
  visible: boolean;
  made: boolean;
  steps: number;
}

type LandingWindow = Window & {
  gallery: {
    view: string;
    demo?: string;
    runner: { stepCount: number; world: unknown };
    landing: {
      paused: boolean;
      shown: boolean;
      thumbnails(): ThumbnailState[];
      advance(steps: number): void;
      restart(): void;
    };
  };
};

function thumbnails(page: Page): Promise<ThumbnailState[]> {
  return page.evaluate(() => (window as unknown as LandingWindow).gallery.landing.thumbnails());
}

/**
 * Pixels of every card's canvas that are not the background (#15171d, within 8 levels), as a share,
 * and kept in the page (under `key`) for `changedPixels`.
 */
function inkOfCanvases(page: Page, key: string): Promise<Record<string, number>> {
  return page.evaluate((k) => {
    const store = ((
      window as unknown as { shots?: Record<string, Record<string, Uint8ClampedArray>> }
    ).shots ??= {});
    const shots: Record<string, Uint8ClampedArray> = {};
    const ink: Record<string, number> = {};
    for (const canvas of Array.from(document.querySelectorAll<HTMLCanvasElement>('#cards .card canvas'))) {
      const id = (canvas.closest('.card') as HTMLElement).dataset.card ?? '';
      const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data;
      if (!data) continue;
      shots[id] = data;
      let count = 0;
      for (let i = 0; i < data.length; i += 4) {
        if (Math.abs(data[i] - 21) > 8 || Math.abs(data[i + 1] - 23) > 8 || Math.abs(data[i + 2] - 29) > 8)
          count++;
      }
      ink[id] = count / (data.length / 4);
    }
    store[k] = shots;
    return ink;
  }, key);
}

/** Pixels (differing by more than 8 levels in a channel) between two sets of pictures kept by `inkOfCanvases`. */
function changedPixels(page: Page, a: string, b: string): Promise<Record<string, number>> {
  return page.evaluate(
    ([ka, kb]) => {
      const store = (window as unknown as { shots: Record<string, Record<string, Uint8ClampedArray>> }).shots;
      const changed: Record<string, number> = {};
      for (const [id, before] of Object.entries(store[ka])) {
        const after = store[kb][id];
        let count = 0;
        for (let i = 0; i < before.length; i += 4) {
          if (
            Math.abs(before[i] - after[i]) > 8 ||
            Math.abs(before[i + 1] - after[i + 1]) > 8 ||
            Math.abs(before[i + 2] - after[i + 2]) > 8
          )
            count++;
        }
        changed[id] = count;
      }
      return changed;
    },
    [a, b],
  );
}

/** Scrolls every card into view in turn, waiting each time until its thumbnail is made. */
async function makeEveryThumbnail(page: Page): Promise<void> {
  for (const demo of demos) {
    await page.locator(`.card[data-card="${demo.id}"]`).scrollIntoViewIfNeeded();
    await page.waitForFunction(
      (id) =>
        (window as unknown as LandingWindow).gallery.landing.thumbnails().find((t) => t.id === id)?.made ===
        true,
      demo.id,
    );
  }
}

describe('the landing view', () => {
  it('shows a card per demo, in the list order, with its title and a line in plain words', async () => {
    const open = await openLanding(browser.context, url);
    try {
      const shown = await open.page.$$eval('#cards .card', (elements) =>
        elements.map((el) => ({
          id: (el as HTMLElement).dataset.card,
          href: el.getAttribute('href'),
          title: el.querySelector('h3')?.textContent,
          summary: el.querySelector('p')?.textContent,
        })),
      );
      expect(shown.map((c) => c.id)).toEqual(demos.map((d) => d.id));
      for (const [i, demo] of demos.entries()) {
        expect(shown[i].href).toBe(`#${demo.id}`);
        expect(shown[i].title).toBe(demo.title);
        // every demo has its own line (not the fallback to its description), short enough for a line
        expect(cards[demo.id], `a card line for ${demo.id} in examples/cards.ts`).toBeDefined();
        expect(shown[i].summary).toBe(cards[demo.id].summary);
        expect(shown[i].summary?.length ?? 0).toBeLessThanOrEqual(110);
      }
      expect(await open.page.title()).toBe('Fulcrum — demo gallery');
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('draws every thumbnail, and the live ones move as they are stepped', async () => {
    const open = await openLanding(browser.context, url);
    try {
      // stopped and started again, so that every live thumbnail is at its first step when it is measured
      await open.page.evaluate(() => {
        const landing = (window as unknown as LandingWindow).gallery.landing;
        landing.paused = true;
        landing.restart();
      });
      await makeEveryThumbnail(open.page);
      const made = await thumbnails(open.page);
      expect(made.every((t) => t.made)).toBe(true);
      const live = made.filter((t) => t.kind === 'live').map((t) => t.id);
      expect(live.length).toBeGreaterThanOrEqual(15);
      for (const t of made) if (t.kind === 'live') expect(t.steps, t.id).toBe(0);

      const ink = await inkOfCanvases(open.page, 'first');
      for (const t of made) {
        if (t.kind === 'picture') continue;
        expect(ink[t.id], `share of ${t.id}'s thumbnail that is not background`).toBeGreaterThan(0.01);
      }
      // a stored picture is loaded and decoded
      for (const t of made.filter((m) => m.kind === 'picture')) {
        const img = open.page.locator(`.card[data-card="${t.id}"] img`);
        await img.scrollIntoViewIfNeeded();
        await expect
          .poll(() =>
            img.evaluate((el) => (el as HTMLImageElement).complete && (el as HTMLImageElement).naturalWidth),
          )
          .toBeGreaterThan(100);
      }

      await open.page.evaluate(() => (window as unknown as LandingWindow).gallery.landing.advance(30));
      const after = await thumbnails(open.page);
      for (const t of after) if (t.kind === 'live') expect(t.steps, t.id).toBe(30);
      await inkOfCanvases(open.page, 'second');
      const changed = await changedPixels(open.page, 'first', 'second');
      for (const id of live)
        expect(changed[id], `pixels of ${id}'s thumbnail changed by 30 steps`).toBeGreaterThan(30);
      // a still is drawn once: stepping the others leaves it as it was
      for (const t of after.filter((m) => m.kind === 'still')) expect(changed[t.id], t.id).toBe(0);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('steps only the thumbnails on screen, and keeps stepping while shown', async () => {
    const open = await openLanding(browser.context, url);
    try {
      // read before and after 20 animation frames, in the page: the landing view's loop runs once a frame,
      // as this does, so at most 21 of its frames come between the two readings
      const { first, second } = await open.page.evaluate(
        () =>
          new Promise<{ first: ThumbnailState[]; second: ThumbnailState[] }>((done) => {
            const landing = (window as unknown as LandingWindow).gallery.landing;
            let left = 20;
            let first: ThumbnailState[] = [];
            const next = () => {
              if (left-- === 20) first = landing.thumbnails();
              if (left < 0) done({ first, second: landing.thumbnails() });
              else requestAnimationFrame(next);
            };
            // after 20 frames, so that the thumbnails on screen are made
            let warm = 20;
            const warmUp = () => (--warm <= 0 ? next() : requestAnimationFrame(warmUp));
            requestAnimationFrame(warmUp);
          }),
      );
      const onScreen = second.filter((t) => t.visible && t.kind === 'live');
      expect(onScreen.length).toBeGreaterThan(0);
      // a frame takes at most 6 steps in all, and the cards off screen take none
      const taken = second.reduce((sum, t, i) => sum + t.steps - first[i].steps, 0);
      expect(taken).toBeGreaterThan(0);
      expect(taken).toBeLessThanOrEqual(6 * 21);
      for (const t of second.filter((s) => !s.visible)) expect(t.steps, t.id).toBe(0);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('opens the demo a card names, lets the thumbnails go, and the Gallery link comes back', async () => {
    const open = await openLanding(browser.context, url);
    try {
      await open.page.locator('.card[data-card="golf"]').click();
      await open.page.waitForFunction(() => {
        const g = (window as unknown as LandingWindow).gallery;
        return g.demo === 'golf' && g.runner.stepCount >= 3;
      });
      expect(open.page.url()).toMatch(/#golf$/);
      expect(await open.page.textContent('#demo-title')).toBe('Golf green');
      expect(await open.page.isVisible('#stage')).toBe(true);
      expect(await open.page.isVisible('#landing')).toBe(false);
      const left = await open.page.evaluate(() => {
        const landing = (window as unknown as LandingWindow).gallery.landing;
        return { shown: landing.shown, thumbnails: landing.thumbnails().length };
      });
      expect(left).toEqual({ shown: false, thumbnails: 0 });
      expect(await open.page.locator('#cards > *').count()).toBe(0);

      await open.page.click('#back-link');
      await open.page.waitForFunction(() => (window as unknown as LandingWindow).gallery.view === 'landing');
      expect(await open.page.locator('#cards .card').count()).toBe(demos.length);
      expect(await open.page.isVisible('#stage')).toBe(false);
      const back = await open.page.evaluate(() => {
        const g = (window as unknown as LandingWindow).gallery;
        return { demo: g.demo ?? null, world: g.runner.world };
      });
      expect(back).toEqual({ demo: null, world: null });

      // and the sidebar's Gallery link, from another demo
      await open.page.goto(`${url}#pyramid`);
      await open.page.waitForFunction(() => (window as unknown as LandingWindow).gallery.demo === 'pyramid');
      await open.page.click('#home-link');
      await open.page.waitForFunction(() => (window as unknown as LandingWindow).gallery.view === 'landing');
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

/** The .ts files of a demo's source, as the code panel names them. */
function sourceFilesOf(name: string): string[] {
  const folder = resolve(EXAMPLES, 'demos', name);
  return readdirSync(folder)
    .filter((f) => f.endsWith('.ts'))
    .map((f) => `examples/demos/${name}/${f}`);
}

describe('the Show code panel', () => {
  const codeText = (page: Page) => page.textContent('#code-text');

  it("shows the running demo's source, switches with the demo, and closes", async () => {
    const open = await openDemo(browser.context, url, 'pyramid');
    try {
      expect(await open.page.isVisible('#code-panel')).toBe(false);
      await open.page.click('#btn-code');
      const pyramid = readFileSync(resolve(EXAMPLES, 'demos/pyramid.ts'), 'utf8');
      await expect.poll(() => codeText(open.page)).toBe(pyramid);
      expect(pyramid).toContain("id: 'pyramid'");
      expect(await open.page.getAttribute('#btn-code', 'aria-expanded')).toBe('true');
      expect(await open.page.textContent('#btn-code')).toBe('Hide code');
      const font = await open.page.$eval('#code-panel pre', (el) => getComputedStyle(el).fontFamily);
      expect(font).toMatch(/monospace/);
      // the text scrolls within the panel, which is no taller than the stage beside it
      const sizes = await open.page.evaluate(() => {
        const pre = document.querySelector('#code-panel pre') as HTMLElement;
        return {
          overflow: getComputedStyle(pre).overflow,
          scrolls: pre.scrollHeight > pre.clientHeight,
          panel: (document.getElementById('code-panel') as HTMLElement).getBoundingClientRect().height,
          stage: (document.getElementById('stage') as HTMLElement).getBoundingClientRect().height,
          page: document.documentElement.scrollHeight,
          window: window.innerHeight,
        };
      });
      expect(sizes.overflow).toBe('auto');
      expect(sizes.scrolls).toBe(true);
      expect(sizes.panel).toBeLessThanOrEqual(sizes.stage + 1);
      expect(sizes.page).toBeLessThanOrEqual(sizes.window);

      // another demo with the panel open: its source; a demo in a folder: a tab per file, demo.ts first
      await open.page.click('a[data-demo="slingshot"]');
      const slingshot = readFileSync(resolve(EXAMPLES, 'demos/slingshot/demo.ts'), 'utf8');
      await expect.poll(() => codeText(open.page)).toBe(slingshot);
      const tabs = await open.page.$$eval('.code-tab', (els) => els.map((el) => el.getAttribute('title')));
      expect(tabs[0]).toBe('examples/demos/slingshot/demo.ts');
      expect([...tabs].sort()).toEqual(sourceFilesOf('slingshot').sort());
      expect(await open.page.textContent('.code-path')).toBe('examples/demos/slingshot/');
      await open.page.click('.code-tab:has-text("levels.ts")');
      const levels = readFileSync(resolve(EXAMPLES, 'demos/slingshot/levels.ts'), 'utf8');
      await expect.poll(() => codeText(open.page)).toBe(levels);

      // a demo whose file is not named by its id
      await open.page.click('a[data-demo="p5"]');
      const p5 = readFileSync(resolve(EXAMPLES, 'demos/p5-sketch.ts'), 'utf8');
      await expect.poll(() => codeText(open.page)).toBe(p5);

      await open.page.click('#code-close');
      expect(await open.page.isVisible('#code-panel')).toBe(false);
      expect(await open.page.textContent('#btn-code')).toBe('Show code');
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('the layout', () => {
  const sizes = [
    { width: 1280, height: 800 },
    { width: 1024, height: 600 },
    { width: 390, height: 844 },
    // a phone on its side and a 4K monitor
    { width: 844, height: 390 },
    { width: 3840, height: 2160 },
  ];
  const demoView = {
    boxes: [
      '#sidebar',
      '#back-link',
      '#demo-title',
      '.controls > *',
      '#flags label',
      '#flags legend',
      '#stage',
      '#code-panel',
      '#readout > *',
      '#demo-description',
      '#demo-ui > *',
      '.code-header > *',
    ],
    oneLine: [
      '#back-link',
      '#demo-title',
      '.controls button',
      '.controls label',
      '#flags label',
      '#readout > span:not(#demo-status)',
      '#demo-ui button',
    ],
    prose: ['#demo-description', '#demo-status'],
  };

  for (const size of sizes) {
    it(`has no overlaps, no word-by-word wrapping and a stage that fills the window at ${size.width}×${size.height}`, async () => {
      const open = await openLanding(browser.context, url);
      try {
        await open.page.setViewportSize(size);
        const landing = await measureLayout(open.page, {
          boxes: ['#sidebar', '.landing-header > *', '#cards .card', '.card > *'],
          oneLine: ['#home-link', '.card h3'],
          prose: ['.card p', '.landing-header p'],
        });
        expect(landing.measured).toBeGreaterThan(4);
        expect(landing.overlaps).toEqual([]);
        expect(landing.wrapped).toEqual([]);
        expect(landing.outside).toEqual([]);

        // a demo with buttons over the stage, the game's heads-up display, and two long status lines
        for (const id of ['car', 'slingshot', 'heavy-loads', 'bullets']) {
          await open.page.goto(`${url}#${id}`);
          await open.page.waitForFunction(
            (demo) => (window as unknown as LandingWindow).gallery.demo === demo,
            id,
          );
          // the canvas takes the space the controls leave: a good part of any window, phone to 4K
          // (1024×600 with its readout and description lines is the tightest, about half)
          if (await open.page.isVisible('#code-panel')) await open.page.click('#code-close');
          const stage = await open.page.locator('#stage').boundingBox();
          const share = (stage!.width * stage!.height) / (size.width * size.height);
          expect(share, `${id}: share of the window the stage takes`).toBeGreaterThan(0.45);
          await open.page.click('#btn-code');
          const view = await measureLayout(open.page, demoView);
          expect(view.measured, id).toBeGreaterThan(15);
          expect(view.overlaps, id).toEqual([]);
          expect(view.wrapped, id).toEqual([]);
          expect(view.outside, id).toEqual([]);
          // beside the stage on a laptop, the code panel leaves the demo view within the window
          if (size.width > 1000) {
            const page = await open.page.evaluate(() => document.documentElement.scrollHeight);
            expect(page, id).toBeLessThanOrEqual(size.height);
          }
        }
        const scrollWidth = await open.page.evaluate(() => document.documentElement.scrollWidth);
        expect(scrollWidth).toBeLessThanOrEqual(size.width);
        expect(open.errors).toEqual([]);
      } finally {
        await open.close();
      }
    });
  }
});

describe('a phone', () => {
  type CameraWindow = Window & {
    gallery: {
      demo: string;
      render: { camera: { visibleBounds(): { lowerBound: { x: number }; upperBound: { x: number } } } };
    };
  };

  it('held upright: each demo shows the width it asks for (fitWidth), the stage takes the screen under the controls', async () => {
    const fitted = demos.filter((d) => d.fitWidth !== undefined);
    expect(fitted.length).toBeGreaterThan(5);
    const open = await openLanding(browser.context, url);
    try {
      await open.page.setViewportSize({ width: 390, height: 844 });
      for (const demo of fitted) {
        await open.page.goto(`${url}#${demo.id}`);
        await open.page.waitForFunction(
          (id) => (window as unknown as CameraWindow).gallery.demo === id,
          demo.id,
        );
        const seen = await open.page.evaluate(() => {
          const b = (window as unknown as CameraWindow).gallery.render.camera.visibleBounds();
          return (b.upperBound.x - b.lowerBound.x) / 2;
        });
        // to rounding: the zoom is worked out from the canvas' size in whole pixels
        expect(seen, demo.id).toBeGreaterThan(demo.fitWidth! - 1e-9);
        // the list of demos gives way ("← Gallery" leads back to it)
        expect(await open.page.isVisible('#demo-list'), demo.id).toBe(false);
        const stage = await open.page.locator('#stage').boundingBox();
        expect(stage!.y, demo.id).toBeLessThan(844 / 2);
        expect(stage!.y + stage!.height, demo.id).toBeGreaterThan(844 * 0.8);
      }
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});
