import { checkBoolean, checkKnownKeys, FulcrumError, fail } from '../core/errors';
import { checkRoom } from '../core/index-bound';
import { checkCoordinates, checkDensity, checkNonNegativeRate } from '../core/limits';
import { rayCastGeometry, testPoint } from '../geometry/raycast';
import {
  type Chain,
  type Concave,
  type Geometry,
  isChain,
  isConcave,
  isGeometry,
  makeRayHit,
  ShapeKind,
} from '../geometry/types';
import type { AABB } from '../math/aabb';
import { makeTransform, type Vec2 } from '../math/vec2';
import { BodyKind } from '../store/body-store';
import { ShapeFlag } from '../store/shape-store';
import { replaceShapeGeometry } from '../world/world-edits';
import type { Body } from './body';
import type { WorldHandles } from './handles';

export interface Filter {
  /** the categories this shape belongs to (bits) */
  categoryBits: number;
  /** the categories this shape collides with (bits) */
  maskBits: number;
  /** shapes sharing a non-zero group always collide (> 0) or never collide (< 0) */
  groupIndex: number;
}

export interface ShapeDef {
  density?: number;
  friction?: number;
  restitution?: number;
  isSensor?: boolean;
  filter?: Partial<Filter>;
  enableContactEvents?: boolean;
  enableSensorEvents?: boolean;
  enableHitEvents?: boolean;
  userData?: unknown;
}

const SHAPE_DEF_KEYS = [
  'density',
  'friction',
  'restitution',
  'isSensor',
  'filter',
  'enableContactEvents',
  'enableSensorEvents',
  'enableHitEvents',
  'userData',
] as const;

const FILTER_KEYS = ['categoryBits', 'maskBits', 'groupIndex'] as const;

export interface RayCastResult {
  point: Vec2;
  normal: Vec2;
  fraction: number;
}

function checkBits(argument: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < 0 || value > 0xffffffff) {
    fail(argument, value, 'an integer in [0, 0xffffffff]');
  }
  return value;
}

/** Validates a filter and fills defaults: category 1, mask all, group 0. */
function checkFilter(argument: string, filter: unknown): Filter {
  if (typeof filter !== 'object' || filter === null) fail(argument, filter, 'an object');
  checkKnownKeys(argument, filter, FILTER_KEYS);
  const f = filter as Partial<Filter>;
  const groupIndex = f.groupIndex === undefined ? 0 : f.groupIndex;
  if (!Number.isInteger(groupIndex) || groupIndex < -0x80000000 || groupIndex > 0x7fffffff) {
    fail(`${argument}.groupIndex`, groupIndex, 'a 32-bit integer');
  }
  return {
    categoryBits: checkBits(`${argument}.categoryBits`, f.categoryBits === undefined ? 1 : f.categoryBits),
    maskBits: checkBits(`${argument}.maskBits`, f.maskBits === undefined ? 0xffffffff : f.maskBits),
    groupIndex,
  };
}

/** Validated shape definition with every default filled in. */
export interface ResolvedShapeDef {
  density: number;
  friction: number;
  restitution: number;
  flags: number;
  filter: Filter;
  userData: unknown;
}

