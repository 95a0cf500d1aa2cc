/**
 * The 5,000-body scene in a Web Worker (examples/demos/stress-worker.ts) in Chromium: the gallery is
 * cross-origin isolated, so the worker world shares its state through a SharedArrayBuffer; its bodies
 * move as the same calls move a World in this process (same bits); the page draws frames while the
 * worker's steps are still out, and both counts go on. Steps are taken by hand or waited for as
 * counts: nothing here depends on how fast the machine is.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { build } from 'esbuild';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { buildStressScene } from '../../examples/demos/stress';
import { World } from '../../src/index';
import { type Browser, launchChromium } from './browser';
import {
  openDemo,
  restartPaused,
  shootStage,
  stepByHand,
  waitForWorkerSteps,
  worldToPage,
} from './gallery-page';
import { GALLERY_DIR } from './global-setup';
import { inkStats } from './png';

let browser: Browser;
const url = inject('galleryUrl');

beforeAll(async () => {
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
});

interface DemoState {
  frames: number;
  framesWithStepsOut: number;
  bufferMode: string;
  crossOriginIsolated: boolean;
}

type WorkerGallery = Window & {
  gallery: {
    runner: { stepCount: number; stepsInFlight: number; paused: boolean };
    instance: {
      state: DemoState;
      world: { stepCount: number; bodies: Iterable<{ position: { x: number; y: number } }> };
    };
  };
};

/** Every body's position as the page reads it from the worker's last published state, and the step it is from. */
function readBodies(page: Page): Promise<{ step: number; xy: number[] }> {
  return page.evaluate(() => {
    const world = (window as unknown as WorkerGallery).gallery.instance.world;
    const xy: number[] = [];
    for (const body of world.bodies) xy.push(body.position.x, body.position.y);
    return { step: world.stepCount, xy };
  });
}

function readState(page: Page): Promise<DemoState & { steps: number }> {
  return page.evaluate(() => {
    const g = (window as unknown as WorkerGallery).gallery;
    return { ...g.instance.state, steps: g.instance.world.stepCount };
  });
}

