/** The demo gallery: `npm start` serves examples/ with Vite; `npm run build:gallery` builds it. */
import { fileURLToPath } from 'node:url';
import { build as esbuild } from 'esbuild';
import { defineConfig, type Plugin } from 'vite';

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
  plugins: [scriptTagBuild()],
  build: {
    outDir: fileURLToPath(new URL('./gallery-dist', import.meta.url)),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1500,
    rollupOptions: {
      onwarn(warning, warn) {
        // p5's dependency zod places /*@__PURE__*/ comments where Rollup cannot use them: not ours to fix
        if (warning.code === 'INVALID_ANNOTATION' && warning.id?.includes('/node_modules/')) return;
        warn(warning);
      },
    },
  },
  server: {
    // open a browser tab where there is a desktop; on CI and headless machines just print the address
    open: !process.env.CI && (process.platform !== 'linux' || Boolean(process.env.DISPLAY)),
  },
});
