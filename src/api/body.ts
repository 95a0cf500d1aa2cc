import { checkBoolean, checkKnownKeys, FulcrumError, fail } from '../core/errors';
import {
  checkAngle,
  checkCoordinates,
  checkForce,
  checkNonNegativeRate,
  checkRange,
  checkRate,
  checkVector,
  Limits,
} from '../core/limits';
import { localScale, scaleGeometry } from '../geometry/scale-geometry';
import type { Chain, Concave, Geometry } from '../geometry/types';
import type { Joint } from '../joints/joint';
import { makeRotInto, rotAngle } from '../math/rot';
import type { Vec2 } from '../math/vec2';
import { BodyFlag, BodyKind, BodyState } from '../store/body-store';
import { ContactFlag } from '../store/contact-store';
import type { WorldCore } from '../world/world-core';
import { changeBodyKind, replaceShapeGeometry, sleepIsland } from '../world/world-edits';
import type { WorldHandles } from './handles';
import { attachShapes, detachShape, type ShapeDef, type ShapeHandle } from './shape';
import type { World } from './world';

export type BodyType = 'static' | 'kinematic' | 'dynamic';

/** A body's mass (kg), rotational inertia about its centre of mass, and that centre in the body's frame. */
export interface MassData {
  mass: number;
  inertia: number;
  center?: Vec2;
}

/** A point of a touching contact: where, how far apart its surfaces are (negative: overlapping), and the normal impulse of the last substep. */
export interface ContactPointData {
  point: Vec2;
  separation: number;
  normalImpulse: number;
}

/** A touching contact of a body (Body.getContacts). */
export interface ContactData {
  shapeA: ShapeHandle;
  shapeB: ShapeHandle;
  /** unit normal, from shape A to shape B */
  normal: Vec2;
  points: ContactPointData[];
}

const MASS_DATA_KEYS = ['mass', 'inertia', 'center'] as const;

export interface BodyDef {
  type?: BodyType;
  position?: Vec2;
  angle?: number;
  linearVelocity?: Vec2;
  angularVelocity?: number;
  linearDamping?: number;
  angularDamping?: number;
  gravityScale?: number;
  fixedRotation?: boolean;
  bullet?: boolean;
  allowSleep?: boolean;
  awake?: boolean;
  userData?: unknown;
}

export const BODY_DEF_KEYS = [
  'type',
  'position',
  'angle',
  'linearVelocity',
  'angularVelocity',
  'linearDamping',
  'angularDamping',
  'gravityScale',
  'fixedRotation',
  'bullet',
  'allowSleep',
  'awake',
  'userData',
] as const;

export const BODY_TYPES: readonly BodyType[] = ['static', 'kinematic', 'dynamic'];
export const BODY_KINDS = {
  static: BodyKind.STATIC,
  kinematic: BodyKind.KINEMATIC,
  dynamic: BodyKind.DYNAMIC,
} as const;

/** @internal A body definition checked, with every default filled in (World.createBody). */
export interface ResolvedBodyDef {
  type: BodyType;
  position: Vec2;
  angle: number;
  v: Vec2;
  w: number;
  linearDamping: number;
  angularDamping: number;
  gravityScale: number;
  fixedRotation: boolean;
  bullet: boolean;
  allowSleep: boolean;
  awake: boolean;
}

/**
 * @internal Checks a body definition completely (World.createBody, and fulcrum/worker on the calling
 * thread) and fills in its defaults; throws FulcrumError naming the option.
 */
export function resolveBodyDef(def: BodyDef): ResolvedBodyDef {
  if (typeof def !== 'object' || def === null) fail('def', def, 'an object');
  checkKnownKeys('def', def, BODY_DEF_KEYS);
  const type = def.type === undefined ? 'static' : def.type;
  if (!BODY_TYPES.includes(type)) fail('type', type, "'static', 'kinematic' or 'dynamic'");
  return {
    type,
    position: def.position === undefined ? { x: 0, y: 0 } : checkCoordinates('position', def.position),
    angle: def.angle === undefined ? 0 : checkAngle('angle', def.angle),
    v:
      def.linearVelocity === undefined
        ? { x: 0, y: 0 }
        : checkVector('linearVelocity', def.linearVelocity, Limits.RATE),
    w: def.angularVelocity === undefined ? 0 : checkRate('angularVelocity', def.angularVelocity),
    linearDamping:
      def.linearDamping === undefined ? 0 : checkNonNegativeRate('linearDamping', def.linearDamping),
    angularDamping:
      def.angularDamping === undefined ? 0 : checkNonNegativeRate('angularDamping', def.angularDamping),
    gravityScale: def.gravityScale === undefined ? 1 : checkRate('gravityScale', def.gravityScale),
    fixedRotation: def.fixedRotation === undefined ? false : checkBoolean('fixedRotation', def.fixedRotation),
    bullet: def.bullet === undefined ? false : checkBoolean('bullet', def.bullet),
    allowSleep: def.allowSleep === undefined ? true : checkBoolean('allowSleep', def.allowSleep),
    awake: def.awake === undefined ? true : checkBoolean('awake', def.awake),
  };
}

