import {
  checkBoolean,
  checkInteger,
  checkKnownKeys,
  checkNonNegative,
  FulcrumError,
  fail,
} from '../core/errors';
import { IndexBound } from '../core/index-bound';
import {
  checkAngle,
  checkCoordinates,
  checkNonNegativeRate,
  checkRange,
  checkRate,
  checkVector,
  checkZeroOrRange,
  Limits,
} from '../core/limits';
import { maxExtentFrom } from '../geometry/extent';
import { Pack, packGeometry } from '../geometry/packed';
import { type Geometry, isGeometry, ShapeKind } from '../geometry/types';
import {
  buildJoint,
  type DistanceJointDef,
  type JointDef,
  type MotorJointDef,
  type MouseJointDef,
  type PrismaticJointDef,
  type RevoluteJointDef,
  type WeldJointDef,
  type WheelJointDef,
} from '../joints/create-joint';
import type { DistanceJoint } from '../joints/distance-joint';
import { Joint } from '../joints/joint';
import type { MotorJoint } from '../joints/motor-joint';
import type { MouseJoint } from '../joints/mouse-joint';
import type { PrismaticJoint } from '../joints/prismatic-joint';
import type { RevoluteJoint } from '../joints/revolute-joint';
import type { WeldJoint } from '../joints/weld-joint';
import type { WheelJoint } from '../joints/wheel-joint';
import type { AABB } from '../math/aabb';
import { makeRotInto } from '../math/rot';
import type { Vec2 } from '../math/vec2';
import type { CastHit, QueryFilter, QueryTransform } from '../query/index';
import * as queries from '../query/index';
import { BodyFlag, BodyKind, S } from '../store/body-store';
import { ContactFlag } from '../store/contact-store';
import { collectAwakeBodies, finalizeBodies, solve, updateSleep } from '../world/solve';
import { createNewContacts, updateContacts } from '../world/update-contacts';
import { WorldCore } from '../world/world-core';
import { BODY_DEF_KEYS, BODY_TYPES, Body, type BodyDef, type BodyType } from './body';
import { EventDispatcher, type WorldEventMap, type WorldEvents } from './events';
import { resolveShapeDef, type ShapeDef, ShapeHandle } from './shape';
import { readSnapshot, writeSnapshot } from './snapshot';

export interface WorldDef {
  gravity?: Vec2;
  subSteps?: number;
  enableSleep?: boolean;
  enableContinuous?: boolean;
  lengthUnitsPerMeter?: number;
}

const WORLD_DEF_KEYS = [
  'gravity',
  'subSteps',
  'enableSleep',
  'enableContinuous',
  'lengthUnitsPerMeter',
] as const;
const BODY_KINDS = {
  static: BodyKind.STATIC,
  kinematic: BodyKind.KINEMATIC,
  dynamic: BodyKind.DYNAMIC,
} as const;
const rotScratch = { c: 1, s: 0 };

/** A physics world: bodies, their shapes, contacts and the step that moves them. */
export class World {
  /** @internal the engine state behind this API */
  readonly core: WorldCore;
  private readonly bodyHandles: (Body | undefined)[] = [];
  /** @internal */
  readonly shapeHandles: (ShapeHandle | undefined)[] = [];
  private readonly dispatcher = new EventDispatcher(this);

  constructor(def: WorldDef = {}) {
    if (typeof def !== 'object' || def === null) fail('def', def, 'an object');
    checkKnownKeys('def', def, WORLD_DEF_KEYS);
    const gravity =
      def.gravity === undefined ? { x: 0, y: -10 } : checkVector('gravity', def.gravity, Limits.RATE);
    const subSteps = def.subSteps === undefined ? 4 : checkInteger('subSteps', def.subSteps, 1, 64);
    const enableSleep = def.enableSleep === undefined ? true : checkBoolean('enableSleep', def.enableSleep);
    const enableContinuous =
      def.enableContinuous === undefined ? true : checkBoolean('enableContinuous', def.enableContinuous);
    const units =
      def.lengthUnitsPerMeter === undefined
        ? 1
        : checkRange('lengthUnitsPerMeter', def.lengthUnitsPerMeter, Limits.MIN_UNITS, Limits.MAX_UNITS);
    this.core = new WorldCore(units);
    this.core.gravityX = gravity.x;
    this.core.gravityY = gravity.y;
    this.core.subSteps = subSteps;
    this.core.enableSleep = enableSleep;
    this.core.enableContinuous = enableContinuous;
  }

