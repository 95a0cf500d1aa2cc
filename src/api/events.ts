import type { IntList } from '../broad-phase/int-list';
import { Emitter } from '../core/emitter';
import { fail } from '../core/errors';
import type { Vec2 } from '../math/vec2';
import { BEGIN_STRIDE, HIT_STRIDE, WarningCode } from '../store/event-buffers';
import type { Body } from './body';
import type { WorldHandles } from './handles';
import type { ShapeHandle } from './shape';

export interface ContactBeginEvent {
  shapeA: ShapeHandle;
  shapeB: ShapeHandle;
  bodyA: Body;
  bodyB: Body;
  /** world unit normal from A to B */
  normal: Vec2;
  /** world contact points (one or two) */
  points: Vec2[];
}

export interface ContactEndEvent {
  shapeA: ShapeHandle;
  shapeB: ShapeHandle;
  bodyA: Body;
  bodyB: Body;
}

export interface ContactHitEvent {
  shapeA: ShapeHandle;
  shapeB: ShapeHandle;
  bodyA: Body;
  bodyB: Body;
  point: Vec2;
  normal: Vec2;
  /** normal speed at which the shapes approached, m/s */
  approachSpeed: number;
}

export interface SensorEvent {
  sensorShape: ShapeHandle;
  visitorShape: ShapeHandle;
}

/**
 * Something the engine did to stay within its limits, that the simulation shows:
 * - `'contactLimit'`: `count` shapes reached `limit` contacts (`world.maxContactsPerShape`) while they
 *   overlap shapes they have no contact with, which pass through them for now (bodies created on top
 *   of each other). Their contacts push them apart; the pairs left out are made as the contacts they
 *   have end. `world.crowdedShapeCount` tells how many are still waiting.
 * - `'pairSearchLimit'`: the search for new pairs examined its `limit` of box overlaps in one step;
 *   `count` shapes look for theirs at the next step (they may overlap others for a step).
 * Recorded at the first step where it happens, and again only after a step without it. `shape` is one
 * of the shapes concerned (null if none is left), `message` says all of this in words.
 */
export interface WarningEvent {
  type: 'contactLimit' | 'pairSearchLimit';
  count: number;
  limit: number;
  shape: ShapeHandle | null;
  message: string;
}

export interface StepEvent {
  dt: number;
}

export interface BodyEvent {
  body: Body;
}

export interface WorldEventMap {
  contactBegin: ContactBeginEvent;
  contactEnd: ContactEndEvent;
  contactHit: ContactHitEvent;
  sensorBegin: SensorEvent;
  sensorEnd: SensorEvent;
  preStep: StepEvent;
  postStep: StepEvent;
  sleep: BodyEvent;
  wake: BodyEvent;
  warning: WarningEvent;
}

/** The events of the last step as arrays. */
export interface WorldEvents {
  contactBegin: ContactBeginEvent[];
  contactEnd: ContactEndEvent[];
  contactHit: ContactHitEvent[];
  sensorBegin: SensorEvent[];
  sensorEnd: SensorEvent[];
  sleep: BodyEvent[];
  wake: BodyEvent[];
  warning: WarningEvent[];
}

/** @internal Every event World.on takes, in the order its error lists them. */
export const EVENT_NAMES = [
  'contactBegin',
  'contactEnd',
  'contactHit',
  'sensorBegin',
  'sensorEnd',
  'preStep',
  'postStep',
  'sleep',
  'wake',
  'warning',
] as const;

/**
 * Turns the step's recorded numbers into event objects, lazily: only when a handler listens or the
 * arrays are read. Handlers run after the step, so they may create and destroy bodies.
 *
 * The events are a record of the step: from the end of one step to the next, `world.events` returns
 * the same arrays of the same objects whenever it is read, and handlers receive those objects. They
 * name the body and shape handles that took part, also when these have been destroyed since (in a
 * handler or before the arrays were read): such a handle reads `isValid === false`, and a new body
 * that took over its slot is never named instead. For that, the World calls `settle()` before it
 * destroys a shape, so that the record is made into objects while its handles still exist.
 * Sleep and wake that happen between steps (setAwake, setters) are reported with the next step; a
 * body destroyed before then is left out of them. So are the ends of touching pairs dropped between
 * steps (a shape's filter or sensor flag or its body's type changed, a joint forbade the collision),
 * unless a shape of the pair is destroyed first; the handlers for ends run before those for begins,
 * so that every pair's begins and ends alternate. Destroying a body or shape ends its pairs without
 * events (its handles read isValid === false).
 */
