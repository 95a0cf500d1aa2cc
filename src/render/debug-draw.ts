/**
 * The debug-draw interface: the engine describes what it holds (shapes, AABBs, contacts, joints,
 * velocities, centres of mass) through a handful of callbacks, and any renderer draws them.
 * `drawWorld` walks a world through its public handles and reads the engine's columns read-only;
 * it never changes the world, so drawing can never affect the simulation.
 */
import type { Body } from '../api/body';
import type { ShapeHandle } from '../api/shape';
import type { World } from '../api/world';
import { ShapeKind } from '../geometry/types';
import type { MouseJoint } from '../joints/mouse-joint';
import type { Transform, Vec2 } from '../math/vec2';
import { BodyFlag, BodyKind, BodyState } from '../store/body-store';
import { ContactFlag } from '../store/contact-store';
import { ShapeFlag } from '../store/shape-store';

/** A colour as 0xRRGGBB. */
export type Color = number;

/** How a shape is drawn. The object is reused between calls: read it, do not keep it. */
export interface ShapeStyle {
  /** fill colour, or null to draw the outline only (wireframe) */
  fill: Color | null;
  fillAlpha: number;
  stroke: Color;
  /** the shape being drawn and its body, so a renderer can look up its own styles */
  shape: ShapeHandle;
  body: Body;
}

/**
 * The callbacks a renderer implements. Shapes come in the body's local frame with the transform to
 * apply (possibly interpolated); everything else comes in world coordinates (metres, y up).
 * Sizes in pixels are screen sizes, independent of the zoom.
 */
export interface DebugDraw {
  /** Convex polygon; `radius` > 0 rounds it. Vertices are local, counter-clockwise. */
  drawPolygon(xf: Transform, vertices: readonly Vec2[], radius: number, style: ShapeStyle): void;
  /** Circle, with a line from the centre to the rim that shows its rotation. */
  drawCircle(xf: Transform, center: Vec2, radius: number, style: ShapeStyle): void;
  drawCapsule(xf: Transform, p1: Vec2, p2: Vec2, radius: number, style: ShapeStyle): void;
  /** A line between two world points. */
  drawLine(p1: Vec2, p2: Vec2, color: Color): void;
  /** A dot of `size` screen pixels at a world point. */
  drawPoint(p: Vec2, size: number, color: Color): void;
  /** An axis-aligned box (world). */
  drawAABB(minX: number, minY: number, maxX: number, maxY: number, color: Color): void;
  /** A frame: a short red x axis and green y axis. */
  drawTransform(xf: Transform): void;
  /**
   * Optional: called once per body before its shapes, with the transform it is drawn at.
   * Return true when the renderer drew the body itself (a sprite), and its shapes are skipped.
   */
  drawBody?(body: Body, xf: Transform): boolean;
}

/** What `drawWorld` draws. */
export interface DebugDrawFlags {
  shapes: boolean;
  /** outlines only */
  wireframe: boolean;
  joints: boolean;
  aabbs: boolean;
  contacts: boolean;
  contactNormals: boolean;
  velocities: boolean;
  centersOfMass: boolean;
  /** tint sleeping bodies grey */
  sleeping: boolean;
}

export const defaultDebugDrawFlags: Readonly<DebugDrawFlags> = Object.freeze({
  shapes: true,
  wireframe: false,
  joints: true,
  aabbs: false,
  contacts: false,
  contactNormals: false,
  velocities: false,
  centersOfMass: false,
  sleeping: true,
});

/** Hooks that let a renderer change where and how bodies are drawn. */
export interface DrawWorldOptions {
  /**
   * The transform a body is drawn at (for example interpolated between the last two steps).
   * Fill `out` and return it. By default bodies are drawn where they are.
   */
  transformOf?(body: Body, out: Transform): Transform;
  /** A body's colour; undefined keeps the default palette. */
  colorOf?(body: Body): Color | undefined;
}

