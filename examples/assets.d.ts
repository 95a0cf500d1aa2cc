/** Vite's raw imports: `import text from './file.svg?raw'` gives the file's text. */
declare module '*?raw' {
  const text: string;
  export default text;
}

/** Vite's worker URLs: `import url from './entry.ts?worker&url'` bundles the script and gives its URL. */
declare module '*?worker&url' {
  const url: string;
  export default url;
}

/** Vite's glob imports: `import.meta.glob('./dir/*.ts', { query: '?raw', import: 'default' })` gives a loader per file. */
interface ImportMeta {
  glob<T = unknown>(
    pattern: string | string[],
    options?: { query?: string; import?: string; eager?: false },
  ): Record<string, () => Promise<T>>;
}
