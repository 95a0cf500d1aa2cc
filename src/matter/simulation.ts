import type { Body as FulcrumBody } from '../api/body';
import type { World as FulcrumWorld } from '../api/world';
import { Limits } from '../core/limits';
import { Shape } from '../geometry/shapes';
import type { Geometry } from '../geometry/types';
import type { Joint } from '../joints/joint';
import { arcTangent2 } from '../math/arc-tangent';
import { makeRot } from '../math/rot';
import { type MatterBody, Stale, VELOCITY_TO_SI } from './body';
import { Composite, type MatterComposite } from './composite';
import type { MatterConstraint } from './constraint';
import { Events } from './events';
import type { MatterVector } from './vector';

/*
 * The link between a matter engine's plain objects and the Fulcrum world that simulates them: each
 * matter body in the world has a Fulcrum body whose origin is the matter body's position (its centre
 * of mass) and whose shapes are its parts, in matter's pixels with y down. After each step the matter
 * bodies are written from the Fulcrum bodies (readBack).
 */

/** A matter body in the world and its Fulcrum body. */
export interface Simulated {
  body: MatterBody;
  fulcrum: FulcrumBody;
  /** each part's outline in the body's frame (x, y of each vertex in turn), in the order of body.parts */
  outlines: Float64Array[];
  /** each part's position in the body's frame (compound bodies) */
  offsets: MatterVector[];
  /** the fields a program may set directly that the Fulcrum body was last given */
  frictionAir: number;
  surfaces: SurfaceFields[];
  /**
   * the Fulcrum body's rotation when the matter body's angle was last written, and that angle: the
   * next read-back adds the turn since (matter's angle keeps counting turns, where the rotation's own
   * angle would wrap at pi)
   */
  c: number;
  s: number;
  angle: number;
}

/** A part's contact fields as its Fulcrum shapes have them. */
interface SurfaceFields {
  friction: number;
  frictionStatic: number;
  restitution: number;
  isSensor: boolean;
  category: number;
  mask: number;
  group: number;
}

export interface JointRecord {
  joint: Joint | null;
  /** what the joint was made from: a change to any of them makes it again */
  bodyA: MatterBody | null;
  bodyB: MatterBody | null;
  length: number;
  stiffness: number;
  damping: number;
  /** the world points of ends without a body */
  worldA: MatterVector | null;
  worldB: MatterVector | null;
}

export interface FulcrumLink {
  world: FulcrumWorld;
  /** a static body without shapes at the origin: the world end of a constraint with one body */
  anchor: FulcrumBody;
  /** the world's matter constraints, each with its Fulcrum joint (null while an end has no body in the world) and the bodies it was made for */
  joints: Map<MatterConstraint, JointRecord>;
  /** the simulated bodies, in the order they joined the world */
  list: Simulated[];
  bodies: Map<MatterBody, Simulated>;
  /** scratch for Body.readState */
  state: Float64Array;
  /** how many shape pairs touch in each active matter pair (see collision-pairs.ts) */
  touching: Map<object, number>;
}

/**
 * Fulcrum's damping that takes matter's `frictionAir` off the velocity every 1000/60 ms. The world
 * damps each of its 4 substeps by 1 / (1 + h d): d = ((1 - frictionAir)^(-1/4) - 1) / h, h = 1/240 s.
 */
function dampingOf(frictionAir: number): number {
  const kept = 1 - Math.min(Math.max(frictionAir, 0), 0.999);
  return 4 * VELOCITY_TO_SI * (1 / Math.sqrt(Math.sqrt(kept)) - 1);
}

/** A friction or restitution as the engine takes it: a negative one or NaN is 0 (matter would not check it). */
function coefficient(value: number): number {
  return value > 0 ? Math.min(value, Limits.RATE) : 0;
}

/**
 * matter's friction as a Coulomb coefficient. matter takes a fixed amount of speed off a sliding body
 * each update, about 2.5 times its `friction` in px per update per update, whatever the load: under
 * its default gravity (0.278 px per update per update) that is a coefficient of about 9 times
 * `friction`, measured against matter-js 0.20 with boxes slid on flat ground (friction 0.01, 0.05 and
 * 0.1 stop as a coefficient of 0.13, 0.53 and 0.93 would) and on slopes (the default 0.1 holds a box,
 * creeping, up to 40 degrees). Pairs take the smaller of their two parts' (frictionMixing 'min').
 */
