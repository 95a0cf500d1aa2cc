/**
 * The showcase demos do what their cards say, played as a visitor plays them but wholly paused: each
 * demo is started again paused, every step is taken by hand through its step hook (`advance`, one
 * page.evaluate), and a drag is a sequence of mouse events between given steps. So the outcome is the
 * same on every run and every machine speed.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { type Browser, launchChromium } from './browser';
import { type OpenDemo, openDemo, restartPaused, worldToPage } from './gallery-page';

let browser: Browser;
const url = inject('galleryUrl');

beforeAll(async () => {
  browser = await launchChromium();
});

afterAll(async () => {
  await browser?.close();
});

interface Point {
  x: number;
  y: number;
}

interface BodyView {
  position: Point;
  isValid: boolean;
}

type ShowcaseWindow = Window & {
  gallery: {
    world: { joints: readonly unknown[] };
    instance: Record<string, unknown> & { advance(limit: number, until?: () => boolean): number };
  };
};

/** Takes `n` steps by hand. */
const advance = (page: Page, n: number) =>
  page.evaluate((steps) => (window as unknown as ShowcaseWindow).gallery.instance.advance(steps), n);

/**
 * Presses at world point `from`, moves to `to` in `moves` moves with a step after each, holds there for
 * `holdSteps` steps and lets go.
 */
async function dragBySteps(
  page: Page,
  from: Point,
  to: Point,
  moves: number,
  holdSteps: number,
): Promise<void> {
  const start = await worldToPage(page, from);
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  for (let i = 1; i <= moves; i++) {
    const p = await worldToPage(page, {
      x: from.x + ((to.x - from.x) * i) / moves,
      y: from.y + ((to.y - from.y) * i) / moves,
    });
    await page.mouse.move(p.x, p.y);
    await advance(page, 1);
  }
  await advance(page, holdSteps);
  await page.mouse.up();
}

async function openPaused(id: string): Promise<OpenDemo> {
  const open = await openDemo(browser.context, url, id);
  await restartPaused(open.page);
  return open;
}

const jointCount = (page: Page) =>
  page.evaluate(() => (window as unknown as ShowcaseWindow).gallery.world.joints.length);

