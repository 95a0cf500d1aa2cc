import {
  type Body,
  FulcrumError,
  type Geometry,
  type Joint,
  Shape,
  type ShapeHandle,
  stateHash,
  World,
  type WorldDef,
  type WorldEvents,
} from '../../src/index';
import { invalidCalls } from './invalid-calls';
import type { EventName, GeometrySpec, JointSpec, Op, QuerySpec } from './ops';
import { tame } from './settings';

/** A broken invariant: fails the property (never caught as an API error). */
export class InvariantError extends Error {
  override readonly name = 'InvariantError';
}

function fail(message: string): never {
  throw new InvariantError(message);
}

export interface HarnessOptions {
  /** snapshotRestore ops really replace the world (false: they only take the snapshot) */
  restore: boolean;
  /** 'handlers': events are taken by handlers as they are delivered; 'arrays': read from world.events late */
  events: 'handlers' | 'arrays';
  /** check every invariant (false: only record the trace, for a replay) */
  check: boolean;
}

const SPEED_LIMIT_PER_UNIT = 400; // m/s, README "Speed limits"
const MAX_TURN_PER_SUBSTEP = Math.PI / 4; // a quarter turn per substep, README "Speed limits"
/** relative slack on the clamps: the clamp scales onto the limit, one rounding may land above it */
const CLAMP_SLACK = 1e-12;
/** nested world.step() calls from preStep/postStep handlers */
const MAX_DEPTH = 2;

interface HandlerEntry {
  event: EventName;
  budget: number;
  ops: Op[];
  unsubscribe: () => void;
  active: boolean;
}

interface Counts {
  bodies: number;
  shapes: number;
}

/**
 * Runs an op sequence against a World through the public API, keeping its own model of which handles
 * are alive, which contacts and sensor overlaps have begun, and checking the invariants after every
 * step (see checkStep) and around every call that throws (see guard). Everything it does depends on
 * the ops only, so two harnesses given the same ops must produce the same trace.
 */
export class Harness {
  world: World;
  readonly trace: (number | string)[] = [];
  readonly bodies: Body[] = [];
  readonly shapes: ShapeHandle[] = [];
  readonly joints: Joint[] = [];
  private readonly bodyAlive: boolean[] = [];
  private readonly shapeAlive: boolean[] = [];
  private readonly shapeBody: number[] = [];
  private readonly jointAlive: boolean[] = [];
  private readonly jointBodies: [number, number][] = [];
  private readonly bodyIndex = new Map<Body, number>();
  private readonly shapeIndex = new Map<ShapeHandle, number>();
  private readonly jointIndex = new Map<Joint, number>();
  private readonly handlers: HandlerEntry[] = [];
  /** contact pairs (registry indices, low first) and sensor overlaps (sensor, visitor) that have begun */
  private readonly touching = new Set<string>();
  private readonly sensing = new Set<string>();
  /** handles that existed when the last top-level step began, and the ones destroyed since */
  private stepCounts: Counts = { bodies: 0, shapes: 0 };
  private readonly createdInPreStep = new Set<number>();
  private readonly destroyedSinceStep = { bodies: new Set<number>(), shapes: new Set<number>() };
  private hitThreshold = 1;
  /** bodies that handlers changed since the top-level step began (see noteHandlerTouch) */
  private readonly touchedByHandlers = new Set<number>();
  /** a step has begun whose first event has not been delivered yet */
  private awaitingDelivery = false;
  private depth = 0;
  private handlerEvent: EventName | null = null;
  /** events of the last step still to be read from world.events ('arrays' mode) */
  private eventsPending = false;
  readonly units: number;

  constructor(
    def: WorldDef,
    readonly options: HarnessOptions,
  ) {
    this.world = new World(def);
    this.units = def.lengthUnitsPerMeter ?? 1;
    this.listen();
  }

  run(ops: readonly Op[]): void {
    for (const op of ops) this.exec(op);
    if (this.eventsPending) this.readEventArrays();
  }

  // ---- calls and their outcome -------------------------------------------------------------------

  /**
   * Runs one API call: it either succeeds (then `after` updates the model) or throws a FulcrumError
   * that left the world as it was. Anything else thrown is a bug. With `full`, "as it was" is checked
   * on the snapshot's bytes, otherwise on a cheap fingerprint.
   */
  private guard<T>(what: string, call: () => T, full = false): { ok: true; value: T } | { ok: false } {
    const before = this.fingerprint();
    const bytes = full ? this.world.snapshot() : undefined;
    try {
      const value = call();
      this.trace.push('ok');
      return { ok: true, value };
    } catch (e) {
      if (e instanceof InvariantError) throw e;
      if (!(e instanceof FulcrumError)) {
        fail(`${what} threw ${(e as Error)?.name ?? typeof e} instead of FulcrumError: ${String(e)}`);
      }
      if (!e.message) fail(`${what} threw a FulcrumError without a message`);
      this.trace.push('err');
      if (!this.options.check) return { ok: false };
      const after = this.fingerprint();
      if (after !== before) fail(`${what} threw "${e.message}" but changed the world: ${before} -> ${after}`);
      if (bytes !== undefined) {
        const now = this.world.snapshot();
        const at = firstDifference(bytes, now);
        if (at >= 0) fail(`${what} threw "${e.message}" but changed the snapshot at byte ${at}`);
      }
      return { ok: false };
    }
  }

  /** state hash, counts and settings: what a rejected call must leave as it was */
  private fingerprint(): string {
    const w = this.world;
    const g = w.gravity;
    return [
      stateHash(w),
      w.bodyCount,
      w.awakeBodyCount,
      w.contactCount,
      w.joints.length,
      g.x,
      g.y,
      w.subSteps,
      w.enableSleep,
      w.enableContinuous,
      w.hitEventThreshold,
    ].join(',');
  }

  /** Expects `call` to be refused with a FulcrumError that leaves the world's bytes as they were. */
  expectRejected(what: string, call: () => unknown): void {
    const result = this.guard(what, call, this.options.check);
    if (result.ok) fail(`${what} was accepted; a FulcrumError was expected`);
  }