const FRICTION_SCALE = 9;

function frictionOf(part: MatterBody): number {
  return coefficient(FRICTION_SCALE * part.friction);
}

type Rounded = { corners: MatterVector[]; radius: number };

/**
 * A chamfered convex outline as the engine's exact shape in the body's frame (the frame its corners
 * were recorded in, when the body was made): the polygon of its arcs' centres rounded by the radius;
 * a capsule where the arcs take whole sides (a pill), a circle where they take all of them.
 */
function roundedShape({ corners, radius }: Rounded): Geometry {
  const points: MatterVector[] = [];
  const near = 1e-6 * radius;
  for (const p of corners) {
    if (!points.some((o) => Math.abs(o.x - p.x) <= near && Math.abs(o.y - p.y) <= near)) points.push(p);
  }
  if (points.length === 1) return Shape.circle(radius, points[0]);
  let doubleArea = 0;
  let extent = 0;
  let ends = [points[0], points[1]];
  for (let i = 0; i < points.length; i++) {
    const p = points[i];
    const q = points[(i + 1) % points.length];
    doubleArea += p.x * q.y - q.x * p.y;
    for (let j = i + 1; j < points.length; j++) {
      const dx = points[j].x - p.x;
      const dy = points[j].y - p.y;
      const d = dx * dx + dy * dy;
      if (d > extent) {
        extent = d;
        ends = [p, points[j]];
      }
    }
  }
  if (points.length === 2 || Math.abs(doubleArea) <= 1e-9 * extent)
    return Shape.capsule(ends[0], ends[1], radius);
  return Shape.polygon(points, radius);
}

/** Turns world point `p` into the frame of a body at `origin` turned by angle (c, s). */
function toLocal(p: MatterVector, origin: MatterVector, c: number, s: number): MatterVector {
  const dx = p.x - origin.x;
  const dy = p.y - origin.y;
  return { x: c * dx + s * dy, y: -s * dx + c * dy };
}

/**
 * Gives the Fulcrum body shapes for the matter body's parts, and matter's mass and inertia (matter
 * weighs a circle as the polygon it draws, and gives every body four times its inertia), and records
 * the parts' outlines in the body's frame.
 */
function buildShapes(sim: Simulated): void {
  const { body, fulcrum } = sim;
  const { c, s } = makeRot(body.angle);
  const origin = body.position;
  const parts = body.parts.length > 1 ? body.parts.slice(1) : [body];
  for (const part of parts) {
    const def = {
      friction: frictionOf(part),
      restitution: coefficient(part.restitution),
      isSensor: part.isSensor,
      filter: {
        categoryBits: part.collisionFilter.category >>> 0,
        maskBits: part.collisionFilter.mask >>> 0,
        groupIndex: part.collisionFilter.group,
      },
      userData: part,
    };
    const density = densityOf(part);
    if (part.circleRadius > 0) {
      // a true circle
      fulcrum.createShape(Shape.circle(part.circleRadius, toLocal(part.position, origin, c, s)), {
        ...def,
        density,
      });
    } else if (part._rounded && body.parts.length === 1) {
      fulcrum.createShape(roundedShape(part._rounded), { ...def, density });
    } else {
      const outline = part.vertices.map((p) => toLocal(p, origin, c, s));
      if (outline.length <= 8) fulcrum.createShape(Shape.polygon(outline), { ...def, density });
      else fulcrum.createShape(Shape.concave(outline), { ...def, density });
    }
  }
  sim.surfaces = body.parts.map(surfaceOf);
  sim.outlines = body.parts.map((part) => {
    const outline = new Float64Array(2 * part.vertices.length);
    part.vertices.forEach((p, i) => {
      const q = toLocal(p, origin, c, s);
      outline[2 * i] = q.x;
      outline[2 * i + 1] = q.y;
    });
    return outline;
  });
  sim.offsets = body.parts.map((part) => toLocal(part.position, origin, c, s));
  applyMass(sim);
  body._stale = Stale.NO;
}

