import {
  checkBoolean,
  checkInteger,
  checkKnownKeys,
  checkNonNegative,
  FulcrumError,
  fail,
} from '../core/errors';
import { checkRoom, IndexBound } from '../core/index-bound';
import { checkRange, checkVector, checkZeroOrRange, Limits } from '../core/limits';
import type { Geometry } from '../geometry/types';
import { buildJoint } from '../joints/create-joint';
import { Joint } from '../joints/joint';
import type { JointType, JointTypes } from '../joints/registry';
import type { AABB } from '../math/aabb';
import { makeRotInto } from '../math/rot';
import type { Rot, Vec2 } from '../math/vec2';
import type { SolverTeam } from '../parallel/team';
import type { CastHit, QueryFilter, QueryTransform } from '../query/index';
import * as queries from '../query/index';
import { CONTACT_PASSES } from '../solver/contact-team';
import { BodyFlag, BodyKind, BodyState } from '../store/body-store';
import { stepWorld } from '../world/step';
import { WorldCore } from '../world/world-core';
import { sleepIsland } from '../world/world-edits';
import { BODY_KINDS, Body, type BodyDef, resolveBodyDef } from './body';
import type { WorldEventMap, WorldEvents } from './events';
import { WorldHandles } from './handles';
import type { ShapeHandle } from './shape';
import { readSnapshot, writeSnapshot } from './snapshot';

export interface WorldDef {
  gravity?: Vec2;
  subSteps?: number;
  enableSleep?: boolean;
  enableContinuous?: boolean;
  lengthUnitsPerMeter?: number;
  /** how a contact's friction comes from its two shapes': 'geometric' (default) sqrt(a * b), 'min' the smaller */
  frictionMixing?: FrictionMixing;
  /**
   * threads that solve each step's contacts, the calling one included (default 1): `workers - 1`
   * workers share the contact columns through SharedArrayBuffer. Same bits as one thread. Where
   * SharedArrayBuffer is missing (a page not cross-origin isolated) the world steps on one thread.
   */
  workers?: number;
  /** the workers' script: by default the package's `solver-worker.js`, beside the engine's files */
  workerUrl?: URL | string;
}

export type FrictionMixing = 'geometric' | 'min';

const FRICTION_MIXINGS: readonly FrictionMixing[] = ['geometric', 'min'];

function checkFrictionMixing(value: unknown): FrictionMixing {
  if (!FRICTION_MIXINGS.includes(value as FrictionMixing))
    fail('frictionMixing', value, "'geometric' or 'min'");
  return value as FrictionMixing;
}

const WORLD_DEF_KEYS = [
  'gravity',
  'subSteps',
  'enableSleep',
  'enableContinuous',
  'lengthUnitsPerMeter',
  'frictionMixing',
  'workers',
  'workerUrl',
] as const;

/** @internal Checks a definition's `workers` and `workerUrl` (World's and WorkerWorld's); returns the threads. */
export function checkWorkers(def: WorldDef): number {
  const workerUrl = def.workerUrl;
  if (workerUrl !== undefined && typeof workerUrl !== 'string' && !(workerUrl instanceof URL))
    fail('workerUrl', workerUrl, 'a URL or a string');
  return def.workers === undefined ? 1 : checkInteger('workers', def.workers, 1, 64);
}