  // ---- handles -------------------------------------------------------------------------------------

  pickBody(i: number): Body | undefined {
    return this.bodies.length === 0 ? undefined : this.bodies[i % this.bodies.length];
  }
  pickShape(i: number): ShapeHandle | undefined {
    return this.shapes.length === 0 ? undefined : this.shapes[i % this.shapes.length];
  }
  pickJoint(i: number): Joint | undefined {
    return this.joints.length === 0 ? undefined : this.joints[i % this.joints.length];
  }
  liveBody(i: number): Body | undefined {
    const live = this.bodies.filter((_, k) => this.bodyAlive[k]);
    return live.length === 0 ? undefined : live[i % live.length];
  }
  liveShape(i: number): ShapeHandle | undefined {
    const live = this.shapes.filter((_, k) => this.shapeAlive[k]);
    return live.length === 0 ? undefined : live[i % live.length];
  }
  liveJoint(i: number): Joint | undefined {
    const live = this.joints.filter((_, k) => this.jointAlive[k]);
    return live.length === 0 ? undefined : live[i % live.length];
  }
  deadBody(i: number): Body | undefined {
    const dead = this.bodies.filter((_, k) => !this.bodyAlive[k]);
    return dead.length === 0 ? undefined : dead[i % dead.length];
  }
  deadShape(i: number): ShapeHandle | undefined {
    const dead = this.shapes.filter((_, k) => !this.shapeAlive[k]);
    return dead.length === 0 ? undefined : dead[i % dead.length];
  }
  deadJoint(i: number): Joint | undefined {
    const dead = this.joints.filter((_, k) => !this.jointAlive[k]);
    return dead.length === 0 ? undefined : dead[i % dead.length];
  }

  private addBody(body: Body): number {
    const i = this.bodies.length;
    this.bodies.push(body);
    this.bodyAlive.push(true);
    this.bodyIndex.set(body, i);
    return i;
  }

  private addShape(shape: ShapeHandle, body: number): void {
    const i = this.shapes.length;
    this.shapes.push(shape);
    this.shapeAlive.push(true);
    this.shapeBody.push(body);
    this.shapeIndex.set(shape, i);
    if (this.handlerEvent === 'preStep') this.createdInPreStep.add(i);
  }

  private killShape(s: number): void {
    if (!this.shapeAlive[s]) return;
    this.shapeAlive[s] = false;
    this.destroyedSinceStep.shapes.add(s);
    this.forgetPairsOf([s]);
  }

  private killBody(b: number): void {
    this.bodyAlive[b] = false;
    this.destroyedSinceStep.bodies.add(b);
    for (let s = 0; s < this.shapes.length; s++) if (this.shapeBody[s] === b) this.killShape(s);
    for (let j = 0; j < this.joints.length; j++) {
      const [a, c] = this.jointBodies[j];
      if (a === b || c === b) this.jointAlive[j] = false;
    }
  }

  private shapesOfBody(b: number): number[] {
    const out: number[] = [];
    for (let s = 0; s < this.shapes.length; s++)
      if (this.shapeBody[s] === b && this.shapeAlive[s]) out.push(s);
    return out;
  }

  /**
   * A destroyed shape's contacts end without events; they cannot begin again. (Every other way a
   * contact ends must report it: a pair that began twice without an end between is a broken pair.)
   */
  private forgetPairsOf(shapes: readonly number[]): void {
    const set = new Set(shapes);
    for (const pairs of [this.touching, this.sensing]) {
      for (const key of [...pairs]) {
        const [a, b] = key.split(':').map(Number);
        if (set.has(a) || set.has(b)) pairs.delete(key);
      }
    }
  }

  // ---- ops -----------------------------------------------------------------------------------------

