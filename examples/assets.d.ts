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