describe('cloth', () => {
  // 25 x 17 circles: a link along each row and column, and two across each cell
  const COLUMNS = 25;
  const ROWS = 17;
  const LINKS = ROWS * (COLUMNS - 1) + (ROWS - 1) * COLUMNS + 2 * (ROWS - 1) * (COLUMNS - 1);

  it('hangs whole when left alone, breeze and bumping ball and all', async () => {
    const open = await openPaused('cloth');
    try {
      await advance(open.page, 1);
      expect(await jointCount(open.page)).toBe(LINKS);
      await advance(open.page, 900);
      expect(await jointCount(open.page)).toBe(LINKS);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });

  it('tears where it is pulled hard: its links are destroyed', async () => {
    const open = await openPaused('cloth');
    try {
      await advance(open.page, 60);
      // a fistful of the hem's middle, pulled down and aside by 3 m
      const hem = await open.page.evaluate(
        (i) => ((window as unknown as ShowcaseWindow).gallery.instance.nodes as BodyView[])[i].position,
        (ROWS - 1) * COLUMNS + Math.floor(COLUMNS / 2),
      );
      await dragBySteps(open.page, hem, { x: hem.x + 1, y: hem.y - 3 }, 20, 40);
      const torn = await open.page.evaluate(() =>
        ((window as unknown as ShowcaseWindow).gallery.instance.torn as () => number)(),
      );
      const links = await jointCount(open.page);
      expect(torn, 'links torn').toBeGreaterThan(5);
      expect(links).toBe(LINKS - torn);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

interface GolfState {
  hole(): number;
  strokes(): number;
  card(): number[];
  sunk(): boolean;
  ready(): boolean;
}

type GolfWindow = Window & {
  gallery: {
    instance: { ball: BodyView; state: GolfState; advance(limit: number, until?: () => boolean): number };
  };
};

describe('golf', () => {
  const read = (page: Page) =>
    page.evaluate(() => {
      const { ball, state } = (window as unknown as GolfWindow).gallery.instance;
      return {
        ball: ball.position,
        hole: state.hole(),
        strokes: state.strokes(),
        card: state.card(),
        ready: state.ready(),
      };
    });
  /** Pulls back from the ball by `pull` (metres) in ten moves and lets go. */
  const putt = async (page: Page, pull: Point) => {
    const { ball } = await read(page);
    await dragBySteps(page, ball, { x: ball.x - pull.x, y: ball.y - pull.y }, 10, 5);
  };
  /** Steps until the ball may be struck again (or the hole is sunk and the next laid). */
  const untilReady = (page: Page) =>
    page.evaluate(() => {
      const { state, advance } = (window as unknown as GolfWindow).gallery.instance;
      return advance(1200, () => state.ready());
    });

  it('putts by a drag, counts the strokes, and a 2.5 m pull sinks the first hole', async () => {
    const open = await openPaused('golf');
    try {
      await advance(open.page, 30);
      const tee = await read(open.page);
      expect(tee).toMatchObject({ hole: 0, strokes: 0, ready: true });
      // a short putt: it rolls, and stops short of the hump
      await putt(open.page, { x: 0.6, y: 0 });
      expect((await read(open.page)).strokes).toBe(1);
      expect(await untilReady(open.page)).toBeLessThan(1200);
      const first = await read(open.page);
      expect(first.ball.x - tee.ball.x, 'metres rolled').toBeGreaterThan(1.5);
      expect(first.hole).toBe(0);
      // a full putt over the hump, down into the cup
      await putt(open.page, { x: 2.5, y: 0 });
      expect((await read(open.page)).strokes).toBe(2);
      const steps = await open.page.evaluate(() => {
        const { state, advance } = (window as unknown as GolfWindow).gallery.instance;
        return advance(900, () => state.sunk());
      });
      expect(steps, 'steps until the ball is in the cup').toBeLessThan(900);
      // the next hole is laid, the card holds the first
      expect(await untilReady(open.page)).toBeLessThan(1200);
      const next = await read(open.page);
      expect(next).toMatchObject({ hole: 1, strokes: 0, card: [2] });
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('planets', () => {
  it('a rock thrown across the sun at the speed of a circle stays in orbit', async () => {
    const open = await openPaused('planets');
    try {
      await advance(open.page, 10);
      // thrown from 6.5 m above the sun, 10.5 m of drag to the left at 3 m/s per metre: 31.5 m/s,
      // where a circle asks sqrt(6000 / 6.5) = 30.4 m/s; an ellipse from 6.5 m out to 7.5 m
      await dragBySteps(open.page, { x: 0, y: 6.5 }, { x: -10.5, y: 6.5 }, 10, 0);
      const path = await open.page.evaluate(() => {
        const instance = (window as unknown as ShowcaseWindow).gallery.instance;
        const rock = (instance.lastRock as () => BodyView)();
        const thrown = (instance.thrown as () => number)();
        let near = Number.POSITIVE_INFINITY;
        let far = 0;
        let turned = 0;
        let last = Math.atan2(rock.position.y, rock.position.x);
        for (let i = 0; i < 600; i++) {
          instance.advance(1);
          if (!rock.isValid) break;
          const { x, y } = rock.position;
          const r = Math.hypot(x, y);
          near = Math.min(near, r);
          far = Math.max(far, r);
          const angle = Math.atan2(y, x);
          let d = angle - last;
          if (d > Math.PI) d -= 2 * Math.PI;
          if (d < -Math.PI) d += 2 * Math.PI;
          turned += d;
          last = angle;
        }
        return { thrown, valid: rock.isValid, near, far, turns: turned / (2 * Math.PI) };
      });
      expect(path.thrown).toBe(1);
      expect(path.valid, 'the rock is still there').toBe(true);
      expect(path.near).toBeGreaterThan(5.5);
      expect(path.far).toBeLessThan(9.5);
      // 600 steps are 10 s; a turn at 6.5 to 7.5 m takes about 1.5 s: six turns or so, anticlockwise
      expect(path.turns).toBeGreaterThan(4);
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});

describe('ragdolls', () => {
  it('every ragdoll goes down the stairs', async () => {
    const open = await openPaused('ragdolls');
    try {
      const result = await open.page.evaluate(() => {
        const instance = (window as unknown as ShowcaseWindow).gallery.instance;
        const dolls = instance.dolls as BodyView[][];
        const start = dolls.map((parts) => ({ ...parts[0].position }));
        const lowest = start.map((p) => p.y);
        const farthest = start.map((p) => p.x);
        for (let i = 0; i < 60; i++) {
          instance.advance(10);
          dolls.forEach((parts, k) => {
            lowest[k] = Math.min(lowest[k], parts[0].position.y);
            farthest[k] = Math.max(farthest[k], parts[0].position.x);
          });
        }
        return { start, lowest, farthest };
      });
      // the landing is 5 m up, ten stairs of 0.5 m down to the floor, 8 m of them to the right
      result.start.forEach((start, k) => {
        expect(start.y, `ragdoll ${k} starts on the landing`).toBeGreaterThan(5);
        expect(start.y - result.lowest[k], `ragdoll ${k}: metres down`).toBeGreaterThan(3);
        expect(result.farthest[k] - start.x, `ragdoll ${k}: metres along`).toBeGreaterThan(4);
      });
      expect(open.errors).toEqual([]);
    } finally {
      await open.close();
    }
  });
});
