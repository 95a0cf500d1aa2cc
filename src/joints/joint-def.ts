import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkBoolean, FulcrumError, fail } from '../core/errors';
import { checkCoordinates, checkRange } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { relativeAngle } from '../solver/joint-math';
import type { Joint } from './joint';

/*
 * What the definitions of the joint types share, and the checks their builders share: each joint
 * type's file holds its definition, defaults and validation (its JointKind), and registry.ts lists
 * the types.
 */

/** The two bodies of a joint and its common options. */
export interface BaseDef {
  bodyA: Body;
  bodyB: Body;
  collideConnected?: boolean;
  userData?: unknown;
}

/** Where a joint holds its bodies. */
export interface AnchorDef {
  /** world point; or give localAnchorA and localAnchorB */
  anchor?: Vec2;
  localAnchorA?: Vec2;
  localAnchorB?: Vec2;
}

/** A joint's optional spring. */
export interface SpringDef {
  enableSpring?: boolean;
  hertz?: number;
  dampingRatio?: number;
}

/** @internal The keys of BaseDef (and `type`), of AnchorDef and of SpringDef. */
export const BASE_KEYS: readonly string[] = Object.freeze([
  'type',
  'bodyA',
  'bodyB',
  'collideConnected',
  'userData',
]);
/** @internal */
export const ANCHOR_KEYS: readonly string[] = Object.freeze(['anchor', 'localAnchorA', 'localAnchorB']);
/** @internal */
export const SPRING_KEYS: readonly string[] = Object.freeze(['enableSpring', 'hertz', 'dampingRatio']);

/**
 * @internal A joint type as registry.ts lists it: its class, the keys its definition may have, and
 * its builder, which validates a definition completely (with its defaults) and makes the joint; it
 * throws before anything is made, so a bad definition leaves the world as it was.
 */
export interface JointKind<D, J extends Joint> {
  /** the class's name in snapshots: never renamed (it is in the bytes), whatever a minifier does */
  readonly className: string;
  readonly jointClass: abstract new (...args: never[]) => J;
  readonly keys: readonly string[];
  build(world: World, def: D): J;
}

/** @internal `value` checked as a boolean, or `fallback` when it is not given. */
export function optionalBoolean(name: string, value: unknown, fallback: boolean): boolean {
  return value === undefined ? fallback : checkBoolean(name, value);
}

/** @internal `check` applied to `value`, or `fallback` when it is not given (core/limits.ts has the ranges). */
export function optionalNumber(
  check: (name: string, value: unknown) => number,
  name: string,
  value: unknown,
  fallback: number,
): number {
  return value === undefined ? fallback : check(name, value);
}

/** @internal A joint's two bodies, checked (of this world, not the same), and its collideConnected. */
export function jointBodies(world: World, def: BaseDef): { a: Body; b: Body; collide: boolean } {
  world.checkBody('bodyA', def.bodyA);
  world.checkBody('bodyB', def.bodyB);
  const a = def.bodyA;
  const b = def.bodyB;
  if (a === b) fail('bodyB', 'the same body as bodyA', 'a different body from bodyA');
  return { a, b, collide: optionalBoolean('collideConnected', def.collideConnected, false) };
}

/** @internal Anchors in both bodies' frames from a world `anchor` or from local anchors (default: origins). */
export function anchorsOf(def: AnchorDef, a: Body, b: Body): { la: Vec2; lb: Vec2 } {
  if (def.anchor !== undefined) {
    if (def.localAnchorA !== undefined || def.localAnchorB !== undefined) {
      throw new FulcrumError('anchor: give either anchor or localAnchorA/localAnchorB, not both');
    }
    const p = checkCoordinates('anchor', def.anchor);
    return { la: a.getLocalPoint(p), lb: b.getLocalPoint(p) };
  }
  return {
    la: def.localAnchorA === undefined ? { x: 0, y: 0 } : checkCoordinates('localAnchorA', def.localAnchorA),
    lb: def.localAnchorB === undefined ? { x: 0, y: 0 } : checkCoordinates('localAnchorB', def.localAnchorB),
  };
}

/** @internal The angle of B relative to A now (a reference angle's default). */
export function currentAngle(a: Body, b: Body): number {
  const qa = a.rotation;
  const qb = b.rotation;
  return relativeAngle(qa.c, qa.s, qb.c, qb.s);
}

/** @internal Throws unless `lower` <= `upper`. */
export function checkOrder(lowerName: string, lower: number, upperName: string, upper: number): void {
  if (lower > upper) throw new FulcrumError(`${lowerName} must be <= ${upperName}, got ${lower} > ${upper}`);
}

/** @internal An axis as given, checked non-zero, made a unit vector. */
export function unitAxis(value: unknown): Vec2 {
  const v = checkCoordinates('axis', value);
  const len = Math.sqrt(v.x * v.x + v.y * v.y);
  if (len < 1e-9) fail('axis', value, 'a non-zero vector');
  return { x: v.x / len, y: v.y / len };
}

/** @internal A number in [0, 1]. */
export function checkFraction(name: string, value: unknown): number {
  return checkRange(name, value, 0, 1);
}