export function resolveShapeDef(def: ShapeDef | undefined): ResolvedShapeDef {
  // undefined is "not given"; null, like any other value that is not an object, is refused
  const d = def === undefined ? {} : def;
  if (typeof d !== 'object' || d === null) fail('def', def, 'an object');
  checkKnownKeys('def', d, SHAPE_DEF_KEYS);
  let flags = 0;
  if (d.isSensor !== undefined && checkBoolean('isSensor', d.isSensor)) flags |= ShapeFlag.SENSOR;
  if (d.enableContactEvents === undefined || checkBoolean('enableContactEvents', d.enableContactEvents)) {
    flags |= ShapeFlag.CONTACT_EVENTS;
  }
  if (d.enableSensorEvents === undefined || checkBoolean('enableSensorEvents', d.enableSensorEvents)) {
    flags |= ShapeFlag.SENSOR_EVENTS;
  }
  if (d.enableHitEvents !== undefined && checkBoolean('enableHitEvents', d.enableHitEvents)) {
    flags |= ShapeFlag.HIT_EVENTS;
  }
  return {
    density: d.density === undefined ? 1 : checkDensity('density', d.density),
    friction: d.friction === undefined ? 0.6 : checkNonNegativeRate('friction', d.friction),
    restitution: d.restitution === undefined ? 0 : checkNonNegativeRate('restitution', d.restitution),
    flags,
    filter:
      d.filter === undefined
        ? { categoryBits: 1, maskBits: 0xffffffff, groupIndex: 0 }
        : checkFilter('filter', d.filter),
    userData: d.userData,
  };
}

/** A shape handle: valid until the shape or its body is destroyed. */
export class ShapeHandle {
  /** @internal */
  readonly slot: number;
  /** @internal */
  readonly generation: number;
  readonly body: Body;
  userData: unknown;
  /** @internal the geometry, until setGeometry replaces it */
  current: Geometry;

  /** @internal created by Body.createShape */
  constructor(body: Body, slot: number, generation: number, geometry: Geometry, userData: unknown) {
    this.body = body;
    this.slot = slot;
    this.generation = generation;
    this.current = geometry;
    this.userData = userData;
  }

  /** The shape's geometry in its body's frame (immutable; setGeometry gives the shape another). */
  get geometry(): Geometry {
    return this.current;
  }

  /** @internal */
  check(): number {
    const shapes = this.body.core.shapes;
    if (shapes.alive[this.slot] === 0 || shapes.generation[this.slot] !== this.generation) {
      throw new FulcrumError('shape has been destroyed');
    }
    return this.slot;
  }

  private unlocked(): number {
    if (this.body.core.locked) throw new FulcrumError('the world is locked during step()');
    return this.check();
  }

  get isValid(): boolean {
    const shapes = this.body.core.shapes;
    return shapes.alive[this.slot] === 1 && shapes.generation[this.slot] === this.generation;
  }

  get type(): Geometry['type'] {
    this.check();
    return this.current.type;
  }

  get friction(): number {
    return this.body.core.shapes.friction[this.check()];
  }

  set friction(value: number) {
    const s = this.unlocked();
    this.body.core.shapes.friction[s] = checkNonNegativeRate('friction', value);
  }

  get restitution(): number {
    return this.body.core.shapes.restitution[this.check()];
  }

  set restitution(value: number) {
    const s = this.unlocked();
    this.body.core.shapes.restitution[s] = checkNonNegativeRate('restitution', value);
  }

  get density(): number {
    return this.body.core.shapes.density[this.check()];
  }

  /** Changing the density updates the body's mass at once. */
  set density(value: number) {
    const s = this.unlocked();
    const core = this.body.core;
    core.shapes.density[s] = checkDensity('density', value);
    core.updateMass(core.shapes.body[s]);
    core.wake(core.shapes.body[s]);
  }

  get filter(): Filter {
    const s = this.check();
    const shapes = this.body.core.shapes;
    return {
      categoryBits: shapes.categoryBits[s],
      maskBits: shapes.maskBits[s],
      groupIndex: shapes.groupIndex[s],
    };
  }

  /** A new filter takes effect next step: the shape's contacts are rebuilt. */
  set filter(value: Partial<Filter>) {
    const s = this.unlocked();
    const f = checkFilter('filter', value);
    const shapes = this.body.core.shapes;
    const category = shapes.categoryBits[s];
    const mask = shapes.maskBits[s];
    const group = shapes.groupIndex[s];
    shapes.categoryBits[s] = f.categoryBits;
    shapes.maskBits[s] = f.maskBits;
    shapes.groupIndex[s] = f.groupIndex;
    // the same filter again changes nothing: its contacts go on (no end and begin, no wake)
    if (shapes.categoryBits[s] === category && shapes.maskBits[s] === mask && shapes.groupIndex[s] === group)
      return;
    this.resetContacts(s);
  }

