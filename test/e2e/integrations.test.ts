/**
 * The integrations of the gallery in Chromium: the p5.js sketch, the Phaser 4 scene, the PixiJS demo's
 * draw switches, and the plain page that loads the `<script>` build. Everything that moves is driven
 * by steps taken by hand while the runner is paused, never by waiting for time to pass.
 */
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { type Browser, launchChromium } from './browser';
import {
  openDemo,
  restartPaused,
  shootStage,
  stepByHand,
  waitForDrawnStep,
  waitForOwnRenderer,
} from './gallery-page';
import { decodePng, differingShare, type Image, inkStats } from './png';

const SCREENSHOTS = resolve(__dirname, '../../test-results/e2e/screenshots');
/** standard gravity of a default World, m/s² */
const G = 10;
const DT = 1 / 60;

let browser: Browser;
const url = inject('galleryUrl');

beforeAll(async () => {
  mkdirSync(SCREENSHOTS, { recursive: true });
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
});

interface Vec {
  x: number;
  y: number;
}

type AnyWindow = Window & {
  gallery: {
    world: { bodyCount: number; bodies: Iterable<{ position: Vec; angle: number; type: string }> };
    runner: { stepCount: number };
    instance: Record<string, unknown> & { state: Record<string, unknown> };
  };
};

/** The position of the body created last (the world has destroyed none, so it is the last one listed). */
const lastBody = (page: Page) =>
  page.evaluate(() => {
    const bodies = [...(window as unknown as AnyWindow).gallery.world.bodies];
    return bodies[bodies.length - 1].position;
  });

const bodyCount = (page: Page) =>
  page.evaluate(() => (window as unknown as AnyWindow).gallery.world.bodyCount);

/** Opens a demo, starts it again paused, and waits until its own renderer draws. */
async function openPaused(id: string) {
  const open = await openDemo(browser.context, url, id);
  await restartPaused(open.page);
  await waitForOwnRenderer(open.page);
  return open;
}

/**
 * Drop of a body let go at rest after `steps` steps: ½ g t² with t = steps × dt. The engine's
 * semi-implicit Euler over 4 substeps adds g·t·h/2 (h = dt/4), under 3% here, hence the tolerance.
 */
const freeFallDrop = (steps: number) => 0.5 * G * (steps * DT) ** 2;

