import type { ContactConstraints } from '../solver/contact-solver';
import type { ContactPasses, ContactTeam } from '../solver/contact-team';
import type { GraphColoring } from '../solver/graph-color';
import type { BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';
import {
  barrier,
  bodyBoundsAt,
  Control,
  controlLength,
  Param,
  Pass,
  runPass,
  TEAM_COLUMNS,
  type TeamColumns,
  type TeamThread,
} from './control';
import { IslandSplit } from './island-split';
import type { TeamMessage } from './solver-worker';
import { startThread, type Thread } from './thread';

/**
 * A colour's constraints are split between the threads only from this many per thread: below it the
 * barrier costs more than the share saves, and the calling thread solves the colour alone.
 */
const MIN_PER_THREAD = 64;
/**
 * Below this many constraints in a step the team stays idle. Measured on a 2-core virtual machine
 * (npm run bench, 2 rounds): two threads made the scenes of 1,300 to 3,000 contacts 1.1 to 1.6 times
 * slower, and a 9,600-contact pyramid no faster: the barriers between colours cost more than the
 * halves of them save. Only the 5,050-box pyramid (15,000 contacts) gained: 13.7 -> 11.0 ms a step in
 * one run, 9.1 -> 9.5 in another.
 */
const MIN_CONSTRAINTS = 12_000;
/**
 * Below this many constraints a step is not split by island either. A split by island costs two
 * barriers a step (with contacts alone) and a union-find over the step's bodies: measured on the
 * 2-core machine, five pyramids of 55 boxes (725 contacts) stepped in 0.50 ms on two threads against
 * 0.63-0.64 on one (medians of 400 steps, two runs each).
 */
const MIN_ISLAND_CONSTRAINTS = 500;
/** steps without a try after a step whose islands could not be shared evenly */
const SPLIT_RETRY_STEPS = 16;

/** `to[0..count)` = `from[0..count)` (a loop: subarray() would make a view every step) */
function copyOrder(from: Int32Array, count: number, to: Int32Array): void {
  for (let i = 0; i < count; i++) to[i] = from[i];
}

function mayBlock(): boolean {
  try {
    Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 1, 0);
    return true;
  } catch {
    return false;
  }
}

type Column = Float64Array | Int32Array | Uint8Array;

/** `a`, or a copy of it in shared memory if it is not there yet. */
function shared<T extends Column>(a: T): T {
  if (a.buffer instanceof SharedArrayBuffer) return a;
  const b = new (a.constructor as new (buffer: SharedArrayBuffer) => T)(new SharedArrayBuffer(a.byteLength));
  b.set(a as never);
  return b;
}

/** Moves `owner`'s columns `names` into shared memory; true if one of them moved since `bound`. */
function shareColumns(owner: object, names: readonly string[], bound: Record<string, Column>): boolean {
  const columns = owner as Record<string, Column>;
  let moved = false;
  for (const name of names) {
    const column = shared(columns[name]);
    columns[name] = column;
    if (bound[name] !== column) {
      bound[name] = column;
      moved = true;
    }
  }
  return moved;
}

/**
 * @internal The calling thread's side of a team: it moves the columns the contact passes write into
 * shared memory (once, and again after they grow), hands each pass to the workers through the control
 * block and runs its own share as thread 0.
 */
export class SolverTeam implements ContactTeam {
  private readonly workers: Thread[];
  /** this thread's side: thread 0; its `cc` is a view of the world's constraints' columns */
  private readonly self: TeamThread;
  /** the columns the workers work on */
  private readonly bound: TeamColumns = {
    order: new Int32Array(0),
    awake: new Int32Array(0),
    update: new Float64Array(0),
    owners: { cc: {}, bodies: {}, contacts: {}, shapes: {} },
  };
  private stopped = false;
  /** whether a column the workers have not been given yet moved (shareBodies; the order grown) */
  private moved = false;
  private readonly islands: IslandSplit;
  /** steps whose contacts the team solved: how a test knows the workers did the work */
  parallelSteps = 0;
  /** calls of begin() with enough constraints, and the first at which a split by island is tried again */
  private begins = 0;
  private retryAt = 0;
  /** parallelSteps at the last rouse */
  private rousedAt = 0;
  /** steps among them split by island rather than by colour */
  islandSteps = 0;
  /** whether this step's constraints are in the islands' order (see ContactTeam) */
  reordered = false;
  /** the thresholds below which a colour or a step stays on this thread (tests lower them) */
  minPerThread = MIN_PER_THREAD;
  minConstraints = MIN_CONSTRAINTS;
  minIslands = MIN_ISLAND_CONSTRAINTS;

  private constructor(workers: Thread[], self: TeamThread) {
    this.workers = workers;
    this.self = self;
    this.islands = new IslandSplit(self.threads);
  }

  get threads(): number {
    return this.self.threads;
  }

