/** The demo gallery: `npm start` serves examples/ with Vite; `npm run build:gallery` builds it. */
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

export default defineConfig({
  root: fileURLToPath(new URL('./examples', import.meta.url)),
  base: './',
  build: {
    outDir: fileURLToPath(new URL('./gallery-dist', import.meta.url)),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1500,
  },
  server: {
    // open a browser tab where there is a desktop; on CI and headless machines just print the address
    open: !process.env.CI && (process.platform !== 'linux' || Boolean(process.env.DISPLAY)),
  },
});
