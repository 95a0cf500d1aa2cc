/**
 * The documentation site in Chromium: built fresh (`npm run docs`) into the built gallery's docs/
 * folder, as `npm run build:gallery` places it, and served with the gallery. Every page must render
 * (a heading, no console or page error) and every link to this server must resolve; the gallery links
 * to the docs. The browser-only examples of the guides (docs/examples: canvas, PixiJS) run here too.
 */
import { execFileSync } from 'node:child_process';
import { mkdirSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import { build } from 'esbuild';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, inject, it } from 'vitest';
import { type Browser, launchChromium } from './browser';
import { GALLERY_DIR } from './global-setup';

const ROOT = resolve(__dirname, '../..');
const DOCS_DIR = join(GALLERY_DIR, 'docs');
const EXAMPLES_DIR = join(GALLERY_DIR, 'docs-examples');
const galleryUrl = inject('galleryUrl');
const docsUrl = new URL('docs/', galleryUrl).href;

let browser: Browser;

beforeAll(async () => {
  rmSync(DOCS_DIR, { recursive: true, force: true });
  execFileSync('npm', ['run', 'docs', '--', '--outDir', DOCS_DIR, '--base', '/docs/'], {
    cwd: ROOT,
    stdio: 'pipe',
  });
  browser = await launchChromium();
}, 240_000);

afterAll(async () => {
  await browser?.close();
});

/** Opens a page and records console errors and uncaught exceptions. */
async function open(url: string): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.context.newPage();
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`page: ${error.message}`));
  const response = await page.goto(url, { waitUntil: 'load' });
  expect(response?.status(), url).toBe(200);
  return { page, errors };
}

function htmlPages(dir: string): string[] {
  return readdirSync(dir, { recursive: true, encoding: 'utf8' })
    .filter((f) => f.endsWith('.html'))
    .map((f) => relative(dir, join(dir, f)).split('\\').join('/'))
    .sort();
}

describe('the documentation site', () => {
  it('is linked from the gallery', async () => {
    const { page, errors } = await open(galleryUrl);
    try {
      await page.click('#docs-link');
      await page.waitForURL(docsUrl);
      await expect(page.locator('h1').first().textContent()).resolves.toContain('Fulcrum');
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  });

  it('renders every page with a heading and no error, and every link on it resolves', async () => {
    const pages = htmlPages(DOCS_DIR).filter((f) => f !== '404.html');
    expect(pages.length).toBeGreaterThan(100); // the guides, the reference pages and the API reference
    const checked = new Map<string, number>();
    const broken: string[] = [];
    // one tab for all the pages: a new tab per page costs more than the page
    const { page, errors } = await open(docsUrl);
    try {
      for (const file of pages) {
        errors.length = 0;
        const response = await page.goto(new URL(file, docsUrl).href, { waitUntil: 'load' });
        expect(response?.status(), file).toBe(200);
        const heading = (await page.locator('h1').first().textContent())?.trim();
        expect(heading, file).toBeTruthy();
        expect(errors, file).toEqual([]);
        const links = await page.$$eval('a[href], link[href], img[src], script[src]', (nodes) =>
          nodes.map((n) => (n as HTMLAnchorElement).href || (n as HTMLImageElement).src),
        );
        for (const link of links) {
          const target = new URL(link);
          if (target.origin !== new URL(galleryUrl).origin) continue;
          target.hash = '';
          const key = target.href;
          if (!checked.has(key)) checked.set(key, (await browser.context.request.get(key)).status());
          if (checked.get(key) !== 200) broken.push(`${file} -> ${key} (${checked.get(key)})`);
        }
      }
    } finally {
      await page.close();
    }
    expect(broken).toEqual([]);
    expect(checked.size).toBeGreaterThan(pages.length);
  }, 600_000);
});

/** Bundles a docs example for the browser, the package name mapped to the sources. */
async function bundleExample(name: string): Promise<void> {
  await build({
    entryPoints: [join(ROOT, 'docs/examples', `${name}.ts`)],
    outfile: join(EXAMPLES_DIR, `${name}.js`),
    bundle: true,
    format: 'esm',
    target: 'es2022',
    logLevel: 'warning',
    alias: { fulcrum: join(ROOT, 'src/index.ts'), 'fulcrum/render': join(ROOT, 'src/render/index.ts') },
  });
  // the example's page, as in the guide, loading the bundle and exposing its exports to the test
  writeFileSync(
    join(EXAMPLES_DIR, `${name}.html`),
    `<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"><style>html,body{margin:0;height:100%}` +
      `#app{width:800px;height:500px}</style></head><body><div id="app"></div><script type="module">` +
      `import * as example from './${name}.js'; window.example = example;</script></body></html>`,
  );
}

type ExampleWindow = Window & { example: Record<string, unknown> };

describe('the guides’ browser examples', () => {
  beforeAll(async () => {
    mkdirSync(EXAMPLES_DIR, { recursive: true });
    await bundleExample('canvas-render');
    await bundleExample('pixi-render');
  });

  it('canvas (fulcrum/render): the runner steps the pyramid and the canvas is drawn', async () => {
    const { page, errors } = await open(new URL('docs-examples/canvas-render.html', galleryUrl).href);
    try {
      await page.waitForFunction(
        () =>
          ((window as unknown as ExampleWindow).example?.runner as { stepCount: number })?.stepCount >= 30,
      );
      const drawn = await page.evaluate(() => {
        const canvas = document.querySelector('canvas')!;
        const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
        // pixels that are not the background #15171d
        let ink = 0;
        for (let i = 0; i < data.length; i += 4) {
          if (Math.abs(data[i] - 0x15) + Math.abs(data[i + 1] - 0x17) + Math.abs(data[i + 2] - 0x1d) > 30)
            ink++;
        }
        return { ink, width: canvas.width, height: canvas.height };
      });
      expect(drawn.width).toBe(800);
      expect(drawn.height).toBe(500);
      expect(drawn.ink).toBeGreaterThan(800 * 500 * 0.02); // 36 boxes and the ground
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  });

  it('PixiJS: one Graphics per body, following the bodies as the world steps', async () => {
    const { page, errors } = await open(new URL('docs-examples/pixi-render.html', galleryUrl).href);
    try {
      await page.waitForFunction(() => ((window as unknown as ExampleWindow).example?.steps as number) >= 30);
      const state = await page.evaluate(() => {
        const { app, world } = (window as unknown as ExampleWindow).example as {
          app: { stage: { children: { position: { x: number; y: number } }[] } };
          world: { bodies: Iterable<{ position: { x: number; y: number } }> };
        };
        const bodies = [...world.bodies];
        const children = app.stage.children;
        return {
          bodies: bodies.length,
          children: children.length,
          // each Graphics at its body's position in pixels (40 px/m, origin 400, 450)
          offsets: bodies.map((b, i) =>
            Math.hypot(
              children[i].position.x - (400 + b.position.x * 40),
              children[i].position.y - (450 - b.position.y * 40),
            ),
          ),
        };
      });
      expect(state.bodies).toBe(21);
      expect(state.children).toBe(21);
      for (const offset of state.offsets) expect(offset).toBeLessThan(1e-6);
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  });
});