  get awake(): Int32Array {
    return this.self.awake;
  }

  get update(): Float64Array {
    return this.self.update;
  }

  groupBodies(awake: Int32Array, count: number): boolean {
    const self = this.self;
    if (self.awake.length < count) {
      const capacity = Math.max(count, 2 * self.awake.length);
      self.awake = shared(new Int32Array(capacity));
      self.update = shared(new Float64Array(capacity * self.passes.updateStride));
      this.bound.awake = self.awake;
      this.bound.update = self.update;
      this.bind();
    }
    const at = bodyBoundsAt(self.threads, self.passes.colors);
    return this.islands.group(awake, count, self.bodies.kind, self.awake, self.control, at);
  }

  integrateVelocities(h: number, maxLinearSpeed: number): void {
    const params = this.self.params;
    params[Param.H] = h;
    params[Param.MAX_LINEAR_SPEED] = maxLinearSpeed;
    this.run(Pass.VELOCITIES);
  }

  integratePositions(h: number, maxLinearSpeed: number, last: boolean): void {
    const params = this.self.params;
    params[Param.H] = h;
    params[Param.MAX_LINEAR_SPEED] = maxLinearSpeed;
    params[Param.LAST] = last ? 1 : 0;
    this.run(Pass.POSITIONS);
  }

  /** Starts `threads - 1` workers on `url`; resolves once every one waits for passes. */
  static async start(
    threads: number,
    url: URL | string | undefined,
    passes: ContactPasses,
  ): Promise<SolverTeam> {
    // written out in full, so that bundlers find the script
    const script = url ?? new URL('./solver-worker.js', import.meta.url);
    const control = new Int32Array(new SharedArrayBuffer(controlLength(threads, passes.colors) * 4));
    const params = new Float64Array(new SharedArrayBuffer(Param.SIZE * 8));
    const workers: Thread[] = [];
    try {
      for (let t = 1; t < threads; t++) workers.push(await startThread(script));
      await Promise.all(
        workers.map((worker, i) => {
          const start: TeamMessage = { start: { control, params, thread: i + 1, threads } };
          return worker.ask(start);
        }),
      );
    } catch (error) {
      for (const worker of workers) worker.end();
      throw error;
    }
    // thread 0 works on the world's own columns, handed to begin() before any pass: none until then
    const self: TeamThread = {
      control,
      params,
      thread: 0,
      threads,
      canSleep: mayBlock(),
      passes,
      cc: null as unknown as ContactConstraints,
      bodies: null as unknown as BodyStore,
      contacts: null as unknown as ContactStore,
      shapes: null as unknown as ShapeStore,
      order: new Int32Array(0),
      awake: new Int32Array(0),
      update: new Float64Array(0),
    };
    return new SolverTeam(workers, self);
  }

  rouse(): void {
    // only while the team works: an idle team's workers may sleep through the step
    if (this.stopped || this.parallelSteps === this.rousedAt) return;
    this.rousedAt = this.parallelSteps;
    Atomics.notify(this.self.control, Control.EPOCH);
  }

  shareBodies(bodies: BodyStore): void {
    if (this.stopped) return;
    // before the step hands the columns to others (the joints' context): all of them, now
    if (shareColumns(bodies, TEAM_COLUMNS.bodies, this.bound.owners.bodies)) this.moved = true;
  }

  begin(
    cc: ContactConstraints,
    coloring: GraphColoring,
    contacts: ContactStore,
    bodies: BodyStore,
    shapes: ShapeStore,
  ): boolean {
    const count = cc.count;
    this.reordered = false;
    if (this.stopped || count < Math.min(this.minIslands, this.minConstraints)) return false;
    const self = this.self;
    if (self.order.length < count) {
      self.order = shared(new Int32Array(Math.max(count, 2 * self.order.length)));
      this.bound.order = self.order;
      // posted at the next bind, whether or not this step goes to the team
      this.moved = true;
    }
    const at = this.begins++;
    this.reordered = count >= this.minIslands && at >= this.retryAt;
    if (this.reordered) {
      this.reordered = this.islands.split(coloring.order, count, contacts, bodies, self.order);
      // one pile: it will be one pile for a while yet, and each try costs a union-find
      if (!this.reordered) this.retryAt = at + 1 + SPLIT_RETRY_STEPS;
    }
    if (!this.reordered) {
      if (count < this.minConstraints) return false;
      copyOrder(coloring.order, count, self.order);
    }
    self.cc = cc;
    self.bodies = bodies;
    self.contacts = contacts;
    self.shapes = shapes;
    const owners = this.bound.owners;
    // every owner's columns are shared, whichever moved
    let moved = this.moved;
    moved = shareColumns(cc, TEAM_COLUMNS.cc, owners.cc) || moved;
    moved = shareColumns(contacts, TEAM_COLUMNS.contacts, owners.contacts) || moved;
    moved = shareColumns(shapes, TEAM_COLUMNS.shapes, owners.shapes) || moved;
    if (moved) this.bind();
    this.moved = false;
    if (this.reordered) this.planIslands();
    else this.plan(coloring);
    self.control[Control.COUNT] = count;
    this.parallelSteps++;
    return true;
  }

