import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

export default defineConfig({
  // the docs' examples (docs/examples, run by test/docs) import the package by name, as a user would
  resolve: {
    alias: [
      { find: /^fulcrum$/, replacement: fileURLToPath(new URL('./src/index.ts', import.meta.url)) },
      {
        find: /^fulcrum\/render$/,
        replacement: fileURLToPath(new URL('./src/render/index.ts', import.meta.url)),
      },
      {
        find: /^fulcrum\/worker$/,
        replacement: fileURLToPath(new URL('./src/worker/index.ts', import.meta.url)),
      },
    ],
  },
  test: {
    include: ['test/**/*.test.ts'],
    exclude: ['test/e2e/**', 'node_modules/**'],
    testTimeout: 60_000,
    pool: 'forks',
    // The engine and the scenes load as plain ES modules through Node (tsx compiles the TypeScript), not
    // through Vite's module transform: that transform routes every cross-module call through a getter,
    // which made the physics tests run about 3x slower than the same code in Node.
    poolOptions: { forks: { execArgv: ['--import', 'tsx'] } },
    server: { deps: { external: [/[\\/](src|scenes)[\\/]/] } },
    // Files share a worker's modules: saves a process start per file, and lets a test fail if the engine
    // kept state from one world (or one query) that changed the result of another.
    isolate: false,
    // Vitest leaves a core free by default, which on a 2-core machine means one worker: use both.
    maxWorkers: 2,
    minWorkers: 1,
  },
});