/** A scale factor: finite, not 0, at most Limits.COORDINATE in size (a negative one mirrors). */
/** @internal Body.scale's check of one factor (`given`: the argument as passed); fulcrum/worker's too. */
export function checkScaleFactor(argument: string, value: unknown, given: unknown): number {
  if (
    typeof value !== 'number' ||
    !Number.isFinite(value) ||
    value === 0 ||
    Math.abs(value) > Limits.COORDINATE
  ) {
    fail(argument, given, `a non-zero number or { x, y } of them, at most ${Limits.COORDINATE} in size`);
  }
  return value;
}

/**
 * A body handle: a slot and a generation into the world's columns. It stays valid until the body is
 * destroyed; after that every use throws FulcrumError.
 */
export class Body {
  /** @internal */
  readonly slot: number;
  /** @internal */
  readonly generation: number;
  readonly world: World;
  userData: unknown;
  /** @internal the engine state of the body's world */
  readonly core: WorldCore;
  /** @internal the handles of the world's bodies and shapes */
  readonly handles: WorldHandles;

  /** @internal created by World.createBody */
  constructor(world: World, handles: WorldHandles, slot: number, generation: number, userData: unknown) {
    this.world = world;
    this.handles = handles;
    this.core = handles.core;
    this.slot = slot;
    this.generation = generation;
    this.userData = userData;
  }

  /** @internal */
  check(): number {
    const core = this.core;
    if (core.bodies.alive[this.slot] === 0 || core.bodies.generation[this.slot] !== this.generation) {
      throw new FulcrumError('body has been destroyed');
    }
    return this.slot;
  }

  private unlocked(): number {
    if (this.core.locked) throw new FulcrumError('the world is locked during step()');
    return this.check();
  }

  get isValid(): boolean {
    const core = this.core;
    return core.bodies.alive[this.slot] === 1 && core.bodies.generation[this.slot] === this.generation;
  }

  get type(): BodyType {
    return BODY_TYPES[this.core.bodies.kind[this.check()]];
  }

  get position(): Vec2 {
    const b = this.check();
    const bodies = this.core.bodies;
    return { x: bodies.px[b], y: bodies.py[b] };
  }

  get angle(): number {
    const b = this.check();
    return rotAngle(this.core.bodies.qc[b], this.core.bodies.qs[b]);
  }

  /** rotation as a (cos, sin) pair, exactly as the engine keeps it */
  get rotation(): { c: number; s: number } {
    const b = this.check();
    return { c: this.core.bodies.qc[b], s: this.core.bodies.qs[b] };
  }

  get worldCenter(): Vec2 {
    const b = this.check();
    return { x: this.core.bodies.cx[b], y: this.core.bodies.cy[b] };
  }

  /**
   * Writes the body's state into `out` from `offset`, making no objects (for code that reads many
   * bodies every frame): the centre of mass x, y; the rotation's cosine and sine; the linear velocity
   * x, y; the angular velocity; 1 if awake, else 0. Eight numbers.
   */
  readState(out: Float64Array, offset = 0): void {
    const b = this.check();
    const bodies = this.core.bodies;
    const s = b * BodyState.STRIDE;
    out[offset] = bodies.cx[b];
    out[offset + 1] = bodies.cy[b];
    out[offset + 2] = bodies.qc[b];
    out[offset + 3] = bodies.qs[b];
    out[offset + 4] = bodies.state[s + BodyState.VX];
    out[offset + 5] = bodies.state[s + BodyState.VY];
    out[offset + 6] = bodies.state[s + BodyState.W];
    out[offset + 7] = (bodies.flags[b] & BodyFlag.AWAKE) !== 0 ? 1 : 0;
  }

