import type { Body } from '../api/body';
import type { ShapeHandle } from '../api/shape';
import { stateHash } from '../api/state-hash';
import { World, type WorldDef } from '../api/world';
import { FulcrumError } from '../core/errors';
import type { DistanceJoint } from '../joints/distance-joint';
import type { Joint } from '../joints/joint';
import type { MouseJoint } from '../joints/mouse-joint';
import type { JointDef } from '../joints/registry';
import type { RevoluteJoint } from '../joints/revolute-joint';
import type { SliderJoint } from '../joints/slider-joint';
import type { CastHit } from '../query/index';
import { BodyFlag, BodyState } from '../store/body-store';
import { deepFreeze } from './plain';
import {
  type Batch,
  bodySettingsOf,
  type Command,
  EVENT_ORDER,
  type EventRecord,
  JointRead,
  type Plain,
  type Reply,
  type Request,
  type RestoredHandles,
  Row,
  type ShapeSetting,
  type ShapeSettings,
} from './protocol';

function isShared(buffer: ArrayBufferLike): boolean {
  return typeof SharedArrayBuffer === 'function' && buffer instanceof SharedArrayBuffer;
}

/** A query's answer with shape handles as ids. */
function hitOut(hit: CastHit, shapeId: (s: ShapeHandle) => number): Plain {
  return {
    shape: shapeId(hit.shape),
    point: { x: hit.point.x, y: hit.point.y },
    normal: { x: hit.normal.x, y: hit.normal.y },
    fraction: hit.fraction,
  };
}

function shapeSettings(shape: ShapeHandle): ShapeSettings {
  return {
    friction: shape.friction,
    restitution: shape.restitution,
    density: shape.density,
    filter: shape.filter,
    isSensor: shape.isSensor,
    enableHitEvents: shape.enableHitEvents,
  };
}

/**
 * The worker's side of a WorkerWorld: one Fulcrum World, the handles of its bodies, shapes and joints
 * by the ids the calling thread gave them, and the answer to each batch (see protocol.ts). It knows
 * no platform: worker-entry.ts feeds it messages and posts its replies.
 */
export class WorldHost {
  #world: World | null = null;
  readonly #bodies: (Body | undefined)[] = [];
  readonly #generations: number[] = [];
  readonly #shapes: (ShapeHandle | undefined)[] = [];
  readonly #joints: (Joint | undefined)[] = [];
  readonly #bodyIds = new WeakMap<Body, number>();
  readonly #shapeIds = new WeakMap<ShapeHandle, number>();
  readonly #jointIds = new WeakMap<Joint, number>();
  /** the joints the current batch made, with their ids, whose anchors go into its reply */
  #madeJoints: number[] = [];
  /** the bodies the current batch scaled, whose shapes' geometries go into its reply */
  #scaledBodies: number[] = [];