export class EventDispatcher {
  private readonly handlers = new Emitter<WorldEventMap>();
  private cache: WorldEvents | null = null;
  private sleepEvents: BodyEvent[] = [];
  private wakeEvents: BodyEvent[] = [];

  constructor(private readonly handles: WorldHandles) {}

  /** World.on, its arguments checked: plain JavaScript may pass anything. */
  on<K extends keyof WorldEventMap>(event: K, handler: (e: WorldEventMap[K]) => void): () => void {
    if (!(EVENT_NAMES as readonly string[]).includes(event))
      fail('event', event, `one of ${EVENT_NAMES.join(', ')}`);
    if (typeof handler !== 'function') fail('handler', handler, 'a function');
    return this.handlers.on(event, handler);
  }

  emitStep(event: 'preStep' | 'postStep', dt: number): void {
    if (this.handlers.has(event)) this.handlers.emit(event, { dt });
  }

  /** Called at the end of step(): drops the old arrays and runs the handlers. */
  deliver(): void {
    this.cache = null;
    const core = this.handles.core;
    core.events.seal(core.contacts, core.shapes);
    // sleep and wake also happen between steps (setAwake, setters): they are taken here and cleared
    const islands = core.islands;
    this.sleepEvents = this.bodyEvents(islands.slept);
    this.wakeEvents = this.bodyEvents(islands.woken);
    islands.slept.clear();
    islands.woken.clear();
    const warned = this.handles.core.events.warningCount > 0;
    const handlers = this.handlers;
    let any = false;
    for (const name of EVENT_NAMES) if (handlers.has(name)) any = true;
    if (!any && !warned) return;
    const events = this.current();
    // a warning nobody listens to goes to the console, so that a crowd does not go unnoticed
    if (warned && !handlers.has('warning')) {
      for (const w of events.warning) console.warn(`Fulcrum: ${w.message}`);
    }
    // ends first: a pair dropped between steps (a filter or sensor flag changed, a joint created) and
    // found again in this step has both its end and its new begin in this record, in that order
    handlers.emitEach('contactEnd', events.contactEnd);
    handlers.emitEach('sensorEnd', events.sensorEnd);
    handlers.emitEach('contactBegin', events.contactBegin);
    handlers.emitEach('contactHit', events.contactHit);
    handlers.emitEach('sensorBegin', events.sensorBegin);
    handlers.emitEach('sleep', events.sleep);
    handlers.emitEach('wake', events.wake);
    handlers.emitEach('warning', events.warning);
  }

  /** Makes the record into objects now, while every shape it names still has its handle. */
  settle(): void {
    if (this.cache === null) this.current();
  }

