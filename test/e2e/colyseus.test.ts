/**
 * The gallery's Colyseus page (examples/colyseus.html) in a real browser, against a Colyseus server of
 * Fulcrum physics rooms started here (examples/colyseus/server.ts): the page draws the room's world,
 * and what it holds, with the ball it dropped, is the world a game room on this thread reaches after
 * the same steps and commands. The waits are for the server's messages; what is checked does not
 * depend on when they came.
 */
import { type AddressInfo, createServer } from 'node:net';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { startPhysicsServer } from '../../examples/colyseus/server';
import type { RoomCommand } from '../../examples/server/room';
import { replayPhysicsRoom } from '../helpers/physics-room-replay';
import { type Browser, launchChromium } from './browser';

type Server = Awaited<ReturnType<typeof startPhysicsServer>>['server'];

interface PageView {
  last: { step: number; poses: number[]; count: number } | null;
  accepted: { step: number; command: RoomCommand }[];
  refused: string[];
}

let browser: Browser;
let server: Server;
let port: number;
const url = inject('galleryUrl');

beforeAll(async () => {
  browser = await launchChromium();
  ({ server, port } = await startPhysicsServer(0, '127.0.0.1'));
});

afterAll(async () => {
  await browser?.close();
  await server?.gracefullyShutdown(false);
});

const read = (page: Page) =>
  page.evaluate((): PageView => {
    const p = (window as unknown as { colyseusPage: PageView }).colyseusPage;
    return JSON.parse(JSON.stringify({ last: p.last, accepted: p.accepted, refused: p.refused }));
  });

const waitFor = (page: Page, test: string) =>
  page.waitForFunction(test, undefined, { timeout: 30_000, polling: 50 });

describe('the Colyseus page', () => {
  it("draws the server room's world, and a click drops a ball the room applies at its next step", async () => {
    const page = await browser.context.newPage();
    const errors: string[] = [];
    page.on('pageerror', (error) => errors.push(error.message));
    page.on('console', (message) => {
      if (message.type() === 'error') errors.push(message.text());
    });
    try {
      await page.goto(`${url}colyseus.html?server=ws://127.0.0.1:${port}&seed=4`);
      await waitFor(page, 'window.colyseusPage.last && window.colyseusPage.last.step >= 20');
      const first = await read(page);
      if (!first.last) throw new Error('no state');
      expect(first.last.count).toBe(200);
      expect(first.last.poses).toEqual(replayPhysicsRoom(4, first.last.step));
      expect(await page.getAttribute('#room-status', 'data-state')).toBe('connected');
      // the canvas shows the bodies: orange bodies drawn over the background
      const painted = await page.evaluate(() => {
        const canvas = document.getElementById('room-canvas') as HTMLCanvasElement;
        const data = canvas.getContext('2d')?.getImageData(0, 0, canvas.width, canvas.height).data;
        let orange = 0;
        for (let i = 0; data && i < data.length; i += 4) if (data[i] > 200 && data[i + 2] < 120) orange++;
        return orange;
      });
      expect(painted).toBeGreaterThan(1000);

      // a click high over the middle drops a ball there
      const box = await page.locator('#room-canvas').boundingBox();
      if (!box) throw new Error('no canvas');
      await page.mouse.click(box.x + box.width / 2, box.y + box.height * 0.1);
      await waitFor(page, 'window.colyseusPage.accepted.length === 1');
      const { accepted } = await read(page);
      const spawnStep = accepted[0].step;
      await waitFor(page, `window.colyseusPage.last.step >= ${spawnStep + 40}`);
      const after = await read(page);
      if (!after.last) throw new Error('no state');
      expect(after.last.count).toBe(201);
      expect(after.last.poses).toEqual(replayPhysicsRoom(4, after.last.step, accepted));
      // the ball was dropped where the click was: the middle of the view (x = 0), and it fell
      const command = accepted[0].command;
      if (command.kind !== 'spawn') throw new Error('not a spawn');
      expect(Math.abs(command.body.position.x)).toBeLessThan(0.1);
      expect(after.last.poses[3 * 200 + 1]).toBeLessThan(command.body.position.y);
      expect(after.refused).toEqual([]);
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  });

  it('says how to start a server when there is none', async () => {
    const page = await browser.context.newPage();
    try {
      // a port nothing listens on (one that was free a moment ago)
      const probe = createServer();
      await new Promise<void>((resolve) => probe.listen(0, '127.0.0.1', resolve));
      const free = (probe.address() as AddressInfo).port;
      await new Promise((resolve) => probe.close(resolve));
      await page.goto(`${url}colyseus.html?server=ws://127.0.0.1:${free}`);
      await page.waitForFunction(
        () => document.getElementById('room-status')?.dataset.state === 'error',
        undefined,
        { timeout: 30_000 },
      );
      expect(await page.textContent('#room-status')).toMatch(/npm run demo:colyseus/);
    } finally {
      await page.close();
    }
  });
});