  exec(op: Op): void {
    if (this.depth > 0) this.noteHandlerTouch(op);
    switch (op.op) {
      case 'createBody': {
        const r = this.guard('createBody', () => this.world.createBody({ ...op.body }));
        if (!r.ok) return;
        const b = this.addBody(r.value);
        for (const s of op.shapes) this.createShape(b, s.geometry, s.def);
        return;
      }
      case 'createShape': {
        const body = this.pickBody(op.body);
        if (body) this.createShape(this.bodyIndex.get(body)!, op.geometry, op.def);
        return;
      }
      case 'destroyShape': {
        const shape = this.pickShape(op.shape);
        if (!shape) return;
        const s = this.shapeIndex.get(shape)!;
        const body = this.bodies[this.shapeBody[s]];
        if (this.guard('destroyShape', () => body.destroyShape(shape)).ok) this.killShape(s);
        return;
      }
      case 'destroyBody': {
        const body = this.pickBody(op.body);
        if (!body) return;
        if (this.guard('destroyBody', () => this.world.destroyBody(body)).ok)
          this.killBody(this.bodyIndex.get(body)!);
        return;
      }
      case 'createJoint': {
        const a = this.pickBody(op.a);
        const b = this.pickBody(op.b);
        if (a && b) this.createJoint(a, b, op.joint);
        return;
      }
      case 'network': {
        const made: Body[] = [];
        for (let i = 0; i < op.count; i++) {
          const spec = { type: 'dynamic' as const, position: { x: (i - op.count / 2) * 0.6, y: 2 } };
          const r = this.guard('createBody', () => this.world.createBody(spec));
          if (!r.ok) return;
          const b = this.addBody(r.value);
          made.push(r.value);
          this.createShape(
            b,
            { kind: 'box', hw: 0.25, hh: 0.1, center: undefined, angle: undefined },
            { density: op.density },
          );
        }
        // index 0 of the links' picks is the session's first body (the ground), the others the new ones
        const ends = [this.bodies[0], ...made];
        for (const link of op.links)
          this.createJoint(ends[link.a % ends.length], ends[link.b % ends.length], link.joint);
        return;
      }
      case 'destroyJoint': {
        const joint = this.pickJoint(op.joint);
        if (!joint) return;
        if (this.guard('destroyJoint', () => this.world.destroyJoint(joint)).ok)
          this.jointAlive[this.jointIndex.get(joint)!] = false;
        return;
      }
      case 'setJoint': {
        const joint = this.pickJoint(op.joint);
        if (!joint) return;
        const setters = jointSetters(joint, op);
        const [name, call] = setters[op.setter % setters.length];
        this.guard(`${joint.type}.${name}`, call);
        return;
      }
      case 'setTransform': {
        const body = this.pickBody(op.body);
        if (!body) return;
        this.guard(`setTransform(${op.which})`, () => {
          if (op.which === 'position') body.setPosition(op.position);
          else if (op.which === 'angle') body.setAngle(op.angle);
          else body.setTransform(op.position, op.angle);
        });
        return;
      }
      case 'setVelocity': {
        const body = this.pickBody(op.body);
        if (!body) return;
        if (op.linear) this.guard('setLinearVelocity', () => body.setLinearVelocity(op.linear!));
        if (op.angular !== undefined)
          this.guard('setAngularVelocity', () => body.setAngularVelocity(op.angular!));
        return;
      }
      case 'setType': {
        const body = this.pickBody(op.body);
        if (!body) return;
        this.guard('setType', () => body.setType(op.type));
        return;
      }
      case 'setAwake': {
        const body = this.pickBody(op.body);
        if (body) this.guard('setAwake', () => body.setAwake(op.awake));
        return;
      }
      case 'setBody': {
        const body = this.pickBody(op.body);
        if (!body) return;
        const { prop, value } = op.set;
        this.guard(`set ${prop}`, () => {
          if (prop === 'linearDamping') body.setLinearDamping(value as number);
          else if (prop === 'angularDamping') body.setAngularDamping(value as number);
          else if (prop === 'gravityScale') body.setGravityScale(value as number);
          else if (prop === 'fixedRotation') body.setFixedRotation(value as boolean);
          else if (prop === 'bullet') body.setBullet(value as boolean);
          else body.setAllowSleep(value as boolean);
        });
        return;
      }
      case 'apply': {
        const body = this.pickBody(op.body);
        if (!body) return;
        this.guard(`apply ${op.kind}`, () => {
          if (op.kind === 'force') body.applyForce(op.v, op.point);
          else if (op.kind === 'torque') body.applyTorque(op.n);
          else if (op.kind === 'linearImpulse') body.applyLinearImpulse(op.v, op.point);
          else body.applyAngularImpulse(op.n);
        });
        return;
      }
      case 'setShape': {
        const shape = this.pickShape(op.shape);
        if (!shape) return;
        const set = op.set;
        this.guard(`shape.${set.prop}`, () => {
          if (set.prop === 'filter') shape.filter = set.value;
          else if (set.prop === 'isSensor') shape.isSensor = set.value;
          else if (set.prop === 'enableHitEvents') shape.enableHitEvents = set.value;
          else shape[set.prop] = set.value as number;
        });
        return;
      }
      case 'setWorld': {
        const set = op.set;
        this.guard(`world.${set.prop}`, () => {
          if (set.prop === 'gravity') this.world.gravity = set.value;
          else if (set.prop === 'subSteps') this.world.subSteps = set.value;
          else if (set.prop === 'enableSleep') this.world.enableSleep = set.value;
          else if (set.prop === 'enableContinuous') this.world.enableContinuous = set.value;
          else this.world.hitEventThreshold = set.value as number;
        });
        return;
      }
      case 'query':
        this.query(op.query);
        return;
      case 'step':
        this.step(op.dt);
        return;
      case 'steps':
        for (let i = 0; i < op.count; i++) this.step(1 / 60);
        return;
      case 'snapshotRestore':
        if (this.depth === 0) this.snapshotRestore();
        return;
      case 'readEvents':
        this.readEventArrays();
        return;
      case 'on': {
        if (this.depth > 0) return;
        const entry: HandlerEntry = {
          event: op.event,
          budget: op.budget,
          ops: op.ops,
          unsubscribe: () => {},
          active: true,
        };
        this.handlers.push(entry);
        this.subscribe(entry);
        return;
      }
      case 'off': {
        if (this.handlers.length === 0) return;
        const entry = this.handlers[op.handler % this.handlers.length];
        entry.unsubscribe();
        entry.active = false;
        return;
      }
      case 'invalid': {
        const calls = invalidCalls;
        calls[op.call.target % calls.length](this, op.call.bad);
        return;
      }
    }
  }

  /**
   * A handler's op that sets a body's velocity, type or pose (or makes a body) runs after the solve:
   * the step's clamps do not apply to what it sets, so checkStep leaves that body's speed alone.
   */
  private noteHandlerTouch(op: Op): void {
    if (op.op === 'createBody') this.touchedByHandlers.add(this.bodies.length);
    else if (
      op.op === 'setVelocity' ||
      op.op === 'apply' ||
      op.op === 'setType' ||
      op.op === 'setTransform' ||
      op.op === 'setBody' ||
      op.op === 'setAwake'
    ) {
      const body = this.pickBody(op.body);
      if (body) this.touchedByHandlers.add(this.bodyIndex.get(body)!);
    }
  }

  private createShape(b: number, spec: GeometrySpec, def: object): void {
    const geometry = this.guard(`Shape.${spec.kind}`, () => makeGeometry(spec));
    if (!geometry.ok) return;
    const body = this.bodies[b];
    const r = this.guard(`createShape(${spec.kind})`, () => body.createShape(geometry.value, { ...def }));
    if (r.ok) this.addShape(r.value, b);
  }

  private createJoint(bodyA: Body, bodyB: Body, spec: JointSpec): void {
    const def = jointDef(spec, bodyA, bodyB);
    const a = this.bodyIndex.get(bodyA)!;
    const b = spec.type === 'mouse' ? a : this.bodyIndex.get(bodyB)!;
    const r = this.guard(`createJoint(${spec.type})`, () => this.world.createJoint(def as never));
    if (!r.ok) return;
    const i = this.joints.length;
    this.joints.push(r.value);
    this.jointAlive.push(true);
    this.jointBodies.push([a, b]);
    this.jointIndex.set(r.value, i);
  }

