import { type Body, type BodyDef, type MassData, type ResolvedBodyDef, resolveBodyDef } from '../api/body';
import { EVENT_NAMES } from '../api/events';
import type { Filter, ShapeHandle } from '../api/shape';
import { checkWorkers, World, type WorldDef } from '../api/world';
import { Emitter } from '../core/emitter';
import { checkKnownKeys, FulcrumError, fail } from '../core/errors';
import { checkRoom } from '../core/index-bound';
import { checkVector, checkZeroOrRange, Limits } from '../core/limits';
import { Shape } from '../geometry/shapes';
import type { Geometry } from '../geometry/types';
import { buildJoint } from '../joints/create-joint';
import type { Joint } from '../joints/joint';
import type { JointDef, JointType, JointTypes } from '../joints/registry';
import type { AABB } from '../math/aabb';
import type { Vec2 } from '../math/vec2';
import type { QueryFilter, QueryTransform } from '../query/index';
import { decodeEvents, type WorkerWorldEventMap } from './events';
import { WorkerBody, type WorkerContactData, WorkerJoint, WorkerShape } from './handles';
import { deepFreeze, toPlain } from './plain';
import { type PortListener, startWorker, type WorkerPort } from './platform';
import {
  bodySettingsOf,
  type Command,
  EVENT_ORDER,
  type EventKind,
  JOINT_ANCHORS_STRIDE,
  type JointCommand,
  JointRead,
  type Plain,
  type PlainDef,
  type QueryName,
  type Reply,
  type Request,
  type RestoredHandles,
  Row,
  type ShapeSettings,
} from './protocol';

/** How the worker hands each step's state over: one shared memory, or buffers moved back and forth. */
export type BufferMode = 'shared' | 'transfer';

export interface WorkerOptions {
  /** the worker's script; by default the package's worker-entry.js beside this module */
  url?: URL | string;
  /** 'auto' (default): 'shared' where SharedArrayBuffer is available (Node; a cross-origin isolated page), 'transfer' otherwise */
  buffers?: 'auto' | BufferMode;
  /**
   * How long the worker may leave a request unanswered, in milliseconds, before the world fails as if
   * the worker had crashed (default 10,000; Infinity, or anything over 24 days, never). It counts from
   * the request, or from the last reply when requests queue behind one another.
   */
  requestTimeoutMs?: number;
}

export interface WorkerWorldDef extends WorldDef {
  worker?: WorkerOptions;
}

/** A definition's value with its Body handles as WorkerBody handles. */
type WithWorkerBodies<D> = { [K in keyof D]: D[K] extends Body ? WorkerBody : D[K] };

/** A joint definition of World.createJoint, its bodies WorkerBody handles. */
export type WorkerJointDef = { [T in JointType]: WithWorkerBodies<JointTypes[T]['def']> }[JointType];

/** A ray or shape cast's answer (see CastHit) with worker handles. */
export interface WorkerCastHit {
  shape: WorkerShape;
  body: WorkerBody;
  point: Vec2;
  normal: Vec2;
  fraction: number;
}

const OPTION_KEYS = ['url', 'buffers', 'requestTimeoutMs'] as const;
const DEFAULT_TIMEOUT_MS = 10_000;
/** The longest delay timers take (2^31 - 1 ms, 24.8 days): a longer one fires at once. */
const MAX_TIMER_MS = 0x7fffffff;
const BODY_KEYS = ['bodyA', 'bodyB', 'body'] as const;

/** A request waiting for its reply: `settle` reads the reply (in order, as it arrives) and ends the promise. */
interface Waiting {
  seq: number;
  settle(reply: Reply): void;
  reject(error: unknown): void;
}

/** A destroyed handle's id, given back for reuse once the reply to batch `seq` has arrived. */
interface Release {
  seq: number;
  list: 'bodies' | 'shapes' | 'joints';
  id: number;
}

interface CheckedOptions {
  url: URL | string | undefined;
  shared: boolean;
  timeoutMs: number;
}

/** A request timeout: a positive number of milliseconds, or Infinity. */
function checkTimeout(argument: string, value: unknown): number {
  if (typeof value !== 'number' || Number.isNaN(value) || value <= 0) {
    fail(argument, value, 'a positive number of milliseconds, or Infinity');
  }
  return value;
}

