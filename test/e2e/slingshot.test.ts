/**
 * The slingshot game in a real browser, played as a visitor plays it (mouse and touch on the canvas)
 * but wholly paused: every step is taken by hand through the game's step hook (`advance`, one
 * page.evaluate that steps until a condition or a limit), and the pointer comes down, moves and
 * comes up between given steps. So the world each shot lands on is the same on every run and every
 * machine, and so is the outcome.
 */
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { type Browser, launchChromium } from './browser';
import { openDemo, restartPaused, shootStage, worldToPage } from './gallery-page';

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

interface Point {
  x: number;
  y: number;
}

interface GameView {
  state: string;
  level: number;
  score: number;
  stars: number;
  shots: number;
  targets: number;
  destroyed: number;
  bird: Point | null;
  velocity: Point | null;
  angularVelocity: number | null;
  birdType: string | null;
}

/** What the page's game exposes (examples/demos/slingshot). */
interface GameWindow {
  gallery: {
    world: { gravity: Point };
    render: { camera: { scale: number } };
    instance: {
      anchor: Point;
      step: number;
      camera: { settled: boolean };
      preview: { points: Float64Array; count: number };
      advance(limit: number, until?: (game: GameState) => boolean): number;
      game: GameState;
    };
  };
}

interface GameState {
  state: string;
  level: number;
  score: number;
  stars: number;
  shots: number;
  targets: unknown[];
  targetsDestroyed: number;
  loaded: { type: { kind: string } } | null;
  flying: unknown[];
  bird: { position: Point; linearVelocity: Point; angularVelocity: number } | null;
}

const read = (page: Page): Promise<GameView> =>
  page.evaluate(() => {
    const game = (window as unknown as GameWindow).gallery.instance.game;
    const bird = game.bird;
    return {
      state: game.state,
      level: game.level,
      score: game.score,
      stars: game.stars,
      shots: game.shots,
      targets: game.targets.length,
      destroyed: game.targetsDestroyed,
      bird: bird ? bird.position : null,
      velocity: bird ? bird.linearVelocity : null,
      angularVelocity: bird ? bird.angularVelocity : null,
      birdType: game.loaded ? game.loaded.type.kind : null,
    };
  });

/** Steps by hand until the game is ready for a shot and the camera has come to rest. */
async function untilReady(page: Page): Promise<void> {
  const steps = await page.evaluate(() => {
    const instance = (window as unknown as GameWindow).gallery.instance;
    return instance.advance(1500, (game) => game.state !== 'flying' && instance.camera.settled);
  });
  expect(steps, 'steps until the next bird is ready').toBeLessThan(1500);
}

/** Opens the game, starts it again paused, and steps until the first bird is ready. */
async function openGame(): Promise<{ page: Page; errors: string[]; close(): Promise<void> }> {
  const open = await openDemo(browser.context, url, 'slingshot');
  await restartPaused(open.page);
  await untilReady(open.page);
  return open;
}

/** One metre in page pixels, and the anchor of the sling. */
async function scaleAndAnchor(page: Page): Promise<{ scale: number; anchor: Point }> {
  return page.evaluate(() => {
    const g = (window as unknown as GameWindow).gallery;
    return { scale: g.render.camera.scale, anchor: g.instance.anchor };
  });
}

/** Takes `n` steps by hand. */
const advance = (page: Page, n: number) =>
  page.evaluate((steps) => (window as unknown as GameWindow).gallery.instance.advance(steps), n);

/**
 * Presses on the bird at `grip` (metres from its centre), pulls by `pull` (metres, from the sling's
 * anchor to where the hand ends) in `moves` moves, holds for `holdSteps` steps, and lets go.
 */
async function shoot(page: Page, pull: Point, grip: Point = { x: 0, y: 0 }, holdSteps = 10): Promise<void> {
  const before = await read(page);
  expect(before.state).toBe('ready');
  if (!before.bird) throw new Error('no bird in the sling');
  const from = await worldToPage(page, { x: before.bird.x + grip.x, y: before.bird.y + grip.y });
  const { anchor } = await scaleAndAnchor(page);
  const to = await worldToPage(page, { x: anchor.x + pull.x + grip.x, y: anchor.y + pull.y + grip.y });
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 10 });
  await advance(page, holdSteps);
  await page.mouse.up();
  expect((await read(page)).shots).toBe(before.shots + 1);
}

