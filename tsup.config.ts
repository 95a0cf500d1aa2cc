import { defineConfig } from 'tsup';

// What a user installs: minified ESM and CommonJS for `fulcrum`, `fulcrum/render` and `fulcrum/matter` (sharing their
// common code through chunks, so both entries see the same classes), declarations without the
// engine's `@internal` members, and one IIFE bundle for a `<script>` tag (global `Fulcrum`).
// No source maps: they tripled the tarball.
export default defineConfig([
  {
    entry: { index: 'src/index.ts', render: 'src/render/index.ts', matter: 'src/matter/index.ts' },
    format: ['esm', 'cjs'],
    dts: { compilerOptions: { stripInternal: true } },
    splitting: true,
    sourcemap: false,
    clean: true,
    minify: true,
    target: 'es2022',
    treeshake: true,
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