  get localCenter(): Vec2 {
    const b = this.check();
    return { x: this.core.bodies.lcx[b], y: this.core.bodies.lcy[b] };
  }

  get linearVelocity(): Vec2 {
    const s = this.check() * BodyState.STRIDE;
    const state = this.core.bodies.state;
    return { x: state[s + BodyState.VX], y: state[s + BodyState.VY] };
  }

  get angularVelocity(): number {
    return this.core.bodies.state[this.check() * BodyState.STRIDE + BodyState.W];
  }

  get mass(): number {
    return this.core.bodies.mass[this.check()];
  }

  /** rotational inertia about the centre of mass */
  get inertia(): number {
    return this.core.bodies.inertia[this.check()];
  }

  get isAwake(): boolean {
    return (this.core.bodies.flags[this.check()] & BodyFlag.AWAKE) !== 0;
  }

  get linearDamping(): number {
    return this.core.bodies.linearDamping[this.check()];
  }

  get angularDamping(): number {
    return this.core.bodies.angularDamping[this.check()];
  }

  get gravityScale(): number {
    return this.core.bodies.gravityScale[this.check()];
  }

  get fixedRotation(): boolean {
    return (this.core.bodies.flags[this.check()] & BodyFlag.FIXED_ROTATION) !== 0;
  }

  get bullet(): boolean {
    return (this.core.bodies.flags[this.check()] & BodyFlag.BULLET) !== 0;
  }

  get allowSleep(): boolean {
    return (this.core.bodies.flags[this.check()] & BodyFlag.ALLOW_SLEEP) !== 0;
  }

  /** joints attached to this body, in creation order */
  get joints(): Joint[] {
    // every joint in a world's core is a Joint that World.createJoint made
    return (this.core.bodyJoints[this.check()] ?? []).slice() as Joint[];
  }

  /** shapes in creation order */
  /**
   * The body's touching contacts as of the last step (sensors have none): for each, its two shapes,
   * the normal from shape A to shape B, and its one or two points with their separation (negative
   * when overlapping) and the normal impulse of the last substep there (the step applies about
   * `world.subSteps` times as much).
   */
  getContacts(): ContactData[] {
    const b = this.check();
    const contacts = this.core.contacts;
    const shapes = this.handles.shapes;
    const result: ContactData[] = [];
    for (let e = this.core.bodies.contactHead[b]; e !== -1; e = contacts.edgeNext[e]) {
      const c = e >> 1;
      if ((contacts.flags[c] & (ContactFlag.TOUCHING | ContactFlag.SENSOR)) !== ContactFlag.TOUCHING)
        continue;
      const points: ContactPointData[] = [];
      for (let j = 0; j < contacts.pointCount[c]; j++) {
        const k = c * 2 + j;
        points.push({
          point: { x: contacts.pointX[k], y: contacts.pointY[k] },
          separation: contacts.separation[k],
          normalImpulse: contacts.normalImpulse[k],
        });
      }
      result.push({
        shapeA: shapes[contacts.shapeA[c]]!,
        shapeB: shapes[contacts.shapeB[c]]!,
        normal: { x: contacts.normalX[c], y: contacts.normalY[c] },
        points,
      });
    }
    return result;
  }

  get shapes(): ShapeHandle[] {
    const b = this.check();
    const result: ShapeHandle[] = [];
    const shapes = this.core.shapes;
    for (let s = this.core.bodies.shapeHead[b]; s !== -1; s = shapes.next[s])
      result.push(this.handles.shapes[s]!);
    return result.reverse();
  }

  setPosition(position: Vec2): void {
    const b = this.unlocked();
    const p = checkCoordinates('position', position);
    this.core.bodies.px[b] = p.x;
    this.core.bodies.py[b] = p.y;
    this.moved(b);
  }

  setAngle(angle: number): void {
    const b = this.unlocked();
    const a = checkAngle('angle', angle);
    const rot = makeRotInto(a, { c: 1, s: 0 });
    this.core.bodies.qc[b] = rot.c;
    this.core.bodies.qs[b] = rot.s;
    this.moved(b);
  }