  /** Posts the columns to the workers and waits until they took them. */
  private bind(): void {
    const b = this.bound;
    const owners = b.owners;
    const message: TeamMessage = {
      columns: {
        order: b.order,
        awake: b.awake,
        update: b.update,
        owners: {
          cc: { ...owners.cc },
          bodies: { ...owners.bodies },
          contacts: { ...owners.contacts },
          shapes: { ...owners.shapes },
        },
      },
    };
    for (const worker of this.workers) worker.post(message);
    this.dispatch(Pass.BIND);
    barrier(this.self);
  }

  /** One phase: each thread its islands (IslandSplit), in colour order. */
  private planIslands(): void {
    const control = this.self.control;
    const starts = this.islands.starts;
    for (let t = 0; t <= this.threads; t++) control[Control.PLAN + t] = starts[t];
    control[Control.PHASES] = 1;
    this.islandSteps++;
  }

  /**
   * Phases of the passes: the colours in order, each split evenly between the threads when it is large
   * enough, else solved by this thread alone (with the small colours next to it, in order); the
   * overflow's constraints, which may share bodies, on this thread alone, last.
   */
  private plan(coloring: GraphColoring): void {
    const control = this.self.control;
    const threads = this.threads;
    const stride = threads + 1;
    let phases = 0;
    let alone = false;
    let start = 0;
    const colors = this.self.passes.colors;
    for (let c = 0; c <= colors; c++) {
      const end = coloring.colorEnd(c);
      if (end === start) continue;
      const split = c < colors && end - start >= this.minPerThread * threads;
      const at = Control.PLAN + phases * stride;
      if (!split && alone) {
        // this thread's phase before goes on to the end of this colour
        for (let t = 1; t <= threads; t++) control[at - stride + t] = end;
      } else {
        control[at] = start;
        for (let t = 1; t < threads; t++)
          control[at + t] = split ? start + Math.floor(((end - start) * t) / threads) : end;
        control[at + threads] = end;
        phases++;
      }
      alone = !split;
      start = end;
    }
    control[Control.PHASES] = phases;
  }

  private dispatch(pass: Pass): void {
    const control = this.self.control;
    control[Control.PASS] = pass;
    Atomics.add(control, Control.EPOCH, 1);
    Atomics.notify(control, Control.EPOCH);
  }

  private run(pass: Pass): void {
    this.dispatch(pass);
    runPass(this.self, pass);
  }

  stepIslands(
    h: number,
    invH: number,
    subSteps: number,
    maxLinearSpeed: number,
    maxPushSpeed: number,
    threshold: number,
  ): void {
    const params = this.self.params;
    params[Param.H] = h;
    params[Param.INV_H] = invH;
    params[Param.SUBSTEPS] = subSteps;
    params[Param.MAX_LINEAR_SPEED] = maxLinearSpeed;
    params[Param.MAX_PUSH_SPEED] = maxPushSpeed;
    params[Param.THRESHOLD] = threshold;
    this.run(Pass.ISLANDS);
  }

  prepare(frictionMin: boolean): boolean {
    const control = this.self.control;
    this.self.params[Param.FRICTION_MIN] = frictionMin ? 1 : 0;
    control[Control.HEAVY] = 0;
    this.run(Pass.PREPARE);
    const heavy = control[Control.HEAVY] === 1;
    if (heavy && this.reordered) {
      // the step falls back to one thread (see ContactTeam.reordered): no island split for a while
      this.retryAt = this.begins + SPLIT_RETRY_STEPS;
      this.islandSteps--;
    }
    return heavy;
  }

  warmStart(): void {
    this.run(Pass.WARM_START);
  }

  solve(invH: number, useBias: boolean, maxPushSpeed: number): void {
    const params = this.self.params;
    params[Param.INV_H] = invH;
    params[Param.USE_BIAS] = useBias ? 1 : 0;
    params[Param.MAX_PUSH_SPEED] = maxPushSpeed;
    this.run(Pass.SOLVE);
  }

  restitution(threshold: number): void {
    this.self.params[Param.THRESHOLD] = threshold;
    this.run(Pass.RESTITUTION);
  }

  store(): void {
    this.run(Pass.STORE);
  }

  /** Ends the workers; the world steps on one thread from then on. */
  stop(): void {
    if (this.stopped) return;
    this.stopped = true;
    this.dispatch(Pass.STOP);
    for (const worker of this.workers) worker.end();
  }
}
