import type { Body as FulcrumBody } from '../api/body';
import type { ContactBeginEvent, ContactEndEvent } from '../api/events';
import type { ShapeHandle } from '../api/shape';
import { World as FulcrumWorld } from '../api/world';
import { Shape } from '../geometry/shapes';
import type { Geometry } from '../geometry/types';
import type { Joint } from '../joints/joint';
import { MouseJoint } from '../joints/mouse-joint';
import { makeRot } from '../math/rot';
import { type MatterBody, VELOCITY_TO_SI } from './body';
import { Bounds } from './bounds';
import { Common } from './common';
import { Composite, type MatterComposite } from './composite';
import { Constraint, type MatterConstraint } from './constraint';
import { Events } from './events';
import type { MatterVector } from './vector';
import { Vertices } from './vertices';

/*
 * The engine runs a Fulcrum world in matter's own coordinates: pixels, y down (so Fulcrum's angles,
 * counter-clockwise in the numbers, turn clockwise on the screen as matter's do). Fulcrum takes
 * seconds where matter takes milliseconds: a matter acceleration of 1 px/ms² is 1e6 px/s², a matter
 * velocity of 1 px per 1000/60 ms is 60 px/s.
 */

/** Fulcrum's tolerances for a world whose unit is matter's pixel: about 100 px to the metre. */
const PIXELS_PER_METRE = 100;
/**
 * How many of matter's constraint corrections a soft constraint's period reflects per update: the
 * exponent that fits the periods matter.js 0.20 gives a mass on a spring of stiffness 0.005 to 0.05
 * (34.4, 17.2 and 11.2 updates at 0.005, 0.02 and 0.05: 6.7, 6.7 and 6.3 times the stiffness for
 * (omega dt)^2). Its own count of passes would be four.
 */
const SPRING_PASSES = 6.7;
/** px/ms² to px/s² */
const ACCELERATION_TO_SI = 1e6;

/** A collision pair as matter.js reports it in its collision events. */
export interface MatterPair {
  id: string;
  bodyA: MatterBody;
  bodyB: MatterBody;
  collision: {
    collided: boolean;
    bodyA: MatterBody;
    bodyB: MatterBody;
    parentA: MatterBody;
    parentB: MatterBody;
    normal: MatterVector;
    tangent: MatterVector;
    depth: number;
    supports: MatterVector[];
  };
  isActive: boolean;
  isSensor: boolean;
  timeCreated: number;
  timeUpdated: number;
  friction: number;
  frictionStatic: number;
  restitution: number;
  slop: number;
}

export interface MatterEngine {
  world: MatterComposite;
  gravity: { x: number; y: number; scale: number };
  timing: {
    timeScale: number;
    timestamp: number;
    lastDelta: number;
    lastElapsed: number;
    lastUpdatesPerFrame?: number;
  };
  enableSleeping: boolean;
  positionIterations: number;
  velocityIterations: number;
  constraintIterations: number;
  pairs: { table: Record<string, MatterPair>; list: MatterPair[] };
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
  plugin: Record<string, unknown>;
  /** the Fulcrum world underneath and what links it to the matter objects (not enumerable) */
  _fulcrum: FulcrumLink;
}

interface JointRecord {
  joint: Joint | null;
  bodyA: MatterBody | null;
  bodyB: MatterBody | null;
}

interface FulcrumLink {
  world: FulcrumWorld;
  /** a static body without shapes at the origin: the world end of a constraint with one body */
  anchor: FulcrumBody;
  /** the world's matter constraints, each with its Fulcrum joint (null while an end has no body in the world) and the bodies it was made for */
  joints: Map<MatterConstraint, JointRecord>;
  /** the matter bodies simulated, and their Fulcrum bodies */
  bodies: Map<MatterBody, FulcrumBody>;
  /** each part's outline in its parent's frame, to move its vertices after a step */
  outlines: Map<MatterBody, MatterVector[]>;
  begun: ContactBeginEvent[];
  ended: ContactEndEvent[];
}

/** Fulcrum's linear damping that takes matter's `frictionAir` off the velocity every 1000/60 ms. */
function dampingOf(frictionAir: number): number {
  const kept = 1 - Math.min(Math.max(frictionAir, 0), 0.999);
  return VELOCITY_TO_SI * (1 / kept - 1);
}

function pairId(a: MatterBody, b: MatterBody): string {
  return a.id < b.id ? `A${a.id}B${b.id}` : `A${b.id}B${a.id}`;
}

