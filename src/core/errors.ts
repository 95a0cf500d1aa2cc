/** The one error type of the public API. Its message names the argument and the value. */
export class FulcrumError extends Error {
  override readonly name = 'FulcrumError';
}

function show(value: unknown): string {
  if (typeof value === 'number') return Object.is(value, -0) ? '-0' : String(value);
  if (typeof value === 'string') return JSON.stringify(value);
  if (value === null || value === undefined) return String(value);
  if (typeof value === 'object') {
    const v = value as { x?: unknown; y?: unknown };
    if ('x' in v || 'y' in v) return `{ x: ${show(v.x)}, y: ${show(v.y)} }`;
    try {
      return JSON.stringify(value);
    } catch {
      return Object.prototype.toString.call(value);
    }
  }
  return String(value);
}

export function fail(argument: string, value: unknown, expected: string): never {
  throw new FulcrumError(`${argument} must be ${expected}, got ${show(value)}`);
}

export function checkNonNegative(argument: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < 0) {
    fail(argument, value, 'a finite number >= 0');
  }
  return value;
}

export function checkBoolean(argument: string, value: unknown): boolean {
  if (typeof value !== 'boolean') fail(argument, value, 'a boolean');
  return value;
}

export function checkInteger(argument: string, value: unknown, min: number, max: number): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < min || value > max) {
    fail(argument, value, `an integer in [${min}, ${max}]`);
  }
  return value;
}

/** Rejects keys that a definition object does not know, so typos do not pass silently. */
export function checkKnownKeys(argument: string, def: object, known: readonly string[]): void {
  for (const key of Object.keys(def)) {
    if (!known.includes(key)) {
      throw new FulcrumError(`${argument} has an unknown option ${JSON.stringify(key)}`);
    }
  }
}
