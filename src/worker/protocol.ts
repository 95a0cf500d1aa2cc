import type { BodyType } from '../api/body';
import type { JointType } from '../joints/registry';

/*
 * What the calling thread and the worker say to each other. The calling thread sends batches: the
 * commands queued since the last batch, in the order they were given, and one request (a step, a
 * query, a snapshot, a hash); the worker applies the commands, then answers the request with a reply
 * of the same `seq`. Batches are answered in the order they were sent. Handles travel as ids that the
 * calling thread assigns; everything else travels as plain, structured-cloneable data.
 */

/** Body methods that a WorkerBody queues as they are, with their checked arguments. */
export const BODY_COMMANDS = Object.freeze([
  'setPosition',
  'setAngle',
  'setTransform',
  'setLinearVelocity',
  'setAngularVelocity',
  'setType',
  'setAwake',
  'applyForce',
  'applyTorque',
  'applyLinearImpulse',
  'applyAngularImpulse',
  'setLinearDamping',
  'setAngularDamping',
  'setGravityScale',
  'setFixedRotation',
  'setBullet',
  'setAllowSleep',
  'setMassData',
  'resetMassData',
  'scale',
] as const);

export type BodyCommand = (typeof BODY_COMMANDS)[number];

/** Shape settings that a WorkerShape's setters queue, with their checked values (ShapeHandle's setters). */
export type ShapeSetting = 'friction' | 'restitution' | 'density' | 'filter' | 'isSensor' | 'enableHitEvents';

/** Joint methods that a WorkerJoint queues as they are, with their checked arguments (each on the joint types that have it). */
export const JOINT_COMMANDS = Object.freeze([
  'setTarget',
  'enableMotor',
  'setMotorSpeed',
  'setMaxMotorTorque',
  'setMaxMotorForce',
  'enableLimit',
  'setLimits',
  'enableSpring',
  'setSpring',
  'setLength',
  'setLengthRange',
  'setStiffness',
  'setLinearOffset',
  'setAngularOffset',
  'setMaxForce',
  'setMaxTorque',
] as const);

export type JointCommand = (typeof JOINT_COMMANDS)[number];

/** A body's settings that the calling thread reads without asking (Body's reads of the same names). */
export interface BodySettings {
  linearDamping: number;
  angularDamping: number;
  gravityScale: number;
  fixedRotation: boolean;
  bullet: boolean;
  allowSleep: boolean;
}

/**
 * The settings of `from`, copied: a Body's reads or a checked body definition, which name them alike.
 * @internal
 */
export function bodySettingsOf(from: Readonly<BodySettings>): BodySettings {
  return {
    linearDamping: from.linearDamping,
    angularDamping: from.angularDamping,
    gravityScale: from.gravityScale,
    fixedRotation: from.fixedRotation,
    bullet: from.bullet,
    allowSleep: from.allowSleep,
  };
}

/** A shape's settings that the calling thread reads without asking (ShapeHandle's reads of the same names). */
export interface ShapeSettings {
  friction: number;
  restitution: number;
  density: number;
  filter: { categoryBits: number; maskBits: number; groupIndex: number };
  isSensor: boolean;
  enableHitEvents: boolean;
}

/**
 * A plain value: what a checked definition or argument holds once its handles are ids and its
 * objects plain copies (structured-cloneable; see plain.ts).
 */
export type Plain = unknown;

/** A checked definition as plain data. */
export type PlainDef = Record<string, unknown>;

export type Command =
  /** id, generation, a body definition with every option given (no userData) */
  | ['createBody', number, number, PlainDef]
  | ['destroyBody', number]
  /** body id, the ids of its new shapes (a concave shape's pieces, a chain's segments), geometry, definition */
  | ['createShape', number, number[], Plain, PlainDef | undefined]
  | ['destroyShape', number, number]
  /** id, the definition with its bodies as ids */
  | ['createJoint', number, PlainDef]
  | ['destroyJoint', number]
  | ['body', number, BodyCommand, Plain[]]
  /** shape id, the setting, its checked value */
  | ['shape', number, ShapeSetting, Plain]
  /** shape id, its new geometry (checked): ShapeHandle.setGeometry */
  | ['shapeGeometry', number, Plain]
  /** joint id, a method of the joint's type, its checked arguments */
  | ['joint', number, JointCommand, Plain[]]
  | ['gravity', { x: number; y: number }];

/** The world's queries that a WorkerWorld forwards. */
export type QueryName =
  | 'castRay'
  | 'castRayAll'
  | 'queryAABB'
  | 'queryPoint'
  | 'castShape'
  | 'overlapShape'
  /** a body's touching contacts (Body.getContacts); its one argument is the body's id */
  | 'getContacts';

/** The event kinds a WorkerWorld delivers, in the order World delivers them after a step. */
export const EVENT_ORDER = Object.freeze([
  'contactEnd',
  'sensorEnd',
  'contactBegin',
  'contactHit',
  'sensorBegin',
  'sleep',
  'wake',
  'warning',
] as const);

