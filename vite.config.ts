/**
 * The demo gallery: `npm start` serves examples/ with Vite; `npm run build:gallery` builds it. The
 * documentation site, once built (`npm run docs`, into docs/.vitepress/dist), is served beside it under
 * /docs/, by the dev server and in the built gallery; the `<script>` build beside them at
 * ./fulcrum.global.js, for the plain page examples/public/script-tag.html.
 */
import { cpSync, existsSync, readFileSync, statSync } from 'node:fs';
import { extname, join, normalize, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build as esbuild } from 'esbuild';
import { defineConfig, type Plugin } from 'vite';

const DOCS_DIST = fileURLToPath(new URL('./docs/.vitepress/dist', import.meta.url));

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.woff2': 'font/woff2',
};

/**
 * Cross-origin isolation, so that SharedArrayBuffer exists and a worker world (fulcrum/worker) shares
 * its state with the page instead of passing buffers back and forth. Everything the gallery loads is
 * its own (bundled), so require-corp blocks nothing.
 */
export const ISOLATION_HEADERS = Object.freeze({
  'Cross-Origin-Opener-Policy': 'same-origin',
  'Cross-Origin-Embedder-Policy': 'require-corp',
});

const NOT_BUILT = `<!doctype html><meta charset="utf-8"><title>Fulcrum docs</title>
<h1>The documentation is not built</h1>
<p>Run <code>npm run docs</code> and reload, or <code>npm run docs:dev</code> to work on it.</p>`;

/** Serves the built docs under /docs/ in the dev server and copies them into the built gallery. */
function docsBesideGallery(): Plugin {
  let outDir = '';
  return {
    name: 'fulcrum-docs',
    configResolved(config) {
      outDir = config.build.outDir;
    },
    configureServer(server) {
      server.middlewares.use('/docs', (request, response) => {
        const path = decodeURIComponent(new URL(request.url ?? '/', 'http://localhost').pathname);
        let file = normalize(join(DOCS_DIST, path));
        if (file !== DOCS_DIST && !file.startsWith(DOCS_DIST + sep)) {
          response.writeHead(403).end();
          return;
        }
        if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
        if (!existsSync(DOCS_DIST)) {
          response.writeHead(200, { 'content-type': TYPES['.html'], ...ISOLATION_HEADERS }).end(NOT_BUILT);
        } else if (existsSync(file)) {
          response.writeHead(200, {
            'content-type': TYPES[extname(file)] ?? 'application/octet-stream',
            ...ISOLATION_HEADERS,
          });
          response.end(readFileSync(file));
        } else {
          response.writeHead(404).end('not found');
        }
      });
    },
    closeBundle() {
      if (existsSync(DOCS_DIST)) cpSync(DOCS_DIST, join(outDir, 'docs'), { recursive: true });
    },
  };
}

/**
 * The `<script>` build at ./fulcrum.global.js, for examples/public/script-tag.html: bundled from
 * src/global.ts with the options tsup uses for dist/fulcrum.global.js (IIFE, global `Fulcrum`,
 * minified, ES2022), which gives the same bytes from the same source, without depending on dist/ being
 * built and current; the built file itself is checked by `npm run pack:check`.
 */
function scriptTagBuild(): Plugin {
  const bundle = async (): Promise<string> => {
    const result = await esbuild({
      entryPoints: [fileURLToPath(new URL('./src/global.ts', import.meta.url))],
      bundle: true,
      format: 'iife',
      globalName: 'Fulcrum',
      minify: true,
      target: 'es2022',
      write: false,
      logLevel: 'silent',
    });
    return result.outputFiles[0].text;
  };
  return {
    name: 'fulcrum-script-tag-build',
    configureServer(server) {
      // built on each request (well under a second), so an edit in src/ shows on reload
      server.middlewares.use('/fulcrum.global.js', (_request, response, next) => {
        bundle().then((code) => {
          response.setHeader('content-type', 'text/javascript; charset=utf-8');
          response.setHeader('cache-control', 'no-store');
          for (const [name, value] of Object.entries(ISOLATION_HEADERS)) response.setHeader(name, value);
          response.end(code);
        }, next);
      });
    },
    async generateBundle() {
      this.emitFile({ type: 'asset', fileName: 'fulcrum.global.js', source: await bundle() });
    },
  };
}

export default defineConfig({
  root: fileURLToPath(new URL('./examples', import.meta.url)),
  base: './',
  plugins: [docsBesideGallery(), scriptTagBuild()],
  build: {
    outDir: fileURLToPath(new URL('./gallery-dist', import.meta.url)),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1500,
    rollupOptions: {
      // the demo gallery, its page of matter.js programs run on fulcrum/matter and on matter.js, and
      // its client of the Colyseus physics rooms (examples/colyseus)
      input: {
        index: fileURLToPath(new URL('./examples/index.html', import.meta.url)),
        matter: fileURLToPath(new URL('./examples/matter.html', import.meta.url)),
        colyseus: fileURLToPath(new URL('./examples/colyseus.html', import.meta.url)),
      },
      onwarn(warning, warn) {
        // p5's dependency zod places /*@__PURE__*/ comments where Rollup cannot use them: not ours to fix
        if (warning.code === 'INVALID_ANNOTATION' && warning.id?.includes('/node_modules/')) return;
        warn(warning);
      },
    },
  },
  // fulcrum/worker's worker script, bundled by `?worker&url`: a module worker, as WorkerWorld starts it
  worker: { format: 'es' },
  server: {
    // open a browser tab where there is a desktop; on CI and headless machines just print the address
    open: !process.env.CI && (process.platform !== 'linux' || Boolean(process.env.DISPLAY)),
    headers: { ...ISOLATION_HEADERS },
  },
  preview: { headers: { ...ISOLATION_HEADERS } },
});