function checkOptions(options: unknown): CheckedOptions {
  if (options === undefined)
    return { url: undefined, shared: sharedAvailable(), timeoutMs: DEFAULT_TIMEOUT_MS };
  if (typeof options !== 'object' || options === null) fail('worker', options, 'an object');
  checkKnownKeys('worker', options, OPTION_KEYS);
  const { url, buffers, requestTimeoutMs } = options as WorkerOptions;
  if (url !== undefined && typeof url !== 'string' && !(url instanceof URL)) {
    fail('worker.url', url, 'a string or a URL');
  }
  if (buffers !== undefined && buffers !== 'auto' && buffers !== 'shared' && buffers !== 'transfer') {
    fail('worker.buffers', buffers, "'auto', 'shared' or 'transfer'");
  }
  if (buffers === 'shared' && !sharedAvailable()) {
    throw new FulcrumError(
      "worker.buffers: 'shared' needs SharedArrayBuffer, which this page does not have (it is not cross-origin isolated)",
    );
  }
  return {
    url,
    shared: buffers === 'shared' || ((buffers ?? 'auto') === 'auto' && sharedAvailable()),
    timeoutMs:
      requestTimeoutMs === undefined
        ? DEFAULT_TIMEOUT_MS
        : checkTimeout('worker.requestTimeoutMs', requestTimeoutMs),
  };
}

function sharedAvailable(): boolean {
  const g = globalThis as { crossOriginIsolated?: boolean };
  return typeof SharedArrayBuffer === 'function' && g.crossOriginIsolated !== false;
}

/** A body definition with every option given, as the worker's World.createBody takes it. */
function fullBodyDef(d: ResolvedBodyDef): PlainDef {
  return {
    type: d.type,
    position: d.position,
    angle: d.angle,
    linearVelocity: d.v,
    angularVelocity: d.w,
    linearDamping: d.linearDamping,
    angularDamping: d.angularDamping,
    gravityScale: d.gravityScale,
    fixedRotation: d.fixedRotation,
    bullet: d.bullet,
    allowSleep: d.allowSleep,
    awake: d.awake,
  };
}

/**
 * A Fulcrum World running in a worker (worker_threads on Node, a Web Worker in browsers), behind an
 * API that mirrors World's for building and commanding it.
 *
 * - Building and commanding (createBody, createShape, createJoint, destroy*, the body setters and
 *   forces, gravity) returns at once: handles get their ids here, and the command is queued. Queued
 *   commands go to the worker with the next request (a step, a query, a snapshot, a hash), which
 *   applies them in the order given before it answers: the same calls give the same bits as on World.
 * - `step(dt)` resolves once the worker has stepped. The state it left (every body's pose, velocities,
 *   centre of mass, awake flag, mass data and the pose before the step; every joint's reads) then
 *   reads synchronously from the handles, and the step's events have been delivered to the `on`
 *   handlers.
 * - Bad input throws the FulcrumError World would throw, at the call, and queues nothing: the calling
 *   thread checks everything with the engine's own checks. What only the worker can tell (bytes that
 *   are no snapshot, a command the worker's World refuses) rejects the request's promise with a
 *   FulcrumError of World's message; the commands it refused change nothing, the others apply.
 * - A worker that fails (throws, exits) rejects every waiting promise with a FulcrumError that says
 *   so; every later call throws it (or rejects, for the calls that return a promise).
 */
export class WorkerWorld {
  /** checks what the calling thread is given with the engine's own checks (and nothing else) */
  readonly #scratch: World;
  /** bodies of #scratch that stand for a joint definition's bodies while it is checked */
  readonly #scratchBodies: Body[] = [];
  readonly #shared: boolean;
  /** stand-ins on #scratch that check what World checks on a body, a shape or a joint of each type */
  #massStandIn: Body | null = null;
  #filterStandIn: ShapeHandle | null = null;
  readonly #jointStandIns = new Map<JointType, Joint>();
  #timeoutMs: number;
  /** runs out when the worker has left what waits unanswered for #timeoutMs */
  #timer: ReturnType<typeof setTimeout> | null = null;
  #port: WorkerPort | null = null;
  #failure: FulcrumError | null = null;
  #queue: Command[] = [];
  #nextSeq = 0;
  readonly #waiting: Waiting[] = [];
  readonly #releases: Release[] = [];
  /** the state of the last finished step, and spare buffers for the next ones */
  #view: Float64Array = new Float64Array(0);
  #current: ArrayBufferLike | null = null;
  readonly #spares: ArrayBufferLike[] = [];
  readonly #bodies: (WorkerBody | undefined)[] = [];
  readonly #shapes: (WorkerShape | undefined)[] = [];
  readonly #joints: (WorkerJoint | undefined)[] = [];
  readonly #free = { bodies: [] as number[], shapes: [] as number[], joints: [] as number[] };
  readonly #generations: number[] = [];
  #bodyCount = 0;
  #shapeCount = 0;
  #jointCount = 0;
  #gravity: Vec2;
  #stepCount = 0;
  #stepMs = 0;
  #threads = 1;
  readonly #handlers = new Emitter<WorkerWorldEventMap>();

