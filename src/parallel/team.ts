import type { ContactConstraints } from '../solver/contact-solver';
import type { ContactPasses, ContactTeam } from '../solver/contact-team';
import type { GraphColoring } from '../solver/graph-color';
import type { BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';
import {
  barrier,
  Control,
  controlLength,
  Param,
  Pass,
  runPass,
  TEAM_COLUMNS,
  type TeamColumns,
  type TeamThread,
} from './control';
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
    owners: { cc: {}, bodies: {}, contacts: {}, shapes: {} },
  };
  private stopped = false;
  /** whether shareBodies moved a body column the workers have not been given yet */
  private moved = false;
  /** steps whose contacts the team solved: how a test knows the workers did the work */
  parallelSteps = 0;
  /** the thresholds below which a colour or a step stays on this thread (tests lower them) */
  minPerThread = MIN_PER_THREAD;
  minConstraints = MIN_CONSTRAINTS;

  private constructor(workers: Thread[], self: TeamThread) {
    this.workers = workers;
    this.self = self;
  }

  get threads(): number {
    return this.self.threads;
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
    };
    return new SolverTeam(workers, self);
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
    if (this.stopped || cc.count < this.minConstraints) return false;
    const self = this.self;
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
    coloring.order = shared(coloring.order);
    self.order = coloring.order;
    if (this.bound.order !== coloring.order) {
      this.bound.order = coloring.order;
      moved = true;
    }
    if (moved) this.bind();
    this.moved = false;
    this.plan(coloring);
    self.control[Control.COUNT] = cc.count;
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

  prepare(frictionMin: boolean): boolean {
    const control = this.self.control;
    this.self.params[Param.FRICTION_MIN] = frictionMin ? 1 : 0;
    control[Control.HEAVY] = 0;
    this.run(Pass.PREPARE);
    return control[Control.HEAVY] === 1;
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