  get isSensor(): boolean {
    return (this.body.core.shapes.flags[this.check()] & ShapeFlag.SENSOR) !== 0;
  }

  set isSensor(value: boolean) {
    const s = this.unlocked();
    checkBoolean('isSensor', value);
    const shapes = this.body.core.shapes;
    if (value === ((shapes.flags[s] & ShapeFlag.SENSOR) !== 0)) return;
    // the pairs end as what they were (a sensor's overlaps end as sensor events)
    this.resetContacts(s);
    if (value) shapes.flags[s] |= ShapeFlag.SENSOR;
    else shapes.flags[s] &= ~ShapeFlag.SENSOR;
  }

  get enableHitEvents(): boolean {
    return (this.body.core.shapes.flags[this.check()] & ShapeFlag.HIT_EVENTS) !== 0;
  }

  set enableHitEvents(value: boolean) {
    const s = this.unlocked();
    checkBoolean('enableHitEvents', value);
    const shapes = this.body.core.shapes;
    if (value) shapes.flags[s] |= ShapeFlag.HIT_EVENTS;
    else shapes.flags[s] &= ~ShapeFlag.HIT_EVENTS;
  }

  /**
   * Gives the shape another geometry, e.g. new polygon points: `shape.setGeometry(Shape.polygon(points))`.
   * The body's mass, centre of mass and inertia follow at once; the shape's contacts end (touching
   * ones report their ends) and are found again from the new outline in the next step.
   */
  setGeometry(geometry: Geometry): void {
    const s = this.unlocked();
    const core = this.body.core;
    const b = core.shapes.body[s];
    checkGeometryFor(core.bodies.kind[b], geometry);
    replaceShapeGeometry(core, s, geometry);
    this.current = geometry;
    core.updateMass(b);
    core.wake(b);
  }

  private resetContacts(s: number): void {
    const core = this.body.core;
    core.destroyShapeContacts(s, true, true);
    core.broadPhase.bufferMove(core.shapes.proxyKey[s]);
  }

  /** Tight world AABB as of the last step or move. */
  getAABB(): AABB {
    const s = this.check();
    const shapes = this.body.core.shapes;
    return {
      lowerBound: { x: shapes.minX[s], y: shapes.minY[s] },
      upperBound: { x: shapes.maxX[s], y: shapes.maxY[s] },
    };
  }

  testPoint(point: Vec2): boolean {
    const s = this.check();
    const p = checkCoordinates('point', point);
    const core = this.body.core;
    return testPoint(this.current, core.fillTransform(core.shapes.body[s], makeTransform()), p.x, p.y);
  }

  /** Ray from `origin` along `translation`; null when it misses (see geometry/raycast.ts for the rules). */
  rayCast(origin: Vec2, translation: Vec2): RayCastResult | null {
    const s = this.check();
    const o = checkCoordinates('origin', origin);
    const t = checkCoordinates('translation', translation);
    const core = this.body.core;
    const xf = core.fillTransform(core.shapes.body[s], makeTransform());
    const hit = makeRayHit();
    if (!rayCastGeometry(this.current, xf, o.x, o.y, t.x, t.y, hit)) return null;
    return {
      point: { x: hit.pointX, y: hit.pointY },
      normal: { x: hit.normalX, y: hit.normalY },
      fraction: hit.fraction,
    };
  }
}

/**
 * @internal Throws unless `geometry` is a geometry a body of kind `kind` can hold; `makers` names the
 * factories the caller takes.
 */
export function checkGeometryFor(
  kind: BodyKind,
  geometry: unknown,
  makers = 'Shape.circle/box/polygon/capsule/segment',
): asserts geometry is Geometry {
  if (!isGeometry(geometry)) fail('geometry', geometry, `a geometry made by ${makers}`);
  if (geometry.kind === ShapeKind.SEGMENT && kind === BodyKind.DYNAMIC) {
    throw new FulcrumError('geometry: a segment can only be attached to a static or kinematic body');
  }
}