  private constructor(scratch: World, options: CheckedOptions) {
    this.#scratch = scratch;
    this.#shared = options.shared;
    this.#timeoutMs = options.timeoutMs;
    this.#gravity = scratch.gravity;
  }

  /**
   * A new world in a new worker: `def` as World's (checked here as World checks it) and `worker`
   * options. Resolves once the worker runs the world.
   */
  static create(def: WorkerWorldDef = {}): Promise<WorkerWorld> {
    if (typeof def !== 'object' || def === null) fail('def', def, 'an object');
    const { worker, workers, workerUrl, ...worldDef } = def;
    const options = checkOptions(worker);
    // the world in the worker starts its own solver workers (see WorldDef.workers); this thread's
    // stand-in only checks the definition, so it gets none
    checkWorkers({ workers, workerUrl });
    const world = new WorkerWorld(new World(worldDef), options);
    const url = workerUrl === undefined ? undefined : String(workerUrl);
    return world
      .#start(options.url, {
        kind: 'create',
        def: toPlain({ ...worldDef, workers, workerUrl: url }) as PlainDef,
        buffer: world.#buffer(),
      })
      .then(() => world);
  }

  /**
   * A world restored from `world.snapshot()` bytes (of a World or a WorkerWorld) in a new worker; it
   * steps on bit-identically. Its bodies, shapes and joints get new handles, listed by `bodies`,
   * `body.shapes` and `joints` in the order World.restore's world lists them. The bytes are read in
   * the worker: bytes that are no snapshot reject with World.restore's FulcrumError.
   */
  static restore(bytes: Uint8Array, options?: WorkerOptions): Promise<WorkerWorld> {
    if (!(bytes instanceof Uint8Array)) fail('bytes', bytes, 'a Uint8Array made by world.snapshot()');
    const checked = checkOptions(options);
    const world = new WorkerWorld(new World(), checked);
    return world
      .#start(checked.url, { kind: 'restore', bytes, buffer: world.#buffer() }, (reply) =>
        world.#adoptRestored(reply),
      )
      .then(() => world);
  }

  #start(url: URL | string | undefined, request: Request, read?: (reply: Reply) => void): Promise<void> {
    const listener: PortListener = {
      reply: (reply) => this.#onReply(reply),
      failure: (error) => this.#fail(error),
    };
    return startWorker(url, listener).then((port) => {
      this.#port = port;
      return this.#request(request, (reply) => {
        // a world the worker could not make (bytes that are no snapshot) has no state to read
        if (reply.error !== undefined) return;
        this.#adopt(reply);
        read?.(reply);
      }).catch((error: unknown) => {
        this.terminate();
        throw error;
      });
    });
  }

  /** 'shared' when the worker writes each step's state into shared memory, 'transfer' when it moves buffers */
  get bufferMode(): BufferMode {
    return this.#shared ? 'shared' : 'transfer';
  }

  get gravity(): Vec2 {
    return { x: this.#gravity.x, y: this.#gravity.y };
  }

  set gravity(value: Vec2) {
    this.#usable();
    const g = checkVector('gravity', value, Limits.RATE);
    this.queue(['gravity', g]);
    this.#gravity = g;
  }

  /** Live bodies in id order. */
  get bodies(): Iterable<WorkerBody> {
    return this.#bodies.filter((body): body is WorkerBody => body !== undefined && !body.destroyed);
  }

  get bodyCount(): number {
    return this.#bodyCount;
  }

  /** Live joints in id order. */
  get joints(): readonly WorkerJoint[] {
    return this.#joints.filter((joint): joint is WorkerJoint => joint !== undefined && !joint.destroyed);
  }

  /** @internal the shapes the world holds, counting those its queued commands make */
  get shapeCount(): number {
    return this.#shapeCount;
  }

  /** @internal the state of the last finished step, one Row per body id */
  get stateView(): Float64Array {
    return this.#view;
  }

  /** @internal every body handle by id, destroyed ones and empty ids included (for drawing) */
  get bodyList(): readonly (WorkerBody | undefined)[] {
    return this.#bodies;
  }

  /**
   * How long the worker may leave a request unanswered before the world fails (see
   * WorkerOptions.requestTimeoutMs); changed, it counts from now for what waits.
   */
  get requestTimeoutMs(): number {
    return this.#timeoutMs;
  }

  set requestTimeoutMs(value: number) {
    this.#timeoutMs = checkTimeout('requestTimeoutMs', value);
    if (this.#waiting.length > 0 && this.#failure === null) this.#arm();
  }

  /**
   * Why the world stopped: the FulcrumError its worker failed with (it threw, exited, or left a
   * request unanswered too long), or that it was terminated; null while it runs. Every command
   * throws it then, and every request rejects with it.
   */
  get failure(): FulcrumError | null {
    return this.#failure;
  }

  /** Steps the worker has finished (whose promise has resolved or is about to). */
  get stepCount(): number {
    return this.#stepCount;
  }

  /** How long the worker's last step took, in milliseconds (measured in the worker; output only). */
  get lastStepMs(): number {
    return this.#stepMs;
  }

  /** The threads that solved the last step: the definition's `workers` once the world's own have started. */
  get workers(): number {
    return this.#threads;
  }

  #usable(): void {
    if (this.#failure !== null) throw this.#failure;
  }

  /** @internal the seq of the batch that the commands queued now will go with */
  get queueSeq(): number {
    return this.#nextSeq;
  }

  /** @internal queues a checked command for the next request */
  queue(command: Command): void {
    this.#usable();
    this.#queue.push(command);
  }

  /** A free id of `list` (the lowest released last), or a new one. */
  #allocate(list: 'bodies' | 'shapes' | 'joints'): number {
    const free = this.#free[list];
    if (free.length > 0) return free.pop()!;
    const handles = list === 'bodies' ? this.#bodies : list === 'shapes' ? this.#shapes : this.#joints;
    handles.push(undefined);
    return handles.length - 1;
  }

  /**
   * Gives a destroyed handle's id back once the batch that carries its destroy command has been
   * answered: until then the worker's replies (events, query answers) may still name it.
   */
  #releaseLater(list: 'bodies' | 'shapes' | 'joints', id: number): void {
    this.#releases.push({ seq: this.#nextSeq, list, id });
  }

  #release(seq: number): void {
    const releases = this.#releases;
    let kept = 0;
    for (const r of releases) {
      if (r.seq > seq) {
        releases[kept++] = r;
        continue;
      }
      const handles = r.list === 'bodies' ? this.#bodies : r.list === 'shapes' ? this.#shapes : this.#joints;
      handles[r.id] = undefined;
      this.#free[r.list].push(r.id);
    }
    releases.length = kept;
  }

  // Building and commanding: checked here, applied in the worker at the next request

  createBody(def: BodyDef = {}): WorkerBody {
    this.#usable();
    checkRoom('bodies', this.#bodyCount);
    const resolved = resolveBodyDef(def);
    const id = this.#allocate('bodies');
    const generation = (this.#generations[id] ?? 0) + 1;
    this.#generations[id] = generation;
    const body = new WorkerBody(
      this,
      id,
      generation,
      resolved.type,
      resolved,
      bodySettingsOf(resolved),
      def.userData,
    );
    this.#bodies[id] = body;
    this.#bodyCount++;
    this.queue(['createBody', id, generation, fullBodyDef(resolved)]);
    return body;
  }

  /** Destroys a body with its shapes and joints (their handles too). */
  destroyBody(body: WorkerBody): void {
    this.#usable();
    if (!(body instanceof WorkerBody) || body.world !== this) fail('body', body, 'a Body of this world');
    body.check();
    this.queue(['destroyBody', body.id]);
    for (const joint of body.jointList.slice()) this.#dropJoint(joint);
    for (const shape of body.shapeList.slice()) this.removeShape(shape);
    body.destroyed = true;
    this.#bodyCount--;
    this.#releaseLater('bodies', body.id);
  }

  /** @internal a new shape handle of `body` (WorkerBody.createShape has checked it) */
  addShape(body: WorkerBody, geometry: Geometry, settings: ShapeSettings, userData: unknown): WorkerShape {
    const id = this.#allocate('shapes');
    const shape = new WorkerShape(body, id, geometry, settings, userData);
    this.#shapes[id] = shape;
    body.shapeList.push(shape);
    this.#shapeCount++;
    return shape;
  }

  /** @internal marks a shape destroyed (its command is queued by the caller) */
  removeShape(shape: WorkerShape): void {
    const list = shape.body.shapeList;
    list.splice(list.indexOf(shape), 1);
    shape.destroyed = true;
    this.#shapeCount--;
    this.#releaseLater('shapes', shape.id);
  }

  /**
   * Creates a joint of the definition's type, its bodies WorkerBody handles. The definition is checked
   * here by World's own joint builder, on stand-ins for the bodies; defaults that depend on where the
   * bodies are (a reference angle, a length) are worked out in the worker when it makes the joint.
   */
  createJoint(def: WorkerJointDef): WorkerJoint {
    this.#usable();
    checkRoom('joints', this.#jointCount);
    buildJoint(this.#scratch, this.#standIns(def) as JointDef);
    const d = def as unknown as Record<string, unknown>;
    const type = d.type as JointType;
    const bodyA = (type === 'mouse' ? d.body : d.bodyA) as WorkerBody;
    const bodyB = (type === 'mouse' ? d.body : d.bodyB) as WorkerBody;
    const sent: Record<string, unknown> = { ...d };
    for (const key of BODY_KEYS) if (key in sent) sent[key] = (sent[key] as WorkerBody).id;
    const id = this.#allocate('joints');
    const target = type === 'mouse' ? (d.target as Vec2) : null;
    const joint = new WorkerJoint(this, id, type, bodyA, bodyB, target, d.userData);
    this.#joints[id] = joint;
    bodyA.jointList.push(joint);
    if (bodyB !== bodyA) bodyB.jointList.push(joint);
    this.#jointCount++;
    this.queue(['createJoint', id, toPlain(sent) as PlainDef]);
    return joint;
  }

  /**
   * `def` with each WorkerBody of this world replaced by a body of the scratch world (the same body
   * for the same handle), so that World's joint builder checks it; anything else is left for the
   * builder to refuse as World would.
   */
  #standIns(def: unknown): unknown {
    if (typeof def !== 'object' || def === null) return def;
    const copy: Record<string, unknown> = { ...def };
    const seen: WorkerBody[] = [];
    for (const key of BODY_KEYS) {
      const value = copy[key];
      if (!(value instanceof WorkerBody) || value.world !== this) continue;
      value.check();
      let i = seen.indexOf(value);
      if (i < 0) i = seen.push(value) - 1;
      copy[key] = this.#scratchBody(i);
    }
    return copy;
  }

  /** The scratch world's `i`th stand-in body for a joint's bodies. */
  #scratchBody(i: number): Body {
    while (this.#scratchBodies.length <= i) {
      const x = this.#scratchBodies.length;
      this.#scratchBodies.push(this.#scratch.createBody({ type: 'dynamic', position: { x, y: 0 } }));
    }
    return this.#scratchBodies[i];
  }

  /** @internal checks `data` as Body.setMassData does; gives the checked values */
  checkMassData(data: MassData): MassData {
    this.#massStandIn ??= this.#scratch.createBody({ type: 'dynamic' });
    this.#massStandIn.setMassData(data);
    const { mass, inertia, center } = data;
    return center === undefined ? { mass, inertia } : { mass, inertia, center: { x: center.x, y: center.y } };
  }

  /** @internal checks a filter as ShapeHandle's setter does; gives it as World would read it back */
  checkFilter(value: Partial<Filter>): Filter {
    this.#filterStandIn ??= this.#scratch.createBody().createShape(Shape.circle(1));
    this.#filterStandIn.filter = value;
    return this.#filterStandIn.filter;
  }

  /**
   * @internal Checks a call of a joint setter as a joint of type `type` checks it (destroyed or not):
   * on a joint of that type between stand-in bodies, which the call changes and nothing reads.
   */
  checkJointCall(type: JointType, destroyed: boolean, method: JointCommand, args: unknown[]): void {
    let joint = this.#jointStandIns.get(type);
    if (joint === undefined) {
      const a = this.#scratchBody(0);
      const b = this.#scratchBody(1);
      const axis = { x: 1, y: 0 };
      const def =
        type === 'mouse'
          ? { type, body: a, target: { x: 0, y: 0 } }
          : type === 'prismatic' || type === 'wheel'
            ? { type, bodyA: a, bodyB: b, axis }
            : { type, bodyA: a, bodyB: b };
      joint = buildJoint(this.#scratch, def as JointDef);
      this.#jointStandIns.set(type, joint);
    }
    const call = (joint as unknown as Record<string, unknown>)[method];
    if (typeof call !== 'function') throw new FulcrumError(`${method}: a ${type} joint has no ${method}()`);
    joint.destroyed = destroyed;
    try {
      call.apply(joint, args);
    } finally {
      joint.destroyed = false;
    }
  }

  /** @internal `body.getContacts()`, answered by the worker */
  bodyContacts(body: WorkerBody): Promise<WorkerContactData[]> {
    return this.#query('getContacts', [body.id], (list) =>
      (list as { shapeA: number; shapeB: number; normal: Vec2; points: WorkerContactData['points'] }[]).map(
        (c) => ({
          shapeA: this.#shapes[c.shapeA]!,
          shapeB: this.#shapes[c.shapeB]!,
          normal: c.normal,
          points: c.points,
        }),
      ),
    );
  }

  /** Destroys a joint. */
  destroyJoint(joint: WorkerJoint): void {
    this.#usable();
    if (!(joint instanceof WorkerJoint) || joint.world !== this)
      fail('joint', joint, 'a Joint of this world');
    joint.check();
    this.queue(['destroyJoint', joint.id]);
    this.#dropJoint(joint);
  }

  #dropJoint(joint: WorkerJoint): void {
    for (const body of [joint.bodyA, joint.bodyB]) {
      const i = body.jointList.indexOf(joint);
      if (i >= 0) body.jointList.splice(i, 1);
    }
    joint.destroyed = true;
    this.#jointCount--;
    this.#releaseLater('joints', joint.id);
  }

  /**
   * World's events, with worker handles. 'preStep' runs on this thread when `step` is called, before
   * the step's commands are sent (so what its handlers queue is in that step); the step's events and
   * then 'postStep' when its reply arrives, before its promise resolves.
   */
  on<K extends keyof WorkerWorldEventMap>(
    event: K,
    handler: (e: WorkerWorldEventMap[K]) => void,
  ): () => void {
    if (!(EVENT_NAMES as readonly string[]).includes(event))
      fail('event', event, `one of ${EVENT_NAMES.join(', ')}`);
    if (typeof handler !== 'function') fail('handler', handler, 'a function');
    return this.#handlers.on(event, handler);
  }

  // Requests: each sends the queued commands, and resolves in the order they were made

  /**
   * Sends the queued commands and a step of `dt` seconds. Resolves once the worker has stepped: the
   * handles then read the new state, and the step's events have been delivered.
   */
  step(dt: number): Promise<void> {
    checkZeroOrRange('dt', dt, Limits.MIN_DT, Limits.MAX_DT);
    if (this.#failure !== null) return Promise.reject(this.#failure);
    const handlers = this.#handlers;
    if (handlers.has('preStep')) handlers.emit('preStep', { dt });
    const events = EVENT_ORDER.filter((kind) => handlers.has(kind)) as EventKind[];
    return this.#request({ kind: 'step', dt, buffer: this.#buffer(), events }, (reply) => {
      this.#adopt(reply);
      this.#stepCount++;
      this.#stepMs = reply.stepMs ?? 0;
      this.#threads = reply.threads ?? 1;
      if (reply.events !== undefined) this.#deliver(reply);
      if (handlers.has('postStep')) handlers.emit('postStep', { dt });
    });
  }

  #deliver(reply: Reply): void {
    const events = decodeEvents(reply.events!, this.#shapes, this.#bodies);
    const handlers = this.#handlers;
    for (const kind of EVENT_ORDER) {
      const list = events[kind];
      if (list !== undefined) handlers.emitEach(kind, list as never[]);
    }
  }

  /** The closest shape hit by origin + f * translation (f in [0, 1]), or null (see World.castRay). */
  castRay(origin: Vec2, translation: Vec2, filter?: QueryFilter): Promise<WorkerCastHit | null> {
    this.#scratch.castRay(origin, translation, filter);
    return this.#query('castRay', [origin, translation, filter], (hit) => this.#hit(hit));
  }

  /** Every shape hit by the ray, sorted by fraction, then by shape (see World.castRayAll). */
  castRayAll(origin: Vec2, translation: Vec2, filter?: QueryFilter): Promise<WorkerCastHit[]> {
    this.#scratch.castRayAll(origin, translation, filter);
    return this.#query('castRayAll', [origin, translation, filter], (hits) =>
      (hits as Plain[]).map((hit) => this.#hit(hit)!),
    );
  }

  /** Shapes whose tight AABB overlaps or touches the box (see World.queryAABB). */
  queryAABB(aabb: AABB, filter?: QueryFilter): Promise<WorkerShape[]> {
    this.#scratch.queryAABB(aabb, filter);
    return this.#query('queryAABB', [aabb as unknown as Plain, filter], (ids) => this.#shapeList(ids));
  }

  /** Shapes containing the point (see World.queryPoint). */
  queryPoint(point: Vec2, filter?: QueryFilter): Promise<WorkerShape[]> {
    this.#scratch.queryPoint(point, filter);
    return this.#query('queryPoint', [point, filter], (ids) => this.#shapeList(ids));
  }

  /** The first shape that `geometry` at `transform` moved by `translation` touches (see World.castShape). */
  castShape(
    geometry: Geometry,
    transform: QueryTransform,
    translation: Vec2,
    filter?: QueryFilter,
  ): Promise<WorkerCastHit | null> {
    this.#scratch.castShape(geometry, transform, translation, filter);
    return this.#query(
      'castShape',
      [geometry as unknown as Plain, transform as unknown as Plain, translation, filter],
      (hit) => this.#hit(hit),
    );
  }

  /** Shapes overlapping or touching `geometry` at `transform` (see World.overlapShape). */
  overlapShape(geometry: Geometry, transform: QueryTransform, filter?: QueryFilter): Promise<WorkerShape[]> {
    this.#scratch.overlapShape(geometry, transform, filter);
    return this.#query(
      'overlapShape',
      [geometry as unknown as Plain, transform as unknown as Plain, filter],
      (ids) => this.#shapeList(ids),
    );
  }

  #query<T>(name: QueryName, args: unknown[], read: (result: Plain) => T): Promise<T> {
    if (this.#failure !== null) return Promise.reject(this.#failure);
    return this.#request({ kind: 'query', name, args: args.map(toPlain) }, (reply) =>
      read(reply.result as Plain),
    );
  }

  #hit(plain: Plain): WorkerCastHit | null {
    if (plain === null) return null;
    const hit = plain as { shape: number; point: Vec2; normal: Vec2; fraction: number };
    const shape = this.#shapes[hit.shape]!;
    return { shape, body: shape.body, point: hit.point, normal: hit.normal, fraction: hit.fraction };
  }

  #shapeList(ids: Plain): WorkerShape[] {
    return (ids as number[]).map((id) => this.#shapes[id]!);
  }

  /** The whole state of the world as bytes, after the queued commands (see World.snapshot). */
  snapshot(): Promise<Uint8Array> {
    if (this.#failure !== null) return Promise.reject(this.#failure);
    return this.#request({ kind: 'snapshot' }, (reply) => reply.result as Uint8Array);
  }

  /** `stateHash` of the worker's world, after the queued commands. */
  stateHash(): Promise<number> {
    if (this.#failure !== null) return Promise.reject(this.#failure);
    return this.#request({ kind: 'hash' }, (reply) => reply.result as number);
  }

  /**
   * Ends the worker at once: commands still queued are dropped, waiting promises reject, and every
   * later call throws (or rejects).
   */
  terminate(): void {
    if (this.#failure === null) this.#fail(new FulcrumError('worker: the world has been terminated'));
  }

  // The protocol

  /**
   * Sends the queued commands with `request`. `read` takes the reply in the order replies arrive
   * (before any later one is read) and gives the promise's value; a reply that carries the message
   * of a FulcrumError the worker met rejects the promise with it, after `read` has run.
   */
  #request<T>(request: Request, read: (reply: Reply) => T): Promise<T> {
    const port = this.#port!;
    const seq = this.#nextSeq++;
    const commands = this.#queue;
    this.#queue = [];
    return new Promise<T>((resolve, reject) => {
      this.#waiting.push({
        seq,
        settle: (reply) => {
          try {
            const value = read(reply);
            if (reply.error !== undefined) reject(new FulcrumError(reply.error));
            else resolve(value);
          } catch (error) {
            reject(error);
          }
        },
        reject,
      });
      port.hold(true);
      if (this.#timer === null) this.#arm();
      const buffer = 'buffer' in request ? request.buffer : undefined;
      const transfer: Transferable[] = [];
      if (buffer !== undefined && !this.#shared) transfer.push(buffer as ArrayBuffer);
      try {
        port.post({ seq, commands, request }, transfer);
      } catch (error) {
        this.#fail(error instanceof Error ? error : new Error(String(error)));
      }
    });
  }

  #onReply(reply: Reply): void {
    const waiting = this.#waiting.shift();
    if (waiting === undefined || waiting.seq !== reply.seq) {
      this.#fail(new Error(`a reply out of order (${reply.seq})`));
      return;
    }
    this.#release(reply.seq);
    const more = this.#waiting.length > 0;
    this.#port?.hold(more);
    // an answer shows the worker alive: what waits next gets the whole time from now
    this.#disarm();
    if (more) this.#arm();
    // before settle, so that what the request's promise or a step's events run reads them
    if (reply.joints !== undefined) this.#adoptJointReads(reply.joints);
    if (reply.geometries !== undefined) this.#adoptGeometries(reply.geometries, reply.seq);
    waiting.settle(reply);
    // after settle, which makes a restored world's joints; before any code awaiting the reply runs
    if (reply.anchors !== undefined) this.#adoptAnchors(reply.anchors);
  }

  /** The anchors of the joints the worker made (see Reply.anchors), for drawing. */
  #adoptAnchors(anchors: number[]): void {
    for (let i = 0; i < anchors.length; i += JOINT_ANCHORS_STRIDE) {
      const joint = this.#joints[anchors[i]];
      if (joint === undefined) continue;
      joint.localAnchors = Float64Array.of(anchors[i + 1], anchors[i + 2], anchors[i + 3], anchors[i + 4]);
    }
  }

  /** The joints' reads (see JointRead) of the last step, or of joints just made. */
  #adoptJointReads(rows: number[]): void {
    for (let i = 0; i < rows.length; i += JointRead.STRIDE) {
      this.#joints[rows[i + JointRead.ID]]?.adoptReads(rows, i);
    }
  }

  /**
   * The geometries of scaled bodies' shapes, as the worker made them after batch `seq`; a shape given
   * a geometry by a later batch's setGeometry keeps that one.
   */
  #adoptGeometries(geometries: [number, Plain][], seq: number): void {
    for (const [id, geometry] of geometries) {
      const shape = this.#shapes[id];
      if (shape !== undefined && shape.geometrySeq <= seq)
        shape.current = deepFreeze(geometry) as unknown as Geometry;
    }
  }

  /** (Re)starts the count towards the request timeout. */
  #arm(): void {
    this.#disarm();
    const ms = this.#timeoutMs;
    if (ms > MAX_TIMER_MS) return;
    this.#timer = setTimeout(() => {
      this.#timer = null;
      this.#fail(
        new FulcrumError(
          `worker: the world's worker did not answer within ${ms} ms (requestTimeoutMs); it has been terminated`,
        ),
      );
    }, ms);
  }

  #disarm(): void {
    if (this.#timer !== null) clearTimeout(this.#timer);
    this.#timer = null;
  }

  /** Ends the worker and rejects what waits, with a FulcrumError that says why. */
  #fail(error: Error): void {
    if (this.#failure !== null) return;
    this.#disarm();
    this.#failure =
      error instanceof FulcrumError
        ? error
        : new FulcrumError(`worker: the world's worker failed: ${error.message}`, { cause: error });
    this.#queue = [];
    this.#port?.terminate();
    for (const waiting of this.#waiting.splice(0)) waiting.reject(this.#failure);
  }

  /** A buffer for the next state: a spare one that is large enough, or a new one. */
  #buffer(): ArrayBufferLike {
    const bytes = this.#bodies.length * Row.STRIDE * Float64Array.BYTES_PER_ELEMENT;
    while (this.#spares.length > 0) {
      const spare = this.#spares.pop()!;
      if (spare.byteLength >= bytes) return spare;
    }
    const size = Math.max(64 * Row.STRIDE * Float64Array.BYTES_PER_ELEMENT, bytes * 2);
    return this.#shared ? new SharedArrayBuffer(size) : new ArrayBuffer(size);
  }

  /** Makes the reply's state the current one; the one it replaces becomes a spare. */
  #adopt(reply: Reply): void {
    const buffer = reply.buffer!;
    if (this.#current !== null) this.#spares.push(this.#current);
    this.#current = buffer;
    this.#view = new Float64Array(buffer);
  }

  /** Handles for a restored world's bodies, shapes and joints, ids in the order the worker gave them. */
  #adoptRestored(reply: Reply): void {
    const restored = reply.restored as RestoredHandles;
    this.#gravity = restored.gravity;
    restored.bodies.forEach(([type, settings], id) => {
      this.#bodies.push(new WorkerBody(this, id, 1, type, null, settings, undefined));
      this.#generations.push(1);
    });
    this.#bodyCount = restored.bodies.length;
    for (const [bodyId, geometry, settings] of restored.shapes) {
      this.addShape(this.#bodies[bodyId]!, deepFreeze(geometry) as unknown as Geometry, settings, undefined);
    }
    for (const [type, a, b, target] of restored.joints) {
      const bodyA = this.#bodies[a]!;
      const bodyB = this.#bodies[b]!;
      const id = this.#allocate('joints');
      const joint = new WorkerJoint(this, id, type, bodyA, bodyB, target, undefined);
      this.#joints[id] = joint;
      bodyA.jointList.push(joint);
      if (bodyB !== bodyA) bodyB.jointList.push(joint);
      this.#jointCount++;
    }
    if (reply.joints !== undefined) this.#adoptJointReads(reply.joints);
  }
}
