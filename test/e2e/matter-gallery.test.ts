/**
 * The gallery's page of matter.js programs (examples/matter.html) in a real browser: each program on
 * fulcrum/matter and on matter.js 0.20 side by side, driven through window.matterGallery by
 * simulation steps taken by hand (never by the clock), against the gallery built by Vite and served
 * on 127.0.0.1 (see global-setup.ts).
 */
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { programs } from '../../examples/matter/programs/index';
import { type Browser, launchChromium } from './browser';
import { decodePng, differingShare, type Image, inkStats } from './png';

const SCREENSHOTS = resolve(__dirname, '../../test-results/e2e/screenshots');
const PANES = ['fulcrum', 'matter'] as const;
type PaneName = (typeof PANES)[number];

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

interface Open {
  page: Page;
  /** console errors and page errors seen since the page opened */
  errors: string[];
  close(): Promise<void>;
}

/** The page's hook, as far as these tests read it. */
interface HookPane {
  Matter: {
    Composite: { allBodies(world: unknown): { isStatic: boolean; position: Point; angle: number }[] };
  };
  engine: { world: unknown };
  render: { canvas: HTMLCanvasElement };
}
type HookWindow = Window & {
  matterGallery: {
    program: string;
    panes: Record<PaneName, HookPane | null>;
    pause(): void;
    reset(): void;
    step(n: number): void;
  };
};

/**
 * Opens `id` on the matter.js page, with the matter.js pane when `compare`, then pauses it and starts
 * it again (in one task of the page, so no frame comes between): the program is then at its first
 * update on both panes, and moves only by steps taken by hand.
 */
async function openProgram(id: string, compare: boolean): Promise<Open> {
  const page = await browser.context.newPage();
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`page: ${error.message}`));
  await page.goto(`${url}matter.html${compare ? '?compare=1' : ''}#${id}`);
  await page.waitForFunction(
    ([program, both]) => {
      const g = (window as unknown as Partial<HookWindow>).matterGallery;
      return g?.program === program && g.panes.fulcrum !== null && (g.panes.matter !== null) === both;
    },
    [id, compare] as const,
    { timeout: 20_000 },
  );
  await page.evaluate(() => {
    const g = (window as unknown as HookWindow).matterGallery;
    g.pause();
    g.reset();
  });
  return { page, errors, close: () => page.close() };
}

/** Steps every pane `n` updates of 1000/60 ms and draws it. */
async function step(page: Page, n: number): Promise<void> {
  await page.evaluate((count) => (window as unknown as HookWindow).matterGallery.step(count), n);
}

/** The positions of the moving bodies of a pane, in the world's order. */
async function bodies(page: Page, pane: PaneName): Promise<Point[]> {
  return page.evaluate((name) => {
    const p = (window as unknown as HookWindow).matterGallery.panes[name];
    if (!p) throw new Error(`no ${name} pane`);
    return p.Matter.Composite.allBodies(p.engine.world)
      .filter((body) => !body.isStatic)
      .map((body) => ({ x: body.position.x, y: body.position.y }));
  }, pane);
}

async function shootPane(page: Page, pane: PaneName, path?: string): Promise<Image> {
  const png = await page.locator(`#pane-${pane} canvas`).screenshot({ path, animations: 'allow' });
  return decodePng(png);
}

/** Page (CSS pixel) coordinates of a world point (px) of a pane: its canvas is the world scaled by CSS. */
async function worldToPage(page: Page, pane: PaneName, p: Point): Promise<Point> {
  return page.evaluate(
    ([name, point]) => {
      const canvas = (window as unknown as HookWindow).matterGallery.panes[name]?.render.canvas;
      if (!canvas) throw new Error(`no ${name} pane`);
      const rect = canvas.getBoundingClientRect();
      return {
        x: rect.left + (point.x * rect.width) / canvas.width,
        y: rect.top + (point.y * rect.height) / canvas.height,
      };
    },
    [pane, p] as const,
  );
}

describe('every matter.js program, on fulcrum/matter and on matter.js', () => {
  for (const program of programs) {
    it(`${program.id}: opens without errors, moves, stays finite and draws, on both`, async () => {
      const open = await openProgram(program.id, true);
      try {
        const firsts = new Map<PaneName, Image>();
        const before = new Map<PaneName, Point[]>();
        for (const pane of PANES) {
          before.set(pane, await bodies(open.page, pane));
          firsts.set(pane, await shootPane(open.page, pane));
        }
        await step(open.page, 120);
        for (const pane of PANES) {
          const start = before.get(pane) ?? [];
          const end = await bodies(open.page, pane);
          expect(end.length, `${pane}: moving bodies`).toBe(start.length);
          expect(start.length, `${pane}: moving bodies`).toBeGreaterThan(0);
          const notFinite = end.filter((p) => !Number.isFinite(p.x) || !Number.isFinite(p.y));
          expect(notFinite, `${pane}: bodies whose position is not a finite number`).toEqual([]);
          // every program starts something moving (a fall, a swing, a settling under gravity)
          const moved = Math.max(...end.map((p, i) => Math.hypot(p.x - start[i].x, p.y - start[i].y)));
          expect(moved, `${pane}: the largest move in 120 updates (px)`).toBeGreaterThan(1);

          const picture = await shootPane(
            open.page,
            pane,
            resolve(SCREENSHOTS, `matter-${program.id}-${pane}.png`),
          );
          const { ink, colors } = inkStats(picture);
          expect(ink, `${pane}: share of the canvas that is not background`).toBeGreaterThan(0.01);
          expect(colors, `${pane}: colours drawn`).toBeGreaterThan(3);
          const first = firsts.get(pane) as Image;
          const changed = differingShare(first, picture) * first.width * first.height;
          expect(changed, `${pane}: pixels that changed in 120 updates`).toBeGreaterThan(50);
        }
        expect(open.errors).toEqual([]);
      } finally {
        await open.close();
      }
    });
  }
});