  setTransform(position: Vec2, angle: number): void {
    const b = this.unlocked();
    const p = checkCoordinates('position', position);
    const a = checkAngle('angle', angle);
    const bodies = this.core.bodies;
    const rot = makeRotInto(a, { c: 1, s: 0 });
    bodies.px[b] = p.x;
    bodies.py[b] = p.y;
    bodies.qc[b] = rot.c;
    bodies.qs[b] = rot.s;
    this.moved(b);
  }

  /**
   * Scales the body's shapes by `factor` (one number, or `{ x, y }` along the world's axes) about the
   * world `point` (default: the centre of mass), which stays where it is; the body's origin moves
   * with the scale. Mass, centre of mass and inertia follow from the scaled shapes (mass scales with
   * area); velocities are kept. Circles, capsules and rounded polygons take one factor only. The
   * shapes' contacts end (touching ones report their ends) and are found again in the next step.
   * Nothing changes when any shape cannot take the scale.
   */
  scale(factor: number | Vec2, point?: Vec2): void {
    const b = this.unlocked();
    const sx = checkScaleFactor('factor', typeof factor === 'number' ? factor : factor?.x, factor);
    const sy = typeof factor === 'number' ? sx : checkScaleFactor('factor', factor.y, factor);
    const core = this.core;
    const bodies = core.bodies;
    const p = point === undefined ? { x: bodies.cx[b], y: bodies.cy[b] } : checkCoordinates('point', point);
    const origin = checkCoordinates('factor', {
      x: p.x + sx * (bodies.px[b] - p.x),
      y: p.y + sy * (bodies.py[b] - p.y),
    });
    // every new geometry first: one that fails leaves the body as it was
    const m = localScale(sx, sy, bodies.qc[b], bodies.qs[b]);
    const shapes = this.shapes;
    const scaled = shapes.map((shape) => scaleGeometry(shape.geometry, m, 'factor'));
    for (let i = 0; i < shapes.length; i++) {
      replaceShapeGeometry(core, shapes[i].slot, scaled[i]);
      shapes[i].current = scaled[i];
    }
    bodies.px[b] = origin.x;
    bodies.py[b] = origin.y;
    core.updateMass(b);
    this.moved(b);
  }

  private moved(b: number): void {
    const core = this.core;
    core.poseEpoch++;
    core.bodies.updateCenter(b);
    core.syncBodyProxies(b);
    core.wake(b);
  }

  setLinearVelocity(velocity: Vec2): void {
    const b = this.unlocked();
    const v = checkVector('velocity', velocity, Limits.RATE);
    const core = this.core;
    if (core.bodies.kind[b] === BodyKind.STATIC) return;
    const s = b * BodyState.STRIDE;
    core.bodies.state[s + BodyState.VX] = v.x;
    core.bodies.state[s + BodyState.VY] = v.y;
    this.wakeWithNeighbours(b);
  }

  setAngularVelocity(omega: number): void {
    const b = this.unlocked();
    const w = checkRate('angularVelocity', omega);
    const core = this.core;
    if (core.bodies.kind[b] === BodyKind.STATIC) return;
    if ((core.bodies.flags[b] & BodyFlag.FIXED_ROTATION) !== 0 && core.bodies.kind[b] === BodyKind.DYNAMIC)
      return;
    core.bodies.state[b * BodyState.STRIDE + BodyState.W] = w;
    this.wakeWithNeighbours(b);
  }

  /** A kinematic body that starts moving wakes what rests on it. */
  private wakeWithNeighbours(b: number): void {
    const core = this.core;
    core.wake(b);
    if (core.bodies.kind[b] === BodyKind.KINEMATIC) core.wakeTouching(b);
  }

  setLinearDamping(damping: number): void {
    const b = this.unlocked();
    this.core.bodies.linearDamping[b] = checkNonNegativeRate('linearDamping', damping);
  }

  setAngularDamping(damping: number): void {
    const b = this.unlocked();
    this.core.bodies.angularDamping[b] = checkNonNegativeRate('angularDamping', damping);
  }

  setGravityScale(scale: number): void {
    const b = this.unlocked();
    this.core.bodies.gravityScale[b] = checkRate('gravityScale', scale);
    this.core.wake(b);
  }

  setFixedRotation(fixed: boolean): void {
    const b = this.unlocked();
    checkBoolean('fixedRotation', fixed);
    const core = this.core;
    if (fixed) core.bodies.flags[b] |= BodyFlag.FIXED_ROTATION;
    else core.bodies.flags[b] &= ~BodyFlag.FIXED_ROTATION;
    if (fixed) core.bodies.state[b * BodyState.STRIDE + BodyState.W] = 0;
    core.updateMass(b);
    core.wake(b);
  }