/**
 * A part's density for its Fulcrum shapes (mass over area; a circle weighs the polygon matter draws),
 * held to the engine's range: the body's mass is matter's anyway (applyMass), this only places it.
 */
function densityOf(part: MatterBody): number {
  const density = part.mass / part.area;
  return density > 0
    ? Math.min(Math.max(density, Limits.MIN_DENSITY), Limits.MAX_DENSITY)
    : Limits.MIN_DENSITY;
}

function surfaceOf(part: MatterBody): SurfaceFields {
  const filter = part.collisionFilter;
  return {
    friction: part.friction,
    frictionStatic: part.frictionStatic,
    restitution: part.restitution,
    isSensor: part.isSensor,
    category: filter.category,
    mask: filter.mask,
    group: filter.group,
  };
}

/**
 * matter's mass and inertia on the Fulcrum body, about the matter body's position (held to the
 * engine's accepted ranges: matter takes any number a program sets; a massless body keeps its shapes').
 */
function applyMass({ body, fulcrum }: Simulated): void {
  const fixed = body.inertia === Number.POSITIVE_INFINITY;
  fulcrum.setFixedRotation(fixed);
  if (!(body.mass > 0)) return;
  const inertia = fixed || !(body.inertia > 0) ? fulcrum.inertia || 1 : body.inertia;
  fulcrum.setMassData({
    mass: Math.min(Math.max(body.mass, Limits.MIN_MASS), Limits.MAX_MASS),
    inertia: Math.min(Math.max(inertia, Limits.MIN_INERTIA), Limits.MAX_INERTIA),
    center: { x: 0, y: 0 },
  });
}

/** The Fulcrum body of matter body `body`, at its position and angle, with its velocities and damping. */
function simulate(link: FulcrumLink, body: MatterBody): Simulated {
  const damping = dampingOf(body.frictionAir);
  const fulcrum = link.world.createBody({
    type: body.isStatic ? 'static' : 'dynamic',
    position: body.position,
    angle: body.angle,
    linearVelocity: { x: body.velocity.x * VELOCITY_TO_SI, y: body.velocity.y * VELOCITY_TO_SI },
    angularVelocity: body.angularVelocity * VELOCITY_TO_SI,
    linearDamping: damping,
    angularDamping: damping,
    userData: body,
  });
  const sim: Simulated = {
    body,
    fulcrum,
    outlines: [],
    offsets: [],
    frictionAir: body.frictionAir,
    surfaces: [],
    ...makeRot(body.angle),
    angle: body.angle,
  };
  buildShapes(sim);
  body._fulcrum = fulcrum;
  return sim;
}

/**
 * Brings the Fulcrum body up to what the program changed since the last update: new shapes and mass
 * for a body whose outline or parts changed (Body.setVertices, setParts, scale; at its current position
 * and angle, its joints kept), its mass for Body.setMass & co., and the fields a program sets directly
 * on the object (frictionAir; a part's friction, restitution, isSensor, collisionFilter).
 */
export function refresh(sim: Simulated): void {
  const { body, fulcrum } = sim;
  if (body._stale === Stale.SHAPES) {
    for (const shape of fulcrum.shapes) fulcrum.destroyShape(shape);
    fulcrum.setTransform(body.position, body.angle);
    buildShapes(sim);
  } else if (body._stale === Stale.MASS) {
    applyMass(sim);
    body._stale = Stale.NO;
  }
  if (body.frictionAir !== sim.frictionAir) {
    sim.frictionAir = body.frictionAir;
    const damping = dampingOf(body.frictionAir);
    fulcrum.setLinearDamping(damping);
    fulcrum.setAngularDamping(damping);
  }
  const parts = body.parts;
  const first = parts.length > 1 ? 1 : 0;
  for (let k = first; k < parts.length; k++) {
    const part = parts[k];
    const was = sim.surfaces[k];
    const filter = part.collisionFilter;
    if (
      part.friction === was.friction &&
      part.frictionStatic === was.frictionStatic &&
      part.restitution === was.restitution &&
      part.isSensor === was.isSensor &&
      filter.category === was.category &&
      filter.mask === was.mask &&
      filter.group === was.group
    ) {
      continue;
    }
    sim.surfaces[k] = surfaceOf(part);
    for (const shape of fulcrum.shapes) {
      if (shape.userData !== part) continue;
      shape.friction = frictionOf(part);
      shape.restitution = coefficient(part.restitution);
      shape.isSensor = part.isSensor;
      shape.filter = {
        categoryBits: filter.category >>> 0,
        maskBits: filter.mask >>> 0,
        groupIndex: filter.group,
      };
    }
  }
}