type Rounded = { halfWidth: number; halfHeight: number; radius: number };

/**
 * A chamfered rectangle as the engine's exact shape, about its centre in its own frame: a rounded box,
 * a capsule when the radius takes a whole side, a circle when it takes both.
 */
function roundedShape({ halfWidth, halfHeight, radius }: Rounded): Geometry {
  const r = Math.min(radius, halfWidth, halfHeight);
  const a = halfWidth - r;
  const b = halfHeight - r;
  const flat = 1e-9 * Math.max(halfWidth, halfHeight);
  if (a <= flat && b <= flat) return Shape.circle(r);
  if (b <= flat) return Shape.capsule({ x: -a, y: 0 }, { x: a, y: 0 }, r);
  if (a <= flat) return Shape.capsule({ x: 0, y: -b }, { x: 0, y: b }, r);
  return Shape.polygon(
    [
      { x: -a, y: -b },
      { x: a, y: -b },
      { x: a, y: b },
      { x: -a, y: b },
    ],
    r,
  );
}

/** The area of a rectangle whose corners are rounded with `radius`. */
function roundedArea({ halfWidth, halfHeight, radius }: Rounded): number {
  const r = Math.min(radius, halfWidth, halfHeight);
  return 4 * halfWidth * halfHeight - (4 - Math.PI) * r * r;
}

/** The Fulcrum body of matter body `body`, built from its parts in its frame (centre of mass, angle). */
function createFulcrumBody(link: FulcrumLink, body: MatterBody): FulcrumBody {
  const damping = dampingOf(body.frictionAir);
  const fulcrum = link.world.createBody({
    type: body.isStatic ? 'static' : 'dynamic',
    position: body.position,
    angle: body.angle,
    linearVelocity: { x: body.velocity.x * VELOCITY_TO_SI, y: body.velocity.y * VELOCITY_TO_SI },
    angularVelocity: body.angularVelocity * VELOCITY_TO_SI,
    linearDamping: damping,
    angularDamping: damping,
    fixedRotation: body.inertia === Number.POSITIVE_INFINITY,
  });
  const { c, s } = makeRot(body.angle);
  const local = (p: MatterVector) => {
    const dx = p.x - body.position.x;
    const dy = p.y - body.position.y;
    return { x: c * dx + s * dy, y: -s * dx + c * dy };
  };
  const parts = body.parts.length > 1 ? body.parts.slice(1) : [body];
  for (const part of parts) {
    const def = {
      friction: part.friction,
      restitution: part.restitution,
      isSensor: part.isSensor,
      filter: {
        categoryBits: part.collisionFilter.category >>> 0,
        maskBits: part.collisionFilter.mask >>> 0,
        groupIndex: part.collisionFilter.group,
      },
      userData: part,
    };
    if (part.circleRadius > 0) {
      // a true circle, of matter's mass (matter weighs the polygon it draws)
      const density = part.mass / (Math.PI * part.circleRadius * part.circleRadius);
      fulcrum.createShape(Shape.circle(part.circleRadius, local(part.position)), { ...def, density });
      continue;
    }
    if (part._rounded && body.parts.length === 1) {
      fulcrum.createShape(roundedShape(part._rounded), {
        ...def,
        density: part.mass / roundedArea(part._rounded),
      });
      continue;
    }
    const outline = part.vertices.map(local);
    const density = part.density;
    if (outline.length <= 8) fulcrum.createShape(Shape.polygon(outline), { ...def, density });
    else fulcrum.createShape(Shape.concave(outline), { ...def, density });
  }
  for (const part of body.parts) link.outlines.set(part, part.vertices.map(local));
  Object.defineProperty(body, '_fulcrum', { value: fulcrum, writable: true, enumerable: false });
  return fulcrum;
}

/**
 * The Fulcrum joint of a matter constraint, or null while one of its bodies is not in the world.
 * Stiffness 0.9 and over is rigid: a revolute joint for length 0 (a pin), a distance joint (a rod)
 * otherwise. Softer is a distance spring of rest length `length` with matter's period. matter moves
 * the ends a share of the way to the rest length several times an update (constraint passes before
 * and after the collisions, and the last update's correction carried over), which acts on the
 * position's second difference like a spring with (omega dt)^2 = 1 - (1 - stiffness)^SPRING_PASSES,
 * dt = 1000/60 ms, whatever the masses.
 */
