/**
 * The part of matter.js's `Common` that programs call: ids, object helpers, a seeded random number
 * generator, logging. A plain, mutable module object.
 */
type Obj = Record<string, unknown>;

function isPlainObject(value: unknown): value is Obj {
  return typeof value === 'object' && value !== null && Object.getPrototypeOf(value) === Object.prototype;
}

export const Common = {
  /** The step a velocity is measured over, in milliseconds: matter's velocities are px per 1000/60 ms. */
  _baseDelta: 1000 / 60,
  _seed: 0,
  _decomp: null as unknown,
  _nextId: 0,
  /** the messages warnOnce has shown */
  _warned: new Set<string>(),
  logLevel: 1,

  /** A new id, unique in this page or process. */
  nextId(): number {
    Common._nextId += 1;
    return Common._nextId;
  },

  /**
   * Copies the properties of the later objects into `target`, plain objects deeply when `deep` (the
   * optional first argument) is true. Returns the target.
   */
  extend(target: unknown, ...rest: unknown[]): Obj {
    let deep = false;
    let out = target as Obj;
    let sources = rest;
    if (typeof target === 'boolean') {
      deep = target;
      out = rest[0] as Obj;
      sources = rest.slice(1);
    }
    for (const source of sources) {
      if (!source) continue;
      for (const key of Object.keys(source as Obj)) {
        const value = (source as Obj)[key];
        if (deep && isPlainObject(value)) {
          if (!isPlainObject(out[key])) out[key] = {};
          Common.extend(true, out[key], value);
        } else {
          out[key] = value;
        }
      }
    }
    return out;
  },

  /** A copy of `object`, deep when `deep` is true. */
  clone<T>(object: T, deep?: boolean): T {
    return Common.extend(deep === true, {}, object) as T;
  },

  keys(object: Obj): string[] {
    return Object.keys(object);
  },

  values(object: Obj): unknown[] {
    return Object.keys(object).map((key) => object[key]);
  },

  /** The value at a dotted `path` in `object` (between path parts `begin` and `end` if given). */
  get(object: Obj, path: string, begin?: number, end?: number): unknown {
    const parts = path.split('.').slice(begin, end);
    let value: unknown = object;
    for (const part of parts) value = (value as Obj)[part];
    return value;
  },

  /** Sets the value at a dotted `path` in `object`; returns the value. */
  set(object: Obj, path: string, value: unknown, begin?: number, end?: number): unknown {
    const parts = path.split('.').slice(begin, end);
    const last = parts.pop() as string;
    (Common.get(object, parts.join('.')) as Obj)[last] = value;
    return value;
  },

  /** Shuffles `array` in place with the seeded generator. */
  shuffle<T>(array: T[]): T[] {
    for (let i = array.length - 1; i > 0; i--) {
      const j = Math.floor(Common.random() * (i + 1));
      const t = array[i];
      array[i] = array[j];
      array[j] = t;
    }
    return array;
  },

  choose<T>(choices: readonly T[]): T {
    return choices[Math.floor(Common.random() * choices.length)];
  },

  isElement(value: unknown): boolean {
    return typeof HTMLElement !== 'undefined' && value instanceof HTMLElement;
  },

  isArray(value: unknown): value is unknown[] {
    return Array.isArray(value);
  },

  isFunction(value: unknown): value is (...args: unknown[]) => unknown {
    return typeof value === 'function';
  },

  isPlainObject,

  isString(value: unknown): value is string {
    return typeof value === 'string';
  },

  clamp(value: number, min: number, max: number): number {
    return Math.min(Math.max(value, min), max);
  },

  sign(value: number): number {
    return value < 0 ? -1 : 1;
  },

  /** Milliseconds, from a high-resolution clock where there is one. */
  now(): number {
    return typeof performance !== 'undefined' ? performance.now() : Date.now();
  },

  /**
   * A number in [min, max) (default [0, 1)) from a seeded generator: `Common._seed` sets the
   * sequence, so a program that seeds it gets the same numbers on every run.
   */
  random(min?: number, max?: number): number {
    const lo = min ?? 0;
    const hi = max ?? 1;
    // matter's own linear congruential generator (modulus 233280), so that a program seeded the same
    // builds the same scene on both
    Common._seed = (Common._seed * 9301 + 49297) % 233280;
    return lo + (Common._seed / 233280) * (hi - lo);
  },

  /** A CSS hex colour ('#f80' or '#ff8800') as a number. */
  colorToNumber(color: string): number {
    let hex = color.replace('#', '');
    if (hex.length === 3) hex = hex.replace(/(.)/g, '$1$1');
    return Number.parseInt(hex, 16);
  },

  log(...args: unknown[]): void {
    if (Common.logLevel > 0) console.log('matter-js:', ...args);
  },

  info(...args: unknown[]): void {
    if (Common.logLevel > 0) console.info('matter-js:', ...args);
  },

  warn(...args: unknown[]): void {
    if (Common.logLevel > 0) console.warn('matter-js:', ...args);
  },

  /** Warns once for each distinct message. */
  warnOnce(...args: unknown[]): void {
    const message = args.join(' ');
    if (Common._warned.has(message)) return;
    Common._warned.add(message);
    Common.warn(message);
  },

  /** Says once that `object[name]` is deprecated when it is first called. */
  deprecated(object: Obj, name: string, warning: string): void {
    const original = object[name] as (...args: unknown[]) => unknown;
    object[name] = function deprecated(this: unknown, ...args: unknown[]) {
      Common.warnOnce('🔅 deprecated 🔅', warning);
      return original.apply(this, args);
    };
  },

  indexOf<T>(haystack: readonly T[], needle: T): number {
    return haystack.indexOf(needle);
  },

  map<T, U>(list: readonly T[], fn: (item: T) => U): U[] {
    return list.map((item) => fn(item));
  },

  /**
   * Nodes of the directed graph `graph` (node to the nodes it points to) in an order where a node
   * comes after those it points to.
   */
  topologicalSort(graph: Record<string, string[]>): string[] {
    const out: string[] = [];
    const visited = new Set<string>();
    const visit = (node: string) => {
      if (visited.has(node)) return;
      visited.add(node);
      for (const neighbour of graph[node] ?? []) visit(neighbour);
      out.push(node);
    };
    for (const node of Object.keys(graph)) visit(node);
    return out;
  },

  /**
   * A function that calls `funcs` in order with its arguments, each with the last defined result so
   * far as `this` (as matter chains them: a hook after Engine.update gets the engine as `this`), and
   * returns that last result.
   */
  chain(...funcs: ((...args: unknown[]) => unknown)[]): (...args: unknown[]) => unknown {
    const chained = (...args: unknown[]) => {
      let last: unknown;
      for (const fn of funcs) {
        const value = fn.apply(last, args);
        if (value !== undefined) last = value;
      }
      return last;
    };
    (chained as unknown as { _chained: unknown[] })._chained = funcs;
    return chained;
  },

  /** Makes the function at `path` in `base` call `func` before it. */
  chainPathBefore(base: Obj, path: string, func: (...args: unknown[]) => unknown) {
    return Common.set(
      base,
      path,
      Common.chain(func, Common.get(base, path) as (...args: unknown[]) => unknown),
    );
  },

  /** Makes the function at `path` in `base` call `func` after it. */
  chainPathAfter(base: Obj, path: string, func: (...args: unknown[]) => unknown) {
    return Common.set(
      base,
      path,
      Common.chain(Common.get(base, path) as (...args: unknown[]) => unknown, func),
    );
  },

  /** Accepted for matter.js programs that pass poly-decomp: Fulcrum splits concave outlines itself. */
  setDecomp(decomp: unknown): void {
    Common._decomp = decomp;
  },

  getDecomp(): unknown {
    return Common._decomp;
  },
};
