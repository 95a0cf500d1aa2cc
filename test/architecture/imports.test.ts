import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import ts from 'typescript';
import { describe, expect, it } from 'vitest';

/*
 * The import graph of src/, read with the TypeScript parser, held to the map in src/README.md:
 * - each folder imports only the folders below it (LAYERS);
 * - no cycle of imports that run (value imports) anywhere;
 * - no cycle at all, type-only imports included, except among the public handles (api/, joints/,
 *   query/, and worker/'s own), whose types name one another by nature: a body's shapes and a shape's
 *   body, a body's joints and a joint's bodies, events and query hits that carry handles.
 */

const SRC = resolve(__dirname, '../../src');

/** Each folder of src/ and the folders it may import besides its own. */
const LAYERS: Record<string, readonly string[]> = {
  core: [],
  math: ['core'],
  geometry: ['core', 'math'],
  'broad-phase': ['core', 'math', 'geometry'],
  'narrow-phase': ['core', 'math', 'geometry'],
  store: ['core', 'math', 'geometry', 'broad-phase'],
  solver: ['core', 'math', 'geometry', 'broad-phase', 'store'],
  world: ['core', 'math', 'geometry', 'broad-phase', 'narrow-phase', 'store', 'solver'],
  // the threads of a multi-core step: the contact passes and the columns they share
  parallel: ['core', 'math', 'geometry', 'broad-phase', 'store', 'solver'],
  api: [
    'core',
    'math',
    'geometry',
    'broad-phase',
    'narrow-phase',
    'store',
    'solver',
    'world',
    'parallel',
    'joints',
    'query',
  ],
  joints: [
    'core',
    'math',
    'geometry',
    'broad-phase',
    'narrow-phase',
    'store',
    'solver',
    'world',
    'api',
    'query',
  ],
  query: [
    'core',
    'math',
    'geometry',
    'broad-phase',
    'narrow-phase',
    'store',
    'solver',
    'world',
    'api',
    'joints',
  ],
  // draws and runs a World or a WorkerWorld (worker/ names no render/ module)
  render: [
    'core',
    'math',
    'geometry',
    'broad-phase',
    'narrow-phase',
    'store',
    'solver',
    'world',
    'api',
    'joints',
    'query',
    'worker',
  ],
  // the matter.js layer: over the public API (index.ts) and the browser layer
  matter: [
    'core',
    'math',
    'geometry',
    'broad-phase',
    'narrow-phase',
    'store',
    'solver',
    'world',
    'api',
    'joints',
    'query',
    'render',
  ],
  // fulcrum/worker: a world in a worker, over the public API and the checks World makes
  worker: [
    'core',
    'math',
    'geometry',
    'broad-phase',
    'narrow-phase',
    'store',
    'solver',
    'world',
    'api',
    'joints',
    'query',
  ],
};
// the worker layer's handles name their world and each other as the engine's do
const PUBLIC_LAYER = new Set(['api', 'joints', 'query', 'worker']);

interface Edge {
  from: string;
  to: string;
  typeOnly: boolean;
}

function sourceFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? sourceFiles(join(dir, e.name)) : e.name.endsWith('.ts') ? [join(dir, e.name)] : [],
  );
}

function resolveImport(from: string, specifier: string): string | null {
  if (!specifier.startsWith('.')) return null;
  const base = resolve(dirname(from), specifier);
  for (const candidate of [`${base}.ts`, join(base, 'index.ts')]) {
    try {
      readFileSync(candidate);
      return candidate;
    } catch {}
  }
  throw new Error(`${relative(SRC, from)}: cannot resolve '${specifier}'`);
}

/** The relative imports and re-exports of a source text, each marked type-only or not. */
function importsOf(fileName: string, text: string): { specifier: string; typeOnly: boolean }[] {
  const source = ts.createSourceFile(fileName, text, ts.ScriptTarget.Latest, false);
  const out: { specifier: string; typeOnly: boolean }[] = [];
  for (const statement of source.statements) {
    if (ts.isImportDeclaration(statement) && ts.isStringLiteral(statement.moduleSpecifier)) {
      const clause = statement.importClause;
      let typeOnly = clause?.isTypeOnly === true;
      if (
        clause &&
        !typeOnly &&
        !clause.name &&
        clause.namedBindings &&
        ts.isNamedImports(clause.namedBindings)
      ) {
        const elements = clause.namedBindings.elements;
        typeOnly = elements.length > 0 && elements.every((e) => e.isTypeOnly);
      }
      out.push({ specifier: statement.moduleSpecifier.text, typeOnly });
    } else if (
      ts.isExportDeclaration(statement) &&
      statement.moduleSpecifier &&
      ts.isStringLiteral(statement.moduleSpecifier)
    ) {
      const clause = statement.exportClause;
      let typeOnly = statement.isTypeOnly;
      if (!typeOnly && clause && ts.isNamedExports(clause)) {
        typeOnly = clause.elements.length > 0 && clause.elements.every((e) => e.isTypeOnly);
      }
      out.push({ specifier: statement.moduleSpecifier.text, typeOnly });
    }
  }
  return out;
}

