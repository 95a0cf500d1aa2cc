import type { Plain } from './protocol';

/*
 * What crosses between the calling thread and the worker is plain, structured-cloneable data: the
 * calling thread copies what it checked (toPlain), the receiving side freezes geometry again
 * (deepFreeze) so that it passes the engine's checks as the `Shape.*` original did.
 */

/** A checked definition or argument as plain data: own keys, nested objects copied, userData left out. */
export function toPlain(value: unknown): Plain {
  if (typeof value !== 'object' || value === null) return value;
  if (Array.isArray(value)) return value.map(toPlain);
  const out: Record<string, unknown> = {};
  for (const key of Object.keys(value)) {
    if (key !== 'userData') out[key] = toPlain((value as Record<string, unknown>)[key]);
  }
  return out;
}

/** Freezes a structured clone of `Shape.*` geometry as deep as Shape froze the original. */
export function deepFreeze<T>(value: T): T {
  if (typeof value === 'object' && value !== null && !Object.isFrozen(value)) {
    for (const key of Object.keys(value)) deepFreeze((value as Record<string, unknown>)[key]);
    Object.freeze(value);
  }
  return value;
}