const MAKERS = 'Shape.circle/box/polygon/capsule/segment/concave/chain';

/**
 * @internal What Body.createShape checks before it changes anything, for a body of kind `kind` in a
 * world holding `shapeCount` shapes: the geometries to attach (a concave shape's pieces or a chain's
 * segments, or the one geometry) and the definition with its defaults. fulcrum/worker checks a call
 * with it on the calling thread.
 */
export function checkShapes(
  kind: BodyKind,
  geometry: unknown,
  def: ShapeDef | undefined,
  shapeCount: number,
): { parts: readonly Geometry[] | null; geometry: Geometry | null; def: ResolvedShapeDef } {
  const parts = isConcave(geometry) ? geometry.pieces : isChain(geometry) ? geometry.segments : null;
  if (parts !== null) {
    if (isChain(geometry) && kind === BodyKind.DYNAMIC) {
      throw new FulcrumError('geometry: a chain can only be attached to a static or kinematic body');
    }
    const d = resolveShapeDef(def);
    checkRoom('shapes', shapeCount + parts.length - 1);
    return { parts, geometry: null, def: d };
  }
  checkGeometryFor(kind, geometry, MAKERS);
  const d = resolveShapeDef(def);
  checkRoom('shapes', shapeCount);
  return { parts: null, geometry, def: d };
}

/**
 * @internal Body.createShape: validates everything, then adds the shape (or a concave shape's pieces,
 * in order) to the body's list and the broad phase.
 */
export function attachShapes(
  handles: WorldHandles,
  body: Body,
  geometry: Geometry | Concave | Chain,
  def: ShapeDef | undefined,
): ShapeHandle | ShapeHandle[] {
  const b = body.check();
  const core = handles.core;
  const checked = checkShapes(core.bodies.kind[b], geometry, def, core.shapes.liveCount);
  const d = checked.def;
  if (checked.parts !== null) {
    const shapes = checked.parts.map((part) => addShape(handles, body, b, part, d));
    core.updateMass(b);
    core.wake(b);
    return shapes;
  }
  const shape = addShape(handles, body, b, checked.geometry!, d);
  core.updateMass(b);
  core.wake(b);
  return shape;
}

/** Adds a checked shape to body slot `b` and the broad phase; the caller then updates the body's mass. */
function addShape(
  handles: WorldHandles,
  body: Body,
  b: number,
  geometry: Geometry,
  d: ResolvedShapeDef,
): ShapeHandle {
  const core = handles.core;
  const shapes = core.shapes;
  const s = shapes.allocate();
  shapes.body[s] = b;
  shapes.setGeometry(s, geometry);
  shapes.flags[s] = d.flags;
  shapes.density[s] = d.density;
  shapes.friction[s] = d.friction;
  shapes.restitution[s] = d.restitution;
  shapes.categoryBits[s] = d.filter.categoryBits;
  shapes.maskBits[s] = d.filter.maskBits;
  shapes.groupIndex[s] = d.filter.groupIndex;
  shapes.next[s] = core.bodies.shapeHead[b];
  core.bodies.shapeHead[b] = s;
  core.createProxy(s, true);
  const handle = new ShapeHandle(body, s, shapes.generation[s], geometry, d.userData);
  handles.shapes[s] = handle;
  return handle;
}

/** @internal Body.destroyShape: ends the shape's contacts without events and takes it off the body. */
export function detachShape(handles: WorldHandles, body: Body, shape: ShapeHandle): void {
  const b = body.check();
  if (!(shape instanceof ShapeHandle) || shape.body !== body) fail('shape', shape, 'a shape of this body');
  const s = shape.check();
  handles.dispatcher.settle();
  const core = handles.core;
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
  handles.shapes[s] = undefined;
  core.updateMass(b);
  core.wake(b);
}