function createJoint(link: FulcrumLink, constraint: MatterConstraint): Joint | null {
  const end = (body: MatterBody | null, point: MatterVector) => {
    if (body === null) return { fulcrum: link.anchor, local: { x: point.x, y: point.y } };
    const fulcrum = link.bodies.get(body);
    if (!fulcrum) return null;
    const { c, s } = makeRot(body.angle);
    return { fulcrum, local: { x: c * point.x + s * point.y, y: -s * point.x + c * point.y } };
  };
  const a = end(constraint.bodyA, constraint.pointA);
  const b = end(constraint.bodyB, constraint.pointB);
  if (!a || !b || a.fulcrum === b.fulcrum) return null;
  const rigid = constraint.stiffness >= 0.9;
  const c = 1 - (1 - Math.min(constraint.stiffness, 1)) ** SPRING_PASSES;
  const hertz = (Math.sqrt(c) * VELOCITY_TO_SI) / (2 * Math.PI);
  if (constraint.bodyA === null && constraint.bodyB !== null && !rigid && constraint.length < 1) {
    // a soft pull of a body to a world point that moves (a mouse constraint's): a mouse joint,
    // whose target follows pointA (see syncConstraints)
    return link.world.createJoint({
      type: 'mouse',
      body: b.fulcrum,
      target: Constraint.pointBWorld(constraint),
      hertz,
      // a hundred times the body's weight under matter's default gravity (1000 px/s²): the pull is
      // the spring's, not a cap's
      maxForce: 1e5 * Math.max(b.fulcrum.mass, 1e-6),
    });
  }
  if (rigid && constraint.length === 0) {
    return link.world.createJoint({
      type: 'revolute',
      bodyA: a.fulcrum,
      bodyB: b.fulcrum,
      localAnchorA: a.local,
      localAnchorB: b.local,
    });
  }
  return link.world.createJoint({
    type: 'distance',
    bodyA: a.fulcrum,
    bodyB: b.fulcrum,
    localAnchorA: a.local,
    localAnchorB: b.local,
    length: constraint.length,
    enableSpring: !rigid,
    hertz: rigid ? 0 : hertz,
    dampingRatio: Math.min(constraint.damping, 1),
  });
}

/** Creates the Fulcrum bodies of the world's new matter bodies and destroys those of removed ones. */
function syncMembers(engine: MatterEngine): void {
  const link = engine._fulcrum;
  const present = new Set(Composite.allBodies(engine.world));
  for (const [body, fulcrum] of link.bodies) {
    if (present.has(body)) continue;
    link.world.destroyBody(fulcrum);
    link.bodies.delete(body);
    for (const part of body.parts) link.outlines.delete(part);
    body._fulcrum = null;
  }
  for (const body of present) {
    if (!link.bodies.has(body)) link.bodies.set(body, createFulcrumBody(link, body));
  }
  const constraints = new Set(Composite.allConstraints(engine.world));
  for (const [constraint, record] of link.joints) {
    if (constraints.has(constraint)) continue;
    if (record.joint?.isValid) link.world.destroyJoint(record.joint);
    link.joints.delete(constraint);
  }
  for (const constraint of constraints) {
    if (!link.joints.has(constraint)) link.joints.set(constraint, { joint: null, bodyA: null, bodyB: null });
  }
  // a joint goes with a destroyed body: syncConstraints makes it again if its bodies are back
  for (const record of link.joints.values()) if (record.joint && !record.joint.isValid) record.joint = null;
  Composite.setModified(engine.world, false, false, true);
}

/**
 * Keeps each constraint's joint in step with it before an update: made again when its bodies
 * changed (a mouse constraint grabbing or letting go), a mouse joint's target moved to `pointA`.
 */
function syncConstraints(link: FulcrumLink): void {
  for (const [constraint, record] of link.joints) {
    if (record.joint !== null && (record.bodyA !== constraint.bodyA || record.bodyB !== constraint.bodyB)) {
      if (record.joint.isValid) link.world.destroyJoint(record.joint);
      record.joint = null;
    }
    if (record.joint === null && (constraint.bodyA !== null || constraint.bodyB !== null)) {
      record.joint = createJoint(link, constraint);
      record.bodyA = constraint.bodyA;
      record.bodyB = constraint.bodyB;
    }
    if (record.joint instanceof MouseJoint) record.joint.setTarget(constraint.pointA);
  }
}

