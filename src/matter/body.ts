import type { Body as FulcrumBody } from '../api/body';
import { fail } from '../core/errors';
import { Bounds, type MatterBounds } from './bounds';
import { Common } from './common';
import { type MatterVector, Vector } from './vector';
import { type MatterVertex, Vertices } from './vertices';

/**
 * A matter.js body: a plain object with matter's fields, kept current by the engine after each
 * update. `position` is the centre of mass; `velocity` is in px per 1000/60 ms whatever the delta;
 * `angle` turns clockwise on a y-down screen.
 */
export interface MatterBody {
  id: number;
  type: 'body';
  label: string;
  parts: MatterBody[];
  parent: MatterBody;
  plugin: Record<string, unknown>;
  angle: number;
  vertices: MatterVertex[];
  position: MatterVector;
  force: MatterVector;
  torque: number;
  velocity: MatterVector;
  angularVelocity: number;
  speed: number;
  angularSpeed: number;
  isSensor: boolean;
  isStatic: boolean;
  isSleeping: boolean;
  sleepThreshold: number;
  density: number;
  restitution: number;
  friction: number;
  frictionStatic: number;
  frictionAir: number;
  collisionFilter: { category: number; mask: number; group: number };
  slop: number;
  timeScale: number;
  render: Record<string, unknown> & { visible: boolean; sprite: Record<string, unknown> };
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
  bounds: MatterBounds;
  chamfer: { radius: number | number[] } | null;
  circleRadius: number;
  positionPrev: MatterVector;
  anglePrev: number;
  area: number;
  mass: number;
  inverseMass: number;
  inertia: number;
  inverseInertia: number;
  deltaTime: number;
  /** the Fulcrum body that simulates it while it is in an engine's world (not enumerable) */
  _fulcrum?: FulcrumBody | null;
  /** what changed since the engine last built the body's Fulcrum body (not enumerable) */
  _stale?: Stale;
  /** a chamfered rectangle's exact shape (Bodies.rectangle; not enumerable), until its vertices change */
  _rounded?: { corners: MatterVector[]; radius: number } | null;
}

/** What `Body.create` takes: any of a body's fields, and its outline as plain points. */
export type BodyOptions = Omit<Partial<MatterBody>, 'vertices' | 'parts' | 'render' | 'collisionFilter'> & {
  vertices?: MatterVector[];
  parts?: MatterBody[];
  /** matter's look: any of fillStyle, strokeStyle, lineWidth, opacity, visible, sprite (in part) */
  render?: Partial<Omit<MatterBody['render'], 'sprite'>> & {
    sprite?: Partial<MatterBody['render']['sprite']>;
  };
  collisionFilter?: Partial<MatterBody['collisionFilter']>;
};

/** What a body's Fulcrum body has to be given again at the next update. */
export enum Stale {
  NO = 0,
  /** mass or inertia */
  MASS = 1,
  /** outline or parts (and so mass) */
  SHAPES = 2,
}

/** Marks what the engine has to rebuild of a body in its world (the most of what was asked). */
function markStale(body: MatterBody, stale: Stale): void {
  if (body._fulcrum && (body._stale ?? Stale.NO) < stale) body._stale = stale;
  if (body.parent !== body && body.parent) markStale(body.parent, stale);
}

/** Seconds per matter velocity unit: matter's velocities are per 1000/60 ms. */
export const VELOCITY_TO_SI = 60;

function defaults(): Partial<MatterBody> {
  return {
    type: 'body',
    label: 'Body',
    plugin: {},
    angle: 0,
    position: { x: 0, y: 0 },
    force: { x: 0, y: 0 },
    torque: 0,
    velocity: { x: 0, y: 0 },
    angularVelocity: 0,
    speed: 0,
    angularSpeed: 0,
    isSensor: false,
    isStatic: false,
    isSleeping: false,
    sleepThreshold: 60,
    density: 0.001,
    restitution: 0,
    friction: 0.1,
    frictionStatic: 0.5,
    frictionAir: 0.01,
    collisionFilter: { category: 0x0001, mask: 0xffffffff, group: 0 },
    slop: 0.05,
    timeScale: 1,
    render: {
      visible: true,
      opacity: 1,
      strokeStyle: null,
      fillStyle: null,
      lineWidth: null,
      sprite: { xScale: 1, yScale: 1, xOffset: 0, yOffset: 0 },
    },
    events: null,
    chamfer: null,
    circleRadius: 0,
    anglePrev: 0,
    deltaTime: 1000 / 60,
  };
}

