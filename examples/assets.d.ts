/** Vite's raw imports: `import text from './file.svg?raw'` gives the file's text. */
declare module '*?raw' {
  const text: string;
  export default text;
}
