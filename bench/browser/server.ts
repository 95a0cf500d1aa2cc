/**
 * The benchmark page's HTTP server on an ephemeral port of 127.0.0.1. Every response carries
 * Cross-Origin-Opener-Policy and Cross-Origin-Embedder-Policy, so the page is cross-origin isolated:
 * box2d3-wasm's SIMD build is built with threads and needs SharedArrayBuffer, and the browser clamps
 * performance.now() least in an isolated page (Chromium 5 us against 100 us).
 *
 * It serves the page at /, the page bundle under /bench/page/, and box2d3-wasm's files under
 * /node_modules/box2d3-wasm/: the box2d3 adapter finds its build at ../../node_modules/box2d3-wasm/
 * from its own module's URL, which from /bench/page/ is that path, as it is from bench/adapters/ in
 * Node. Nothing else is served.
 */
import { readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import { extname, join, normalize, sep } from 'node:path';

export const PAGE_HTML =
  '<!doctype html><meta charset="utf-8"><title>Fulcrum benchmark</title>' +
  '<script type="module" src="/bench/page/page.js"></script>\n';

export const ISOLATION_HEADERS = {
  'cross-origin-opener-policy': 'same-origin',
  'cross-origin-embedder-policy': 'require-corp',
  'cross-origin-resource-policy': 'same-origin',
} as const;

const TYPES: Record<string, string> = {
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.wasm': 'application/wasm',
};

/** the file under `dir` that `rest` names, or null if it would climb out of it */
function inside(dir: string, rest: string): string | null {
  const base = normalize(dir);
  const file = normalize(join(base, rest));
  return file.startsWith(base + sep) ? file : null;
}

/** the file a request's path names: the bundle's or box2d3-wasm's; null for anything else */
export function fileFor(path: string, bundleDir: string, nodeModules: string): string | null {
  const page = '/bench/page/';
  const box2d = '/node_modules/box2d3-wasm/';
  if (path.startsWith(page)) return inside(bundleDir, path.slice(page.length));
  if (path.startsWith(box2d)) return inside(join(nodeModules, 'box2d3-wasm'), path.slice(box2d.length));
  return null;
}

export interface PageServer {
  url: string;
  close(): Promise<void>;
}

export async function servePage(bundleDir: string, nodeModules: string): Promise<PageServer> {
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://127.0.0.1').pathname);
    const headers = { ...ISOLATION_HEADERS, 'cache-control': 'no-store' };
    if (path === '/') {
      response.writeHead(200, { ...headers, 'content-type': 'text/html; charset=utf-8' }).end(PAGE_HTML);
      return;
    }
    const file = fileFor(path, bundleDir, nodeModules);
    if (!file) {
      response.writeHead(404, headers).end('not found');
      return;
    }
    readFile(file).then(
      (body) => {
        const type = TYPES[extname(file)] ?? 'application/octet-stream';
        response.writeHead(200, { ...headers, 'content-type': type }).end(body);
      },
      () => response.writeHead(404, headers).end('not found'),
    );
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return {
    url: `http://127.0.0.1:${port}/`,
    close: () =>
      new Promise<void>((resolve) => {
        server.closeAllConnections();
        server.close(() => resolve());
      }),
  };
}
