/** The browser benchmark's pure parts: its options, file names, engine table and page server. */
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { browserEngines } from '../../../bench/browser/engines';
import { fileFor, type PageServer, servePage } from '../../../bench/browser/server';
import { engines } from '../../../bench/engines';
import { parseOptions, resultsName } from '../../../bench/options';

describe('bench --browser options', () => {
  it('runs in Node unless --browser is given; --browser alone means Chromium', () => {
    expect(parseOptions([]).browser).toBeNull();
    expect(parseOptions(['--browser']).browser).toBe('chromium');
    expect(parseOptions(['--browser', '--quick']).browser).toBe('chromium');
    expect(parseOptions(['--browser', '--quick']).quick).toBe(true);
    expect(parseOptions(['--browser', 'firefox']).browser).toBe('firefox');
    expect(parseOptions(['--quick', '--browser', 'chromium', '--rounds', '2'])).toMatchObject({
      browser: 'chromium',
      quick: true,
      rounds: 2,
    });
  });

  it('rejects an unknown browser, naming it, and --profile with --browser', () => {
    expect(() => parseOptions(['--browser', 'safari'])).toThrow("unknown browser 'safari'");
    expect(() => parseOptions(['--browser', '--profile', 'chain'])).toThrow('--profile');
  });

  it("names the results files so that a browser's never overwrite Node's", () => {
    expect(resultsName({ quick: false, browser: null })).toBe('results');
    expect(resultsName({ quick: true, browser: null })).toBe('results-quick');
    expect(resultsName({ quick: false, browser: 'chromium' })).toBe('browser-chromium');
    expect(resultsName({ quick: true, browser: 'firefox' })).toBe('browser-firefox-quick');
  });

  it('the page knows every engine Node runs, and no other', () => {
    expect(Object.keys(browserEngines).sort()).toEqual(engines.map((e) => e.id).sort());
  });
});

describe('bench page server', () => {
  const bundle = '/tmp/bundle';
  const modules = '/repo/node_modules';

  it('maps the bundle and box2d3-wasm, and nothing else', () => {
    expect(fileFor('/bench/page/page.js', bundle, modules)).toBe('/tmp/bundle/page.js');
    expect(fileFor('/node_modules/box2d3-wasm/build/dist/es/compat/Box2D.compat.wasm', bundle, modules)).toBe(
      '/repo/node_modules/box2d3-wasm/build/dist/es/compat/Box2D.compat.wasm',
    );
    expect(fileFor('/node_modules/planck/package.json', bundle, modules)).toBeNull();
    expect(fileFor('/package.json', bundle, modules)).toBeNull();
    expect(fileFor('/bench/page/../../etc/passwd', bundle, modules)).toBeNull();
    expect(fileFor('/node_modules/box2d3-wasm/../planck/package.json', bundle, modules)).toBeNull();
    expect(fileFor('/bench/page/', bundle, modules)).toBeNull();
  });

  describe('over HTTP', () => {
    let dir: string;
    let server: PageServer;
    beforeAll(async () => {
      dir = mkdtempSync(join(tmpdir(), 'fulcrum-page-test-'));
      mkdirSync(join(dir, 'bundle'));
      writeFileSync(join(dir, 'bundle', 'page.js'), 'export {};\n');
      server = await servePage(join(dir, 'bundle'), join(dir, 'node_modules'));
    });
    afterAll(async () => {
      await server.close();
      rmSync(dir, { recursive: true, force: true });
    });

    it('serves the page and its script cross-origin isolated, and 404 for anything else', async () => {
      for (const path of ['', 'bench/page/page.js']) {
        const response = await fetch(`${server.url}${path}`);
        expect(response.status).toBe(200);
        expect(response.headers.get('cross-origin-opener-policy')).toBe('same-origin');
        expect(response.headers.get('cross-origin-embedder-policy')).toBe('require-corp');
      }
      expect((await fetch(`${server.url}bench/page/page.js`)).headers.get('content-type')).toMatch(
        /^text\/javascript/,
      );
      expect((await fetch(`${server.url}`)).headers.get('content-type')).toMatch(/^text\/html/);
      expect((await fetch(`${server.url}bench/page/missing.js`)).status).toBe(404);
      expect((await fetch(`${server.url}package.json`)).status).toBe(404);
    });
  });
});
