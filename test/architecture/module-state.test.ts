import { readdirSync, readFileSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import ts from 'typescript';
import { describe, expect, it } from 'vitest';

/**
 * Issue 24: no module of src/ holds mutable state. Every world keeps its working memory in its own
 * objects (WorldCore.work and the objects it owns), and the geometry functions take theirs as an
 * argument, so two worlds, or a world and a query made outside it, never share a scratch value, and
 * what one of them did can never change what another computes.
 *
 * The scan reads each file's syntax (the TypeScript parser, no type checking) and reports every
 * top-level binding that can hold state:
 * - `let` and `var`, whatever their value;
 * - a `const` whose value is a fresh object: an object or array literal, a `new` expression, a call
 *   (it may return a mutable object), a regular expression with the g or y flag (its lastIndex);
 * - a class's static field that is not readonly, or whose value is such an object.
 * A literal is immutable when made so: `as const` (deep), `Object.freeze(...)` or a declared readonly
 * type (`readonly T[]`, `Readonly<T>`, `ReadonlyArray`, `ReadonlyMap`, `ReadonlySet`; one level
 * deep): its elements and property values are then checked in turn. Functions, enums, numbers,
 * strings and reads of other bindings are not state.
 */

interface Finding {
  /** file:name, as the allowlists write them */
  readonly key: string;
  readonly line: number;
  readonly reason: string;
}

const READONLY_TYPES = new Set(['Readonly', 'ReadonlyArray', 'ReadonlyMap', 'ReadonlySet']);

/** Whether a declared type makes the value it annotates read only (one level deep). */
function isReadonlyType(type: ts.TypeNode | undefined): boolean {
  if (type === undefined) return false;
  if (ts.isTypeOperatorNode(type)) return type.operator === ts.SyntaxKind.ReadonlyKeyword;
  if (ts.isTypeReferenceNode(type)) return READONLY_TYPES.has(type.typeName.getText());
  return false;
}

function isObjectFreeze(call: ts.CallExpression): boolean {
  const callee = call.expression;
  return (
    ts.isPropertyAccessExpression(callee) &&
    callee.expression.getText() === 'Object' &&
    callee.name.text === 'freeze'
  );
}

/**
 * Why `expr` can hold state, or undefined when it cannot. `readonly`: the value itself was made read
 * only (by a declared type or Object.freeze); `deep`: by `as const`, which covers its contents too.
 */
function mutableValue(expr: ts.Expression, readonly: boolean, deep: boolean): string | undefined {
  if (ts.isParenthesizedExpression(expr) || ts.isNonNullExpression(expr) || ts.isSatisfiesExpression(expr)) {
    return mutableValue(expr.expression, readonly, deep);
  }
  if (ts.isAsExpression(expr) || ts.isTypeAssertionExpression(expr)) {
    const isConst = ts.isTypeReferenceNode(expr.type) && expr.type.typeName.getText() === 'const';
    return mutableValue(expr.expression, readonly || isConst || isReadonlyType(expr.type), deep || isConst);
  }
  if (ts.isObjectLiteralExpression(expr)) {
    if (!readonly) return 'an object literal';
    for (const property of expr.properties) {
      if (ts.isPropertyAssignment(property)) {
        const why = mutableValue(property.initializer, deep, deep);
        if (why !== undefined) return `${why} in a property`;
      } else if (ts.isSpreadAssignment(property) || ts.isShorthandPropertyAssignment(property)) {
        // a spread copies the properties of another binding, a shorthand reads one: neither makes state
      } else if (ts.isGetAccessorDeclaration(property) || ts.isSetAccessorDeclaration(property)) {
        return 'an accessor (it may keep state elsewhere)';
      }
      // methods are functions: not state
    }
    return undefined;
  }
  if (ts.isArrayLiteralExpression(expr)) {
    if (!readonly) return 'an array literal';
    for (const element of expr.elements) {
      const why = mutableValue(ts.isSpreadElement(element) ? element.expression : element, deep, deep);
      if (why !== undefined) return `${why} in an element`;
    }
    return undefined;
  }
  if (ts.isNewExpression(expr)) {
    const name = expr.expression.getText();
    // a Map or Set declared ReadonlyMap/ReadonlySet and filled by its constructor only
    if (readonly && (name === 'Map' || name === 'Set')) {
      for (const arg of expr.arguments ?? []) {
        const why = mutableValue(arg, true, true);
        if (why !== undefined) return `${why} in a ${name}'s entries`;
      }
      return undefined;
    }
    return `a new ${name}`;
  }
  if (ts.isCallExpression(expr)) {
    if (isObjectFreeze(expr) && expr.arguments.length === 1)
      return mutableValue(expr.arguments[0], true, deep);
    // a symbol is a primitive
    if (expr.expression.getText() === 'Symbol') return undefined;
    return 'a call (it may return a mutable object)';
  }
  if (ts.isTaggedTemplateExpression(expr)) return 'a tagged template (a call)';
  if (ts.isRegularExpressionLiteral(expr)) {
    const flags = expr.text.slice(expr.text.lastIndexOf('/') + 1);
    return /[gy]/.test(flags) ? 'a global or sticky regular expression (its lastIndex)' : undefined;
  }
  if (ts.isConditionalExpression(expr)) {
    return mutableValue(expr.whenTrue, readonly, deep) ?? mutableValue(expr.whenFalse, readonly, deep);
  }
  if (ts.isBinaryExpression(expr)) {
    const op = expr.operatorToken.kind;
    // a ?? b and a || b may yield either side
    if (op === ts.SyntaxKind.QuestionQuestionToken || op === ts.SyntaxKind.BarBarToken) {
      return mutableValue(expr.left, readonly, deep) ?? mutableValue(expr.right, readonly, deep);
    }
    if (op === ts.SyntaxKind.EqualsToken) return 'an assignment';
    return undefined;
  }
  // literals, identifiers, property reads, arithmetic, functions and classes: no state of their own
  return undefined;
}

function hasModifier(node: ts.Node, kind: ts.SyntaxKind): boolean {
  return ts.canHaveModifiers(node) && (ts.getModifiers(node) ?? []).some((m) => m.kind === kind);
}

/** Names bound by a declaration (destructuring included). */
function boundNames(name: ts.BindingName): string[] {
  if (ts.isIdentifier(name)) return [name.text];
  const names: string[] = [];
  for (const element of name.elements) {
    if (ts.isBindingElement(element)) names.push(...boundNames(element.name));
  }
  return names;
}

/** Every top-level binding of `source` that can hold state (see the comment at the top). */
function findModuleState(file: string, source: string): Finding[] {
  const sf = ts.createSourceFile(file, source, ts.ScriptTarget.ES2022, true, ts.ScriptKind.TS);
  const findings: Finding[] = [];
  const report = (node: ts.Node, name: string, reason: string): void => {
    const line = sf.getLineAndCharacterOfPosition(node.getStart(sf)).line + 1;
    findings.push({ key: `${file}:${name}`, line, reason });
  };
  const visitStatements = (statements: readonly ts.Statement[]): void => {
    for (const statement of statements) {
      if (ts.isVariableStatement(statement)) {
        const flags = statement.declarationList.flags;
        const isConst = (flags & ts.NodeFlags.Const) !== 0;
        for (const decl of statement.declarationList.declarations) {
          for (const name of boundNames(decl.name)) {
            if (!isConst) {
              report(decl, name, (flags & ts.NodeFlags.Let) !== 0 ? 'a let' : 'a var');
              continue;
            }
            if (decl.initializer === undefined) continue;
            const why = mutableValue(decl.initializer, isReadonlyType(decl.type), false);
            if (why !== undefined) report(decl, name, why);
          }
        }
      } else if (ts.isClassDeclaration(statement)) {
        const className = statement.name?.text ?? 'default';
        for (const member of statement.members) {
          if (ts.isClassStaticBlockDeclaration(member)) {
            report(member, `${className}.static`, 'a static block (it may set state)');
            continue;
          }
          if (!ts.isPropertyDeclaration(member) || !hasModifier(member, ts.SyntaxKind.StaticKeyword))
            continue;
          const name = `${className}.${member.name.getText(sf)}`;
          if (!hasModifier(member, ts.SyntaxKind.ReadonlyKeyword)) {
            report(member, name, 'a static field that is not readonly');
          } else if (member.initializer !== undefined) {
            const why = mutableValue(member.initializer, isReadonlyType(member.type), false);
            if (why !== undefined) report(member, name, `a static field holding ${why}`);
          }
        }
      } else if (ts.isModuleDeclaration(statement) && statement.body && ts.isModuleBlock(statement.body)) {
        visitStatements(statement.body.statements);
      } else if (ts.isExportAssignment(statement)) {
        const why = mutableValue(statement.expression, false, false);
        if (why !== undefined) report(statement, 'default', why);
      }
    }
  };
  visitStatements(sf.statements);
  return findings;
}

/**
 * Module state that stays, and why (file:name). Keep this short: state belongs to the object that owns
 * it (a world's WorkingMemory, a tree, a renderer) or is passed in by the caller.
 */
/**
 * The matter.js layer's modules are by contract plain, mutable module objects: programs and plugins
 * (matter-wrap, matter-attractors) replace their functions by path, and matter's ids count across
 * worlds. They sit above the engine, which they reach through its public API only.
 */
const MATTER_MODULE = 'a matter.js module object, mutable by contract (plugins patch it by path)';

const ALLOWED = new Map<string, string>([
  ['src/matter/bodies.ts:Bodies', MATTER_MODULE],
  ['src/matter/body.ts:Body', MATTER_MODULE],
  ['src/matter/bounds.ts:Bounds', MATTER_MODULE],
  ['src/matter/common.ts:Common', MATTER_MODULE],
  ['src/matter/composite.ts:Composite', MATTER_MODULE],
  ['src/matter/composite.ts:World', MATTER_MODULE],
  ['src/matter/composites.ts:Composites', MATTER_MODULE],
  ['src/matter/constraint.ts:Constraint', MATTER_MODULE],
  ['src/matter/detector.ts:Detector', MATTER_MODULE],
  ['src/matter/detector.ts:Pairs', MATTER_MODULE],
  ['src/matter/engine.ts:Engine', MATTER_MODULE],
  ['src/matter/events.ts:Events', MATTER_MODULE],
  ['src/matter/index.ts:Matter', MATTER_MODULE],
  ['src/matter/mouse.ts:Mouse', MATTER_MODULE],
  ['src/matter/mouse-constraint.ts:MouseConstraint', MATTER_MODULE],
  ['src/matter/plugin.ts:Plugin', MATTER_MODULE],
  ['src/matter/query.ts:Query', MATTER_MODULE],
  ['src/matter/render.ts:Render', MATTER_MODULE],
  ['src/matter/runner.ts:Runner', MATTER_MODULE],
  ['src/matter/sleeping.ts:Sleeping', MATTER_MODULE],
  ['src/matter/svg.ts:Svg', MATTER_MODULE],
  ['src/matter/vector.ts:Vector', MATTER_MODULE],
  ['src/matter/vertices.ts:Vertices', MATTER_MODULE],
  ['src/api/snapshot.ts:CLASS_KEYS', 'the inverse of the frozen CLASSES table, built once and never written'],
  [
    'src/api/snapshot.ts:fingerprint',
    "a memo of the build's layout hash: a pure function of the code, the same for every world",
  ],
]);

const root = resolve(__dirname, '../..');

function sourceFiles(dir: string): string[] {
  const files: string[] = [];
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) files.push(...sourceFiles(path));
    else if (entry.name.endsWith('.ts') && !entry.name.endsWith('.d.ts')) files.push(path);
  }
  return files.sort();
}