export type EventKind = (typeof EVENT_ORDER)[number];

export type Request =
  /** a new world; `buffer` receives its (empty) state */
  | { kind: 'create'; def: PlainDef; buffer: ArrayBufferLike }
  /** a world from snapshot bytes */
  | { kind: 'restore'; bytes: Uint8Array; buffer: ArrayBufferLike }
  /** a step; the state after it goes into `buffer`, the step's events of the kinds `events` names come along */
  | { kind: 'step'; dt: number; buffer: ArrayBufferLike; events: EventKind[] }
  | { kind: 'query'; name: QueryName; args: Plain[] }
  | { kind: 'snapshot' }
  | { kind: 'hash' }
  /** only the commands (e.g. before terminate, so that nothing queued is lost silently) */
  | { kind: 'flush' };

export interface Batch {
  seq: number;
  commands: Command[];
  request: Request;
}

/**
 * A step's events, handles as ids: flat number lists with a fixed stride each.
 * contactBegin: shapeA, shapeB, normal x, y, point count, up to two points (x, y): 9.
 * contactEnd, sensorBegin, sensorEnd (sensor, visitor): 2. contactHit: shapeA, shapeB, point x, y,
 * normal x, y, approach speed: 7. sleep, wake: body ids.
 */
export interface EventRecord {
  contactBegin?: number[];
  contactEnd?: number[];
  contactHit?: number[];
  sensorBegin?: number[];
  sensorEnd?: number[];
  sleep?: number[];
  wake?: number[];
  warning?: {
    type: 'contactLimit' | 'pairSearchLimit';
    count: number;
    limit: number;
    shape: number;
    message: string;
  }[];
}

export enum EventStride {
  CONTACT_BEGIN = 9,
  PAIR = 2,
  CONTACT_HIT = 7,
}

/** A restored world's handles: body i has id i, and so on; generation 1 each. */
export interface RestoredHandles {
  gravity: { x: number; y: number };
  /** each body's type and settings */
  bodies: [BodyType, BodySettings][];
  /** each shape's body id, geometry and settings */
  shapes: [number, Plain, ShapeSettings][];
  /** each joint's type, body ids, and a mouse joint's target (null for other joints) */
  joints: [JointType, number, number, { x: number; y: number } | null][];
}

export interface Reply {
  seq: number;
  /** the message of the first FulcrumError the worker met in this batch (a command it refused, or the request) */
  error?: string;
  /** the state buffer written, back to the calling thread (a step, create or restore) */
  buffer?: ArrayBufferLike;
  events?: EventRecord;
  /** a query's answer, a snapshot's bytes or a hash */
  result?: unknown;
  restored?: RestoredHandles;
  /**
   * the joints this batch made (or a restored world's): per joint its id and its anchors in the
   * bodies' frames (A x, y, B x, y), stride JOINT_ANCHORS_STRIDE, for drawing
   */
  anchors?: number[];
  /**
   * the joints' reads (see JointRead): after a step every joint's, else those of the joints the batch
   * made (or a restored world's)
   */
  joints?: number[];
  /** the new geometries of the shapes of the bodies the batch scaled: shape id, geometry */
  geometries?: [number, Plain][];
  /** a step's duration in the worker, milliseconds (output only) */
  stepMs?: number;
  /** the threads that solved the step (the world's `workers`, once started) */
  threads?: number;
}

export const JOINT_ANCHORS_STRIDE = 5;

/**
 * A joint's reads in a reply's `joints`, a row per joint: its id; the reaction force and torque of
 * the last substep; the anchors in world coordinates; MEASURE, a revolute joint's angle, a prismatic or
 * wheel joint's translation, a distance joint's current length (else 0); SETTING, a revolute joint's
 * motor speed, a distance joint's length (else 0).
 */
export enum JointRead {
  ID = 0,
  FX = 1,
  FY = 2,
  TORQUE = 3,
  AX = 4,
  AY = 5,
  BX = 6,
  BY = 7,
  MEASURE = 8,
  SETTING = 9,
  STRIDE = 10,
}

/**
 * The state buffer: a Float64Array with one row per body id, written by the worker after each step.
 * GENERATION tells which body of that id the row is about; PREV_* is the pose at the start of the
 * step (after that step's commands), for drawing between two steps; MASS, INERTIA and LC* the mass
 * data (four numbers a row: cheaper than a message of their own whenever shapes or settings change).
 */
export enum Row {
  GENERATION = 0,
  PX = 1,
  PY = 2,
  QC = 3,
  QS = 4,
  VX = 5,
  VY = 6,
  W = 7,
  CX = 8,
  CY = 9,
  AWAKE = 10,
  PREV_PX = 11,
  PREV_PY = 12,
  PREV_QC = 13,
  PREV_QS = 14,
  MASS = 15,
  INERTIA = 16,
  LCX = 17,
  LCY = 18,
  STRIDE = 19,
}