  private query(q: QuerySpec): void {
    const w = this.world;
    const hash = stateHash(w);
    if (q.kind === 'castRay' || q.kind === 'castRayAll') {
      const filter = q.includeSensors === undefined ? undefined : { includeSensors: q.includeSensors };
      if (q.kind === 'castRay') {
        const r = this.guard('castRay', () => w.castRay(q.origin, q.translation, filter));
        if (r.ok && r.value) this.checkHit('castRay', r.value);
      } else {
        const r = this.guard('castRayAll', () => w.castRayAll(q.origin, q.translation, filter));
        if (r.ok) {
          let last = 0;
          for (const hit of r.value) {
            this.checkHit('castRayAll', hit);
            if (hit.fraction < last) fail(`castRayAll: fractions not sorted (${hit.fraction} after ${last})`);
            last = hit.fraction;
          }
        }
      }
    } else if (q.kind === 'queryAABB' || q.kind === 'queryPoint') {
      const r = this.guard(q.kind, () =>
        q.kind === 'queryAABB'
          ? w.queryAABB({
              lowerBound: q.lower,
              upperBound: { x: q.lower.x + Math.abs(q.extent.x), y: q.lower.y + Math.abs(q.extent.y) },
            })
          : w.queryPoint(q.point),
      );
      if (r.ok) for (const s of r.value) this.checkLiveShape(q.kind, s);
    } else {
      const shaped = q as Extract<QuerySpec, { geometry: GeometrySpec }>;
      const spec = shaped.geometry;
      const geometry = this.guard(`Shape.${spec.kind}`, () => makeGeometry(spec));
      if (!geometry.ok) return;
      const transform = { position: shaped.position, angle: shaped.angle };
      if (q.kind === 'castShape') {
        const r = this.guard('castShape', () => w.castShape(geometry.value, transform, q.translation));
        if (r.ok && r.value) this.checkHit('castShape', r.value);
      } else {
        const r = this.guard('overlapShape', () => w.overlapShape(geometry.value, transform));
        if (r.ok) for (const s of r.value) this.checkLiveShape('overlapShape', s);
      }
    }
    if (this.options.check && stateHash(w) !== hash) fail(`${q.kind} changed the state hash`);
  }

  private checkHit(
    what: string,
    hit: { shape: ShapeHandle; body: Body; point: Vec; normal: Vec; fraction: number },
  ) {
    if (!this.options.check) return;
    this.checkLiveShape(what, hit.shape);
    if (hit.body !== hit.shape.body) fail(`${what}: hit.body is not hit.shape.body`);
    if (!(hit.fraction >= 0 && hit.fraction <= 1)) fail(`${what}: fraction ${hit.fraction} outside [0, 1]`);
    if (!finiteVec(hit.point) || !finiteVec(hit.normal))
      fail(`${what}: non-finite hit ${JSON.stringify(hit.point)}`);
    const n = Math.hypot(hit.normal.x, hit.normal.y);
    if (!(n === 0 || Math.abs(n - 1) < 1e-6)) fail(`${what}: normal of length ${n}`);
  }

  private checkLiveShape(what: string, shape: ShapeHandle): void {
    if (!this.options.check) return;
    const s = this.shapeIndex.get(shape);
    if (s === undefined) fail(`${what} returned a shape handle the user never made`);
    if (!this.shapeAlive[s]) fail(`${what} returned destroyed shape #${s}`);
  }

  // ---- stepping ------------------------------------------------------------------------------------

  private step(dt: number): void {
    if (this.depth > 0) {
      // world.step() from a handler: from preStep and postStep only (the other handlers run while the
      // step's events are being delivered), and not while events wait to be read from world.events
      if (this.depth > MAX_DEPTH || this.options.events === 'arrays') return;
      if (this.handlerEvent !== 'preStep' && this.handlerEvent !== 'postStep') return;
    }
    if (this.eventsPending) this.readEventArrays();
    const w = this.world;
    const subSteps = w.subSteps;
    this.beginStep();
    this.awaitingDelivery = true;
    const quiet = this.handlers.every((h) => !h.active || h.budget <= 0);
    const poses = this.options.check && quiet && dt > 0 ? this.posesBefore() : undefined;
    const r = this.guard(`step(${dt})`, () => w.step(dt));
    // no event delivered: the step solved all the same, what was destroyed before it is gone for good
    if (this.awaitingDelivery) this.forgetDestroyed();
    // a step from a preStep handler: the outer step's own solve and events are still to come
    if (this.handlerEvent === 'preStep') this.awaitingDelivery = true;
    if (!r.ok) return;
    this.trace.push(stateHash(this.world));
    if (this.options.events === 'arrays') this.eventsPending = true;
    if (this.options.check) this.checkStep(dt, subSteps, poses);
  }

  /**
   * Notes the handles that exist as a step solves: its events may name those, and the ones destroyed
   * after it (until the next step solves, world.events still holds its events, also in the next
   * step's preStep handlers). Called as a step begins, and again when its first event is delivered:
   * preStep handlers may have changed the world in between.
   */
  private beginStep(): void {
    if (this.depth === 0) this.touchedByHandlers.clear();
    this.stepCounts = { bodies: this.bodies.length, shapes: this.shapes.length };
    this.createdInPreStep.clear();
    this.hitThreshold = this.world.hitEventThreshold;
  }

  private forgetDestroyed(): void {
    this.destroyedSinceStep.bodies.clear();
    this.destroyedSinceStep.shapes.clear();
  }

  /** Called by the event recorders: the first event of a step's delivery. */
  private delivering(): void {
    if (!this.awaitingDelivery) return;
    this.awaitingDelivery = false;
    this.beginStep();
    this.forgetDestroyed();
  }