/** Writes the Fulcrum body's state back into the matter body: pose, vertices, bounds, velocities, sleep. */
function readBack(link: FulcrumLink, body: MatterBody, fulcrum: FulcrumBody): void {
  const centre = fulcrum.worldCenter;
  const angle = fulcrum.angle;
  const v = fulcrum.linearVelocity;
  body.positionPrev = { x: body.position.x, y: body.position.y };
  body.anglePrev = body.angle;
  body.velocity = { x: v.x / VELOCITY_TO_SI, y: v.y / VELOCITY_TO_SI };
  body.angularVelocity = fulcrum.angularVelocity / VELOCITY_TO_SI;
  body.speed = Math.sqrt(body.velocity.x * body.velocity.x + body.velocity.y * body.velocity.y);
  body.angularSpeed = Math.abs(body.angularVelocity);
  const wasSleeping = body.isSleeping;
  body.isSleeping = !fulcrum.isAwake && !body.isStatic;
  if (body.isSleeping !== wasSleeping) Events.trigger(body, body.isSleeping ? 'sleepStart' : 'sleepEnd');
  const turned = angle - body.angle;
  const { c, s } = makeRot(angle);
  for (const part of body.parts) {
    const outline = link.outlines.get(part);
    if (outline) {
      for (let i = 0; i < outline.length; i++) {
        const p = outline[i];
        part.vertices[i].x = centre.x + c * p.x - s * p.y;
        part.vertices[i].y = centre.y + s * p.x + c * p.y;
      }
    }
    if (part !== body) {
      const moved = Vertices.centre(part.vertices);
      part.position.x = moved.x;
      part.position.y = moved.y;
      part.angle += turned;
    }
    Bounds.update(part.bounds, part.vertices, body.velocity);
  }
  body.position.x = centre.x;
  body.position.y = centre.y;
  body.angle = angle;
}

/**
 * Turns each constraint's offsets with its bodies, as matter keeps them: by how far each moving body
 * turned in the update just read back (its angle less anglePrev). One pass over the constraints.
 */
function turnConstraintPoints(link: FulcrumLink): void {
  for (const constraint of link.joints.keys()) {
    turnWith(constraint.bodyA, constraint.pointA);
    turnWith(constraint.bodyB, constraint.pointB);
  }
}

function turnWith(body: MatterBody | null, point: MatterVector): void {
  if (body === null || body.isStatic) return;
  const turned = body.angle - body.anglePrev;
  if (turned === 0) return;
  const { c, s } = makeRot(turned);
  const x = point.x;
  point.x = c * x - s * point.y;
  point.y = s * x + c * point.y;
}

function makePair(event: ContactBeginEvent, timestamp: number): MatterPair {
  const a = (event.shapeA as ShapeHandle).userData as MatterBody;
  const b = (event.shapeB as ShapeHandle).userData as MatterBody;
  const normal = { x: event.normal.x, y: event.normal.y };
  return {
    id: pairId(a, b),
    bodyA: a,
    bodyB: b,
    collision: {
      collided: true,
      bodyA: a,
      bodyB: b,
      parentA: a.parent,
      parentB: b.parent,
      normal,
      tangent: { x: -normal.y, y: normal.x },
      depth: 0,
      supports: event.points.map((p) => ({ x: p.x, y: p.y })),
    },
    isActive: true,
    isSensor: a.isSensor || b.isSensor,
    timeCreated: timestamp,
    timeUpdated: timestamp,
    friction: Math.min(a.friction, b.friction),
    frictionStatic: Math.max(a.frictionStatic, b.frictionStatic),
    restitution: Math.max(a.restitution, b.restitution),
    slop: Math.max(a.slop, b.slop),
  };
}