  current(): WorldEvents {
    if (this.cache) return this.cache;
    const handles = this.handles.shapes;
    const buf = this.handles.core.events;
    const gens = buf.generations.data;
    let g = 0;
    // the handle of a shape as the record names it, or undefined when it is gone: in a live world
    // settle() keeps that from happening; a world restored from a snapshot taken after the shape was
    // destroyed has no handle for it, and such events are left out
    const shape = (s: number): ShapeHandle | undefined => {
      const h = handles[s];
      return h !== undefined && (h.generation | 0) === gens[g++] ? h : undefined;
    };
    const contactBegin: ContactBeginEvent[] = [];
    for (let i = 0, n = buf.contactBegin.length / 3; i < n; i++) {
      const a = shape(buf.contactBegin.data[i * 3 + 1]);
      const b = shape(buf.contactBegin.data[i * 3 + 2]);
      if (a === undefined || b === undefined) continue;
      const d = buf.beginData;
      const k = i * BEGIN_STRIDE;
      const points: Vec2[] = [];
      for (let j = 0; j < d[k + 2]; j++) points.push({ x: d[k + 3 + 2 * j], y: d[k + 4 + 2 * j] });
      contactBegin.push({
        shapeA: a,
        shapeB: b,
        bodyA: a.body,
        bodyB: b.body,
        normal: { x: d[k], y: d[k + 1] },
        points,
      });
    }
    const contactEnd: ContactEndEvent[] = [];
    for (let i = 0; i < buf.contactEnd.length; i += 2) {
      const a = shape(buf.contactEnd.data[i]);
      const b = shape(buf.contactEnd.data[i + 1]);
      if (a === undefined || b === undefined) continue;
      contactEnd.push({ shapeA: a, shapeB: b, bodyA: a.body, bodyB: b.body });
    }
    const sensors = (list: IntList): SensorEvent[] => {
      const out: SensorEvent[] = [];
      for (let i = 0; i < list.length; i += 2) {
        const sensorShape = shape(list.data[i]);
        const visitorShape = shape(list.data[i + 1]);
        if (sensorShape !== undefined && visitorShape !== undefined) out.push({ sensorShape, visitorShape });
      }
      return out;
    };
    const sensorBegin = sensors(buf.sensorBegin);
    const sensorEnd = sensors(buf.sensorEnd);
    const contactHit: ContactHitEvent[] = [];
    for (let i = 0; i < buf.hitShapes.length; i += 2) {
      const a = shape(buf.hitShapes.data[i]);
      const b = shape(buf.hitShapes.data[i + 1]);
      if (a === undefined || b === undefined) continue;
      const d = buf.hitData;
      const k = (i / 2) * HIT_STRIDE;
      contactHit.push({
        shapeA: a,
        shapeB: b,
        bodyA: a.body,
        bodyB: b.body,
        point: { x: d[k], y: d[k + 1] },
        normal: { x: d[k + 2], y: d[k + 3] },
        approachSpeed: d[k + 4],
      });
    }
    this.cache = {
      contactBegin,
      contactEnd,
      contactHit,
      sensorBegin,
      sensorEnd,
      sleep: this.sleepEvents,
      wake: this.wakeEvents,
      warning: this.warnings(),
    };
    return this.cache;
  }

  private warnings(): WarningEvent[] {
    const core = this.handles.core;
    const buf = core.events;
    const out: WarningEvent[] = [];
    for (let i = 0; i < buf.warningCount; i++) {
      const d = buf.warningData;
      const count = d[4 * i + 1];
      const limit = d[4 * i + 2];
      const s = d[4 * i + 3];
      const shape = s >= 0 && core.shapes.alive[s] !== 0 ? (this.handles.shapes[s] ?? null) : null;
      const where = shape ? `, e.g. on the body at ${showPoint(shape.body.position)}` : '';
      if (d[4 * i] === WarningCode.CONTACT_LIMIT) {
        out.push({
          type: 'contactLimit',
          count,
          limit,
          shape,
          message:
            `${count} shapes reached the limit of ${limit} contacts per shape (world.maxContactsPerShape) ` +
            `while they overlap shapes they have no contact with${where}: bodies created on top of each ` +
            'other? They pass through each other until the contacts they have push them apart.',
        });
      } else {
        out.push({
          type: 'pairSearchLimit',
          count,
          limit,
          shape,
          message:
            `the search for new contacts examined its limit of ${limit} overlapping boxes in one step; ` +
            `${count} shapes look for theirs at the next step${where}: many shapes overlap each other.`,
        });
      }
    }
    return out;
  }

  /** Body events from (slot, generation) pairs; a body destroyed since it slept or woke is left out. */
  private bodyEvents(list: IntList): BodyEvent[] {
    const out: BodyEvent[] = [];
    const bodies = this.handles.core.bodies;
    for (let i = 0; i < list.length; i += 2) {
      const b = list.data[i];
      if (bodies.alive[b] !== 0 && (bodies.generation[b] | 0) === list.data[i + 1]) {
        out.push({ body: this.handles.bodies[b]! });
      }
    }
    return out;
  }
}

function showPoint(p: Vec2): string {
  return `(${p.x.toFixed(2)}, ${p.y.toFixed(2)})`;
}