  /** World poses of kinematic and static bodies before a step with no handler that could move them. */
  private posesBefore(): Map<
    number,
    { c: Vec; q: { c: number; s: number }; v: Vec; w: number; awake: boolean }
  > {
    const out = new Map();
    for (let b = 0; b < this.bodies.length; b++) {
      if (!this.bodyAlive[b]) continue;
      const body = this.bodies[b];
      if (body.type === 'dynamic') continue;
      out.set(b, {
        c: body.worldCenter,
        q: body.rotation,
        v: body.linearVelocity,
        w: body.angularVelocity,
        awake: body.isAwake,
      });
    }
    return out;
  }

  /** The invariants that hold after every step. */
  private checkStep(
    dt: number,
    subSteps: number,
    poses: ReturnType<Harness['posesBefore']> | undefined,
  ): void {
    const w = this.world;
    const maxSpeed = SPEED_LIMIT_PER_UNIT * this.units * (1 + CLAMP_SLACK);
    const maxTurn = dt > 0 ? ((MAX_TURN_PER_SUBSTEP * subSteps) / dt) * (1 + CLAMP_SLACK) : Infinity;
    let live = 0;
    for (let b = 0; b < this.bodies.length; b++) {
      const body = this.bodies[b];
      if (body.isValid !== this.bodyAlive[b])
        fail(`body #${b}: isValid is ${body.isValid}, model says ${this.bodyAlive[b]}`);
      if (!this.bodyAlive[b]) continue;
      live++;
      const p = body.position;
      const q = body.rotation;
      const v = body.linearVelocity;
      const omega = body.angularVelocity;
      const c = body.worldCenter;
      if (!finiteVec(p) || !finiteVec(c) || !Number.isFinite(q.c) || !Number.isFinite(q.s)) {
        fail(`body #${b} (${body.type}): non-finite pose p=${show(p)} q=${show(q)} center=${show(c)}`);
      }
      if (!finiteVec(v) || !Number.isFinite(omega)) {
        fail(`body #${b} (${body.type}): non-finite velocity v=${show(v)} w=${omega}`);
      }
      const unit = q.c * q.c + q.s * q.s;
      if (!(Math.abs(unit - 1) < 1e-6))
        fail(`body #${b} (${body.type}): rotation not unit (c²+s² = ${unit})`);
      if (!Number.isFinite(body.angle)) fail(`body #${b}: angle ${body.angle}`);
      if (body.type !== 'static' && body.isAwake && dt > 0 && !this.touchedByHandlers.has(b)) {
        const speed = Math.hypot(v.x, v.y);
        if (speed > maxSpeed)
          fail(`body #${b}: speed ${speed} over the clamp ${SPEED_LIMIT_PER_UNIT * this.units}`);
        if (Math.abs(omega) > maxTurn) fail(`body #${b}: angular speed ${omega} over the clamp ${maxTurn}`);
      }
      const before = poses?.get(b);
      if (before && body.type !== 'dynamic') this.checkDrivenPose(b, body, before, dt, subSteps);
    }
    if (w.bodyCount !== live) fail(`world.bodyCount ${w.bodyCount}, model has ${live} live bodies`);
    if (!(w.awakeBodyCount >= 0 && w.awakeBodyCount <= live)) fail(`awakeBodyCount ${w.awakeBodyCount}`);

    for (let s = 0; s < this.shapes.length; s++) {
      if (this.shapes[s].isValid !== this.shapeAlive[s])
        fail(`shape #${s}: isValid is ${this.shapes[s].isValid}, model says ${this.shapeAlive[s]}`);
    }
    const liveJoints = this.joints.filter((_, j) => this.jointAlive[j]);
    for (let j = 0; j < this.joints.length; j++) {
      const joint = this.joints[j];
      if (joint.isValid !== this.jointAlive[j])
        fail(`joint #${j} (${joint.type}): isValid is ${joint.isValid}, model says ${this.jointAlive[j]}`);
      if (!this.jointAlive[j]) continue;
      const f = joint.getReactionForce();
      const t = joint.getReactionTorque();
      if (!finiteVec(f) || !Number.isFinite(t))
        fail(`joint #${j} (${joint.type}): reaction ${show(f)}, ${t}`);
    }
    const listed = w.joints;
    if (listed.length !== liveJoints.length || listed.some((joint, i) => joint !== liveJoints[i]))
      fail(`world.joints lists ${listed.length} joints, model has ${liveJoints.length}`);
    for (let b = 0; b < this.bodies.length; b++) {
      if (!this.bodyAlive[b]) continue;
      const body = this.bodies[b];
      const shapes = this.shapesOfBody(b).map((s) => this.shapes[s]);
      const actual = body.shapes;
      if (actual.length !== shapes.length || actual.some((s, i) => s !== shapes[i]))
        fail(`body #${b}.shapes has ${actual.length} shapes, model has ${shapes.length}`);
      const joints = liveJoints.filter((joint) => {
        const [a, c] = this.jointBodies[this.jointIndex.get(joint)!];
        return a === b || c === b;
      });
      const attached = body.joints;
      if (attached.length !== joints.length || attached.some((joint, i) => joint !== joints[i]))
        fail(`body #${b}.joints has ${attached.length} joints, model has ${joints.length}`);
    }
    this.checkDestroyedHandlesRefuse();
  }