describe('5,000 bodies in a worker', () => {
  it('runs cross-origin isolated on shared memory, and its bodies move as a World here moves them (same bits)', async () => {
    const open = await openDemo(browser.context, url, 'stress-worker');
    try {
      const page = open.page;
      expect(await page.evaluate(() => crossOriginIsolated)).toBe(true);
      const state = await readState(page);
      expect(state.crossOriginIsolated).toBe(true);
      expect(state.bufferMode).toBe('shared');

      await restartPaused(page);
      const start = await readBodies(page);
      expect(start.step).toBe(0);
      await stepByHand(page, 20);
      await waitForWorkerSteps(page, 20);
      const after = await readBodies(page);
      expect(after.step).toBe(20);

      // the same scene in a World on this thread (Node), 20 steps: Fulcrum is deterministic, so the
      // worker in Chromium must have computed the very same numbers
      const local = new World();
      buildStressScene(local);
      const localStart: number[] = [];
      for (const body of local.bodies) localStart.push(body.position.x, body.position.y);
      for (let i = 0; i < 20; i++) local.step(1 / 60);
      const localAfter: number[] = [];
      for (const body of local.bodies) localAfter.push(body.position.x, body.position.y);
      expect(start.xy.length).toBe(2 * 5001);
      expect(start.xy).toEqual(localStart);
      expect(after.xy).toEqual(localAfter);

      // and the top row falls freely: 20 steps of 4 substeps of symplectic Euler from rest drop a body
      // by g h^2 N (N + 1) / 2 (h = 1/240 s, N = 80): 0.5625 m, where g t^2 / 2 would give 0.5556 m
      const h = 1 / 240;
      const drop = (10 * h * h * 80 * 81) / 2;
      let top = -Infinity;
      for (let i = 1; i < start.xy.length; i += 2) top = Math.max(top, start.xy[i]);
      let row = 0;
      let free = 0;
      for (let i = 1; i < start.xy.length; i += 2) {
        if (start.xy[i] !== top) continue;
        row++;
        expect(after.xy[i]).toBeLessThan(top - 0.5);
        if (Math.abs(after.xy[i] - (top - drop)) < 1e-9 && after.xy[i - 1] === start.xy[i - 1]) free++;
      }
      // 65 bodies in the top row; two of them touch a neighbour (a triangle's corner) within 20 steps
      expect(row).toBe(65);
      expect(free).toBeGreaterThanOrEqual(60);

      // the page drew the 20 steps: bodies in the picture
      const picture = await shootStage(page);
      expect(inkStats(picture).ink).toBeGreaterThan(0.02);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('keeps drawing while the worker steps: frames drawn with steps still out, both counts going on', async () => {
    const open = await openDemo(browser.context, url, 'stress-worker');
    try {
      const page = open.page;
      const before = await readState(page);
      await page.waitForFunction(
        ([frames, steps]) => {
          const g = (window as unknown as WorkerGallery).gallery;
          return g.instance.state.frames >= frames + 30 && g.instance.world.stepCount >= steps + 30;
        },
        [before.frames, before.steps],
        { timeout: 60_000 },
      );
      const after = await readState(page);
      // a frame that sends a step draws at once, before the worker can have answered: that it drew
      // without waiting shows in these frames
      expect(after.framesWithStepsOut).toBeGreaterThan(before.framesWithStepsOut);
      // the readout shows the worker's step time and the page's frame time
      await page.waitForFunction(
        () => /worker step \d+\.\d\d ms/.test(document.querySelector('.timings')?.textContent ?? ''),
        undefined,
        {
          timeout: 10_000,
        },
      );
      const readout = (await page.textContent('.timings')) ?? '';
      expect(readout).toMatch(/^page frame \d+\.\d\d ms \(\d+ fps\) · worker step \d+\.\d\d ms · \d+ steps$/);
      expect(Number(/worker step (\d+\.\d\d)/.exec(readout)![1])).toBeGreaterThan(0);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('drags a falling body up with the mouse (a mouse joint in the worker, its target moved by commands)', async () => {
    const open = await openDemo(browser.context, url, 'stress-worker');
    try {
      const page = open.page;
      await restartPaused(page);
      await stepByHand(page, 10);
      await waitForWorkerSteps(page, 10);
      // the body in the middle of the top row
      const pick = await page.evaluate(() => {
        const bodies = [...(window as unknown as WorkerGallery).gallery.instance.world.bodies];
        let best = 1;
        for (let i = 1; i < bodies.length; i++) {
          const p = bodies[i].position;
          const b = bodies[best].position;
          if (p.y > b.y + 1e-9 || (Math.abs(p.y - b.y) <= 1e-9 && Math.abs(p.x) < Math.abs(b.x))) best = i;
        }
        return { index: best, position: bodies[best].position };
      });
      // the top row is above the demo's view: look higher, as a pan would
      await page.evaluate(() =>
        (
          window as unknown as {
            gallery: { render: { camera: { setView(v: object): void } } };
          }
        ).gallery.render.camera.setView({ center: { x: 0, y: 32 }, halfHeight: 19 }),
      );
      const from = await worldToPage(page, pick.position);
      const to = await worldToPage(page, { x: pick.position.x, y: pick.position.y + 3 });
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      await page.mouse.move(to.x, to.y, { steps: 8 });
      expect(
        await page.evaluate(
          () =>
            (window as unknown as { gallery: { pointer: { body: unknown } } }).gallery.pointer.body !== null,
        ),
      ).toBe(true);
      // 50 steps held by the mouse: falling freely, the body would have dropped 4 m more
      await stepByHand(page, 50);
      await waitForWorkerSteps(page, 60);
      const held = await page.evaluate((i) => {
        const bodies = [...(window as unknown as WorkerGallery).gallery.instance.world.bodies];
        return bodies[i].position;
      }, pick.index);
      await page.mouse.up();
      // held near the target, 3 m above where it was picked (the 5 Hz spring sags g / (2 pi 5)^2 = 1 cm)
      expect(held.y).toBeGreaterThan(pick.position.y + 2.5);
      expect(Math.abs(held.x - pick.position.x)).toBeLessThan(1);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('5,000 bodies in a worker whose world has a solver worker (?threads=2)', () => {
  it('starts the second thread in the worker and moves its bodies as a World here moves them (same bits)', async () => {
    const open = await openDemo(browser.context, `${url}?threads=2`, 'stress-worker');
    try {
      const page = open.page;
      await restartPaused(page);
      // the world in the worker starts its solver worker while it steps: steps until a step says it
      // ran on two threads (how many varies; the World here takes as many)
      let steps = 0;
      let threads = 1;
      while (threads !== 2 && steps < 600) {
        await stepByHand(page, 10);
        steps += 10;
        await waitForWorkerSteps(page, steps);
        threads = await page.evaluate(
          () =>
            (window as unknown as { gallery: { instance: { world: { workers: number } } } }).gallery.instance
              .world.workers,
        );
      }
      expect(threads).toBe(2);
      await stepByHand(page, 20);
      steps += 20;
      await waitForWorkerSteps(page, steps);
      const after = await readBodies(page);
      expect(after.step).toBe(steps);
      const local = new World();
      buildStressScene(local);
      for (let i = 0; i < steps; i++) local.step(1 / 60);
      const localAfter: number[] = [];
      for (const body of local.bodies) localAfter.push(body.position.x, body.position.y);
      expect(after.xy).toEqual(localAfter);
      // the readout says so at its next refresh
      await page.waitForFunction(() =>
        /on 2 threads/.test(document.querySelector('[data-role=timings]')?.textContent ?? ''),
      );
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe("the Workers guide's example", () => {
  const ROOT = resolve(__dirname, '../..');
  const DIR = join(GALLERY_DIR, 'docs-examples-worker');

  it('renders a worker world with Render, Runner and Pointer as a World, on shared memory', async () => {
    // bundled as a user's bundler would: the package's worker script beside the page's bundle, where
    // WorkerWorld.create() looks for it by default
    mkdirSync(DIR, { recursive: true });
    await build({
      entryPoints: {
        'worker-render': join(ROOT, 'docs/examples/worker-render.ts'),
        'worker-entry': join(ROOT, 'src/worker/worker-entry.ts'),
      },
      outdir: DIR,
      bundle: true,
      format: 'esm',
      target: 'es2022',
      logLevel: 'warning',
      alias: {
        fulcrum: join(ROOT, 'src/index.ts'),
        'fulcrum/render': join(ROOT, 'src/render/index.ts'),
        'fulcrum/worker': join(ROOT, 'src/worker/index.ts'),
      },
    });
    writeFileSync(
      join(DIR, 'index.html'),
      `<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"><style>html,body{margin:0;height:100%}` +
        `#app{width:800px;height:500px}</style></head><body><div id="app"></div><script type="module">` +
        `import * as example from './worker-render.js'; window.example = example;</script></body></html>`,
    );
    const page = await browser.context.newPage();
    const errors: string[] = [];
    page.on('console', (message) => {
      if (message.type() === 'error') errors.push(`console: ${message.text()}`);
    });
    page.on('pageerror', (error) => errors.push(`page: ${error.message}`));
    try {
      await page.goto(new URL('docs-examples-worker/index.html', url).href);
      type ExampleWindow = Window & {
        example?: {
          runner: { stepCount: number };
          world: { bufferMode: string; bodies: Iterable<{ position: { y: number } }> };
        };
      };
      await page.waitForFunction(
        () => ((window as ExampleWindow).example?.runner.stepCount ?? 0) >= 30,
        undefined,
        {
          timeout: 30_000,
        },
      );
      const seen = await page.evaluate(() => {
        const example = (window as ExampleWindow).example!;
        const canvas = document.querySelector('canvas')!;
        const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
        let ink = 0;
        // the background is #15171d: count the pixels that are not
        for (let i = 0; i < data.length; i += 4) {
          if (Math.abs(data[i] - 0x15) + Math.abs(data[i + 1] - 0x17) + Math.abs(data[i + 2] - 0x1d) > 30)
            ink++;
        }
        const ys = [...example.world.bodies].map((b) => b.position.y);
        return { mode: example.world.bufferMode, share: ink / (data.length / 4), ys };
      });
      expect(seen.mode).toBe('shared');
      expect(seen.share).toBeGreaterThan(0.05);
      // the ground and 36 boxes, the pyramid standing: the top box still about 7.5 m up
      expect(seen.ys.length).toBe(37);
      expect(Math.max(...seen.ys)).toBeGreaterThan(7);
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  });
});