export const colors = Object.freeze({
  static: 0x5f7a66,
  kinematic: 0x5b7fc7,
  bullet: 0xf08a6c,
  sensor: 0xe8d48b,
  sleepingTint: 0x80848c,
  joint: 0x7fd3e6,
  jointAnchor: 0xffffff,
  mouse: 0x9be870,
  aabb: 0xd070e0,
  contactPoint: 0xff5a5a,
  speculativePoint: 0x9aa0aa,
  contactNormal: 0xfff07a,
  velocity: 0x5ce0a0,
});

/** Dynamic bodies cycle through these, by body slot. */
export const dynamicPalette: readonly Color[] = Object.freeze([
  0xe6a04b, 0xd9695f, 0x6fb3d9, 0x8ccf7e, 0xc98bd9, 0xe3cf6a, 0x6fd1c0, 0xe08fb0,
]);

/** Mixes two colours: t = 0 gives `a`, t = 1 gives `b`. */
export function mixColor(a: Color, b: Color, t: number): Color {
  const r = ((a >> 16) & 255) * (1 - t) + ((b >> 16) & 255) * t;
  const g = ((a >> 8) & 255) * (1 - t) + ((b >> 8) & 255) * t;
  const bl = (a & 255) * (1 - t) + (b & 255) * t;
  return (Math.round(r) << 16) | (Math.round(g) << 8) | Math.round(bl);
}

/** Darker or lighter: f < 1 darkens, f > 1 lightens. */
export function scaleColor(c: Color, f: number): Color {
  const ch = (v: number) => Math.max(0, Math.min(255, Math.round(v * f)));
  return (ch((c >> 16) & 255) << 16) | (ch((c >> 8) & 255) << 8) | ch(c & 255);
}

/** The default colour of a body: by type, bullets apart, dynamic bodies from the palette. */
export function defaultBodyColor(world: World, body: Body): Color {
  const bodies = world.core.bodies;
  const b = body.slot;
  const kind = bodies.kind[b];
  if (kind === BodyKind.STATIC) return colors.static;
  if (kind === BodyKind.KINEMATIC) return colors.kinematic;
  if ((bodies.flags[b] & BodyFlag.BULLET) !== 0) return colors.bullet;
  return dynamicPalette[b % dynamicPalette.length];
}

/** Fills `xf` with where a body is drawn. */
function drawnTransform(world: World, body: Body, options: DrawWorldOptions | undefined, xf: Transform) {
  if (options?.transformOf) return options.transformOf(body, xf);
  const bodies = world.core.bodies;
  const b = body.slot;
  xf.p.x = bodies.px[b];
  xf.p.y = bodies.py[b];
  xf.q.c = bodies.qc[b];
  xf.q.s = bodies.qs[b];
  return xf;
}

/**
 * Maps a world point on body `b` (as the body is now) to where it is drawn: identical unless the
 * renderer draws bodies elsewhere, as interpolation does (its transform is then written in `drawnXf`).
 */
function mapPoint(
  world: World,
  body: Body,
  options: DrawWorldOptions | undefined,
  p: Vec2,
  out: Vec2,
  drawnXf: Transform,
): Vec2 {
  if (!options?.transformOf) {
    out.x = p.x;
    out.y = p.y;
    return out;
  }
  const bodies = world.core.bodies;
  const b = body.slot;
  const c = bodies.qc[b];
  const s = bodies.qs[b];
  const dx = p.x - bodies.px[b];
  const dy = p.y - bodies.py[b];
  const lx = c * dx + s * dy;
  const ly = -s * dx + c * dy;
  const xf = options.transformOf(body, drawnXf);
  out.x = xf.q.c * lx - xf.q.s * ly + xf.p.x;
  out.y = xf.q.s * lx + xf.q.c * ly + xf.p.y;
  return out;
}