  /**
   * A static body stays put; a kinematic one moves by exactly its velocity (or stays put asleep): the
   * velocity it reads after the step, which is the one it was given unless that was over the speed
   * limits, where the step scales it down to them (README, Speed limits).
   */
  private checkDrivenPose(
    b: number,
    body: Body,
    before: { c: Vec; q: { c: number; s: number }; v: Vec; w: number; awake: boolean },
    dt: number,
    subSteps: number,
  ): void {
    const c = body.worldCenter;
    const q = body.rotation;
    const same = c.x === before.c.x && c.y === before.c.y && q.c === before.q.c && q.s === before.q.s;
    if (body.type === 'static' || !before.awake) {
      if (!same) fail(`${body.type} body #${b} ${before.awake ? '' : 'asleep '}moved in a step`);
      return;
    }
    const v = body.linearVelocity;
    const w = body.angularVelocity;
    // the same velocity, or the same direction scaled down (never up, never turned)
    const k = Math.hypot(v.x, v.y) / Math.hypot(before.v.x, before.v.y);
    const scaled = v.x === before.v.x && v.y === before.v.y;
    const parallel =
      k <= 1 &&
      Math.abs(v.x - before.v.x * k) <= 1e-9 * Math.abs(before.v.x) &&
      Math.abs(v.y - before.v.y * k) <= 1e-9 * Math.abs(before.v.y);
    if (!scaled && !parallel)
      fail(`kinematic body #${b}: velocity ${show(before.v)} became ${show(v)} in a step`);
    if (!(w === before.w || (Math.sign(w) === Math.sign(before.w) && Math.abs(w) <= Math.abs(before.w))))
      fail(`kinematic body #${b}: angular velocity ${before.w} became ${w} in a step`);
    const ex = before.c.x + v.x * dt;
    const ey = before.c.y + v.y * dt;
    const tol =
      1e-9 * (1 + Math.abs(before.c.x) + Math.abs(before.c.y) + (Math.abs(v.x) + Math.abs(v.y)) * dt);
    if (!(Math.abs(c.x - ex) <= tol && Math.abs(c.y - ey) <= tol))
      fail(`kinematic body #${b}: centre ${show(c)} after a step, expected ${show({ x: ex, y: ey })}`);
    // expected rotation: the old one turned by w dt
    const turn = w * dt;
    if (tame && Math.abs(turn / subSteps) > MAX_TURN_PER_SUBSTEP) return;
    const tc = Math.cos(turn);
    const ts = Math.sin(turn);
    const qc = before.q.c * tc - before.q.s * ts;
    const qs = before.q.s * tc + before.q.c * ts;
    if (!(Math.abs(q.c - qc) < 1e-6 && Math.abs(q.s - qs) < 1e-6))
      fail(
        `kinematic body #${b} turning at ${before.w} rad/s: rotation ${show(q)} after a step of ${dt} s, expected ${show({ c: qc, s: qs })}`,
      );
  }

  private checkDestroyedHandlesRefuse(): void {
    const body = this.deadBody(0);
    const shape = this.deadShape(0);
    const joint = this.deadJoint(0);
    const refuse = (what: string, f: () => unknown) => {
      try {
        f();
      } catch (e) {
        if (e instanceof FulcrumError) return;
        fail(`${what} on a destroyed handle threw ${String(e)} instead of FulcrumError`);
      }
      fail(`${what} on a destroyed handle did not throw`);
    };
    if (body && body.world === this.world) refuse('body.position', () => body.position);
    if (shape && shape.body.world === this.world) refuse('shape.friction', () => shape.friction);
    if (joint && joint.world === this.world)
      refuse('joint.getReactionForce()', () => joint.getReactionForce());
  }

  // ---- events --------------------------------------------------------------------------------------

  private listen(): void {
    if (this.options.events !== 'handlers') return;
    const w = this.world;
    w.on('contactBegin', (e) => this.onContact('contactBegin', e));
    w.on('contactEnd', (e) => this.onContact('contactEnd', e));
    w.on('contactHit', (e) => this.onContact('contactHit', e));
    w.on('sensorBegin', (e) => this.onSensor('sensorBegin', e));
    w.on('sensorEnd', (e) => this.onSensor('sensorEnd', e));
    w.on('sleep', (e) => this.onBodyEvent('sleep', e.body));
    w.on('wake', (e) => this.onBodyEvent('wake', e.body));
  }

  private subscribe(entry: HandlerEntry): void {
    entry.unsubscribe = this.world.on(entry.event, () => {
      // every handler but preStep's runs once the step has solved: its events name what took part,
      // destroyed here or not
      if (entry.event !== 'preStep') this.delivering();
      if (entry.budget <= 0) return;
      entry.budget--;
      const outer = this.handlerEvent;
      this.handlerEvent = entry.event;
      this.depth++;
      try {
        for (const op of entry.ops) this.exec(op);
      } finally {
        this.depth--;
        this.handlerEvent = outer;
      }
    });
  }

  /** Checks one shape named by an event of the last step and returns its registry index. */
  private eventShape(what: string, shape: ShapeHandle | undefined): number {
    const s = shape === undefined ? undefined : this.shapeIndex.get(shape);
    if (s === undefined) fail(`${what} names a shape handle the user never made (${String(shape)})`);
    if (s >= this.stepCounts.shapes && !this.createdInPreStep.has(s))
      fail(`${what} names shape #${s}, made after the step (a reused slot?)`);
    if (!this.shapeAlive[s] && !this.destroyedSinceStep.shapes.has(s))
      fail(`${what} names shape #${s}, destroyed before the step`);
    return s;
  }

  private eventBody(what: string, body: Body | undefined): number {
    const b = body === undefined ? undefined : this.bodyIndex.get(body);
    if (b === undefined) fail(`${what} names a body handle the user never made`);
    if (!this.bodyAlive[b] && !this.destroyedSinceStep.bodies.has(b))
      fail(`${what} names body #${b}, destroyed before the step`);
    return b;
  }