describe('the matter.js page', () => {
  it('drags a box of the stack on fulcrum/matter toward the pointer (MouseConstraint)', async () => {
    const open = await openProgram('stack', false);
    try {
      await step(open.page, 60); // the wall lands and settles
      /** the top right box: nothing above it, nothing to its right */
      const topRight = () =>
        open.page.evaluate(() => {
          const p = (window as unknown as HookWindow).matterGallery.panes.fulcrum as HookPane;
          const boxes = p.Matter.Composite.allBodies(p.engine.world).filter((body) => !body.isStatic);
          const top = Math.min(...boxes.map((b) => b.position.y));
          const row = boxes.filter((b) => b.position.y < top + 5);
          const box = row.reduce((a, b) => (b.position.x > a.position.x ? b : a));
          return boxes.indexOf(box);
        });
      const index = await topRight();
      const start = (await bodies(open.page, 'fulcrum'))[index];
      // up and to the right by 78 px of the world, out of the wall's reach
      const target = { x: start.x + 60, y: start.y - 50 };
      const from = await worldToPage(open.page, 'fulcrum', start);
      const to = await worldToPage(open.page, 'fulcrum', target);
      await open.page.mouse.move(from.x, from.y);
      await open.page.mouse.down();
      await step(open.page, 2); // the mouse constraint takes hold in the engine's next update
      for (let i = 1; i <= 10; i++) {
        await open.page.mouse.move(from.x + ((to.x - from.x) * i) / 10, from.y + ((to.y - from.y) * i) / 10);
        await step(open.page, 3);
      }
      await step(open.page, 40);
      const held = (await bodies(open.page, 'fulcrum'))[index];
      await open.page.mouse.up();
      const distance = Math.hypot(target.x - start.x, target.y - start.y);
      const left = Math.hypot(target.x - held.x, target.y - held.y);
      // a soft pull (stiffness 0.2) holding a 50 by 40 box against gravity: it hangs a little below
      // the point it was grabbed by, a small part of the way it was pulled
      expect(left, 'px left between the box and the pointer').toBeLessThan(0.15 * distance);
      expect(held.y, 'lifted').toBeLessThan(start.y - 30);
      expect(held.x, 'pulled right').toBeGreaterThan(start.x + 40);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('lets go of the last program when another is opened: one canvas a pane, the old worlds emptied', async () => {
    const open = await openProgram('stack', true);
    try {
      await open.page.evaluate(() => {
        const g = (window as unknown as HookWindow).matterGallery;
        Object.assign(window, { previous: [g.panes.fulcrum, g.panes.matter] });
      });
      await open.page.click('a[data-program="pyramid"]');
      await open.page.waitForFunction(
        () => (window as unknown as HookWindow).matterGallery.program === 'pyramid',
      );
      expect(open.page.url()).toMatch(/matter\.html\?compare=1#pyramid$/);
      for (const pane of PANES) expect(await open.page.locator(`#pane-${pane} canvas`).count()).toBe(1);
      const left = await open.page.evaluate(() =>
        (window as unknown as { previous: (HookPane & { engine: { events: object } })[] }).previous.map(
          (p) => ({
            bodies: p.Matter.Composite.allBodies(p.engine.world).length,
            listeners: Object.keys(p.engine.events ?? {}).length,
            attached: p.render.canvas.isConnected,
          }),
        ),
      );
      expect(left).toEqual([
        { bodies: 0, listeners: 0, attached: false },
        { bodies: 0, listeners: 0, attached: false },
      ]);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('keeps the pyramid standing on fulcrum/matter: its top box stays on the axis after 600 updates', async () => {
    const open = await openProgram('pyramid', false);
    try {
      const start = await bodies(open.page, 'fulcrum');
      // the layout: fifteen 40 px boxes from x = 100, so the axis is the bottom row's middle, x = 400,
      // and eight rows standing on the ground as placed (nothing falls)
      const bottom = start.filter((p) => p.y === Math.max(...start.map((q) => q.y)));
      expect(bottom.length).toBe(15);
      const axis = bottom.reduce((sum, p) => sum + p.x, 0) / bottom.length;
      const topIndex = start.findIndex((p) => p.y === Math.min(...start.map((q) => q.y)));
      await step(open.page, 600);
      const top = (await bodies(open.page, 'fulcrum'))[topIndex];
      // Measured on matter.js 0.20 (the same program in the other pane): the top box stays on the axis
      // (0.00 px, the solver is symmetric here) but the pyramid sinks into itself and bounces (the top
      // box 9.1 px down at update 12, 1.5 px at update 24) before settling 6.05 px below where it
      // started. Fulcrum settles without bouncing (0.86 px off the axis, 2.07 px down, measured).
      // Asserted, from the layout and the engine: the top box within 2 px of the axis, and sunk no
      // more than eight contacts (seven boxes and the ground below it) of Fulcrum's linear slop, 0.5 px
      // at matter's 100 px to the metre.
      expect(Math.abs(top.x - axis), 'px off the axis').toBeLessThan(2);
      expect(top.y - start[topIndex].y, 'px sunk').toBeGreaterThanOrEqual(0);
      expect(top.y - start[topIndex].y, 'px sunk').toBeLessThanOrEqual(8 * 0.5);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});