function drawShapes(world: World, draw: DebugDraw, flags: DebugDrawFlags, options?: DrawWorldOptions) {
  const core = world.core;
  const bodies = core.bodies;
  const shapes = core.shapes;
  const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const style = { fill: 0, fillAlpha: 1, stroke: 0 } as ShapeStyle;
  const pA: Vec2 = { x: 0, y: 0 };
  const pB: Vec2 = { x: 0, y: 0 };
  for (let b = 0; b < bodies.slotCount; b++) {
    if (bodies.alive[b] === 0) continue;
    const body = world.handles.bodies[b]!;
    drawnTransform(world, body, options, xf);
    if (draw.drawBody?.(body, xf)) continue;
    let color = options?.colorOf?.(body) ?? defaultBodyColor(world, body);
    const sleeping = bodies.kind[b] === BodyKind.DYNAMIC && (bodies.flags[b] & BodyFlag.AWAKE) === 0;
    if (sleeping && flags.sleeping) color = mixColor(color, colors.sleepingTint, 0.6);
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
      const g = shapes.geometry[s]!;
      const sensor = (shapes.flags[s] & ShapeFlag.SENSOR) !== 0;
      style.body = body;
      style.shape = world.handles.shapes[s]!;
      if (sensor) {
        style.fill = flags.wireframe ? null : colors.sensor;
        style.fillAlpha = 0.18;
        style.stroke = colors.sensor;
      } else {
        style.fill = flags.wireframe ? null : color;
        style.fillAlpha = 1;
        style.stroke = flags.wireframe ? color : scaleColor(color, 0.65);
      }
      switch (g.kind) {
        case ShapeKind.CIRCLE:
          draw.drawCircle(xf, g.center, g.radius, style);
          break;
        case ShapeKind.CAPSULE:
          draw.drawCapsule(xf, g.center1, g.center2, g.radius, style);
          break;
        case ShapeKind.POLYGON:
          draw.drawPolygon(xf, g.vertices, g.radius, style);
          break;
        case ShapeKind.SEGMENT: {
          transformPoint(xf, g.point1, pA);
          transformPoint(xf, g.point2, pB);
          draw.drawLine(pA, pB, sensor ? colors.sensor : color);
          if (g.oneSided) drawFrontTick(pA, pB, draw, sensor ? colors.sensor : color);
          break;
        }
      }
    }
  }
}

/**
 * A chain segment's front: a tick from its middle along its normal (right of the way from a to b), a
 * fifth of its length and at most ONE_SIDED_TICK long.
 */
function drawFrontTick(a: Vec2, b: Vec2, draw: DebugDraw, color: Color): void {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const length = Math.sqrt(ex * ex + ey * ey);
  const tick = Math.min(0.2 * length, ONE_SIDED_TICK) / length;
  const mid = { x: 0.5 * (a.x + b.x), y: 0.5 * (a.y + b.y) };
  draw.drawLine(mid, { x: mid.x + tick * ey, y: mid.y - tick * ex }, color);
}

/** Longest front tick of a chain segment, in metres. */
const ONE_SIDED_TICK = 0.15;

function transformPoint(xf: Transform, p: Vec2, out: Vec2): Vec2 {
  const x = xf.q.c * p.x - xf.q.s * p.y + xf.p.x;
  const y = xf.q.s * p.x + xf.q.c * p.y + xf.p.y;
  out.x = x;
  out.y = y;
  return out;
}

function drawAABBs(world: World, draw: DebugDraw) {
  const core = world.core;
  const shapes = core.shapes;
  for (let s = 0; s < shapes.slotCount; s++) {
    if (shapes.alive[s] === 0) continue;
    draw.drawAABB(shapes.minX[s], shapes.minY[s], shapes.maxX[s], shapes.maxY[s], colors.aabb);
  }
}

function drawContacts(world: World, draw: DebugDraw, flags: DebugDrawFlags, options?: DrawWorldOptions) {
  const core = world.core;
  const contacts = core.contacts;
  const normalLength = 0.3;
  const drawnXf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const pA: Vec2 = { x: 0, y: 0 };
  const pB: Vec2 = { x: 0, y: 0 };
  const pC: Vec2 = { x: 0, y: 0 };
  for (let c = 0; c < contacts.slotCount; c++) {
    if (contacts.alive[c] === 0) continue;
    const f = contacts.flags[c];
    if ((f & ContactFlag.TOUCHING) === 0 || (f & ContactFlag.SENSOR) !== 0) continue;
    const bodyA = world.handles.bodies[contacts.bodyA[c]]!;
    const n = contacts.pointCount[c];
    for (let i = 0; i < n; i++) {
      const k = c * 2 + i;
      pA.x = contacts.pointX[k];
      pA.y = contacts.pointY[k];
      mapPoint(world, bodyA, options, pA, pC, drawnXf);
      if (flags.contacts) {
        draw.drawPoint(pC, 5, contacts.separation[k] > 0 ? colors.speculativePoint : colors.contactPoint);
      }
      if (flags.contactNormals) {
        pB.x = pC.x + contacts.normalX[c] * normalLength;
        pB.y = pC.y + contacts.normalY[c] * normalLength;
        draw.drawLine(pC, pB, colors.contactNormal);
      }
    }
  }
}