/** Steps until the flight is over (the next bird ready, or the level won or lost). */
async function untilLanded(page: Page): Promise<number> {
  return page.evaluate(() =>
    (window as unknown as GameWindow).gallery.instance.advance(1500, (game) => game.state !== 'flying'),
  );
}

describe('the slingshot game', () => {
  it('holds the bird by the point it was taken, steady, and throws it at a speed that follows the pull, along the guide', async () => {
    const { page, errors, close } = await openGame();
    try {
      const { scale, anchor } = await scaleAndAnchor(page);
      const start = await read(page);
      if (!start.bird) throw new Error('no bird in the sling');
      // take the bird off its centre, as a hand does
      const grip = { x: 0.12, y: -0.09 };
      const pull = { x: -1.1, y: -0.35 };
      const from = await worldToPage(page, { x: start.bird.x + grip.x, y: start.bird.y + grip.y });
      const to = await worldToPage(page, { x: anchor.x + pull.x + grip.x, y: anchor.y + pull.y + grip.y });
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      await page.mouse.move(to.x, to.y, { steps: 10 });
      const held = await read(page);
      expect(held.state).toBe('aiming');
      // the centre is where the hand is, less the grip's offset: within a pixel and a half
      const pixel = 1 / scale;
      if (!held.bird) throw new Error('no bird held');
      expect(Math.abs(held.bird.x - (anchor.x + pull.x))).toBeLessThan(1.5 * pixel);
      expect(Math.abs(held.bird.y - (anchor.y + pull.y))).toBeLessThan(1.5 * pixel);
      // held for half a second: it neither moves nor turns
      await advance(page, 30);
      const still = await read(page);
      expect(still.bird).toEqual(held.bird);
      expect(Math.abs(still.angularVelocity ?? 1)).toBeLessThan(1e-9);
      expect(Math.hypot(still.velocity?.x ?? 1, still.velocity?.y ?? 1)).toBeLessThan(1e-9);
      const guide = await page.evaluate(() => {
        const preview = (window as unknown as GameWindow).gallery.instance.preview;
        return Array.from(preview.points.subarray(0, 2 * preview.count));
      });
      expect(guide.length, 'points of the aiming guide').toBeGreaterThanOrEqual(60);
      await shootStage(page, resolve(SCREENSHOTS, 'slingshot-aim.png'));
      await page.mouse.up();

      // the launch: along the pull, its speed in proportion to it
      const launched = await read(page);
      expect(launched.state).toBe('flying');
      const p0 = held.bird;
      const v0 = launched.velocity as Point;
      const pullLength = Math.hypot(anchor.x - p0.x, anchor.y - p0.y);
      const speed = Math.hypot(v0.x, v0.y);
      expect((v0.x * (anchor.x - p0.x) + v0.y * (anchor.y - p0.y)) / (speed * pullLength)).toBeGreaterThan(
        1 - 1e-12,
      );

      // the first half second of flight: a parabola under the world's gravity, and exactly the guide
      const flight = await page.evaluate(() => {
        const g = (window as unknown as GameWindow).gallery;
        const points: Point[] = [];
        for (let i = 0; i < 30; i++) {
          g.instance.advance(1);
          const bird = g.instance.game.bird;
          if (bird) points.push(bird.position);
        }
        return { points, gravity: g.world.gravity, dt: g.instance.step };
      });
      expect(flight.points).toHaveLength(30);
      for (let i = 0; i < 30; i++) {
        const t = (i + 1) * flight.dt;
        const x = p0.x + v0.x * t + 0.5 * flight.gravity.x * t * t;
        const y = p0.y + v0.y * t + 0.5 * flight.gravity.y * t * t;
        // the world integrates in steps of dt/4 (velocity first): after t it is ahead of the smooth
        // parabola by g t (dt/4) / 2, 1 cm at half a second; 2 cm allowed
        expect(Math.hypot(flight.points[i].x - x, flight.points[i].y - y)).toBeLessThan(0.02);
        // the guide is the same physics: the same points, to the last bits
        expect(Math.abs(guide[2 * i] - flight.points[i].x)).toBeLessThan(1e-9);
        expect(Math.abs(guide[2 * i + 1] - flight.points[i].y)).toBeLessThan(1e-9);
      }

      // a longer pull, with a finger this time: a faster bird, speed in proportion to the pull
      await untilLanded(page);
      await untilReady(page);
      const second = await read(page);
      if (!second.bird) throw new Error('no second bird');
      const longPull = { x: -1.9, y: -0.7 };
      const a = await worldToPage(page, second.bird);
      const b = await worldToPage(page, { x: anchor.x + longPull.x, y: anchor.y + longPull.y });
      await page.evaluate(
        ({ a, b }) => {
          const canvas = document.getElementById('view') as HTMLCanvasElement;
          const touch = (type: string, p: Point) =>
            canvas.dispatchEvent(
              new PointerEvent(type, {
                pointerId: 7,
                pointerType: 'touch',
                isPrimary: true,
                clientX: p.x,
                clientY: p.y,
                bubbles: true,
                cancelable: true,
              }),
            );
          touch('pointerdown', a);
          for (let i = 1; i <= 8; i++)
            touch('pointermove', { x: a.x + ((b.x - a.x) * i) / 8, y: a.y + ((b.y - a.y) * i) / 8 });
          (window as unknown as GameWindow).gallery.instance.advance(5);
          touch('pointerup', b);
        },
        { a, b },
      );
      const thrown = await read(page);
      expect(thrown.state).toBe('flying');
      expect(thrown.shots).toBe(2);
      const p1 = thrown.bird as Point;
      const v1 = thrown.velocity as Point;
      const longLength = Math.hypot(anchor.x - p1.x, anchor.y - p1.y);
      const longSpeed = Math.hypot(v1.x, v1.y);
      expect(longLength).toBeGreaterThan(pullLength * 1.5);
      expect(longSpeed).toBeGreaterThan(speed * 1.5);
      expect(longSpeed / longLength).toBeCloseTo(speed / pullLength, 9);
      expect(errors).toEqual([]);
    } finally {
      await close();
    }
  });

  it('a shot destroys a target, a few shots clear level 1 with stars, and the next level loads', async () => {
    const { page, errors, close } = await openGame();
    try {
      // the pull, from the anchor, that flattens the hut of level 1 in two shots
      const PULL = { x: -2.15, y: -0.2 };
      await shoot(page, PULL);
      await untilLanded(page);
      await shootStage(page, resolve(SCREENSHOTS, 'slingshot-hit.png'));
      expect((await read(page)).destroyed).toBeGreaterThanOrEqual(1);
      for (let shot = 2; shot <= 3; shot++) {
        if ((await read(page)).state !== 'ready') break;
        await untilReady(page);
        await shoot(page, PULL);
        await untilLanded(page);
      }
      const end = await read(page);
      expect(end.state).toBe('won');
      expect(end.targets).toBe(0);
      expect(end.stars).toBeGreaterThanOrEqual(1);
      // the page says so: the panel, the score, the stars
      expect(await page.getAttribute('#sling-message', 'data-state')).toBe('won');
      expect(await page.isVisible('#sling-message')).toBe(true);
      expect(await page.textContent('#sling-message')).toMatch(/Level cleared/);
      const score = Number((await page.textContent('#sling-score'))?.replace(/\D+/g, ''));
      expect(score).toBe(end.score);
      expect(score).toBeGreaterThanOrEqual(10000);
      expect(Number(await page.getAttribute('#sling-stars', 'data-stars'))).toBe(end.stars);
      expect(((await page.textContent('#sling-stars')) ?? '').split('★').length - 1).toBe(end.stars);
      await shootStage(page, resolve(SCREENSHOTS, 'slingshot-won.png'));
      // on to level 2
      await page.click('#sling-next');
      expect(await page.textContent('#sling-level')).toMatch(/^Level 2/);
      await untilReady(page);
      const next = await read(page);
      expect(next.level).toBe(2);
      expect(next.state).toBe('ready');
      expect(next.score).toBe(0);
      expect(await page.isVisible('#sling-message')).toBe(false);
      await shootStage(page, resolve(SCREENSHOTS, 'slingshot-level2.png'));
      expect(errors).toEqual([]);
    } finally {
      await close();
    }
  });
});