  /**
   * Gives the body a mass (kg) and a rotational inertia about its centre of mass in place of what its
   * shapes give, and optionally that centre too (a point in the body's frame; by default the shapes'
   * centroid). Kept when shapes are added, removed or changed, until `resetMassData()`; only a dynamic
   * body uses it (a static or kinematic one keeps it for when it becomes dynamic).
   */
  setMassData(data: MassData): void {
    const b = this.unlocked();
    if (typeof data !== 'object' || data === null) fail('massData', data, 'an object');
    checkKnownKeys('massData', data, MASS_DATA_KEYS);
    const mass = checkRange('massData.mass', data.mass, Limits.MIN_MASS, Limits.MAX_MASS);
    const inertia = checkRange('massData.inertia', data.inertia, Limits.MIN_INERTIA, Limits.MAX_INERTIA);
    const center = data.center === undefined ? null : checkCoordinates('massData.center', data.center);
    const bodies = this.core.bodies;
    bodies.givenMass[b] = mass;
    bodies.givenInertia[b] = inertia;
    bodies.givenLcx[b] = center === null ? 0 : center.x;
    bodies.givenLcy[b] = center === null ? 0 : center.y;
    bodies.flags[b] |= BodyFlag.MASS_SET;
    if (center === null) bodies.flags[b] &= ~BodyFlag.CENTER_SET;
    else bodies.flags[b] |= BodyFlag.CENTER_SET;
    this.core.updateMass(b);
    this.core.wake(b);
  }

  /** Goes back to the mass, inertia and centre of mass that the body's shapes give. */
  resetMassData(): void {
    const b = this.unlocked();
    this.core.bodies.flags[b] &= ~(BodyFlag.MASS_SET | BodyFlag.CENTER_SET);
    this.core.updateMass(b);
    this.core.wake(b);
  }

  setBullet(bullet: boolean): void {
    const b = this.unlocked();
    checkBoolean('bullet', bullet);
    if (bullet) this.core.bodies.flags[b] |= BodyFlag.BULLET;
    else this.core.bodies.flags[b] &= ~BodyFlag.BULLET;
  }

  setAllowSleep(allow: boolean): void {
    const b = this.unlocked();
    checkBoolean('allowSleep', allow);
    const core = this.core;
    if (allow) core.bodies.flags[b] |= BodyFlag.ALLOW_SLEEP;
    else {
      core.bodies.flags[b] &= ~BodyFlag.ALLOW_SLEEP;
      core.wake(b);
    }
  }

  setType(type: BodyType): void {
    const b = this.unlocked();
    if (!BODY_TYPES.includes(type)) fail('type', type, "'static', 'kinematic' or 'dynamic'");
    changeBodyKind(this.core, b, BODY_KINDS[type], type);
  }

  /** Wakes the body, or puts it and everything it touches to sleep. */
  setAwake(awake: boolean): void {
    const b = this.unlocked();
    checkBoolean('awake', awake);
    if (awake) this.core.wake(b);
    else sleepIsland(this.core, b);
  }

  /** Force in newtons at a world point (default: the centre of mass), until the end of the next step. */
  applyForce(force: Vec2, point?: Vec2): void {
    const b = this.unlocked();
    const f = checkVector('force', force, Limits.FORCE);
    const core = this.core;
    const bodies = core.bodies;
    const p = point === undefined ? { x: bodies.cx[b], y: bodies.cy[b] } : checkCoordinates('point', point);
    if (bodies.kind[b] !== BodyKind.DYNAMIC) return;
    bodies.fx[b] += f.x;
    bodies.fy[b] += f.y;
    bodies.torque[b] += (p.x - bodies.cx[b]) * f.y - (p.y - bodies.cy[b]) * f.x;
    core.wake(b);
  }

  applyTorque(torque: number): void {
    const b = this.unlocked();
    const t = checkForce('torque', torque);
    const core = this.core;
    if (core.bodies.kind[b] !== BodyKind.DYNAMIC) return;
    core.bodies.torque[b] += t;
    core.wake(b);
  }