/** A physics world: bodies, their shapes, contacts and the step that moves them. */
export class World {
  /** @internal the engine state behind this API */
  readonly core: WorldCore;
  /** @internal the handles of its bodies and shapes, and its events */
  readonly handles: WorldHandles;
  /** a new body's rotation as createBody works it out (a # field: no property key, so no snapshot) */
  readonly #rot: Rot = { c: 1, s: 0 };
  #disposed = false;
  /** see workersReady (a # field: no property key, so no snapshot) */
  readonly #workersReady: Promise<number>;

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
    const frictionMixing =
      def.frictionMixing === undefined ? 'geometric' : checkFrictionMixing(def.frictionMixing);
    const workers = checkWorkers(def);
    this.core = new WorldCore(units);
    this.handles = new WorldHandles(this.core);
    this.core.gravityX = gravity.x;
    this.core.gravityY = gravity.y;
    this.core.subSteps = subSteps;
    this.core.enableSleep = enableSleep;
    this.core.enableContinuous = enableContinuous;
    this.core.frictionMin = frictionMixing === 'min';
    this.#workersReady =
      workers > 1 && typeof SharedArrayBuffer === 'function'
        ? this.#startTeam(workers, def.workerUrl)
        : Promise.resolve(1);
    // a world whose workers failed steps on one thread: that is not an unhandled error of the program
    this.#workersReady.catch(() => {});
  }

  /**
   * Resolves with the number of threads that solve the steps once the workers have started (1 when
   * `workers` is 1 or SharedArrayBuffer is missing); rejects if they could not start, and the world
   * then steps on one thread. Steps taken before are the same bits, on one thread.
   */
  get workersReady(): Promise<number> {
    return this.#workersReady;
  }

  async #startTeam(threads: number, url: URL | string | undefined): Promise<number> {
    // loaded only by worlds that ask for workers: one thread's users do not carry it
    const { SolverTeam } = await import('../parallel/team');
    let team: SolverTeam;
    try {
      team = await SolverTeam.start(threads, url, CONTACT_PASSES);
    } catch (error) {
      throw new FulcrumError(`the world's ${threads - 1} solver workers could not start: ${error}`, {
        cause: error,
      });
    }
    if (this.#disposed) {
      team.stop();
      return 1;
    }
    this.core.team = team;
    return team.threads;
  }

  /** threads solving the steps now: `workers` once they have started, else 1 */
  get workers(): number {
    return this.core.team?.threads ?? 1;
  }

  /**
   * Ends the world's workers (`workers`); it steps on one thread from then on. A world with workers
   * that is dropped without it keeps their threads asleep until the program ends.
   */
  dispose(): void {
    this.#disposed = true;
    this.core.team?.stop();
    this.core.team = null;
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

  /** world units to the metre, as given when the world was made */
  get lengthUnitsPerMeter(): number {
    return this.core.settings.lengthUnitsPerMeter;
  }

  get frictionMixing(): FrictionMixing {
    return this.core.frictionMin ? 'min' : 'geometric';
  }

  set frictionMixing(value: FrictionMixing) {
    this.core.frictionMin = checkFrictionMixing(value) === 'min';
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
    const handles = this.handles.bodies;
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
    const {
      type,
      position,
      angle,
      v,
      w,
      linearDamping,
      angularDamping,
      gravityScale,
      fixedRotation,
      bullet,
      allowSleep,
      awake,
    } = resolveBodyDef(def);

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
    const rot = makeRotInto(angle, this.#rot);
    bodies.px[b] = position.x;
    bodies.py[b] = position.y;
    bodies.qc[b] = rot.c;
    bodies.qs[b] = rot.s;
    if (kind !== BodyKind.STATIC) {
      const s = b * BodyState.STRIDE;
      bodies.state[s + BodyState.VX] = v.x;
      bodies.state[s + BodyState.VY] = v.y;
      bodies.state[s + BodyState.W] = fixedRotation && kind === BodyKind.DYNAMIC ? 0 : w;
    }
    bodies.linearDamping[b] = linearDamping;
    bodies.angularDamping[b] = angularDamping;
    bodies.gravityScale[b] = gravityScale;
    core.updateMass(b);
    if (kind !== BodyKind.STATIC && !awake) sleepIsland(core, b);
    const handle = new Body(this, this.handles, b, bodies.generation[b], def.userData);
    this.handles.bodies[b] = handle;
    return handle;
  }

  /** Destroys a body with its shapes and contacts; the bodies it touched wake up. */
  destroyBody(body: Body): void {
    this.checkUnlocked();
    const b = this.checkBody('body', body);
    this.handles.dispatcher.settle();
    const core = this.core;
    for (const joint of this.jointsOf(b)) this.removeJoint(joint);
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
      this.handles.shapes[s] = undefined;
      s = next;
    }
    core.islands.remove(core.bodies, b);
    core.bodies.free(b);
    this.handles.bodies[b] = undefined;
  }

  /**
   * Creates a joint of the definition's `type`, and returns it typed as that type's class: a
   * RevoluteJointDef (`type: 'revolute'`) makes a RevoluteJoint, and so on for each JointDef. It
   * wakes both bodies.
   */
  createJoint<T extends JointType>(def: JointTypes[T]['def'] & { type: T }): JointTypes[T]['joint'] {
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
    // the joint of the definition's type (registry.ts)
    return joint as JointTypes[T]['joint'];
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
    // every joint in the core is a Joint that createJoint made
    return this.core.joints.slice() as Joint[];
  }

  private jointsOf(b: number): Joint[] {
    return (this.core.bodyJoints[b] ?? []).slice() as Joint[];
  }

  /** @internal */
  checkBody(argument: string, body: unknown): number {
    if (!(body instanceof Body) || body.world !== this) fail(argument, body, 'a Body of this world');
    return body.check();
  }

  on<K extends keyof WorldEventMap>(event: K, handler: (e: WorldEventMap[K]) => void): () => void {
    return this.handles.dispatcher.on(event, handler);
  }

  /** The events of the last step, as arrays, until the next step. */
  get events(): WorldEvents {
    return this.handles.dispatcher.current();
  }

  /** Advances the world by `dt` seconds (use a fixed step such as 1/60). */
  step(dt: number): void {
    this.checkUnlocked();
    checkZeroOrRange('dt', dt, Limits.MIN_DT, Limits.MAX_DT);
    const core = this.core;
    this.handles.dispatcher.emitStep('preStep', dt);
    stepWorld(core, dt);
    this.handles.dispatcher.deliver();
    this.handles.dispatcher.emitStep('postStep', dt);
  }

  // Queries: their rules and orders are documented in src/query/*.ts

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
