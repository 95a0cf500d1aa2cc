import { checkBoolean, checkKnownKeys, fail } from '../core/errors';
import { ShapeFlag, type ShapeStore } from '../store/shape-store';

/**
 * Which shapes a world query sees. A shape passes when
 * `(shape.categoryBits & maskBits) !== 0 && (categoryBits & shape.maskBits) !== 0`.
 * Group indices play no part in queries.
 *
 * Sensors: ray casts (`castRay`, `castRayAll`) and `castShape` skip sensor shapes unless
 * `includeSensors` is true; the overlap queries (`queryAABB`, `queryPoint`, `overlapShape`) report
 * them unless `includeSensors` is false.
 */
export interface QueryFilter {
  /** the categories the query belongs to (bits), default 1 */
  categoryBits?: number;
  /** the categories the query sees (bits), default 0xffffffff */
  maskBits?: number;
  /** default false for casts, true for overlap queries */
  includeSensors?: boolean;
}

const QUERY_FILTER_KEYS = ['categoryBits', 'maskBits', 'includeSensors'] as const;

/** A validated filter in numbers; one scratch instance per query module. */
export interface ResolvedQueryFilter {
  categoryBits: number;
  maskBits: number;
  includeSensors: boolean;
}

export function makeResolvedQueryFilter(): ResolvedQueryFilter {
  return { categoryBits: 1, maskBits: 0xffffffff, includeSensors: false };
}

function checkBits(argument: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < 0 || value > 0xffffffff) {
    fail(argument, value, 'an integer in [0, 0xffffffff]');
  }
  return value;
}

/** Validates `filter` (undefined means defaults) into `out`; throws FulcrumError naming the field. */
export function resolveQueryFilter(
  filter: unknown,
  defaultIncludeSensors: boolean,
  out: ResolvedQueryFilter,
): ResolvedQueryFilter {
  if (filter === undefined) {
    out.categoryBits = 1;
    out.maskBits = 0xffffffff;
    out.includeSensors = defaultIncludeSensors;
    return out;
  }
  if (typeof filter !== 'object' || filter === null) fail('filter', filter, 'an object');
  checkKnownKeys('filter', filter, QUERY_FILTER_KEYS);
  const f = filter as QueryFilter;
  const categoryBits = f.categoryBits === undefined ? 1 : checkBits('filter.categoryBits', f.categoryBits);
  const maskBits = f.maskBits === undefined ? 0xffffffff : checkBits('filter.maskBits', f.maskBits);
  const includeSensors =
    f.includeSensors === undefined
      ? defaultIncludeSensors
      : checkBoolean('filter.includeSensors', f.includeSensors);
  out.categoryBits = categoryBits;
  out.maskBits = maskBits;
  out.includeSensors = includeSensors;
  return out;
}

/** @internal Whether shape slot `s` passes the filter. */
export function passesQueryFilter(shapes: ShapeStore, s: number, filter: ResolvedQueryFilter): boolean {
  if (!filter.includeSensors && (shapes.flags[s] & ShapeFlag.SENSOR) !== 0) return false;
  return (shapes.categoryBits[s] & filter.maskBits) !== 0 && (filter.categoryBits & shapes.maskBits[s]) !== 0;
}