  /**
   * Applies a batch's commands in order, then answers its request. A command the World refuses with a
   * FulcrumError changes nothing (as on World) and the rest go on; the reply carries the first such
   * message. Any other error is the engine's failure and escapes: the worker stops, and the calling
   * thread rejects what it waits for.
   */
  handle(batch: Batch): { reply: Reply; transfer: Transferable[] } {
    let error: string | undefined;
    const refused = (e: unknown): void => {
      if (!(e instanceof FulcrumError)) throw e;
      error ??= e.message;
    };
    for (const command of batch.commands) {
      try {
        this.#apply(command);
      } catch (e) {
        refused(e);
      }
    }
    const reply: Reply = { seq: batch.seq };
    const transfer: Transferable[] = [];
    try {
      this.#answer(batch.request, reply, transfer);
    } catch (e) {
      refused(e);
    }
    if (error !== undefined) reply.error = error;
    if (batch.request.kind === 'step') reply.joints = this.#jointReads(this.#joints.keys());
    else if (this.#madeJoints.length > 0) reply.joints = this.#jointReads(this.#madeJoints);
    if (this.#madeJoints.length > 0) reply.anchors = this.#anchors();
    if (this.#scaledBodies.length > 0) reply.geometries = this.#scaledGeometries();
    return { reply, transfer };
  }

  /** The reads of the joints of `ids` that are alive (see JointRead). */
  #jointReads(ids: Iterable<number>): number[] {
    const out: number[] = [];
    for (const id of ids) {
      const joint = this.#joints[id];
      if (joint === undefined) continue;
      const force = joint.getReactionForce();
      const a = joint.anchorA;
      const b = joint.anchorB;
      let measure = 0;
      let setting = 0;
      if (joint.type === 'revolute') {
        measure = (joint as RevoluteJoint).angle;
        setting = (joint as RevoluteJoint).motorSpeed;
      } else if (joint.type === 'prismatic' || joint.type === 'wheel') {
        measure = (joint as SliderJoint).translation;
      } else if (joint.type === 'distance') {
        measure = (joint as DistanceJoint).currentLength;
        setting = (joint as DistanceJoint).length;
      }
      const at = out.length;
      out.length += JointRead.STRIDE;
      out[at + JointRead.ID] = id;
      out[at + JointRead.FX] = force.x;
      out[at + JointRead.FY] = force.y;
      out[at + JointRead.TORQUE] = joint.getReactionTorque();
      out[at + JointRead.AX] = a.x;
      out[at + JointRead.AY] = a.y;
      out[at + JointRead.BX] = b.x;
      out[at + JointRead.BY] = b.y;
      out[at + JointRead.MEASURE] = measure;
      out[at + JointRead.SETTING] = setting;
    }
    return out;
  }

  /** The geometries of the shapes of the bodies scaled since the last reply (see Reply.geometries). */
  #scaledGeometries(): [number, Plain][] {
    const out: [number, Plain][] = [];
    for (const id of new Set(this.#scaledBodies)) {
      const body = this.#bodies[id];
      if (body === undefined) continue;
      for (const shape of body.shapes)
        out.push([this.#shapeIds.get(shape)!, shape.geometry as unknown as Plain]);
    }
    this.#scaledBodies = [];
    return out;
  }

  /** The anchors of the joints made since the last reply (see Reply.anchors). */
  #anchors(): number[] {
    const out: number[] = [];
    for (const id of this.#madeJoints) {
      const joint = this.#joints[id];
      // made and destroyed in the same batch: the calling thread has dropped it too
      if (joint === undefined) continue;
      out.push(id, joint.localAnchorAx, joint.localAnchorAy, joint.localAnchorBx, joint.localAnchorBy);
    }
    this.#madeJoints = [];
    return out;
  }

  #answer(request: Request, reply: Reply, transfer: Transferable[]): void {
    switch (request.kind) {
      case 'create':
        this.#world = new World(request.def as WorldDef);
        this.#publish(this.#fit(request.buffer), reply, transfer, false);
        return;
      case 'restore':
        this.#restore(request.bytes, reply);
        this.#publish(this.#fit(request.buffer), reply, transfer, false);
        return;
      case 'step': {
        const world = this.#live();
        const buffer = this.#fit(request.buffer);
        this.#writePoses(new Float64Array(buffer), Row.PREV_PX);
        const start = performance.now();
        world.step(request.dt);
        reply.stepMs = performance.now() - start;
        reply.threads = world.workers;
        this.#publish(buffer, reply, transfer, true);
        if (request.events.length > 0) reply.events = this.#events(request.events);
        return;
      }
      case 'query':
        reply.result = this.#query(request.name, request.args);
        return;
      case 'snapshot': {
        const bytes = this.#live().snapshot();
        reply.result = bytes;
        transfer.push(bytes.buffer);
        return;
      }
      case 'hash':
        reply.result = stateHash(this.#live());
        return;
      case 'flush':
        return;
    }
  }

  #live(): World {
    if (this.#world === null) throw new FulcrumError('worker: no world yet');
    return this.#world;
  }

  #body(id: number): Body {
    const body = this.#bodies[id];
    if (body === undefined) throw new FulcrumError('body has been destroyed');
    return body;
  }

  #apply(command: Command): void {
    const world = this.#live();
    switch (command[0]) {
      case 'createBody': {
        const [, id, generation, def] = command;
        const body = world.createBody(def);
        this.#bodies[id] = body;
        this.#generations[id] = generation;
        this.#bodyIds.set(body, id);
        return;
      }
      case 'destroyBody': {
        const body = this.#body(command[1]);
        const shapes = body.shapes;
        const joints = body.joints;
        world.destroyBody(body);
        for (const shape of shapes) this.#shapes[this.#shapeIds.get(shape)!] = undefined;
        for (const joint of joints) this.#joints[this.#jointIds.get(joint)!] = undefined;
        this.#bodies[command[1]] = undefined;
        return;
      }
      case 'createShape': {
        const [, bodyId, ids, geometry, def] = command;
        // the geometry is a structured clone of what Shape.* made: frozen again, it passes the same checks
        const made = this.#body(bodyId).createShape(deepFreeze(geometry) as never, def);
        const shapes = Array.isArray(made) ? made : [made];
        for (let i = 0; i < shapes.length; i++) {
          this.#shapes[ids[i]] = shapes[i];
          this.#shapeIds.set(shapes[i], ids[i]);
        }
        return;
      }
      case 'destroyShape': {
        const shape = this.#shapes[command[2]];
        if (shape === undefined) throw new FulcrumError('shape has been destroyed');
        this.#body(command[1]).destroyShape(shape);
        this.#shapes[command[2]] = undefined;
        return;
      }
      case 'createJoint': {
        const [, id, plain] = command;
        const def: Record<string, unknown> = { ...plain };
        for (const key of ['bodyA', 'bodyB', 'body']) {
          if (typeof def[key] === 'number') def[key] = this.#body(def[key] as number);
        }
        const joint = world.createJoint(def as unknown as JointDef);
        this.#joints[id] = joint;
        this.#jointIds.set(joint, id);
        this.#madeJoints.push(id);
        return;
      }
      case 'destroyJoint': {
        const joint = this.#joints[command[1]];
        if (joint === undefined) throw new FulcrumError('joint has been destroyed');
        world.destroyJoint(joint);
        this.#joints[command[1]] = undefined;
        return;
      }
      case 'body': {
        const [, id, method, args] = command;
        const body = this.#body(id);
        (body[method] as (...a: unknown[]) => void).apply(body, args);
        if (method === 'scale') this.#scaledBodies.push(id);
        return;
      }
      case 'shapeGeometry': {
        const shape = this.#shapes[command[1]];
        if (shape === undefined) throw new FulcrumError('shape has been destroyed');
        // a structured clone of what Shape.* made: frozen again, it passes the same checks
        shape.setGeometry(deepFreeze(command[2]) as never);
        return;
      }
      case 'shape': {
        const [, id, setting, value] = command;
        const shape = this.#shapes[id];
        if (shape === undefined) throw new FulcrumError('shape has been destroyed');
        (shape as unknown as Record<ShapeSetting, unknown>)[setting] = value;
        return;
      }
      case 'joint': {
        const [, id, method, args] = command;
        const joint = this.#joints[id];
        if (joint === undefined) throw new FulcrumError('joint has been destroyed');
        const call = (joint as unknown as Record<string, unknown>)[method];
        // the calling thread sends a joint only the methods of its type
        if (typeof call !== 'function') throw new FulcrumError(`${method}: a ${joint.type} joint has none`);
        call.apply(joint, args);
        return;
      }
      case 'gravity':
        world.gravity = command[1];
        return;
    }
  }

  /** Gives a restored world's bodies, shapes and joints ids in the order the world lists them. */
  #restore(bytes: Uint8Array, reply: Reply): void {
    const world = World.restore(bytes);
    this.#world = world;
    const restored: RestoredHandles = {
      gravity: world.gravity,
      bodies: [],
      shapes: [],
      joints: [],
    };
    for (const body of world.bodies) {
      const id = restored.bodies.length;
      this.#bodies[id] = body;
      this.#generations[id] = 1;
      this.#bodyIds.set(body, id);
      restored.bodies.push([body.type, bodySettingsOf(body)]);
      for (const shape of body.shapes) {
        this.#shapes[restored.shapes.length] = shape;
        this.#shapeIds.set(shape, restored.shapes.length);
        restored.shapes.push([id, shape.geometry as unknown as Plain, shapeSettings(shape)]);
      }
    }
    for (const joint of world.joints) {
      const id = restored.joints.length;
      this.#joints[id] = joint;
      this.#jointIds.set(joint, id);
      this.#madeJoints.push(id);
      const target = joint.type === 'mouse' ? (joint as MouseJoint).target : null;
      restored.joints.push([
        joint.type,
        this.#bodyIds.get(joint.bodyA)!,
        this.#bodyIds.get(joint.bodyB)!,
        target,
      ]);
    }
    reply.restored = restored;
  }

