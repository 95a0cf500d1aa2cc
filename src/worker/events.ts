import type { Vec2 } from '../math/vec2';
import type { WorkerBody, WorkerShape } from './handles';
import { EVENT_ORDER, type EventKind, type EventRecord, EventStride } from './protocol';

/** World's events (api/events.ts) with the handles of a WorkerWorld. */
export interface WorkerContactBeginEvent {
  shapeA: WorkerShape;
  shapeB: WorkerShape;
  bodyA: WorkerBody;
  bodyB: WorkerBody;
  /** world unit normal from A to B */
  normal: Vec2;
  /** world contact points (one or two) */
  points: Vec2[];
}

export interface WorkerContactEndEvent {
  shapeA: WorkerShape;
  shapeB: WorkerShape;
  bodyA: WorkerBody;
  bodyB: WorkerBody;
}

export interface WorkerContactHitEvent {
  shapeA: WorkerShape;
  shapeB: WorkerShape;
  bodyA: WorkerBody;
  bodyB: WorkerBody;
  point: Vec2;
  normal: Vec2;
  /** normal speed at which the shapes approached, m/s */
  approachSpeed: number;
}

export interface WorkerSensorEvent {
  sensorShape: WorkerShape;
  visitorShape: WorkerShape;
}

export interface WorkerBodyEvent {
  body: WorkerBody;
}

export interface WorkerWarningEvent {
  type: 'contactLimit' | 'pairSearchLimit';
  count: number;
  limit: number;
  shape: WorkerShape | null;
  message: string;
}

export interface WorkerStepEvent {
  dt: number;
}

export interface WorkerWorldEventMap {
  contactBegin: WorkerContactBeginEvent;
  contactEnd: WorkerContactEndEvent;
  contactHit: WorkerContactHitEvent;
  sensorBegin: WorkerSensorEvent;
  sensorEnd: WorkerSensorEvent;
  sleep: WorkerBodyEvent;
  wake: WorkerBodyEvent;
  warning: WorkerWarningEvent;
  preStep: WorkerStepEvent;
  postStep: WorkerStepEvent;
}

/** What decodeEvents gives: each kind's events in order. */
export type WorkerEvents = { [K in EventKind]?: WorkerWorldEventMap[K][] };

/**
 * A step's record (protocol.ts) as event objects, its ids made handles again. An id the calling
 * thread no longer maps is left out; protocol ids are released only once the replies that could
 * name them have arrived (see WorkerWorld), so that does not happen in practice.
 */
export function decodeEvents(
  record: EventRecord,
  shapes: readonly (WorkerShape | undefined)[],
  bodies: readonly (WorkerBody | undefined)[],
): WorkerEvents {
  const out: WorkerEvents = {};
  const pairs = (list: number[]): [WorkerShape, WorkerShape][] => {
    const found: [WorkerShape, WorkerShape][] = [];
    for (let i = 0; i < list.length; i += EventStride.PAIR) {
      const a = shapes[list[i]];
      const b = shapes[list[i + 1]];
      if (a !== undefined && b !== undefined) found.push([a, b]);
    }
    return found;
  };
  for (const kind of EVENT_ORDER) {
    switch (kind) {
      case 'contactBegin': {
        const list = record.contactBegin;
        if (list === undefined) break;
        const events: WorkerContactBeginEvent[] = [];
        for (let i = 0; i < list.length; i += EventStride.CONTACT_BEGIN) {
          const a = shapes[list[i]];
          const b = shapes[list[i + 1]];
          if (a === undefined || b === undefined) continue;
          const points = [{ x: list[i + 5], y: list[i + 6] }];
          if (list[i + 4] > 1) points.push({ x: list[i + 7], y: list[i + 8] });
          events.push({
            shapeA: a,
            shapeB: b,
            bodyA: a.body,
            bodyB: b.body,
            normal: { x: list[i + 2], y: list[i + 3] },
            points,
          });
        }
        out.contactBegin = events;
        break;
      }
      case 'contactEnd':
        if (record.contactEnd !== undefined) {
          out.contactEnd = pairs(record.contactEnd).map(([a, b]) => ({
            shapeA: a,
            shapeB: b,
            bodyA: a.body,
            bodyB: b.body,
          }));
        }
        break;
      case 'contactHit': {
        const list = record.contactHit;
        if (list === undefined) break;
        const events: WorkerContactHitEvent[] = [];
        for (let i = 0; i < list.length; i += EventStride.CONTACT_HIT) {
          const a = shapes[list[i]];
          const b = shapes[list[i + 1]];
          if (a === undefined || b === undefined) continue;
          events.push({
            shapeA: a,
            shapeB: b,
            bodyA: a.body,
            bodyB: b.body,
            point: { x: list[i + 2], y: list[i + 3] },
            normal: { x: list[i + 4], y: list[i + 5] },
            approachSpeed: list[i + 6],
          });
        }
        out.contactHit = events;
        break;
      }
      case 'sensorBegin':
      case 'sensorEnd': {
        const list = record[kind];
        if (list !== undefined) {
          out[kind] = pairs(list).map(([sensorShape, visitorShape]) => ({ sensorShape, visitorShape }));
        }
        break;
      }
      case 'sleep':
      case 'wake': {
        const list = record[kind];
        if (list === undefined) break;
        const events: WorkerBodyEvent[] = [];
        for (const id of list) {
          const body = bodies[id];
          if (body !== undefined) events.push({ body });
        }
        out[kind] = events;
        break;
      }
      case 'warning':
        if (record.warning !== undefined) {
          out.warning = record.warning.map((w) => ({
            type: w.type,
            count: w.count,
            limit: w.limit,
            shape: w.shape < 0 ? null : (shapes[w.shape] ?? null),
            message: w.message,
          }));
        }
        break;
    }
  }
  return out;
}