function drawVelocitiesAndCenters(
  world: World,
  draw: DebugDraw,
  flags: DebugDrawFlags,
  options?: DrawWorldOptions,
) {
  const core = world.core;
  const bodies = core.bodies;
  const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const center: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const tip: Vec2 = { x: 0, y: 0 };
  for (let b = 0; b < bodies.slotCount; b++) {
    if (bodies.alive[b] === 0 || bodies.kind[b] === BodyKind.STATIC) continue;
    const body = world.handles.bodies[b]!;
    drawnTransform(world, body, options, xf);
    transformPoint(xf, { x: bodies.lcx[b], y: bodies.lcy[b] }, center.p);
    center.q.c = xf.q.c;
    center.q.s = xf.q.s;
    if (flags.centersOfMass) draw.drawTransform(center);
    if (flags.velocities) {
      const st = b * BodyState.STRIDE;
      const vx = bodies.state[st + BodyState.VX];
      const vy = bodies.state[st + BodyState.VY];
      // a tenth of a second of travel
      tip.x = center.p.x + vx * 0.1;
      tip.y = center.p.y + vy * 0.1;
      draw.drawLine(center.p, tip, colors.velocity);
    }
  }
}

function drawJoints(world: World, draw: DebugDraw, options?: DrawWorldOptions) {
  const drawnXf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  for (const joint of world.joints) {
    const bodyA = joint.bodyA;
    const bodyB = joint.bodyB;
    const a = mapPoint(world, bodyA, options, joint.anchorA, { x: 0, y: 0 }, drawnXf);
    const b = mapPoint(world, bodyB, options, joint.anchorB, { x: 0, y: 0 }, drawnXf);
    if (joint.type === 'mouse') {
      // by type, not instanceof: the render entry may be a separate bundle (CommonJS)
      const target = (joint as MouseJoint).target;
      draw.drawLine(target, b, colors.mouse);
      draw.drawPoint(target, 6, colors.mouse);
      draw.drawPoint(b, 5, colors.mouse);
      continue;
    }
    const xfA = drawnTransform(world, bodyA, options, { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } });
    const xfB = drawnTransform(world, bodyB, options, { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } });
    if (joint.type === 'distance') {
      draw.drawLine(a, b, colors.joint);
    } else {
      // lines from the bodies to their anchors show the structure; a static body's would only clutter
      if (bodyA.type !== 'static') draw.drawLine(xfA.p, a, colors.joint);
      draw.drawLine(a, b, colors.joint);
      if (bodyB.type !== 'static') draw.drawLine(xfB.p, b, colors.joint);
    }
    draw.drawPoint(a, 5, colors.jointAnchor);
    draw.drawPoint(b, 5, colors.jointAnchor);
  }
}

/**
 * Draws a world through `draw`: shapes first, then AABBs, joints, contacts, velocities and centres
 * of mass, as `flags` ask. Reads the world and never changes it.
 */
export function drawWorld(
  world: World,
  draw: DebugDraw,
  flags: DebugDrawFlags = defaultDebugDrawFlags,
  options?: DrawWorldOptions,
): void {
  if (flags.shapes) drawShapes(world, draw, flags, options);
  if (flags.aabbs) drawAABBs(world, draw);
  if (flags.joints) drawJoints(world, draw, options);
  if (flags.contacts || flags.contactNormals) drawContacts(world, draw, flags, options);
  if (flags.velocities || flags.centersOfMass) drawVelocitiesAndCenters(world, draw, flags, options);
}