  get gravity(): Vec2 {
    return { x: this.core.gravityX, y: this.core.gravityY };
  }

  set gravity(value: Vec2) {
    const g = checkVector('gravity', value, Limits.RATE);
    this.core.gravityX = g.x;
    this.core.gravityY = g.y;
  }

  get subSteps(): number {
    return this.core.subSteps;
  }

  set subSteps(value: number) {
    this.core.subSteps = checkInteger('subSteps', value, 1, 64);
  }

  get enableSleep(): boolean {
    return this.core.enableSleep;
  }

  /** Turning sleep off wakes every body. */
  set enableSleep(value: boolean) {
    checkBoolean('enableSleep', value);
    this.core.enableSleep = value;
    if (!value) for (const b of this.bodies) this.core.wake(b.slot);
  }

  get enableContinuous(): boolean {
    return this.core.enableContinuous;
  }

  set enableContinuous(value: boolean) {
    this.core.enableContinuous = checkBoolean('enableContinuous', value);
  }

  /** contactHit events are reported above this approach speed (m/s) */
  get hitEventThreshold(): number {
    return this.core.hitEventThreshold;
  }

  set hitEventThreshold(value: number) {
    this.core.hitEventThreshold = checkNonNegative('hitEventThreshold', value);
  }

  /**
   * Contacts that may count against one shape (default 32; see README, "Crowds"): a contact counts
   * against the smaller of its two shapes, both when they are the same size, and a dynamic shape's
   * contacts with static and kinematic shapes only against those. Shapes at the limit make no more
   * contacts (a 'warning' event tells) until some of theirs end.
   */
  get maxContactsPerShape(): number {
    return this.core.contactLimiter.limit;
  }

  set maxContactsPerShape(value: number) {
    this.core.contactLimiter.limit = checkInteger('maxContactsPerShape', value, 1, IndexBound.MAX);
  }

  /** Shapes that the contact limit left without contacts with some shapes they overlap, after the last step. */
  get crowdedShapeCount(): number {
    return this.core.contactLimiter.crowdedCount;
  }

  get bodyCount(): number {
    return this.core.bodies.liveCount;
  }

  get awakeBodyCount(): number {
    const bodies = this.core.bodies;
    let n = 0;
    for (let b = 0; b < bodies.slotCount; b++) {
      if (bodies.alive[b] !== 0 && (bodies.flags[b] & BodyFlag.AWAKE) !== 0) n++;
    }
    return n;
  }

  get contactCount(): number {
    return this.core.contacts.liveCount;
  }

  /** Live bodies in slot order. */
  get bodies(): Iterable<Body> {
    const handles = this.bodyHandles;
    const bodies = this.core.bodies;
    return {
      *[Symbol.iterator]() {
        for (let b = 0; b < bodies.slotCount; b++) {
          if (bodies.alive[b] !== 0) yield handles[b]!;
        }
      },
    };
  }

  private checkUnlocked(): void {
    if (this.core.locked) throw new FulcrumError('the world is locked during step()');
  }

