/** Opening a demo of the built gallery in a page, and reading its state, for the e2e tests. */
import type { BrowserContext, Page } from 'playwright-core';
import { decodePng, type Image } from './png';

export interface OpenDemo {
  page: Page;
  /** console errors and page errors seen since the page opened */
  errors: string[];
  close(): Promise<void>;
}

/** A new page that records console errors and page errors. */
async function pageWithErrors(context: BrowserContext): Promise<{ page: Page; errors: string[] }> {
  const page = await context.newPage();
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`page: ${error.message}`));
  return { page, errors };
}

/** Opens `#id` in a new page and waits for the runner to have stepped a few times. */
export async function openDemo(context: BrowserContext, baseUrl: string, id: string): Promise<OpenDemo> {
  const { page, errors } = await pageWithErrors(context);
  await page.goto(`${baseUrl}#${id}`);
  await page.waitForFunction(
    (demo) => {
      const g = (window as unknown as { gallery?: { demo: string; runner: { stepCount: number } } }).gallery;
      return g !== undefined && g.demo === demo && g.runner.stepCount >= 3;
    },
    id,
    { timeout: 20_000 },
  );
  return { page, errors, close: () => page.close() };
}

/** Opens the gallery with no demo in the URL (the landing view of cards) in a new page. */
export async function openLanding(context: BrowserContext, baseUrl: string): Promise<OpenDemo> {
  const { page, errors } = await pageWithErrors(context);
  await page.goto(baseUrl);
  await page.waitForFunction(
    () => (window as unknown as { gallery?: { view: string } }).gallery?.view === 'landing',
  );
  return { page, errors, close: () => page.close() };
}

export async function stepCount(page: Page): Promise<number> {
  return page.evaluate(
    () => (window as unknown as { gallery: { runner: { stepCount: number } } }).gallery.runner.stepCount,
  );
}

/** Waits until the runner has taken `steps` more steps. */
export async function waitForSteps(page: Page, steps: number, timeout = 20_000): Promise<void> {
  const start = await stepCount(page);
  await page.waitForFunction(
    (target) =>
      (window as unknown as { gallery: { runner: { stepCount: number } } }).gallery.runner.stepCount >=
      target,
    start + steps,
    { timeout },
  );
}

/** A screenshot of the stage (the demo's canvas), decoded. */
/**
 * Starts the current demo again and pauses it before it takes a step (both in one task of the page, so
 * no frame comes between), as the Reset and Pause buttons do; a demo made asynchronously (a worker
 * world's) is waited for.
 */
export async function restartPaused(page: Page): Promise<void> {
  type Started = { gallery: { runner: { paused: boolean }; started: number } };
  const before = await page.evaluate(() => {
    const started = (window as unknown as Started).gallery.started;
    document.getElementById('btn-reset')?.click();
    const g = (window as unknown as Started).gallery;
    if (!g.runner.paused) document.getElementById('btn-pause')?.click();
    return started;
  });
  // a demo whose world runs in a worker starts once its worker runs: wait for it
  await page.waitForFunction((n) => (window as unknown as Started).gallery.started > n, before, {
    timeout: 20_000,
  });
}

/** Takes `steps` steps by hand, as the Step button does (each step is drawn at once). */
export async function stepByHand(page: Page, steps: number): Promise<void> {
  await page.evaluate((n) => {
    for (let i = 0; i < n; i++) document.getElementById('btn-step')?.click();
  }, steps);
}

export async function shootStage(page: Page, path?: string): Promise<Image> {
  const png = await page.locator('#stage').screenshot({ path, animations: 'allow' });
  return decodePng(png);
}

/** Page (CSS pixel) coordinates of a world point of the current demo. */
export async function worldToPage(
  page: Page,
  p: { x: number; y: number },
): Promise<{ x: number; y: number }> {
  return page.evaluate((point) => {
    const g = (
      window as unknown as {
        gallery: {
          render: {
            canvas: HTMLCanvasElement;
            worldToScreen(p: { x: number; y: number }): { x: number; y: number };
          };
        };
      }
    ).gallery;
    const canvas = g.render.canvas;
    const s = g.render.worldToScreen(point);
    const rect = canvas.getBoundingClientRect();
    // the canvas may be scaled by CSS: layout pixels to viewport pixels
    return {
      x: rect.left + (s.x * rect.width) / canvas.offsetWidth,
      y: rect.top + (s.y * rect.height) / canvas.offsetHeight,
    };
  }, p);
}

/**
 * Drags with the mouse from `from` to `to` (page pixels) in small moves, and holds there while the
 * runner takes `holdSteps` steps: counted in simulation steps, not milliseconds, so the pull lasts as
 * long however fast the page draws.
 */
export async function mouseDrag(
  page: Page,
  from: { x: number; y: number },
  to: { x: number; y: number },
  holdSteps = 24,
): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 12 });
  await waitForSteps(page, (await stepCount(page)) + holdSteps);
  await page.mouse.up();
}

/** The state a demo that draws with its own renderer (PixiJS, p5, Phaser) exposes. */
interface OwnRendererState {
  frames: number;
  drawnStep: number;
}

type StateWindow = Window & {
  gallery: { instance: { state?: Partial<OwnRendererState> }; runner: { stepCount: number } };
};

/** True when the current demo draws with its own renderer, which loads asynchronously. */
export async function drawsItself(page: Page): Promise<boolean> {
  return page.evaluate(
    () => typeof (window as unknown as StateWindow).gallery.instance.state?.drawnStep === 'number',
  );
}

/** Waits until the current demo's own renderer has loaded and drawn a frame. */
export async function waitForOwnRenderer(page: Page, timeout = 30_000): Promise<void> {
  await page.waitForFunction(
    () => ((window as unknown as StateWindow).gallery.instance.state?.frames ?? 0) > 0,
    undefined,
    { timeout },
  );
}

/**
 * Waits until the current demo's own renderer has drawn the runner's latest step (it draws on its own
 * animation frames, so a step taken by hand shows on its next frame).
 */
export async function waitForDrawnStep(page: Page, timeout = 20_000): Promise<void> {
  await page.waitForFunction(
    () => {
      const g = (window as unknown as StateWindow).gallery;
      return g.instance.state?.drawnStep === g.runner.stepCount;
    },
    undefined,
    { timeout },
  );
}

type WorkerGallery = {
  gallery: { instance: { world: { stepCount?: number } }; runner: { stepsInFlight: number } };
};

/** Waits until a demo's worker has finished every step sent, `steps` of them since the demo started. */
export async function waitForWorkerSteps(page: Page, steps: number): Promise<void> {
  await page.waitForFunction(
    (n) => {
      const g = (window as unknown as WorkerGallery).gallery;
      return g.instance.world.stepCount === n && g.runner.stepsInFlight === 0;
    },
    steps,
    { timeout: 60_000 },
  );
}

/** Whether the current demo's world runs in a worker (a World has no step count of its own; a WorkerWorld counts its worker's). */
export function runsInWorker(page: Page): Promise<boolean> {
  return page.evaluate(
    () => typeof (window as unknown as WorkerGallery).gallery.instance.world.stepCount === 'number',
  );
}