  /** Impulse in N·s at a world point (default: the centre of mass): changes the velocity at once. */
  applyLinearImpulse(impulse: Vec2, point?: Vec2): void {
    const b = this.unlocked();
    const i = checkVector('impulse', impulse, Limits.FORCE);
    const core = this.core;
    const bodies = core.bodies;
    const p = point === undefined ? { x: bodies.cx[b], y: bodies.cy[b] } : checkCoordinates('point', point);
    if (bodies.kind[b] !== BodyKind.DYNAMIC) return;
    const s = b * BodyState.STRIDE;
    bodies.state[s + BodyState.VX] += bodies.invMass[b] * i.x;
    bodies.state[s + BodyState.VY] += bodies.invMass[b] * i.y;
    bodies.state[s + BodyState.W] +=
      bodies.invInertia[b] * ((p.x - bodies.cx[b]) * i.y - (p.y - bodies.cy[b]) * i.x);
    core.wake(b);
  }

  applyAngularImpulse(impulse: number): void {
    const b = this.unlocked();
    const i = checkForce('impulse', impulse);
    const core = this.core;
    if (core.bodies.kind[b] !== BodyKind.DYNAMIC) return;
    core.bodies.state[b * BodyState.STRIDE + BodyState.W] += core.bodies.invInertia[b] * i;
    core.wake(b);
  }

  getWorldPoint(localPoint: Vec2): Vec2 {
    const b = this.check();
    const p = checkCoordinates('localPoint', localPoint);
    const bodies = this.core.bodies;
    const c = bodies.qc[b];
    const s = bodies.qs[b];
    return { x: c * p.x - s * p.y + bodies.px[b], y: s * p.x + c * p.y + bodies.py[b] };
  }

  getLocalPoint(worldPoint: Vec2): Vec2 {
    const b = this.check();
    const p = checkCoordinates('worldPoint', worldPoint);
    const bodies = this.core.bodies;
    const c = bodies.qc[b];
    const s = bodies.qs[b];
    const dx = p.x - bodies.px[b];
    const dy = p.y - bodies.py[b];
    return { x: c * dx + s * dy, y: -s * dx + c * dy };
  }

  getWorldVector(localVector: Vec2): Vec2 {
    const b = this.check();
    const v = checkCoordinates('localVector', localVector);
    const bodies = this.core.bodies;
    const c = bodies.qc[b];
    const s = bodies.qs[b];
    return { x: c * v.x - s * v.y, y: s * v.x + c * v.y };
  }

  getLocalVector(worldVector: Vec2): Vec2 {
    const b = this.check();
    const v = checkCoordinates('worldVector', worldVector);
    const bodies = this.core.bodies;
    const c = bodies.qc[b];
    const s = bodies.qs[b];
    return { x: c * v.x + s * v.y, y: -s * v.x + c * v.y };
  }

  /** Velocity of a world point attached to the body. */
  getLinearVelocityAt(worldPoint: Vec2): Vec2 {
    const b = this.check();
    const p = checkCoordinates('worldPoint', worldPoint);
    const bodies = this.core.bodies;
    const s = b * BodyState.STRIDE;
    const w = bodies.state[s + BodyState.W];
    return {
      x: bodies.state[s + BodyState.VX] - w * (p.y - bodies.cy[b]),
      y: bodies.state[s + BodyState.VY] + w * (p.x - bodies.cx[b]),
    };
  }

  /**
   * Attaches a shape made by `Shape.*` with the options `def` and returns its handle. A concave shape
   * (`Shape.concave`) attaches each of its convex pieces with `def`, as shapes of this body that never
   * collide with one another, and returns their handles in the order of `concave.pieces`; a chain
   * (`Shape.chain`, static and kinematic bodies only) likewise its segments, in the order of
   * `chain.segments`. Everything is checked first: a call that throws leaves the world as it was.
   */
  createShape(geometry: Concave | Chain, def?: ShapeDef): ShapeHandle[];
  createShape(geometry: Geometry, def?: ShapeDef): ShapeHandle;
  createShape(geometry: Geometry | Concave | Chain, def?: ShapeDef): ShapeHandle | ShapeHandle[];
  createShape(geometry: Geometry | Concave | Chain, def?: ShapeDef): ShapeHandle | ShapeHandle[] {
    this.unlocked();
    return attachShapes(this.handles, this, geometry, def);
  }

  destroyShape(shape: ShapeHandle): void {
    this.unlocked();
    detachShape(this.handles, this, shape);
  }
}
