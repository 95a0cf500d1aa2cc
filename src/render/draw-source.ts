import type { Body, BodyType } from '../api/body';
import type { ShapeHandle } from '../api/shape';
import type { World } from '../api/world';
import type { Geometry } from '../geometry/types';
import type { JointType } from '../joints/registry';
import type { Transform, Vec2 } from '../math/vec2';
import type { WorkerBody, WorkerShape } from '../worker/handles';
import type { WorkerWorld } from '../worker/worker-world';

/** A world `fulcrum/render` draws and runs: one on this thread, or one in a worker. */
export type AnyWorld = World | WorkerWorld;

/** A body's handle: a World's Body or a WorkerWorld's WorkerBody. Styles and sprites are keyed by it. */
export type AnyBody = Body | WorkerBody;

/** A shape's handle: a World's or a WorkerWorld's. */
export type AnyShape = ShapeHandle | WorkerShape;

/** One body as the debug drawing reads it. A source fills one record and reuses it: read, do not keep. */
export interface BodyRecord {
  handle: AnyBody;
  /** the body's index in its world (a World's slot, a WorkerWorld's id): picks its palette colour */
  index: number;
  type: BodyType;
  bullet: boolean;
  awake: boolean;
  /** where the body is, after the last step */
  transform: Transform;
}

/** One shape of a body: its geometry in the body's frame. Reused like BodyRecord. */
export interface ShapeRecord {
  handle: AnyShape;
  geometry: Geometry;
  sensor: boolean;
}

/** One joint: its anchors in world coordinates, where the bodies are after the last step. Reused. */
export interface JointRecord {
  type: JointType;
  bodyA: BodyRecord;
  bodyB: BodyRecord;
  anchorA: Vec2;
  anchorB: Vec2;
  /** a mouse joint's target, null for other joints */
  target: Vec2 | null;
}

/** One point of a touching contact, in world coordinates, on the contact's first body. Reused. */
export interface ContactPointRecord {
  body: BodyRecord;
  point: Vec2;
  normal: Vec2;
  separation: number;
}

/** A body's mass centre (in its frame) and the velocity of that centre. Reused. */
export interface MotionRecord {
  localCenter: Vec2;
  linearVelocity: Vec2;
}

/**
 * What `drawWorld` reads from a world: bodies with their poses and shapes (local geometry), joints'
 * anchors and, where the source knows them, contacts and bounding boxes. A World's source reads its
 * columns; a WorkerWorld's reads the shapes its create calls made and the state its worker last
 * published, and never the engine's internals (it has none on this thread).
 */
export interface DrawSource {
  /** Each live body, in drawing order. */
  forEachBody(visit: (body: BodyRecord) => void): void;
  /** Each shape of the body just visited, in drawing order. */
  forEachShape(body: BodyRecord, visit: (shape: ShapeRecord) => void): void;
  /** The body's mass centre and velocity, for the velocity and centre-of-mass overlays. */
  motion(body: BodyRecord): MotionRecord;
  /** Each joint. */
  forEachJoint(visit: (joint: JointRecord) => void): void;
  /** Each point of every touching contact (sensors left out); absent where the source has no contacts. */
  forEachContactPoint?(visit: (point: ContactPointRecord) => void): void;
  /** Each shape's bounding box; absent where the source has none. */
  forEachAABB?(visit: (minX: number, minY: number, maxX: number, maxY: number) => void): void;
}

/** Scratch records a drawing source fills and hands to its visitors, one of each kind, reused. */
export function newBodyRecord(): BodyRecord {
  return {
    handle: null!,
    index: 0,
    type: 'static',
    bullet: false,
    awake: false,
    transform: { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } },
  };
}

export function newShapeRecord(): ShapeRecord {
  return { handle: null!, geometry: null!, sensor: false } as ShapeRecord;
}

export function newMotionRecord(): MotionRecord {
  return { localCenter: { x: 0, y: 0 }, linearVelocity: { x: 0, y: 0 } };
}

export function newJointRecord(): JointRecord {
  return {
    type: 'distance',
    bodyA: newBodyRecord(),
    bodyB: newBodyRecord(),
    anchorA: { x: 0, y: 0 },
    anchorB: { x: 0, y: 0 },
    target: null,
  };
}
