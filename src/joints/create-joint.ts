import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkBoolean, checkKnownKeys, FulcrumError, fail } from '../core/errors';
import {
  checkAngle,
  checkCoordinate,
  checkCoordinates,
  checkHertz,
  checkLength,
  checkNonNegativeForce,
  checkNonNegativeRate,
  checkRange,
  checkRate,
} from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { relativeAngle } from '../solver/joint-math';
import { DistanceJoint } from './distance-joint';
import type { Joint } from './joint';
import { MotorJoint } from './motor-joint';
import { MouseJoint } from './mouse-joint';
import { PrismaticJoint } from './prismatic-joint';
import { RevoluteJoint } from './revolute-joint';
import { WeldJoint } from './weld-joint';
import { WheelJoint } from './wheel-joint';

interface BaseDef {
  bodyA: Body;
  bodyB: Body;
  collideConnected?: boolean;
  userData?: unknown;
}
interface AnchorDef {
  /** world point; or give localAnchorA and localAnchorB */
  anchor?: Vec2;
  localAnchorA?: Vec2;
  localAnchorB?: Vec2;
}
interface SpringDef {
  enableSpring?: boolean;
  hertz?: number;
  dampingRatio?: number;
}

export interface DistanceJointDef extends BaseDef, SpringDef {
  type: 'distance';
  localAnchorA?: Vec2;
  localAnchorB?: Vec2;
  length?: number;
  minLength?: number;
  maxLength?: number;
}
export interface RevoluteJointDef extends BaseDef, AnchorDef, SpringDef {
  type: 'revolute';
  referenceAngle?: number;
  enableLimit?: boolean;
  lowerAngle?: number;
  upperAngle?: number;
  enableMotor?: boolean;
  motorSpeed?: number;
  maxMotorTorque?: number;
}
export interface PrismaticJointDef extends BaseDef, AnchorDef, SpringDef {
  type: 'prismatic';
  axis: Vec2;
  referenceAngle?: number;
  enableLimit?: boolean;
  lower?: number;
  upper?: number;
  enableMotor?: boolean;
  motorSpeed?: number;
  maxMotorForce?: number;
}
export interface WeldJointDef extends BaseDef, AnchorDef {
  type: 'weld';
  referenceAngle?: number;
  linearHertz?: number;
  angularHertz?: number;
  dampingRatio?: number;
}
export interface WheelJointDef extends BaseDef, AnchorDef, SpringDef {
  type: 'wheel';
  axis: Vec2;
  enableMotor?: boolean;
  motorSpeed?: number;
  maxMotorTorque?: number;
  enableLimit?: boolean;
  lower?: number;
  upper?: number;
}
export interface MouseJointDef {
  type: 'mouse';
  body: Body;
  target: Vec2;
  maxForce?: number;
  hertz?: number;
  dampingRatio?: number;
  userData?: unknown;
}
export interface MotorJointDef extends BaseDef {
  type: 'motor';
  linearOffset?: Vec2;
  angularOffset?: number;
  maxForce?: number;
  maxTorque?: number;
  correctionFactor?: number;
}

export type JointDef =
  | DistanceJointDef
  | RevoluteJointDef
  | PrismaticJointDef
  | WeldJointDef
  | WheelJointDef
  | MouseJointDef
  | MotorJointDef;

const BASE_KEYS = ['type', 'bodyA', 'bodyB', 'collideConnected', 'userData'];
const ANCHOR_KEYS = ['anchor', 'localAnchorA', 'localAnchorB'];
const SPRING_KEYS = ['enableSpring', 'hertz', 'dampingRatio'];
const KEYS: Record<string, readonly string[]> = {
  distance: [
    ...BASE_KEYS,
    'localAnchorA',
    'localAnchorB',
    'length',
    'minLength',
    'maxLength',
    ...SPRING_KEYS,
  ],
  revolute: [
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    ...SPRING_KEYS,
    'referenceAngle',
    'enableLimit',
    'lowerAngle',
    'upperAngle',
    'enableMotor',
    'motorSpeed',
    'maxMotorTorque',
  ],
  prismatic: [
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    ...SPRING_KEYS,
    'axis',
    'referenceAngle',
    'enableLimit',
    'lower',
    'upper',
    'enableMotor',
    'motorSpeed',
    'maxMotorForce',
  ],
  weld: [...BASE_KEYS, ...ANCHOR_KEYS, 'referenceAngle', 'linearHertz', 'angularHertz', 'dampingRatio'],
  wheel: [
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    ...SPRING_KEYS,
    'axis',
    'enableMotor',
    'motorSpeed',
    'maxMotorTorque',
    'enableLimit',
    'lower',
    'upper',
  ],
  mouse: ['type', 'body', 'target', 'maxForce', 'hertz', 'dampingRatio', 'userData'],
  motor: [...BASE_KEYS, 'linearOffset', 'angularOffset', 'maxForce', 'maxTorque', 'correctionFactor'],
};