  private onContact(
    what: 'contactBegin' | 'contactEnd' | 'contactHit',
    e: {
      shapeA: ShapeHandle;
      shapeB: ShapeHandle;
      bodyA: Body;
      bodyB: Body;
      normal?: Vec;
      points?: Vec[];
      point?: Vec;
      approachSpeed?: number;
    },
  ): void {
    this.delivering();
    const a = this.eventShape(what, e.shapeA);
    const b = this.eventShape(what, e.shapeB);
    this.trace.push(`${what}:${a}:${b}`);
    if (!this.options.check) return;
    if (a === b) fail(`${what} of shape #${a} with itself`);
    if (e.bodyA !== e.shapeA.body || e.bodyB !== e.shapeB.body)
      fail(`${what}: bodyA/bodyB are not the shapes' bodies`);
    this.eventBody(what, e.bodyA);
    this.eventBody(what, e.bodyB);
    if (e.bodyA === e.bodyB) fail(`${what} between two shapes of body #${this.bodyIndex.get(e.bodyA)}`);
    const key = a < b ? `${a}:${b}` : `${b}:${a}`;
    if (what === 'contactBegin') {
      if (!finiteVec(e.normal!) || Math.abs(Math.hypot(e.normal!.x, e.normal!.y) - 1) > 1e-6)
        fail(`contactBegin: normal ${show(e.normal)}`);
      if (e.points!.length > 2 || !e.points!.every(finiteVec)) fail(`contactBegin: points ${show(e.points)}`);
      if (this.touching.has(key)) fail(`contactBegin of shapes #${a} and #${b} twice without a contactEnd`);
      if (this.shapeAlive[a] && this.shapeAlive[b]) this.touching.add(key);
    } else if (what === 'contactEnd') {
      // the record of a step names shapes destroyed since (by an earlier handler): their pairs were
      // forgotten then, and their ends are still delivered
      const gone = !this.shapeAlive[a] || !this.shapeAlive[b];
      if (!this.touching.delete(key) && !gone)
        fail(`contactEnd of shapes #${a} and #${b} without a contactBegin`);
    } else {
      if (!finiteVec(e.point!) || !finiteVec(e.normal!))
        fail(`contactHit: ${show(e.point)} ${show(e.normal)}`);
      if (!(e.approachSpeed! >= this.hitThreshold))
        fail(`contactHit: approach speed ${e.approachSpeed} below the threshold ${this.hitThreshold}`);
    }
  }

  private onSensor(
    what: 'sensorBegin' | 'sensorEnd',
    e: { sensorShape: ShapeHandle; visitorShape: ShapeHandle },
  ): void {
    this.delivering();
    const s = this.eventShape(what, e.sensorShape);
    const v = this.eventShape(what, e.visitorShape);
    this.trace.push(`${what}:${s}:${v}`);
    if (!this.options.check) return;
    if (s === v) fail(`${what} of shape #${s} with itself`);
    const key = `${s}:${v}`;
    if (what === 'sensorBegin') {
      if (this.sensing.has(key)) fail(`sensorBegin of #${s} and #${v} twice without a sensorEnd`);
      if (this.shapeAlive[s] && this.shapeAlive[v]) this.sensing.add(key);
    } else if (!this.sensing.delete(key) && this.shapeAlive[s] && this.shapeAlive[v])
      fail(`sensorEnd of #${s} and #${v} without a sensorBegin`);
  }

  private onBodyEvent(what: 'sleep' | 'wake', body: Body): void {
    this.delivering();
    const b = this.eventBody(what, body);
    this.trace.push(`${what}:${b}`);
  }

  /** Reads world.events (the arrays of the last step) and checks every handle they name. */
  private readEventArrays(): void {
    this.eventsPending = false;
    let events: WorldEvents;
    try {
      events = this.world.events;
    } catch (e) {
      if (e instanceof InvariantError) throw e;
      fail(`reading world.events threw ${String(e)}`);
    }
    const check = (what: string, shapes: (ShapeHandle | undefined)[], bodies: (Body | undefined)[]) => {
      const ids = shapes.map((s) => this.eventShape(what, s));
      for (const b of bodies) this.eventBody(what, b);
      // a restored world's arrays have no sleep and wake events (snapshot.ts): left out of the trace
      if (shapes.length > 0) this.trace.push(`${what}:${ids.join(':')}`);
    };
    for (const e of events.contactBegin)
      check('world.events.contactBegin', [e.shapeA, e.shapeB], [e.bodyA, e.bodyB]);
    for (const e of events.contactEnd)
      check('world.events.contactEnd', [e.shapeA, e.shapeB], [e.bodyA, e.bodyB]);
    for (const e of events.contactHit)
      check('world.events.contactHit', [e.shapeA, e.shapeB], [e.bodyA, e.bodyB]);
    for (const e of events.sensorBegin)
      check('world.events.sensorBegin', [e.sensorShape, e.visitorShape], []);
    for (const e of events.sensorEnd) check('world.events.sensorEnd', [e.sensorShape, e.visitorShape], []);
    for (const e of events.sleep) check('world.events.sleep', [], [e.body]);
    for (const e of events.wake) check('world.events.wake', [], [e.body]);
  }

  // ---- snapshots -----------------------------------------------------------------------------------

  /** Replaces the world by one restored from its snapshot, with every handle mapped to its new one. */
  private snapshotRestore(): void {
    if (this.eventsPending) this.readEventArrays();
    const old = this.world;
    const bytes = old.snapshot();
    if (!this.options.restore) return;
    const restored = World.restore(bytes);
    if (this.options.check) {
      if (stateHash(restored) !== stateHash(old)) fail('the restored world has another state hash');
      const again = restored.snapshot();
      const at = firstDifference(bytes, again);
      if (at >= 0) fail(`the restored world's snapshot differs from the original's at byte ${at}`);
    }
    const newBodies = [...restored.bodies];
    const oldBodies = [...old.bodies];
    if (newBodies.length !== oldBodies.length) fail('the restored world has another number of bodies');
    for (let k = 0; k < oldBodies.length; k++) {
      const b = this.bodyIndex.get(oldBodies[k])!;
      const oldShapes = oldBodies[k].shapes;
      const newShapes = newBodies[k].shapes;
      if (oldShapes.length !== newShapes.length) fail(`restored body #${b} has another number of shapes`);
      this.bodies[b] = newBodies[k];
      this.bodyIndex.set(newBodies[k], b);
      for (let i = 0; i < oldShapes.length; i++) {
        const s = this.shapeIndex.get(oldShapes[i])!;
        this.shapes[s] = newShapes[i];
        this.shapeIndex.set(newShapes[i], s);
      }
    }
    const oldJoints = old.joints;
    const newJoints = restored.joints;
    for (let k = 0; k < oldJoints.length; k++) {
      const j = this.jointIndex.get(oldJoints[k])!;
      this.joints[j] = newJoints[k];
      this.jointIndex.set(newJoints[k], j);
    }
    this.world = restored;
    this.listen();
    for (const entry of this.handlers) if (entry.active) this.subscribe(entry);
  }
}

