import { defineConfig } from 'tsup';

// What a user installs: minified ESM and CommonJS for `fulcrum`, `fulcrum/render`, `fulcrum/matter` and
// `fulcrum/worker` (sharing their common code through chunks, so both entries see the same classes),
// declarations without the engine's `@internal` members, and one IIFE bundle for a `<script>` tag
// (global `Fulcrum`). `worker-entry` is the script a WorkerWorld starts in its worker: fulcrum/worker
// finds it beside itself, `new URL('./worker-entry.js', import.meta.url)`; the CommonJS build gets
// `import.meta.url` from tsup's shim (its own file's URL), so it starts the same ES module script.
// No source maps: they tripled the tarball.
export default defineConfig([
  {
    entry: {
      index: 'src/index.ts',
      render: 'src/render/index.ts',
      matter: 'src/matter/index.ts',
      worker: 'src/worker/index.ts',
      'worker-entry': 'src/worker/worker-entry.ts',
    },
    format: ['esm', 'cjs'],
    shims: true,
    dts: { compilerOptions: { stripInternal: true } },
    splitting: true,
    sourcemap: false,
    clean: true,
    minify: true,
    target: 'es2022',
    treeshake: true,
  },
  {
    entry: { 'solver-worker': 'src/parallel/solver-worker.ts' },
    format: ['esm'],
    sourcemap: false,
    minify: true,
    target: 'es2022',
  },
  {
    entry: { fulcrum: 'src/global.ts' },
    format: ['iife'],
    globalName: 'Fulcrum',
    sourcemap: false,
    minify: true,
    target: 'es2022',
  },
]);