describe('the p5.js sketch', () => {
  it('draws in a p5 canvas; a click drops a ball where it was made, and the ball falls as g says', async () => {
    const open = await openPaused('p5');
    const page = open.page;
    try {
      expect(await page.locator('canvas[data-renderer="p5"]').count()).toBe(1);
      // the gallery's draw switches do not apply to p5's drawing: hidden
      expect(await page.isVisible('#flags')).toBe(false);
      const box = await page.locator('canvas[data-renderer="p5"]').boundingBox();
      if (!box) throw new Error('no p5 canvas on the page');
      const state = (await page.evaluate(() => (window as unknown as AnyWindow).gallery.instance.state)) as {
        scale: number;
        width: number;
        height: number;
      };
      const before = await bodyCount(page);
      // high and to the left: above every body of the scene
      const click = { x: box.x + box.width * 0.25, y: box.y + box.height * 0.15 };
      await page.mouse.click(click.x, click.y);
      expect(await bodyCount(page)).toBe(before + 1);
      // the sketch's stated mapping, pixel = (width / 2 + x * scale, height - (y + 1) * scale), inverted
      const expected = {
        x: (click.x - box.x - state.width / 2) / state.scale,
        y: (state.height - (click.y - box.y)) / state.scale - 1,
      };
      const dropped = await lastBody(page);
      expect(Math.abs(dropped.x - expected.x)).toBeLessThan(1 / state.scale);
      expect(Math.abs(dropped.y - expected.y)).toBeLessThan(1 / state.scale);

      await stepByHand(page, 12);
      await waitForDrawnStep(page);
      const fallen = await lastBody(page);
      expect(fallen.x).toBeCloseTo(dropped.x, 9);
      const drop = dropped.y - fallen.y;
      expect(Math.abs(drop - freeFallDrop(12)) / freeFallDrop(12)).toBeLessThan(0.03);
      await shootStage(page, resolve(SCREENSHOTS, 'p5-click.png'));
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('a drag pours a box for every metre the pointer travels', async () => {
    const open = await openPaused('p5');
    const page = open.page;
    try {
      const box = await page.locator('canvas[data-renderer="p5"]').boundingBox();
      if (!box) throw new Error('no p5 canvas on the page');
      const scale = (await page.evaluate(
        () => (window as unknown as AnyWindow).gallery.instance.state.scale,
      )) as number;
      const before = await bodyCount(page);
      const from = { x: box.x + box.width * 0.2, y: box.y + box.height * 0.15 };
      const metres = 4.5;
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      await page.mouse.move(from.x + metres * scale, from.y, { steps: 45 });
      await page.mouse.up();
      // the ball the press dropped, then the boxes (the runner is paused: nothing has moved)
      const poured = await page.evaluate(
        (n) =>
          [...(window as unknown as AnyWindow).gallery.world.bodies].slice(n + 1).map((b) => b.position.x),
        before,
      );
      // one per whole metre of travel; the browser may merge a few moves, never split them
      expect(poured.length).toBeGreaterThanOrEqual(2);
      expect(poured.length).toBeLessThanOrEqual(Math.floor(metres));
      for (let i = 1; i < poured.length; i++) expect(poured[i] - poured[i - 1]).toBeGreaterThanOrEqual(1);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('the Phaser 4 scene', () => {
  /** every body's sprite against the body: position × 48 px/m with y flipped, rotation = -angle */
  const spriteMismatch = (page: Page) =>
    page.evaluate(() => {
      const g = (window as unknown as AnyWindow).gallery;
      const sprites = g.instance.sprites as Map<unknown, { x: number; y: number; rotation: number }>;
      let worst = 0;
      let count = 0;
      for (const body of g.world.bodies) {
        const sprite = sprites.get(body);
        if (!sprite) return { worst: Number.POSITIVE_INFINITY, count };
        const p = body.position;
        const turn = sprite.rotation + body.angle;
        const angleError = Math.abs(Math.atan2(Math.sin(turn), Math.cos(turn)));
        worst = Math.max(worst, Math.abs(sprite.x - p.x * 48), Math.abs(sprite.y + p.y * 48), angleError);
        count++;
      }
      return { worst, count };
    });

  it('has a sprite on every body, where the body is, step after step; Phaser has no physics of its own', async () => {
    const open = await openPaused('phaser');
    const page = open.page;
    try {
      expect(await page.isVisible('#flags')).toBe(false);
      const physics = await page.evaluate(() => {
        const scene = (window as unknown as AnyWindow).gallery.instance.state.scene as Record<
          string,
          unknown
        >;
        return { physics: scene.physics, matter: scene.matter, impact: scene.impact };
      });
      expect(physics).toEqual({ physics: undefined, matter: undefined, impact: undefined });

      const start = await page.evaluate(() =>
        [...(window as unknown as AnyWindow).gallery.world.bodies].map((b) => ({ ...b.position })),
      );
      for (const steps of [5, 30]) {
        await stepByHand(page, steps);
        await waitForDrawnStep(page);
        const { worst, count } = await spriteMismatch(page);
        expect(count).toBe(start.length);
        // paused and stepped by hand the runner draws the last step itself (no blending)
        expect(worst).toBeLessThan(1e-9);
      }
      // and the bodies did move: the balls above the ramp fell
      const now = await page.evaluate(() =>
        [...(window as unknown as AnyWindow).gallery.world.bodies].map((b) => ({ ...b.position })),
      );
      const fallen = now.filter((p, i) => start[i].y - p.y > 0.5).length;
      expect(fallen).toBeGreaterThanOrEqual(4);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('a click drops a crate at the point of the Phaser world under the pointer', async () => {
    const open = await openPaused('phaser');
    const page = open.page;
    try {
      const box = await page.locator('canvas[data-renderer="phaser"]').boundingBox();
      if (!box) throw new Error('no Phaser canvas on the page');
      // on whole page pixels, where the mouse events land
      const page0 = { x: Math.round(box.x + box.width * 0.5), y: Math.round(box.y + box.height * 0.2) };
      const at = { x: page0.x - box.x, y: page0.y - box.y };
      // Phaser's own camera says which world pixel is there
      const worldPixel = await page.evaluate((p) => {
        const scene = (window as unknown as AnyWindow).gallery.instance.state.scene as {
          cameras: { main: { zoom: number; getWorldPoint(x: number, y: number): { x: number; y: number } } };
        };
        const w = scene.cameras.main.getWorldPoint(p.x, p.y);
        return { x: w.x, y: w.y, zoom: scene.cameras.main.zoom };
      }, at);
      const before = await bodyCount(page);
      await page.mouse.click(page0.x, page0.y);
      expect(await bodyCount(page)).toBe(before + 1);
      const crate = await lastBody(page);
      // within a screen pixel, in metres
      const pixel = 1 / (48 * worldPixel.zoom);
      expect(Math.abs(crate.x - worldPixel.x / 48)).toBeLessThan(pixel);
      expect(Math.abs(crate.y + worldPixel.y / 48)).toBeLessThan(pixel);
      await stepByHand(page, 3);
      await waitForDrawnStep(page);
      expect((await spriteMismatch(page)).worst).toBeLessThan(1e-9);
      await shootStage(page, resolve(SCREENSHOTS, 'phaser-click.png'));
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('the PixiJS demo', () => {
  /** The image without a margin of `m` pixels: the stage's rounded corners and blended edge rows. */
  const inner = (image: Image, m = 4): Image => {
    const width = image.width - 2 * m;
    const height = image.height - 2 * m;
    const data = new Uint8Array(width * height * 4);
    for (let y = 0; y < height; y++) {
      const from = ((y + m) * image.width + m) * 4;
      data.set(image.data.subarray(from, from + width * 4), y * width * 4);
    }
    return { width, height, data };
  };

  /** Sets the draw switches and returns the stage once Pixi has drawn a frame with them. */
  async function drawWith(page: Page, flags: Record<string, boolean>): Promise<Image> {
    for (const [key, on] of Object.entries(flags)) await page.setChecked(`#flag-${key}`, on);
    const frames = (await page.evaluate(
      () => (window as unknown as AnyWindow).gallery.instance.state.frames,
    )) as number;
    // two frames later Pixi has drawn with the new switches at least once
    await page.waitForFunction(
      (f) => ((window as unknown as AnyWindow).gallery.instance.state.frames as number) >= f + 2,
      frames,
    );
    return inner(await shootStage(page));
  }

  it('its draw switches change what Pixi draws', async () => {
    const open = await openPaused('pixi');
    const page = open.page;
    try {
      expect(await page.isVisible('#flags')).toBe(true);
      // most of the pieces in the bin, touching one another
      await stepByHand(page, 150);
      await waitForDrawnStep(page);
      const off = { wireframe: false, aabbs: false, contacts: false, contactNormals: false };
      const filled = inkStats(await drawWith(page, { shapes: true, ...off })).ink;
      const wireframe = inkStats(await drawWith(page, { shapes: true, ...off, wireframe: true })).ink;
      const nothing = inkStats(await drawWith(page, { shapes: false, ...off })).ink;
      const aabbs = inkStats(await drawWith(page, { shapes: false, ...off, aabbs: true })).ink;
      const contactsImage = await drawWith(page, { shapes: false, ...off, contacts: true });
      const contacts = inkStats(contactsImage).ink;
      await shootStage(page, resolve(SCREENSHOTS, 'pixi-contacts.png'));
      expect(filled).toBeGreaterThan(0.1);
      // outlines instead of fills: far less ink, but the bodies are there
      expect(wireframe).toBeLessThan(filled * 0.7);
      expect(wireframe).toBeGreaterThan(0.01);
      // shapes off and nothing else: the background alone
      expect(nothing).toBe(0);
      expect(aabbs).toBeGreaterThan(0.01);
      expect(contacts).toBeGreaterThan(0.002);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('the plain page with a <script> tag', () => {
  type SceneWindow = Window & {
    Fulcrum: {
      render?: unknown;
      Shape: { circle(radius: number): unknown };
    };
    scene: {
      world: {
        createBody(def: object): { position: Vec; createShape(geometry: unknown): unknown };
      };
      runner: { stepCount: number; paused: boolean; step(): void };
      ball?: { position: Vec };
    };
  };

  const shootCanvas = async (page: Page) => decodePng(await page.locator('#view').screenshot());

  it('is linked from the gallery, loads the global build without a module, draws, and steps its world', async () => {
    const open = await openDemo(browser.context, url, 'pyramid');
    const page = open.page;
    try {
      await page.click('#link-script-tag');
      await page.waitForURL(/script-tag\.html$/);
      await page.waitForFunction(
        () => ((window as unknown as SceneWindow).scene?.runner.stepCount ?? 0) >= 1,
        {
          timeout: 20_000,
        },
      );
      // no bundler, no imports: classic scripts only, and the global has its renderer
      expect(await page.locator('script[type="module"]').count()).toBe(0);
      expect(await page.evaluate(() => typeof (window as unknown as SceneWindow).Fulcrum.render)).toBe(
        'object',
      );

      // paused, a ball let go at rest high on the left (through the page's global), one step drawn
      const start = await page.evaluate(() => {
        const w = window as unknown as SceneWindow;
        w.scene.runner.paused = true;
        const ball = w.scene.world.createBody({ type: 'dynamic', position: { x: -9, y: 9 } });
        ball.createShape(w.Fulcrum.Shape.circle(0.45));
        w.scene.ball = ball;
        w.scene.runner.step();
        return { ...ball.position };
      });
      const first = await shootCanvas(page);
      const { ink, colors } = inkStats(first);
      expect(ink, 'share of the canvas that is not background').toBeGreaterThan(0.02);
      expect(colors).toBeGreaterThan(3);
      const end = await page.evaluate(() => {
        const w = window as unknown as SceneWindow;
        for (let i = 0; i < 12; i++) w.scene.runner.step();
        return { ...(w.scene.ball as { position: Vec }).position };
      });
      const second = await shootCanvas(page);
      await page.locator('#view').screenshot({ path: resolve(SCREENSHOTS, 'script-tag.png') });
      expect(
        differingShare(first, second) * first.width * first.height,
        'pixels that changed',
      ).toBeGreaterThan(50);
      // 13 steps of free fall in all, 1 before the first picture
      const drop = 9 - end.y;
      expect(Math.abs(drop - freeFallDrop(13)) / freeFallDrop(13)).toBeLessThan(0.03);
      expect(start.y).toBeLessThan(9);
      expect(end.x).toBe(-9);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});