function graph(): { files: string[]; edges: Edge[] } {
  const files = sourceFiles(SRC).map((f) => relative(SRC, f));
  const edges: Edge[] = [];
  for (const file of files) {
    const path = join(SRC, file);
    for (const { specifier, typeOnly } of importsOf(path, readFileSync(path, 'utf8'))) {
      const target = resolveImport(path, specifier);
      if (target) edges.push({ from: file, to: relative(SRC, target), typeOnly });
    }
  }
  return { files, edges };
}

/** Strongly connected components with more than one file (Tarjan). */
function cycles(files: readonly string[], edges: readonly Edge[]): string[][] {
  const next = new Map<string, string[]>(files.map((f) => [f, []]));
  for (const e of edges) next.get(e.from)?.push(e.to);
  const index = new Map<string, number>();
  const low = new Map<string, number>();
  const stack: string[] = [];
  const onStack = new Set<string>();
  const found: string[][] = [];
  let counter = 0;
  const visit = (v: string): void => {
    index.set(v, counter);
    low.set(v, counter++);
    stack.push(v);
    onStack.add(v);
    for (const w of next.get(v) ?? []) {
      if (!index.has(w)) {
        visit(w);
        low.set(v, Math.min(low.get(v)!, low.get(w)!));
      } else if (onStack.has(w)) low.set(v, Math.min(low.get(v)!, index.get(w)!));
    }
    if (low.get(v) === index.get(v)) {
      const component: string[] = [];
      let w: string;
      do {
        w = stack.pop()!;
        onStack.delete(w);
        component.push(w);
      } while (w !== v);
      if (component.length > 1) found.push(component.sort());
    }
  };
  for (const f of files) if (!index.has(f)) visit(f);
  return found;
}

const folderOf = (file: string): string => (file.includes('/') ? file.slice(0, file.indexOf('/')) : '');

describe('the import graph of src/', () => {
  const { files, edges } = graph();

  it('has every folder in the layer map, and each imports only the folders below it', () => {
    const unknown = [...new Set(files.map(folderOf).filter((f) => f !== '' && !(f in LAYERS)))];
    expect(unknown).toEqual([]);
    const crossing = edges
      .filter((e) => {
        const from = folderOf(e.from);
        const to = folderOf(e.to);
        return from !== '' && from !== to && !LAYERS[from].includes(to);
      })
      .map((e) => `${e.from} -> ${e.to}`);
    expect(crossing).toEqual([]);
  });

  it('has no cycle of value imports', () => {
    expect(
      cycles(
        files,
        edges.filter((e) => !e.typeOnly),
      ),
    ).toEqual([]);
  });

  it('has no cycle through type imports outside the public handles', () => {
    const outside = cycles(files, edges).filter((c) => c.some((f) => !PUBLIC_LAYER.has(folderOf(f))));
    expect(outside).toEqual([]);
  });

  it('reads type-only imports and finds cycles (the checks above can fail)', () => {
    const read = importsOf(
      'x.ts',
      "import type { A } from './a';\nimport { type B, C } from './b';\nimport { type D } from './d';\nexport type { E } from './e';\nexport * from './f';",
    );
    expect(read).toEqual([
      { specifier: './a', typeOnly: true },
      { specifier: './b', typeOnly: false },
      { specifier: './d', typeOnly: true },
      { specifier: './e', typeOnly: true },
      { specifier: './f', typeOnly: false },
    ]);
    const planted = cycles(
      ['a', 'b', 'c'],
      [
        { from: 'a', to: 'b', typeOnly: false },
        { from: 'b', to: 'a', typeOnly: true },
        { from: 'b', to: 'c', typeOnly: false },
      ],
    );
    expect(planted).toEqual([['a', 'b']]);
  });

  it('is mapped in src/README.md: a row for each folder, and every file it names exists', () => {
    const map = readFileSync(join(SRC, 'README.md'), 'utf8');
    const rows = [...map.matchAll(/^\| `([a-z-]+)\/` *\|/gm)].map((m) => m[1]);
    expect(rows.sort()).toEqual(Object.keys(LAYERS).sort());
    const named = new Set([...map.matchAll(/`([a-z-]+(?:\/[a-z-]+)?\.ts)`/g)].map((m) => m[1]));
    const missing = [...named].filter((name) => !files.some((f) => f === name || f.endsWith(`/${name}`)));
    expect(missing).toEqual([]);
  });
});