/** Creates the Fulcrum bodies of the world's new matter bodies and destroys those of removed ones. */
export function syncMembers(link: FulcrumLink, world: MatterComposite): void {
  const present = new Set(Composite.allBodies(world));
  const kept: Simulated[] = [];
  for (const sim of link.list) {
    if (present.has(sim.body)) {
      kept.push(sim);
      continue;
    }
    link.world.destroyBody(sim.fulcrum);
    link.bodies.delete(sim.body);
    sim.body._fulcrum = null;
  }
  link.list = kept;
  for (const body of present) {
    if (link.bodies.has(body)) continue;
    const sim = simulate(link, body);
    link.list.push(sim);
    link.bodies.set(body, sim);
  }
}

/**
 * Writes the Fulcrum body's state into the matter body: pose, vertices, bounds (widened by the
 * velocity, as matter's), velocities, sleep. A body asleep since the last update has not moved.
 */
export function readBack(sim: Simulated, state: Float64Array): void {
  const { body, fulcrum } = sim;
  fulcrum.readState(state);
  const awake = state[7] === 1;
  if (!awake && body.isSleeping) return;
  const cx = state[0];
  const cy = state[1];
  const c = state[2];
  const s = state[3];
  // the turn since the angle was last written (from the angle a program set since, if it did)
  const from = body.angle === sim.angle ? sim : makeRot(body.angle);
  // deterministic: the angle feeds back into the world (constraint points, Body.setAngle)
  const turned = arcTangent2(from.c * s - from.s * c, from.c * c + from.s * s);
  const angle = body.angle + turned;
  sim.c = c;
  sim.s = s;
  sim.angle = angle;
  const position = body.position;
  body.positionPrev.x = position.x;
  body.positionPrev.y = position.y;
  body.anglePrev = body.angle;
  const vx = state[4] / VELOCITY_TO_SI;
  const vy = state[5] / VELOCITY_TO_SI;
  body.velocity.x = vx;
  body.velocity.y = vy;
  body.angularVelocity = state[6] / VELOCITY_TO_SI;
  body.speed = Math.sqrt(vx * vx + vy * vy);
  body.angularSpeed = Math.abs(body.angularVelocity);
  if (!awake !== body.isSleeping) {
    body.isSleeping = !awake;
    Events.trigger(body, body.isSleeping ? 'sleepStart' : 'sleepEnd');
  }
  const parts = body.parts;
  for (let k = 0; k < parts.length; k++) {
    const part = parts[k];
    const outline = sim.outlines[k];
    const vertices = part.vertices;
    let minX = Number.POSITIVE_INFINITY;
    let minY = Number.POSITIVE_INFINITY;
    let maxX = Number.NEGATIVE_INFINITY;
    let maxY = Number.NEGATIVE_INFINITY;
    for (let i = 0, n = outline.length >> 1; i < n; i++) {
      const px = outline[2 * i];
      const py = outline[2 * i + 1];
      const x = cx + c * px - s * py;
      const y = cy + s * px + c * py;
      const vertex = vertices[i];
      vertex.x = x;
      vertex.y = y;
      if (x < minX) minX = x;
      if (x > maxX) maxX = x;
      if (y < minY) minY = y;
      if (y > maxY) maxY = y;
    }
    const bounds = part.bounds;
    bounds.min.x = vx < 0 ? minX + vx : minX;
    bounds.max.x = vx > 0 ? maxX + vx : maxX;
    bounds.min.y = vy < 0 ? minY + vy : minY;
    bounds.max.y = vy > 0 ? maxY + vy : maxY;
    if (part !== body) {
      const o = sim.offsets[k];
      part.position.x = cx + c * o.x - s * o.y;
      part.position.y = cy + s * o.x + c * o.y;
      part.angle += turned;
    }
  }
  position.x = cx;
  position.y = cy;
  body.angle = angle;
}