  createBody(def: BodyDef = {}): Body {
    this.checkUnlocked();
    checkRoom('bodies', this.core.bodies.liveCount);
    if (typeof def !== 'object' || def === null) fail('def', def, 'an object');
    checkKnownKeys('def', def, BODY_DEF_KEYS);
    const type = def.type === undefined ? 'static' : def.type;
    if (!BODY_TYPES.includes(type)) fail('type', type, "'static', 'kinematic' or 'dynamic'");
    const position = def.position === undefined ? { x: 0, y: 0 } : checkCoordinates('position', def.position);
    const angle = def.angle === undefined ? 0 : checkAngle('angle', def.angle);
    const v =
      def.linearVelocity === undefined
        ? { x: 0, y: 0 }
        : checkVector('linearVelocity', def.linearVelocity, Limits.RATE);
    const w = def.angularVelocity === undefined ? 0 : checkRate('angularVelocity', def.angularVelocity);
    const linearDamping =
      def.linearDamping === undefined ? 0 : checkNonNegativeRate('linearDamping', def.linearDamping);
    const angularDamping =
      def.angularDamping === undefined ? 0 : checkNonNegativeRate('angularDamping', def.angularDamping);
    const gravityScale = def.gravityScale === undefined ? 1 : checkRate('gravityScale', def.gravityScale);
    const fixedRotation =
      def.fixedRotation === undefined ? false : checkBoolean('fixedRotation', def.fixedRotation);
    const bullet = def.bullet === undefined ? false : checkBoolean('bullet', def.bullet);
    const allowSleep = def.allowSleep === undefined ? true : checkBoolean('allowSleep', def.allowSleep);
    const awake = def.awake === undefined ? true : checkBoolean('awake', def.awake);

    const core = this.core;
    const bodies = core.bodies;
    const b = bodies.allocate();
    const kind = BODY_KINDS[type];
    bodies.kind[b] = kind;
    let flags = 0;
    if (kind !== BodyKind.STATIC && awake) flags |= BodyFlag.AWAKE;
    if (fixedRotation) flags |= BodyFlag.FIXED_ROTATION;
    if (bullet) flags |= BodyFlag.BULLET;
    if (allowSleep) flags |= BodyFlag.ALLOW_SLEEP;
    bodies.flags[b] = flags;
    makeRotInto(angle, rotScratch);
    bodies.px[b] = position.x;
    bodies.py[b] = position.y;
    bodies.qc[b] = rotScratch.c;
    bodies.qs[b] = rotScratch.s;
    if (kind !== BodyKind.STATIC) {
      const s = b * S.STRIDE;
      bodies.state[s + S.VX] = v.x;
      bodies.state[s + S.VY] = v.y;
      bodies.state[s + S.W] = fixedRotation && kind === BodyKind.DYNAMIC ? 0 : w;
    }
    bodies.linearDamping[b] = linearDamping;
    bodies.angularDamping[b] = angularDamping;
    bodies.gravityScale[b] = gravityScale;
    core.updateMass(b);
    if (kind !== BodyKind.STATIC && !awake) this.sleepBody(b);
    const handle = new Body(this, b, bodies.generation[b], def.userData);
    this.bodyHandles[b] = handle;
    return handle;
  }

  /** Destroys a body with its shapes and contacts; the bodies it touched wake up. */
  destroyBody(body: Body): void {
    this.checkUnlocked();
    const b = this.checkBody('body', body);
    this.dispatcher.settle();
    const core = this.core;
    for (const joint of core.bodyJoints[b]?.slice() ?? []) this.removeJoint(joint);
    core.bodyJoints[b] = undefined;
    core.wakeTouching(b);
    const contacts = core.contacts;
    let e = core.bodies.contactHead[b];
    while (e !== -1) {
      const next = contacts.edgeNext[e];
      core.destroyContact(e >> 1, false);
      e = next;
    }
    let s = core.bodies.shapeHead[b];
    while (s !== -1) {
      const next = core.shapes.next[s];
      core.destroyProxy(s);
      core.shapes.free(s);
      this.shapeHandles[s] = undefined;
      s = next;
    }
    core.islands.remove(core.bodies, b);
    core.bodies.free(b);
    this.bodyHandles[b] = undefined;
  }

