import { checkKnownKeys, FulcrumError, fail } from '../core/errors';
import { checkAngle, Limits } from '../core/limits';
import { type Geometry, isGeometry } from '../geometry/types';
import { makeRotInto } from '../math/rot';
import type { Rot, Transform, Vec2 } from '../math/vec2';

/**
 * Where a query shape is placed: either `{ position, angle? }` (like `createBody`; angle in radians,
 * default 0) or the engine's `{ p, q }` form with q a unit (cos, sin) pair (normalised here).
 */
export type QueryTransform = { position: Vec2; angle?: number } | Transform;

const POSE_KEYS = ['position', 'angle'] as const;
const XF_KEYS = ['p', 'q'] as const;

function isFiniteNumber(value: unknown): value is number {
  return typeof value === 'number' && Number.isFinite(value);
}

/**
 * Validates a point or translation (components within Limits.COORDINATE) without copying it: returns
 * it typed, so callers read x and y once.
 */
export function checkPoint(argument: string, value: unknown): Vec2 {
  if (typeof value !== 'object' || value === null) fail(argument, value, 'a vector { x, y }');
  const v = value as { x: unknown; y: unknown };
  const bound = Limits.COORDINATE;
  if (
    typeof v.x !== 'number' ||
    typeof v.y !== 'number' ||
    !(Math.abs(v.x) <= bound && Math.abs(v.y) <= bound)
  )
    fail(argument, value, `a vector { x, y } of numbers in [-${bound}, ${bound}]`);
  return value as Vec2;
}

export function checkGeometry(argument: string, value: unknown): Geometry {
  if (!isGeometry(value))
    fail(argument, value, 'a geometry made by Shape.circle/box/polygon/capsule/segment');
  return value;
}

/** Validates a QueryTransform and writes it into `out`. */
export function resolveTransform(argument: string, value: unknown, out: Transform): Transform {
  if (typeof value !== 'object' || value === null) {
    fail(argument, value, 'an object { position, angle? } or { p, q }');
  }
  if ('position' in value) {
    checkKnownKeys(argument, value, POSE_KEYS);
    const t = value as { position: unknown; angle?: unknown };
    const p = checkPoint(`${argument}.position`, t.position);
    if (t.angle !== undefined) checkAngle(`${argument}.angle`, t.angle);
    const x = p.x;
    const y = p.y;
    makeRotInto(t.angle === undefined ? 0 : (t.angle as number), out.q);
    out.p.x = x;
    out.p.y = y;
    return out;
  }
  if ('p' in value) {
    checkKnownKeys(argument, value, XF_KEYS);
    const t = value as { p: unknown; q: unknown };
    const p = checkPoint(`${argument}.p`, t.p);
    const q = t.q as Partial<Rot> | null;
    if (typeof q !== 'object' || q === null || !isFiniteNumber(q.c) || !isFiniteNumber(q.s)) {
      fail(`${argument}.q`, q, 'a rotation { c, s } of finite numbers');
    }
    const c = q.c as number;
    const s = q.s as number;
    const length = Math.sqrt(c * c + s * s);
    if (!(Math.abs(length - 1) <= 1e-6)) {
      throw new FulcrumError(
        `${argument}.q must be a unit rotation { c: cos, s: sin }, got { c: ${c}, s: ${s} }`,
      );
    }
    out.p.x = p.x;
    out.p.y = p.y;
    out.q.c = c / length;
    out.q.s = s / length;
    return out;
  }
  return fail(argument, value, 'an object { position, angle? } or { p, q }');
}
