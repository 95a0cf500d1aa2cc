/**
 * The documentation site (VitePress). `npm run docs` generates the API reference from the TSDoc
 * comments (TypeDoc, into docs/api) and builds the site into docs/.vitepress/dist, for serving under
 * /docs/ beside the gallery (DOCS_BASE changes the base, e.g. for a gallery served from a sub-path).
 */
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { type DefaultTheme, defineConfig } from 'vitepress';

const sidebarFile = fileURLToPath(new URL('../api/typedoc-sidebar.json', import.meta.url));

/** The API pages' sidebar, written by TypeDoc; absent until `npx typedoc` has run. */
function apiSidebar(): DefaultTheme.SidebarItem[] {
  if (!existsSync(sidebarFile)) return [];
  return JSON.parse(readFileSync(sidebarFile, 'utf8')) as DefaultTheme.SidebarItem[];
}

const guide: DefaultTheme.SidebarItem[] = [
  {
    text: 'Introduction',
    items: [
      { text: 'Getting started', link: '/guide/getting-started' },
      { text: 'Units and scale', link: '/guide/units' },
    ],
  },
  {
    text: 'Guides',
    items: [
      { text: 'Bodies and shapes', link: '/guide/bodies-and-shapes' },
      { text: 'Compound bodies', link: '/guide/compound-bodies' },
      { text: 'SVG paths', link: '/guide/svg-paths' },
      { text: 'Joints', link: '/guide/joints' },
      { text: 'Events', link: '/guide/events' },
      { text: 'Queries', link: '/guide/queries' },
      { text: 'Sensors and filtering', link: '/guide/sensors-and-filtering' },
      { text: 'Sleeping', link: '/guide/sleeping' },
      { text: 'Continuous collision', link: '/guide/continuous-collision' },
      { text: 'Determinism and snapshots', link: '/guide/determinism' },
      { text: 'Performance tips', link: '/guide/performance' },
      { text: 'Workers', link: '/guide/workers' },
      { text: 'Rendering', link: '/guide/rendering' },
    ],
  },
  {
    text: 'Migrating',
    items: [
      { text: 'Coming from matter.js', link: '/guide/from-matter' },
      { text: 'Coming from planck / Box2D', link: '/guide/from-box2d' },
    ],
  },
  {
    text: 'Reference',
    items: [
      { text: 'The API in brief', link: '/reference/api-in-brief' },
      { text: 'API contract', link: '/reference/api-contract' },
      { text: 'Rules worth knowing', link: '/reference/rules' },
      { text: 'Accepted ranges', link: '/reference/accepted-ranges' },
      { text: 'Benchmark', link: '/reference/benchmark' },
      { text: 'Set-up, tests and fuzzing', link: '/reference/testing' },
      { text: 'API reference (TypeDoc)', link: '/api/' },
    ],
  },
];

export default defineConfig({
  title: 'Fulcrum',
  description: 'A fast, stable, deterministic 2D rigid-body physics engine for the web, in TypeScript.',
  base: process.env.DOCS_BASE ?? '/docs/',
  cleanUrls: false,
  lastUpdated: false,
  // no favicon request (a 404 in the console), as in the gallery
  head: [['link', { rel: 'icon', href: 'data:,' }]],
  themeConfig: {
    nav: [
      { text: 'Guide', link: '/guide/getting-started' },
      { text: 'API', link: '/api/' },
      { text: 'Gallery', link: '../', target: '_self' },
    ],
    sidebar: {
      '/guide/': guide,
      '/reference/': guide,
      '/api/': [{ text: 'Back to the guide', link: '/guide/getting-started' }, ...apiSidebar()],
    },
    search: { provider: 'local' },
    outline: [2, 3],
  },
  // the local search index of the API pages makes one large chunk; it is loaded only when searching
  vite: { build: { chunkSizeWarningLimit: 1500 } },
});