  /** Creates a joint (see JointDef for the types and their options); it wakes both bodies. */
  createJoint(def: DistanceJointDef): DistanceJoint;
  createJoint(def: RevoluteJointDef): RevoluteJoint;
  createJoint(def: PrismaticJointDef): PrismaticJoint;
  createJoint(def: WeldJointDef): WeldJoint;
  createJoint(def: WheelJointDef): WheelJoint;
  createJoint(def: MouseJointDef): MouseJoint;
  createJoint(def: MotorJointDef): MotorJoint;
  createJoint(def: JointDef): Joint;
  createJoint(def: JointDef): Joint {
    this.checkUnlocked();
    checkRoom('joints', this.core.joints.length);
    const joint = buildJoint(this, def);
    const core = this.core;
    const a = joint.bodyA.slot;
    const b = joint.bodyB.slot;
    core.joints.push(joint);
    core.jointListEpoch++;
    const listA = core.bodyJoints[a] ?? [];
    core.bodyJoints[a] = listA;
    listA.push(joint);
    if (b !== a) {
      const listB = core.bodyJoints[b] ?? [];
      core.bodyJoints[b] = listB;
      listB.push(joint);
      if (!joint.collideConnected) core.destroyContactsBetween(a, b);
    }
    core.wake(a);
    core.wake(b);
    return joint;
  }

  /** Destroys a joint and wakes its bodies. */
  destroyJoint(joint: Joint): void {
    this.checkUnlocked();
    if (!(joint instanceof Joint) || joint.world !== this) fail('joint', joint, 'a Joint of this world');
    joint.check();
    this.removeJoint(joint);
  }

  private removeJoint(joint: Joint): void {
    const core = this.core;
    joint.destroyed = true;
    core.joints.splice(core.joints.indexOf(joint), 1);
    core.jointListEpoch++;
    for (const body of [joint.bodyA, joint.bodyB]) {
      const list = core.bodyJoints[body.slot];
      const i = list ? list.indexOf(joint) : -1;
      if (list && i >= 0) list.splice(i, 1);
      if (body.isValid) core.wake(body.slot);
    }
    // the bodies may collide again: let the broad phase find their pair
    if (!joint.collideConnected && joint.bodyA.isValid && joint.bodyB.isValid) {
      for (const shape of joint.bodyA.shapes) core.broadPhase.bufferMove(core.shapes.proxyKey[shape.slot]);
    }
  }

  /** Live joints in creation order. */
  get joints(): readonly Joint[] {
    return this.core.joints.slice();
  }

  /** @internal */
  jointsOf(b: number): Joint[] {
    return (this.core.bodyJoints[b] ?? []).slice();
  }

  /** @internal */
  checkBody(argument: string, body: unknown): number {
    if (!(body instanceof Body) || body.world !== this) fail(argument, body, 'a Body of this world');
    return body.check();
  }

  /** @internal */
  shapesOf(b: number): ShapeHandle[] {
    const result: ShapeHandle[] = [];
    const shapes = this.core.shapes;
    for (let s = this.core.bodies.shapeHead[b]; s !== -1; s = shapes.next[s])
      result.push(this.shapeHandles[s]!);
    return result.reverse();
  }

  /** @internal */
  createShapeOn(body: Body, geometry: Geometry, def: ShapeDef | undefined): ShapeHandle {
    const b = body.check();
    if (!isGeometry(geometry))
      fail('geometry', geometry, 'a geometry made by Shape.circle/box/polygon/capsule/segment');
    const core = this.core;
    if (geometry.kind === ShapeKind.SEGMENT && core.bodies.kind[b] === BodyKind.DYNAMIC) {
      throw new FulcrumError('geometry: a segment can only be attached to a static or kinematic body');
    }
    const d = resolveShapeDef(def);
    const shapes = core.shapes;
    checkRoom('shapes', shapes.liveCount);
    const s = shapes.allocate();
    shapes.body[s] = b;
    shapes.geometry[s] = geometry;
    packGeometry(geometry, shapes.packed, s * Pack.STRIDE);
    shapes.kind[s] = geometry.kind;
    shapes.flags[s] = d.flags;
    shapes.density[s] = d.density;
    shapes.friction[s] = d.friction;
    shapes.restitution[s] = d.restitution;
    shapes.radius[s] = geometry.kind === ShapeKind.SEGMENT ? 0 : geometry.radius;
    shapes.originExtent[s] = maxExtentFrom(geometry, 0, 0);
    shapes.categoryBits[s] = d.filter.categoryBits;
    shapes.maskBits[s] = d.filter.maskBits;
    shapes.groupIndex[s] = d.filter.groupIndex;
    shapes.next[s] = core.bodies.shapeHead[b];
    core.bodies.shapeHead[b] = s;
    core.updateMass(b);
    core.createProxy(s, true);
    const handle = new ShapeHandle(body, s, shapes.generation[s], geometry, d.userData);
    this.shapeHandles[s] = handle;
    core.wake(b);
    return handle;
  }

