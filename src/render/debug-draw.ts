/**
 * The debug-draw interface: the engine describes what it holds (shapes, AABBs, contacts, joints,
 * velocities, centres of mass) through a handful of callbacks, and any renderer draws them.
 * `drawWorld` walks a world through its drawing source (see draw-source.ts), read-only: drawing can
 * never affect the simulation.
 */
import type { Body, BodyType } from '../api/body';
import { ShapeKind } from '../geometry/types';
import type { Transform, Vec2 } from '../math/vec2';
import { BodyFlag } from '../store/body-store';
import type { WorkerBody } from '../worker/handles';
import type { AnyBody, AnyShape, AnyWorld, BodyRecord, DrawSource, ShapeRecord } from './draw-source';
import { drawSourceOf, isWorkerWorld } from './source-of';

/** A colour as 0xRRGGBB. */
export type Color = number;

/** How a shape is drawn. The object is reused between calls: read it, do not keep it. */
export interface ShapeStyle {
  /** fill colour, or null to draw the outline only (wireframe) */
  fill: Color | null;
  fillAlpha: number;
  stroke: Color;
  /** the shape being drawn and its body, so a renderer can look up its own styles */
  shape: AnyShape;
  body: AnyBody;
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
  drawBody?(body: AnyBody, xf: Transform): boolean;
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
  transformOf?(body: AnyBody, out: Transform): Transform;
  /** A body's colour; undefined keeps the default palette. */
  colorOf?(body: AnyBody): Color | undefined;
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
export function defaultBodyColor(world: AnyWorld, body: AnyBody): Color {
  if (isWorkerWorld(world)) {
    const handle = body as WorkerBody;
    return recordColor(handle.kind, handle.bullet, handle.id);
  }
  const bodies = world.core.bodies;
  const b = (body as Body).slot;
  return recordColor(TYPES[bodies.kind[b]], (bodies.flags[b] & BodyFlag.BULLET) !== 0, b);
}

/** body types by BodyKind */
const TYPES = ['static', 'kinematic', 'dynamic'] as const;

function recordColor(type: BodyType, bullet: boolean, index: number): Color {
  if (type === 'static') return colors.static;
  if (type === 'kinematic') return colors.kinematic;
  if (bullet) return colors.bullet;
  return dynamicPalette[index % dynamicPalette.length];
}

/** Fills `xf` with where a body is drawn. */
function drawnTransform(body: BodyRecord, options: DrawWorldOptions | undefined, xf: Transform) {
  if (options?.transformOf) return options.transformOf(body.handle, xf);
  const t = body.transform;
  xf.p.x = t.p.x;
  xf.p.y = t.p.y;
  xf.q.c = t.q.c;
  xf.q.s = t.q.s;
  return xf;
}

/**
 * Maps a world point on a body (as the body is now) to where it is drawn: identical unless the
 * renderer draws bodies elsewhere, as interpolation does (its transform is then written in `drawnXf`).
 */
function mapPoint(
  body: BodyRecord,
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
  const { c, s } = body.transform.q;
  const dx = p.x - body.transform.p.x;
  const dy = p.y - body.transform.p.y;
  const lx = c * dx + s * dy;
  const ly = -s * dx + c * dy;
  const xf = options.transformOf(body.handle, drawnXf);
  out.x = xf.q.c * lx - xf.q.s * ly + xf.p.x;
  out.y = xf.q.s * lx + xf.q.c * ly + xf.p.y;
  return out;
}

function drawShapes(source: DrawSource, draw: DebugDraw, flags: DebugDrawFlags, options?: DrawWorldOptions) {
  const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const style = { fill: 0, fillAlpha: 1, stroke: 0 } as ShapeStyle;
  const pA: Vec2 = { x: 0, y: 0 };
  const pB: Vec2 = { x: 0, y: 0 };
  let color = 0;
  const drawShape = (shape: ShapeRecord): void => {
    const g = shape.geometry;
    const sensor = shape.sensor;
    style.shape = shape.handle;
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
  };
  source.forEachBody((body) => {
    drawnTransform(body, options, xf);
    if (draw.drawBody?.(body.handle, xf)) return;
    color = options?.colorOf?.(body.handle) ?? recordColor(body.type, body.bullet, body.index);
    const sleeping = body.type === 'dynamic' && !body.awake;
    if (sleeping && flags.sleeping) color = mixColor(color, colors.sleepingTint, 0.6);
    style.body = body.handle;
    source.forEachShape(body, drawShape);
  });
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

function drawContacts(
  source: DrawSource,
  draw: DebugDraw,
  flags: DebugDrawFlags,
  options?: DrawWorldOptions,
) {
  const normalLength = 0.3;
  const drawnXf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const pB: Vec2 = { x: 0, y: 0 };
  const pC: Vec2 = { x: 0, y: 0 };
  source.forEachContactPoint?.((contact) => {
    mapPoint(contact.body, options, contact.point, pC, drawnXf);
    if (flags.contacts) {
      draw.drawPoint(pC, 5, contact.separation > 0 ? colors.speculativePoint : colors.contactPoint);
    }
    if (flags.contactNormals) {
      pB.x = pC.x + contact.normal.x * normalLength;
      pB.y = pC.y + contact.normal.y * normalLength;
      draw.drawLine(pC, pB, colors.contactNormal);
    }
  });
}

function drawVelocitiesAndCenters(
  source: DrawSource,
  draw: DebugDraw,
  flags: DebugDrawFlags,
  options?: DrawWorldOptions,
) {
  const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const center: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  const tip: Vec2 = { x: 0, y: 0 };
  source.forEachBody((body) => {
    if (body.type === 'static') return;
    const motion = source.motion(body);
    drawnTransform(body, options, xf);
    transformPoint(xf, motion.localCenter, center.p);
    center.q.c = xf.q.c;
    center.q.s = xf.q.s;
    if (flags.centersOfMass) draw.drawTransform(center);
    if (flags.velocities) {
      // a tenth of a second of travel
      tip.x = center.p.x + motion.linearVelocity.x * 0.1;
      tip.y = center.p.y + motion.linearVelocity.y * 0.1;
      draw.drawLine(center.p, tip, colors.velocity);
    }
  });
}

function drawJoints(source: DrawSource, draw: DebugDraw, options?: DrawWorldOptions) {
  const drawnXf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  source.forEachJoint((joint) => {
    const bodyA = joint.bodyA;
    const bodyB = joint.bodyB;
    const a = mapPoint(bodyA, options, joint.anchorA, { x: 0, y: 0 }, drawnXf);
    const b = mapPoint(bodyB, options, joint.anchorB, { x: 0, y: 0 }, drawnXf);
    if (joint.target !== null) {
      const target = joint.target;
      draw.drawLine(target, b, colors.mouse);
      draw.drawPoint(target, 6, colors.mouse);
      draw.drawPoint(b, 5, colors.mouse);
      return;
    }
    const xfA = drawnTransform(bodyA, options, { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } });
    const xfB = drawnTransform(bodyB, options, { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } });
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
  });
}

/**
 * Draws a world through `draw`: shapes first, then AABBs, joints, contacts, velocities and centres
 * of mass, as `flags` ask. `world` is a World, a WorkerWorld (no AABBs or contacts: its worker keeps
 * them) or any drawing source. Reads the world and never changes it.
 */
export function drawWorld(
  world: AnyWorld | DrawSource,
  draw: DebugDraw,
  flags: DebugDrawFlags = defaultDebugDrawFlags,
  options?: DrawWorldOptions,
): void {
  const source = 'forEachBody' in world ? world : drawSourceOf(world);
  if (flags.shapes) drawShapes(source, draw, flags, options);
  if (flags.aabbs)
    source.forEachAABB?.((minX, minY, maxX, maxY) => draw.drawAABB(minX, minY, maxX, maxY, colors.aabb));
  if (flags.joints) drawJoints(source, draw, options);
  if (flags.contacts || flags.contactNormals) drawContacts(source, draw, flags, options);
  if (flags.velocities || flags.centersOfMass) drawVelocitiesAndCenters(source, draw, flags, options);
}