type Vec = { x: number; y: number };

function finiteVec(v: Vec): boolean {
  return Number.isFinite(v.x) && Number.isFinite(v.y);
}

function show(v: unknown): string {
  return JSON.stringify(v, (_, x) => (typeof x === 'number' && !Number.isFinite(x) ? String(x) : x));
}

export function firstDifference(a: Uint8Array, b: Uint8Array): number {
  const n = Math.min(a.length, b.length);
  for (let i = 0; i < n; i++) if (a[i] !== b[i]) return i;
  return a.length === b.length ? -1 : n;
}

export function makeGeometry(spec: GeometrySpec): Geometry {
  switch (spec.kind) {
    case 'circle':
      return Shape.circle(spec.radius, spec.center);
    case 'box':
      return Shape.box(spec.hw, spec.hh, spec.center, spec.angle);
    case 'polygon':
      return Shape.polygon(spec.points, spec.radius);
    case 'capsule':
      return Shape.capsule(spec.p1, spec.p2, spec.radius);
    case 'segment':
      return Shape.segment(spec.p1, spec.p2);
  }
}

/** The definition of the spec's joint type, with only the options that type takes. */
export function jointDef(spec: JointSpec, bodyA: Body, bodyB: Body): Record<string, unknown> {
  const anchors =
    spec.anchor !== undefined
      ? { anchor: spec.anchor }
      : { localAnchorA: spec.localAnchorA, localAnchorB: spec.localAnchorB };
  const lower = Math.min(spec.lower, spec.upper);
  const upper = Math.max(spec.lower, spec.upper);
  const spring = { enableSpring: spec.enableSpring, hertz: spec.hertz, dampingRatio: spec.dampingRatio };
  const base = { bodyA, bodyB, collideConnected: spec.collideConnected };
  let def: Record<string, unknown>;
  switch (spec.type) {
    case 'distance':
      def = {
        ...base,
        localAnchorA: spec.localAnchorA,
        localAnchorB: spec.localAnchorB,
        length: spec.length,
        minLength: spec.minLength,
        maxLength: spec.maxLength,
        ...spring,
      };
      break;
    case 'revolute':
      def = {
        ...base,
        ...anchors,
        ...spring,
        referenceAngle: spec.referenceAngle,
        enableLimit: spec.enableLimit,
        lowerAngle: lower,
        upperAngle: upper,
        enableMotor: spec.enableMotor,
        motorSpeed: spec.motorSpeed,
        maxMotorTorque: spec.maxMotor,
      };
      break;
    case 'prismatic':
      def = {
        ...base,
        ...anchors,
        ...spring,
        axis: spec.axis,
        referenceAngle: spec.referenceAngle,
        enableLimit: spec.enableLimit,
        lower,
        upper,
        enableMotor: spec.enableMotor,
        motorSpeed: spec.motorSpeed,
        maxMotorForce: spec.maxMotor,
      };
      break;
    case 'weld':
      def = {
        ...base,
        ...anchors,
        referenceAngle: spec.referenceAngle,
        linearHertz: spec.linearHertz,
        angularHertz: spec.angularHertz,
        dampingRatio: spec.dampingRatio,
      };
      break;
    case 'wheel':
      def = {
        ...base,
        ...anchors,
        ...spring,
        axis: spec.axis,
        enableMotor: spec.enableMotor,
        motorSpeed: spec.motorSpeed,
        maxMotorTorque: spec.maxMotor,
        enableLimit: spec.enableLimit,
        lower,
        upper,
      };
      break;
    case 'mouse':
      def = {
        body: bodyA,
        target: spec.target,
        maxForce: spec.maxForce,
        hertz: spec.hertz,
        dampingRatio: spec.dampingRatio,
      };
      break;
    case 'motor':
      def = {
        ...base,
        linearOffset: spec.linearOffset,
        angularOffset: spec.angularOffset,
        maxForce: spec.maxForce,
        maxTorque: spec.maxTorque,
        correctionFactor: spec.correctionFactor,
      };
      break;
  }
  for (const key of Object.keys(def)) if (def[key] === undefined) delete def[key];
  if (tame)
    for (const key of ['enableLimit', 'enableMotor', 'enableSpring']) if (key in def) def[key] = false;
  return { type: spec.type, ...def };
}

type SetterOp = { n1: number; n2: number; n3: number; flag: boolean; v: Vec };

/** The joint's own setters, called with the op's values. */
export function jointSetters(joint: Joint, op: SetterOp): [string, () => void][] {
  const j = joint as unknown as Record<string, (...args: unknown[]) => void>;
  const lo = Math.min(op.n1, op.n2);
  const hi = Math.max(op.n1, op.n2);
  const has = (name: string) => typeof j[name] === 'function';
  const out: [string, () => void][] = [];
  const add = (name: string, ...args: unknown[]) => {
    if (tame && name.startsWith('enable')) return;
    if (has(name)) out.push([name, () => j[name].call(joint, ...args)]);
  };
  add('enableMotor', op.flag);
  add('setMotorSpeed', op.n1);
  add('setMaxMotorTorque', Math.abs(op.n2));
  add('setMaxMotorForce', Math.abs(op.n2));
  add('enableLimit', op.flag);
  add('setLimits', lo, hi);
  add('enableSpring', op.flag);
  add('setSpring', Math.abs(op.n1), op.n3);
  add('setLength', Math.abs(op.n1));
  add(
    'setLengthRange',
    Math.min(Math.abs(op.n1), Math.abs(op.n2)),
    Math.max(Math.abs(op.n1), Math.abs(op.n2)),
  );
  add('setStiffness', Math.abs(op.n1), Math.abs(op.n2), op.n3);
  add('setTarget', op.v);
  add('setLinearOffset', op.v);
  add('setAngularOffset', op.n1);
  add('setMaxForce', Math.abs(op.n2));
  add('setMaxTorque', Math.abs(op.n2));
  return out;
}