  /**
   * `buffer`, or a larger one of the same kind when it has no row for some body (the calling thread
   * sizes it for the ids it gave; a restored world's count only the worker knows).
   */
  #fit(buffer: ArrayBufferLike): ArrayBufferLike {
    const bytes = this.#bodies.length * Row.STRIDE * Float64Array.BYTES_PER_ELEMENT;
    if (buffer.byteLength >= bytes) return buffer;
    return isShared(buffer) ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes);
  }

  /** Writes every live body's pose, from `column` on (PX or PREV_PX), into its row. */
  #writePoses(view: Float64Array, column: Row): void {
    const columns = this.#live().core.bodies;
    const bodies = this.#bodies;
    for (let id = 0; id < bodies.length; id++) {
      const body = bodies[id];
      if (body === undefined) continue;
      const b = body.slot;
      const r = id * Row.STRIDE + column;
      view[r] = columns.px[b];
      view[r + 1] = columns.py[b];
      view[r + 2] = columns.qc[b];
      view[r + 3] = columns.qs[b];
    }
  }

  /**
   * Writes the state after a step (or of a new or restored world) into `buffer` and puts it in the
   * reply; a step wrote the previous poses first, a new or restored world takes its current ones.
   */
  #publish(buffer: ArrayBufferLike, reply: Reply, transfer: Transferable[], stepped: boolean): void {
    const view = new Float64Array(buffer);
    if (!stepped) this.#writePoses(view, Row.PREV_PX);
    this.#writePoses(view, Row.PX);
    const columns = this.#live().core.bodies;
    const state = columns.state;
    const bodies = this.#bodies;
    for (let id = 0; id < bodies.length; id++) {
      const body = bodies[id];
      if (body === undefined) continue;
      const b = body.slot;
      const r = id * Row.STRIDE;
      const s = b * BodyState.STRIDE;
      view[r + Row.GENERATION] = this.#generations[id];
      view[r + Row.VX] = state[s + BodyState.VX];
      view[r + Row.VY] = state[s + BodyState.VY];
      view[r + Row.W] = state[s + BodyState.W];
      view[r + Row.CX] = columns.cx[b];
      view[r + Row.CY] = columns.cy[b];
      view[r + Row.AWAKE] = (columns.flags[b] & BodyFlag.AWAKE) !== 0 ? 1 : 0;
      view[r + Row.MASS] = columns.mass[b];
      view[r + Row.INERTIA] = columns.inertia[b];
      view[r + Row.LCX] = columns.lcx[b];
      view[r + Row.LCY] = columns.lcy[b];
    }
    reply.buffer = buffer;
    if (!isShared(buffer)) transfer.push(buffer as ArrayBuffer);
  }

  /** The last step's events of the kinds asked for, handles as ids. */
  #events(kinds: readonly string[]): EventRecord {
    const events = this.#live().events;
    const shape = (s: ShapeHandle): number => this.#shapeIds.get(s)!;
    const body = (b: Body): number => this.#bodyIds.get(b)!;
    const record: EventRecord = {};
    for (const kind of EVENT_ORDER) {
      if (!kinds.includes(kind)) continue;
      switch (kind) {
        case 'contactBegin':
          record.contactBegin = events.contactBegin.flatMap((e) => {
            const p = e.points;
            const second = p.length > 1 ? [p[1].x, p[1].y] : [0, 0];
            return [
              shape(e.shapeA),
              shape(e.shapeB),
              e.normal.x,
              e.normal.y,
              p.length,
              p[0].x,
              p[0].y,
              ...second,
            ];
          });
          break;
        case 'contactEnd':
          record.contactEnd = events.contactEnd.flatMap((e) => [shape(e.shapeA), shape(e.shapeB)]);
          break;
        case 'contactHit':
          record.contactHit = events.contactHit.flatMap((e) => [
            shape(e.shapeA),
            shape(e.shapeB),
            e.point.x,
            e.point.y,
            e.normal.x,
            e.normal.y,
            e.approachSpeed,
          ]);
          break;
        case 'sensorBegin':
        case 'sensorEnd':
          record[kind] = events[kind].flatMap((e) => [shape(e.sensorShape), shape(e.visitorShape)]);
          break;
        case 'sleep':
        case 'wake':
          record[kind] = events[kind].map((e) => body(e.body));
          break;
        case 'warning':
          record.warning = events.warning.map((w) => ({
            type: w.type,
            count: w.count,
            limit: w.limit,
            shape: w.shape === null ? -1 : shape(w.shape),
            message: w.message,
          }));
          break;
      }
    }
    return record;
  }

  #query(name: string, args: Plain[]): Plain {
    const world = this.#live();
    const shapeId = (s: ShapeHandle): number => this.#shapeIds.get(s)!;
    switch (name) {
      case 'castRay': {
        const hit = world.castRay(...(args as Parameters<World['castRay']>));
        return hit === null ? null : hitOut(hit, shapeId);
      }
      case 'castRayAll':
        return world.castRayAll(...(args as Parameters<World['castRayAll']>)).map((h) => hitOut(h, shapeId));
      case 'castShape': {
        deepFreeze(args[0]);
        const hit = world.castShape(...(args as Parameters<World['castShape']>));
        return hit === null ? null : hitOut(hit, shapeId);
      }
      case 'queryAABB':
        return world.queryAABB(...(args as Parameters<World['queryAABB']>)).map(shapeId);
      case 'queryPoint':
        return world.queryPoint(...(args as Parameters<World['queryPoint']>)).map(shapeId);
      case 'overlapShape':
        deepFreeze(args[0]);
        return world.overlapShape(...(args as Parameters<World['overlapShape']>)).map(shapeId);
      case 'getContacts':
        return this.#body(args[0] as number)
          .getContacts()
          .map((c) => ({
            shapeA: shapeId(c.shapeA),
            shapeB: shapeId(c.shapeB),
            normal: c.normal,
            points: c.points,
          }));
      default:
        throw new FulcrumError(`worker: unknown query ${JSON.stringify(name)}`);
    }
  }
}