function scanSource(): Finding[] {
  const findings: Finding[] = [];
  for (const path of sourceFiles(join(root, 'src'))) {
    const file = relative(root, path).split('\\').join('/');
    findings.push(...findModuleState(file, readFileSync(path, 'utf8')));
  }
  return findings;
}

describe('the module-state scanner', () => {
  const keys = (source: string): string[] => findModuleState('x.ts', source).map((f) => f.key.slice(5));

  it('finds every kind of top-level binding that can hold state', () => {
    const planted = `
      let count = 0;
      var legacy;
      export let exported = 1;
      const scratch = new Float64Array(4);
      export const point = { x: 0, y: 0 };
      const list: number[] = [];
      const made = makeThing();
      const cache = new Map<number, string>();
      const typedCache: Map<number, string> = new Map();
      const { a, b } = makePair();
      const wrapped = (someFlag ? { x: 0 } : null);
      const shallow = Object.freeze({ inner: { x: 0 } });
      const rows: readonly Row[] = [new Row()];
      const pattern = /a+/g;
      const lazy = (() => { let n = 0; return () => n++; })();
      class Pool { static count = 0; static readonly items: Item[] = []; static { init(); } }
      namespace Inner { export let hidden = 0; }
    `;
    expect(keys(planted).sort()).toEqual(
      [
        'count',
        'legacy',
        'exported',
        'scratch',
        'point',
        'list',
        'made',
        'cache',
        'typedCache',
        'a',
        'b',
        'wrapped',
        'shallow',
        'rows',
        'pattern',
        'lazy',
        'Pool.count',
        'Pool.items',
        'Pool.static',
        'hidden',
      ].sort(),
    );
  });

  it('passes constants, frozen or readonly literals, enums, functions and locals', () => {
    const clean = `
      const LIMIT = 5;
      export const NAME = 'fulcrum';
      const HALF = LIMIT / 2;
      const KEYS = ['a', 'b'] as const;
      const TABLE = { x: { y: 1 } } as const;
      const FROZEN = Object.freeze({ a: 1, f() { return 2; } });
      const PAIRS: readonly Fn[] = [f, g];
      const RECORD: Readonly<Record<string, number>> = { a: 1 };
      const NAMES: ReadonlyMap<string, number> = new Map([['a', 1]]);
      const DEEP = Object.freeze([Object.freeze({ x: 0 })]);
      const word = /a+/i;
      const TOKEN = Symbol('token');
      const f = (x: number) => x + 1;
      enum Kind { A, B }
      class Thing { static readonly ZERO = 0; count = 0; items: number[] = []; }
      function g() { let local = 0; const scratch = new Float64Array(4); return local + scratch[0]; }
    `;
    expect(keys(clean)).toEqual([]);
  });
});

describe('src/ holds no module state', () => {
  const findings = scanSource();

  it('has no top-level mutable binding outside the allowlists', () => {
    const unexpected = findings
      .filter((f) => !ALLOWED.has(f.key))
      .map((f) => `${f.key} (line ${f.line}): ${f.reason}`);
    expect(unexpected).toEqual([]);
  });

  it('lists in its allowlists only bindings that still exist', () => {
    const found = new Set(findings.map((f) => f.key));
    const stale = [...ALLOWED.keys()].filter((key) => !found.has(key));
    expect(stale).toEqual([]);
  });
});
