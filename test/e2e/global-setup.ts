/**
 * Builds the gallery with Vite into test-results/e2e/gallery (git-ignored) and serves it on
 * 127.0.0.1; the tests get its address through `inject('galleryUrl')`.
 */
import { resolve } from 'node:path';
import { build } from 'vite';
import type { TestProject } from 'vitest/node';
import { serveDirectory } from './server';

declare module 'vitest' {
  export interface ProvidedContext {
    galleryUrl: string;
  }
}

export const GALLERY_DIR = resolve(__dirname, '../../test-results/e2e/gallery');

export default async function setup(project: TestProject) {
  await build({
    configFile: resolve(__dirname, '../../vite.config.ts'),
    logLevel: 'warn',
    build: { outDir: GALLERY_DIR, emptyOutDir: true },
  });
  const server = await serveDirectory(GALLERY_DIR);
  project.provide('galleryUrl', server.url);
  return async () => {
    await server.close();
  };
}