function bool(name: string, value: unknown, fallback: boolean): boolean {
  return value === undefined ? fallback : checkBoolean(name, value);
}
/** `check` applied to `value`, or `fallback` when it is not given (core/limits.ts has the ranges) */
function opt(
  check: (name: string, value: unknown) => number,
  name: string,
  value: unknown,
  fallback: number,
): number {
  return value === undefined ? fallback : check(name, value);
}

/** Anchors in both bodies' frames from a world `anchor` or from local anchors (default: origins). */
function anchors(def: AnchorDef, a: Body, b: Body): { la: Vec2; lb: Vec2 } {
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

/** `p` in `body`'s frame, unchecked: B's centre may lie beyond the range getLocalPoint accepts */
function localPointOf(body: Body, p: Vec2): Vec2 {
  const q = body.rotation;
  const o = body.position;
  const dx = p.x - o.x;
  const dy = p.y - o.y;
  return { x: q.c * dx + q.s * dy, y: -q.s * dx + q.c * dy };
}

function checkFraction(name: string, value: unknown): number {
  return checkRange(name, value, 0, 1);
}

function unitAxis(value: unknown): Vec2 {
  const v = checkCoordinates('axis', value);
  const len = Math.sqrt(v.x * v.x + v.y * v.y);
  if (len < 1e-9) fail('axis', value, 'a non-zero vector');
  return { x: v.x / len, y: v.y / len };
}

function limits(lowerName: string, lower: number, upperName: string, upper: number): void {
  if (lower > upper) throw new FulcrumError(`${lowerName} must be <= ${upperName}, got ${lower} > ${upper}`);
}

/**
 * Validates a joint definition completely and builds the joint; it throws before anything is
 * created, so a bad definition leaves the world as it was.
 */
export function buildJoint(world: World, def: JointDef): Joint {
  if (typeof def !== 'object' || def === null) fail('def', def, 'an object');
  const type = (def as { type?: unknown }).type;
  if (typeof type !== 'string' || !(type in KEYS)) {
    fail('type', type, "'distance', 'revolute', 'prismatic', 'weld', 'wheel', 'mouse' or 'motor'");
  }
  checkKnownKeys('def', def, KEYS[type]);
  if (def.type === 'mouse') {
    world.checkBody('body', def.body);
    const body = def.body;
    const target = checkCoordinates('target', def.target);
    const mass = body.mass;
    return new MouseJoint(world, body, body.getLocalPoint(target), def.userData, {
      targetX: target.x,
      targetY: target.y,
      maxForce: opt(checkNonNegativeForce, 'maxForce', def.maxForce, 1000 * Math.max(mass, 1)),
      hertz: opt(checkHertz, 'hertz', def.hertz, 5),
      dampingRatio: opt(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 0.7),
    });
  }
  world.checkBody('bodyA', def.bodyA);
  world.checkBody('bodyB', def.bodyB);
  const a = def.bodyA;
  const b = def.bodyB;
  if (a === b) fail('bodyB', 'the same body as bodyA', 'a different body from bodyA');
  const collide = bool('collideConnected', def.collideConnected, false);
  const currentAngle = () => {
    const qa = a.rotation;
    const qb = b.rotation;
    return relativeAngle(qa.c, qa.s, qb.c, qb.s);
  };
  switch (def.type) {
    case 'distance': {
      const la =
        def.localAnchorA === undefined ? { x: 0, y: 0 } : checkCoordinates('localAnchorA', def.localAnchorA);
      const lb =
        def.localAnchorB === undefined ? { x: 0, y: 0 } : checkCoordinates('localAnchorB', def.localAnchorB);
      const pa = a.getWorldPoint(la);
      const pb = b.getWorldPoint(lb);
      const current = Math.sqrt((pb.x - pa.x) * (pb.x - pa.x) + (pb.y - pa.y) * (pb.y - pa.y));
      const length = opt(checkLength, 'length', def.length, current);
      const minLength = opt(checkLength, 'minLength', def.minLength, 0);
      const maxLength =
        def.maxLength === undefined || def.maxLength === Number.POSITIVE_INFINITY
          ? Number.POSITIVE_INFINITY
          : checkLength('maxLength', def.maxLength);
      limits('minLength', minLength, 'maxLength', maxLength);
      return new DistanceJoint(world, a, b, la, lb, collide, def.userData, {
        length,
        minLength,
        maxLength,
        enableSpring: bool('enableSpring', def.enableSpring, false),
        hertz: opt(checkHertz, 'hertz', def.hertz, 0),
        dampingRatio: opt(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 0),
      });
    }
    case 'revolute': {
      const { la, lb } = anchors(def, a, b);
      const lowerAngle = opt(checkAngle, 'lowerAngle', def.lowerAngle, 0);
      const upperAngle = opt(checkAngle, 'upperAngle', def.upperAngle, 0);
      limits('lowerAngle', lowerAngle, 'upperAngle', upperAngle);
      return new RevoluteJoint(world, a, b, la, lb, collide, def.userData, {
        referenceAngle: opt(checkAngle, 'referenceAngle', def.referenceAngle, currentAngle()),
        enableLimit: bool('enableLimit', def.enableLimit, false),
        lowerAngle,
        upperAngle,
        enableMotor: bool('enableMotor', def.enableMotor, false),
        motorSpeed: opt(checkRate, 'motorSpeed', def.motorSpeed, 0),
        maxMotorTorque: opt(checkNonNegativeForce, 'maxMotorTorque', def.maxMotorTorque, 0),
        enableSpring: bool('enableSpring', def.enableSpring, false),
        hertz: opt(checkHertz, 'hertz', def.hertz, 0),
        dampingRatio: opt(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 0),
      });
    }
    case 'prismatic':
    case 'wheel': {
      const { la, lb } = anchors(def, a, b);
      const axis = a.getLocalVector(unitAxis(def.axis));
      const lower = opt(checkCoordinate, 'lower', def.lower, 0);
      const upper = opt(checkCoordinate, 'upper', def.upper, 0);
      limits('lower', lower, 'upper', upper);
      const wheel = def.type === 'wheel';
      const slider = {
        localAxisX: axis.x,
        localAxisY: axis.y,
        enableLimit: bool('enableLimit', def.enableLimit, false),
        lower,
        upper,
        enableSpring: bool('enableSpring', def.enableSpring, wheel),
        hertz: opt(checkHertz, 'hertz', def.hertz, wheel ? 1 : 0),
        dampingRatio: opt(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, wheel ? 0.7 : 0),
      };
      if (def.type === 'wheel') {
        return new WheelJoint(world, a, b, la, lb, collide, def.userData, slider, {
          enableMotor: bool('enableMotor', def.enableMotor, false),
          motorSpeed: opt(checkRate, 'motorSpeed', def.motorSpeed, 0),
          maxMotorTorque: opt(checkNonNegativeForce, 'maxMotorTorque', def.maxMotorTorque, 0),
        });
      }
      return new PrismaticJoint(world, a, b, la, lb, collide, def.userData, slider, {
        referenceAngle: opt(checkAngle, 'referenceAngle', def.referenceAngle, currentAngle()),
        enableMotor: bool('enableMotor', def.enableMotor, false),
        motorSpeed: opt(checkRate, 'motorSpeed', def.motorSpeed, 0),
        maxMotorForce: opt(checkNonNegativeForce, 'maxMotorForce', def.maxMotorForce, 0),
      });
    }
    case 'weld': {
      const { la, lb } = anchors(def, a, b);
      return new WeldJoint(world, a, b, la, lb, collide, def.userData, {
        referenceAngle: opt(checkAngle, 'referenceAngle', def.referenceAngle, currentAngle()),
        linearHertz: opt(checkHertz, 'linearHertz', def.linearHertz, 0),
        angularHertz: opt(checkHertz, 'angularHertz', def.angularHertz, 0),
        dampingRatio: opt(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 1),
      });
    }
    case 'motor': {
      const offset =
        def.linearOffset === undefined
          ? localPointOf(a, b.worldCenter)
          : checkCoordinates('linearOffset', def.linearOffset);
      return new MotorJoint(world, a, b, collide, def.userData, {
        linearOffsetX: offset.x,
        linearOffsetY: offset.y,
        angularOffset: opt(checkAngle, 'angularOffset', def.angularOffset, currentAngle()),
        maxForce: opt(checkNonNegativeForce, 'maxForce', def.maxForce, 1),
        maxTorque: opt(checkNonNegativeForce, 'maxTorque', def.maxTorque, 1),
        correctionFactor: opt(checkFraction, 'correctionFactor', def.correctionFactor, 0.3),
      });
    }
  }
}