/** `value`, or a FulcrumError naming `name` where matter would let NaN or Infinity into the world. */
function finite(name: string, value: number): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) fail(name, value, 'a finite number');
  return value;
}

export const Body = {
  _inertiaScale: 4,
  _nextCollidingGroupId: 1,
  _nextNonCollidingGroupId: -1,
  _nextCategory: 0x0001,

  /** A body from `options` (matter's defaults for the rest); vertices default to a 40 px square. */
  create(options: BodyOptions = {}): MatterBody {
    const body = Common.extend(true, defaults(), options) as unknown as MatterBody;
    body.id = options.id ?? Common.nextId();
    Object.defineProperty(body, '_fulcrum', { value: null, writable: true, enumerable: false });
    Object.defineProperty(body, '_stale', { value: Stale.NO, writable: true, enumerable: false });
    const points = options.vertices ?? Vertices.fromPath('L 0 0 L 40 0 L 40 40 L 0 40');
    body.parent = body;
    body.parts = [body];
    body.bounds = Bounds.create();
    body.positionPrev = Vector.clone(body.position);
    body.anglePrev = body.angle;
    const angle = body.angle;
    body.angle = 0;
    Body.setVertices(body, points);
    if (options.parts && options.parts.length > 0) Body.setParts(body, options.parts, true);
    if (angle !== 0) Body.setAngle(body, angle);
    if (options.isStatic) Body.setStatic(body, true);
    if (options.mass !== undefined) Body.setMass(body, options.mass);
    if (options.inertia !== undefined) Body.setInertia(body, options.inertia);
    body.render.fillStyle ??= body.isStatic
      ? '#14151f'
      : Common.choose(['#f19648', '#f5d259', '#f55a3c', '#063e7b', '#ececd1']);
    body.render.strokeStyle ??= body.isStatic ? '#555' : '#ccc';
    body.render.lineWidth ??= 0;
    // a sprite is drawn about the body's position: its offset is where that lies within the bounds
    const { min, max } = body.bounds;
    const sprite = body.render.sprite as { xOffset: number; yOffset: number };
    sprite.xOffset += -(min.x - body.position.x) / (max.x - min.x);
    sprite.yOffset += -(min.y - body.position.y) / (max.y - min.y);
    return body;
  },

  /** A group id for collisionFilter.group: bodies of a positive group always collide, of a negative one never. */
  nextGroup(isNonColliding?: boolean): number {
    return isNonColliding ? Body._nextNonCollidingGroupId-- : Body._nextCollidingGroupId++;
  },

  /** The next unused category bit, for collisionFilter.category. */
  nextCategory(): number {
    Body._nextCategory <<= 1;
    return Body._nextCategory;
  },

  /** Sets one property (`settings` a name) or several (an object of them) through their setters. */
  set(body: MatterBody, settings: string | Record<string, unknown>, value?: unknown): void {
    const entries = typeof settings === 'string' ? [[settings, value] as const] : Object.entries(settings);
    for (const [key, v] of entries) {
      switch (key) {
        case 'isStatic':
          Body.setStatic(body, v as boolean);
          break;
        case 'isSleeping':
          body.isSleeping = v as boolean;
          body._fulcrum?.setAwake(!(v as boolean));
          break;
        case 'mass':
          Body.setMass(body, v as number);
          break;
        case 'density':
          Body.setDensity(body, v as number);
          break;
        case 'inertia':
          Body.setInertia(body, v as number);
          break;
        case 'vertices':
          Body.setVertices(body, v as MatterVector[]);
          break;
        case 'position':
          Body.setPosition(body, v as MatterVector);
          break;
        case 'angle':
          Body.setAngle(body, v as number);
          break;
        case 'velocity':
          Body.setVelocity(body, v as MatterVector);
          break;
        case 'angularVelocity':
          Body.setAngularVelocity(body, v as number);
          break;
        case 'parts':
          Body.setParts(body, v as MatterBody[]);
          break;
        default:
          (body as unknown as Record<string, unknown>)[key] = v;
      }
    }
  },

  setStatic(body: MatterBody, isStatic: boolean): void {
    for (const part of body.parts) part.isStatic = isStatic;
    if (isStatic) {
      body.velocity = { x: 0, y: 0 };
      body.angularVelocity = 0;
      body.inverseMass = 0;
      body.inverseInertia = 0;
    } else {
      body.inverseMass = 1 / body.mass;
      body.inverseInertia = 1 / body.inertia;
    }
    body._fulcrum?.setType(isStatic ? 'static' : 'dynamic');
  },

  setMass(body: MatterBody, mass: number): void {
    finite('mass', mass);
    const moment = body.inertia / (body.mass / 6);
    body.inertia = moment * (mass / 6);
    body.inverseInertia = 1 / body.inertia;
    body.mass = mass;
    body.inverseMass = 1 / mass;
    body.density = mass / body.area;
    markStale(body, Stale.MASS);
  },

  setDensity(body: MatterBody, density: number): void {
    Body.setMass(body, density * body.area);
    body.density = density;
  },

  /** Infinity keeps the body from turning. */
  setInertia(body: MatterBody, inertia: number): void {
    body.inertia = inertia;
    body.inverseInertia = 1 / inertia;
    markStale(body, Stale.MASS);
  },

  /** Replaces the body's outline (world points): its area, mass and inertia follow at its density. */
  setVertices(body: MatterBody, points: readonly MatterVector[]): void {
    if (body._rounded) body._rounded = null;
    body.vertices =
      points.length > 0 && (points[0] as MatterVertex).body === body
        ? (points as MatterVertex[])
        : Vertices.create(points, body);
    body.area = Vertices.area(body.vertices);
    body.mass = body.density * body.area;
    body.inverseMass = 1 / body.mass;
    const centre = Vertices.centre(body.vertices);
    Vertices.translate(body.vertices, centre, -1);
    body.inertia = Body._inertiaScale * Vertices.inertia(body.vertices, body.mass);
    body.inverseInertia = 1 / body.inertia;
    Vertices.translate(body.vertices, body.position);
    Bounds.update(body.bounds, body.vertices, body.velocity);
    markStale(body, Stale.SHAPES);
  },

  /** Makes `parts` the body's parts (a compound body): its position becomes their centre of mass. */
  setParts(body: MatterBody, parts: readonly MatterBody[], autoHull = true): void {
    const list = parts.filter((p) => p !== body);
    body.parts = [body, ...list];
    if (list.length === 0) return;
    for (const part of list) part.parent = body;
    if (autoHull) {
      const hull = Vertices.hull(list.flatMap((p) => p.vertices));
      const centre = Vertices.centre(hull);
      Vertices.clockwiseSort(hull);
      body.vertices = Vertices.create(hull, body);
      body.position = { x: centre.x, y: centre.y };
    }
    let mass = 0;
    let area = 0;
    let cx = 0;
    let cy = 0;
    for (const part of list) {
      mass += part.mass;
      area += part.area;
      cx += part.position.x * part.mass;
      cy += part.position.y * part.mass;
    }
    let inertia = 0;
    for (const part of list) {
      const dx = part.position.x - cx / mass;
      const dy = part.position.y - cy / mass;
      inertia += part.inertia + part.mass * (dx * dx + dy * dy);
    }
    body.position = { x: cx / mass, y: cy / mass };
    body.positionPrev = Vector.clone(body.position);
    body.area = area;
    body.mass = mass;
    body.inverseMass = 1 / mass;
    body.density = mass / area;
    body.inertia = inertia;
    body.inverseInertia = 1 / inertia;
    Bounds.update(body.bounds, body.vertices, body.velocity);
    markStale(body, Stale.SHAPES);
  },

  /** Moves the body (all its parts) so that its centre of mass is at `position`. */
  setPosition(body: MatterBody, position: MatterVector, updateVelocity?: boolean): void {
    const dx = finite('position.x', position.x) - body.position.x;
    const dy = finite('position.y', position.y) - body.position.y;
    if (updateVelocity) {
      body.positionPrev = Vector.clone(body.position);
      Body.setVelocity(body, { x: dx, y: dy });
    } else {
      body.positionPrev.x += dx;
      body.positionPrev.y += dy;
    }
    for (const part of body.parts) {
      if (part !== body) {
        part.position.x += dx;
        part.position.y += dy;
      }
      Vertices.translate(part.vertices, { x: dx, y: dy });
      Bounds.update(part.bounds, part.vertices, body.velocity);
    }
    body.position = { x: body.position.x + dx, y: body.position.y + dy };
    body._fulcrum?.setPosition(body.position);
  },

  /** Turns the body (all its parts) about its centre of mass to `angle`. */
  setAngle(body: MatterBody, angle: number, updateVelocity?: boolean): void {
    const delta = finite('angle', angle) - body.angle;
    if (updateVelocity) {
      body.anglePrev = body.angle;
      Body.setAngularVelocity(body, delta);
    } else {
      body.anglePrev += delta;
    }
    for (const part of body.parts) {
      Vertices.rotate(part.vertices, delta, body.position);
      if (part !== body) Vector.rotateAbout(part.position, delta, body.position, part.position);
      part.angle += part === body ? 0 : delta;
      Bounds.update(part.bounds, part.vertices, body.velocity);
    }
    body.angle = angle;
    body._fulcrum?.setAngle(angle);
  },

  /** Sets the velocity, in px per 1000/60 ms. */
  setVelocity(body: MatterBody, velocity: MatterVector): void {
    body.velocity = { x: finite('velocity.x', velocity.x), y: finite('velocity.y', velocity.y) };
    body.speed = Vector.magnitude(body.velocity);
    body.positionPrev = { x: body.position.x - velocity.x, y: body.position.y - velocity.y };
    body._fulcrum?.setLinearVelocity({ x: velocity.x * VELOCITY_TO_SI, y: velocity.y * VELOCITY_TO_SI });
  },

  getVelocity(body: MatterBody): MatterVector {
    return Vector.clone(body.velocity);
  },

  getSpeed(body: MatterBody): number {
    return body.speed;
  },

  setSpeed(body: MatterBody, speed: number): void {
    Body.setVelocity(body, Vector.mult(Vector.normalise(body.velocity), speed));
  },

  /** Sets the angular velocity, in radians per 1000/60 ms. */
  setAngularVelocity(body: MatterBody, velocity: number): void {
    body.angularVelocity = finite('angularVelocity', velocity);
    body.angularSpeed = Math.abs(velocity);
    body.anglePrev = body.angle - velocity;
    body._fulcrum?.setAngularVelocity(velocity * VELOCITY_TO_SI);
  },

  getAngularVelocity(body: MatterBody): number {
    return body.angularVelocity;
  },

  getAngularSpeed(body: MatterBody): number {
    return body.angularSpeed;
  },

  setAngularSpeed(body: MatterBody, speed: number): void {
    Body.setAngularVelocity(body, Common.sign(body.angularVelocity) * speed);
  },

  translate(body: MatterBody, translation: MatterVector, updateVelocity?: boolean): void {
    Body.setPosition(body, Vector.add(body.position, translation), updateVelocity);
  },

  /** Turns the body by `rotation`, about `point` (default: its centre of mass). */
  rotate(body: MatterBody, rotation: number, point?: MatterVector, updateVelocity?: boolean): void {
    if (point) {
      const moved = Vector.rotateAbout(body.position, rotation, point);
      Body.setPosition(body, moved, updateVelocity);
    }
    Body.setAngle(body, body.angle + rotation, updateVelocity);
  },

  /** Scales the body by `scaleX`, `scaleY` about `point` (default: its centre of mass). */
  scale(body: MatterBody, scaleX: number, scaleY: number, point?: MatterVector): void {
    const origin = point ?? body.position;
    for (const part of body.parts) {
      Vertices.scale(part.vertices, scaleX, scaleY, origin);
      if (part.circleRadius) part.circleRadius *= Math.sqrt(Math.abs(scaleX * scaleY));
    }
    const position = {
      x: origin.x + (body.position.x - origin.x) * scaleX,
      y: origin.y + (body.position.y - origin.y) * scaleY,
    };
    body.position = position;
    Body.setVertices(body, body.vertices);
    Bounds.update(body.bounds, body.vertices, body.velocity);
  },

  /** Adds `force` (matter's units: mass times px per ms²) at the world `position`; cleared after each update. */
  applyForce(body: MatterBody, position: MatterVector, force: MatterVector): void {
    body.force.x += finite('force.x', force.x);
    body.force.y += finite('force.y', force.y);
    body.torque += (position.x - body.position.x) * force.y - (position.y - body.position.y) * force.x;
  },
};