/** matter.js's `Engine`: creates and updates a world. A plain, mutable module object. */
export const Engine = {
  create(options: Partial<Omit<MatterEngine, '_fulcrum'>> = {}): MatterEngine {
    const { world: given, ...settings } = options;
    const engine = Common.extend(
      {
        world: given ?? Composite.create({ label: 'World' }),
        gravity: { x: 0, y: 1, scale: 0.001 },
        timing: { timeScale: 1, timestamp: 0, lastDelta: 0, lastElapsed: 0 },
        enableSleeping: false,
        positionIterations: 6,
        velocityIterations: 4,
        constraintIterations: 2,
        pairs: { table: {}, list: [] },
        events: null,
        plugin: {},
      },
      settings,
    ) as unknown as MatterEngine;
    const world = new FulcrumWorld({
      lengthUnitsPerMeter: PIXELS_PER_METRE,
      enableSleep: engine.enableSleeping,
    });
    const link: FulcrumLink = {
      world,
      anchor: world.createBody(),
      joints: new Map(),
      bodies: new Map(),
      outlines: new Map(),
      begun: [],
      ended: [],
    };
    world.on('contactBegin', (event) => {
      link.begun.push(event);
    });
    world.on('contactEnd', (event) => {
      link.ended.push(event);
    });
    Object.defineProperty(engine, '_fulcrum', { value: link, enumerable: false });
    return engine;
  },

  /**
   * Moves the world on by `delta` milliseconds (default 1000/60) times `timing.timeScale`, and
   * triggers matter's events in matter's order: beforeUpdate, collisionStart, collisionActive,
   * collisionEnd, afterUpdate.
   */
  update(engine: MatterEngine, delta: number = Common._baseDelta): MatterEngine {
    const link = engine._fulcrum;
    const timing = engine.timing;
    const started = Common.now();
    const dt = delta * timing.timeScale;
    timing.timestamp += dt;
    timing.lastDelta = dt;
    const event = { timestamp: timing.timestamp, delta: dt };
    Events.trigger(engine, 'beforeUpdate', event);
    if (engine.world.isModified || link.bodies.size === 0) syncMembers(engine);
    syncConstraints(link);
    const world = link.world;
    world.enableSleep = engine.enableSleeping;
    const g = engine.gravity;
    world.gravity = { x: g.x * g.scale * ACCELERATION_TO_SI, y: g.y * g.scale * ACCELERATION_TO_SI };
    for (const [body, fulcrum] of link.bodies) {
      if (body.isStatic) continue;
      if (body.force.x !== 0 || body.force.y !== 0) {
        fulcrum.applyForce({ x: body.force.x * ACCELERATION_TO_SI, y: body.force.y * ACCELERATION_TO_SI });
      }
      if (body.torque !== 0) fulcrum.applyTorque(body.torque * ACCELERATION_TO_SI);
    }
    link.begun.length = 0;
    link.ended.length = 0;
    if (dt > 0) world.step(dt / 1000);
    for (const [body, fulcrum] of link.bodies) if (!body.isStatic) readBack(link, body, fulcrum);
    turnConstraintPoints(link);

    const pairs = engine.pairs;
    // the pairs active before this update and still active after it: built only when listened to
    const listensActive = (engine.events?.collisionActive?.length ?? 0) > 0;
    const collisionActive: MatterPair[] = listensActive ? pairs.list.slice() : [];
    const collisionStart: MatterPair[] = [];
    const collisionEnd: MatterPair[] = [];
    for (const begun of link.begun) {
      const pair = makePair(begun, timing.timestamp);
      const known = pairs.table[pair.id];
      if (known) {
        known.isActive = true;
        known.timeUpdated = timing.timestamp;
        known.collision = pair.collision;
        collisionStart.push(known);
      } else {
        pairs.table[pair.id] = pair;
        pairs.list.push(pair);
        collisionStart.push(pair);
      }
    }
    for (const ended of link.ended) {
      const a = (ended.shapeA as ShapeHandle).userData as MatterBody;
      const b = (ended.shapeB as ShapeHandle).userData as MatterBody;
      const id = pairId(a, b);
      const pair = pairs.table[id];
      if (!pair?.isActive) continue;
      pair.isActive = false;
      pair.timeUpdated = timing.timestamp;
      collisionEnd.push(pair);
      delete pairs.table[id];
    }
    if (collisionEnd.length > 0) pairs.list = pairs.list.filter((pair) => pair.isActive);
    if (collisionStart.length > 0)
      Events.trigger(engine, 'collisionStart', { pairs: collisionStart, ...event });
    if (listensActive) {
      const active = collisionActive.filter((pair) => pair.isActive);
      if (active.length > 0) Events.trigger(engine, 'collisionActive', { pairs: active, ...event });
    }
    if (collisionEnd.length > 0) Events.trigger(engine, 'collisionEnd', { pairs: collisionEnd, ...event });
    for (const body of link.bodies.keys()) {
      body.force.x = 0;
      body.force.y = 0;
      body.torque = 0;
    }
    timing.lastElapsed = Common.now() - started;
    Events.trigger(engine, 'afterUpdate', event);
    return engine;
  },

  /** Forgets the world's collision pairs. */
  clear(engine: MatterEngine): void {
    engine.pairs.table = {};
    engine.pairs.list = [];
  },
};