  /** @internal */
  destroyShapeOf(body: Body, shape: ShapeHandle): void {
    const b = body.check();
    if (!(shape instanceof ShapeHandle) || shape.body !== body) fail('shape', shape, 'a shape of this body');
    const s = shape.check();
    this.dispatcher.settle();
    const core = this.core;
    core.destroyShapeContacts(s, true, false);
    core.destroyProxy(s);
    const shapes = core.shapes;
    // unlink from the body's list
    let prev = -1;
    let x = core.bodies.shapeHead[b];
    while (x !== s) {
      prev = x;
      x = shapes.next[x];
    }
    if (prev === -1) core.bodies.shapeHead[b] = shapes.next[s];
    else shapes.next[prev] = shapes.next[s];
    shapes.free(s);
    this.shapeHandles[s] = undefined;
    core.updateMass(b);
    core.wake(b);
  }

  /** @internal */
  changeBodyType(b: number, type: BodyType): void {
    const core = this.core;
    const bodies = core.bodies;
    const kind = BODY_KINDS[type];
    if (bodies.kind[b] === kind) return;
    const shapes = core.shapes;
    if (kind === BodyKind.DYNAMIC) {
      for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
        if (shapes.kind[s] === ShapeKind.SEGMENT) {
          throw new FulcrumError(
            `type: a body with a segment shape cannot be 'dynamic', got ${JSON.stringify(type)}`,
          );
        }
      }
    }
    core.wakeTouching(b);
    core.islands.remove(bodies, b);
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
      core.destroyShapeContacts(s, true, true);
      core.destroyProxy(s);
    }
    bodies.kind[b] = kind;
    bodies.awakeEpoch++;
    if (kind === BodyKind.STATIC) {
      bodies.flags[b] &= ~BodyFlag.AWAKE;
      const st = b * S.STRIDE;
      bodies.state[st + S.VX] = 0;
      bodies.state[st + S.VY] = 0;
      bodies.state[st + S.W] = 0;
    } else {
      bodies.flags[b] |= BodyFlag.AWAKE;
      bodies.sleepTime[b] = 0;
    }
    core.updateMass(b);
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) core.createProxy(s, true);
  }

  /** @internal Puts a body and every body it touches (transitively) to sleep as one island. */
  sleepBody(b: number): void {
    const core = this.core;
    const bodies = core.bodies;
    if (bodies.kind[b] === BodyKind.STATIC) return;
    core.wake(b); // leave any island it was in, so the new island is complete
    const contacts = core.contacts;
    const members: number[] = [b];
    const seen = new Set<number>(members);
    for (let i = 0; i < members.length; i++) {
      const x = members[i];
      for (let e = bodies.contactHead[x]; e !== -1; e = contacts.edgeNext[e]) {
        const c = e >> 1;
        if ((contacts.flags[c] & ContactFlag.TOUCHING) === 0) continue;
        const other = contacts.bodyA[c] === x ? contacts.bodyB[c] : contacts.bodyA[c];
        if (bodies.kind[other] !== BodyKind.DYNAMIC || seen.has(other)) continue;
        seen.add(other);
        core.wake(other);
        members.push(other);
      }
    }
    members.sort((p, q) => p - q);
    core.islands.sleepGroup(bodies, members);
  }

  on<K extends keyof WorldEventMap>(event: K, handler: (e: WorldEventMap[K]) => void): () => void {
    return this.dispatcher.on(event, handler);
  }

  /** The events of the last step, as arrays, until the next step. */
  get events(): WorldEvents {
    return this.dispatcher.current();
  }

  /** Advances the world by `dt` seconds (use a fixed step such as 1/60). */
  step(dt: number): void {
    this.checkUnlocked();
    checkZeroOrRange('dt', dt, Limits.MIN_DT, Limits.MAX_DT);
    const core = this.core;
    this.dispatcher.emitStep('preStep', dt);
    core.locked = true;
    core.events.clear();
    core.events.takePending(core.shapes);
    try {
      createNewContacts(core);
      updateContacts(core);
      if (dt > 0) {
        collectAwakeBodies(core);
        solve(core, dt);
        finalizeBodies(core, dt);
        if (core.enableSleep) updateSleep(core);
      }
    } finally {
      core.locked = false;
    }
    this.dispatcher.deliver();
    this.dispatcher.emitStep('postStep', dt);
  }

  /** @internal */
  bodyHandle(b: number): Body {
    return this.bodyHandles[b]!;
  }

  // Queries (issue 4): rules and orders are documented in src/query/*.ts

  /** The closest shape hit by origin + f * translation (f in [0, 1]), or null. Skips sensors by default. */
  castRay(origin: Vec2, translation: Vec2, filter?: QueryFilter): CastHit | null {
    return queries.castRay(this, origin, translation, filter);
  }

  /** Every shape hit by the ray, sorted by fraction, then by shape slot. Skips sensors by default. */
  castRayAll(origin: Vec2, translation: Vec2, filter?: QueryFilter): CastHit[] {
    return queries.castRayAll(this, origin, translation, filter);
  }

  /** Shapes whose tight AABB overlaps or touches the box, by shape slot. Includes sensors by default. */
  queryAABB(aabb: AABB, filter?: QueryFilter): ShapeHandle[] {
    return queries.queryAABB(this, aabb, filter);
  }

  /** Shapes containing the point (surface included), by shape slot. Includes sensors by default. */
  queryPoint(point: Vec2, filter?: QueryFilter): ShapeHandle[] {
    return queries.queryPoint(this, point, filter);
  }

  /**
   * The first shape that `geometry`, placed at `transform` ({ position, angle? } or { p, q }) and moved
   * by `translation`, touches; fraction 0 and normal (0, 0) when it starts touching. Skips sensors by default.
   */
  castShape(
    geometry: Geometry,
    transform: QueryTransform,
    translation: Vec2,
    filter?: QueryFilter,
  ): CastHit | null {
    return queries.castShape(this, geometry, transform, translation, filter);
  }

  /** Shapes overlapping or touching `geometry` placed at `transform`, by shape slot. Includes sensors by default. */
  overlapShape(geometry: Geometry, transform: QueryTransform, filter?: QueryFilter): ShapeHandle[] {
    return queries.overlapShape(this, geometry, transform, filter);
  }

  // Snapshots (src/api/snapshot.ts: format, what is kept and what is not)

  /**
   * The whole state of the world as bytes: `World.restore(bytes)` gives a world whose steps are
   * bit-identical to this one's. Event handlers are not kept, nor userData that is not plain data.
   */
  snapshot(): Uint8Array {
    this.checkUnlocked();
    return writeSnapshot(this, () => new World());
  }

  /** A new world from `world.snapshot()` bytes of this build of Fulcrum, with new handles. */
  static restore(bytes: Uint8Array): World {
    const world = new World();
    readSnapshot(bytes, world, () => new World());
    return world;
  }
}

/** Refuses to add one more of `what` to a world that holds IndexBound.MAX of them. */
function checkRoom(what: string, count: number): void {
  if (count >= IndexBound.MAX) throw new FulcrumError(`${what}: a world holds at most ${IndexBound.MAX}`);
}
