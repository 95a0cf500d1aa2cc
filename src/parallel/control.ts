import type { ContactConstraints } from '../solver/contact-solver';
import type { ContactPasses } from '../solver/contact-team';
import type { BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';

/*
 * The control block a team's threads share (an Int32Array on a SharedArrayBuffer) and the code both
 * sides run: the calling thread is thread 0 and runs its share of a pass with the same code as the
 * workers. Enums, not consts, for the reason given in body-store.ts.
 */

/** @internal Int32 fields of the control block. */
export enum Control {
  /** counts the passes handed out: a worker waits for it to change */
  EPOCH = 0,
  /** the pass handed out last (a Pass) */
  PASS = 1,
  /** the barrier: threads arrived, and its generation */
  ARRIVED = 2,
  GENERATION = 3,
  /** phases in the plan */
  PHASES = 4,
  /** the step's constraints */
  COUNT = 5,
  /** set to 1 by a thread whose share of the preparation found a heavy pair */
  HEAVY = 6,
  /**
   * the plan: per phase, threads + 1 constraint indices, thread t solving from the t-th to the next;
   * after the plan's longest, threads + 1 indices of the awake bodies in the same way (bodyBoundsAt)
   */
  PLAN = 8,
}

/** @internal Float64 fields of the parameter block. */
export enum Param {
  INV_H = 0,
  MAX_PUSH_SPEED = 1,
  THRESHOLD = 2,
  USE_BIAS = 3,
  FRICTION_MIN = 4,
  H = 5,
  MAX_LINEAR_SPEED = 6,
  LAST = 7,
  SUBSTEPS = 8,
  SIZE = 9,
}

/** @internal What a worker is asked to do. */
export enum Pass {
  WARM_START = 0,
  SOLVE = 1,
  RESTITUTION = 2,
  PREPARE = 3,
  STORE = 4,
  /** go back to the event loop and take the columns posted to it (they were moved or grown) */
  BIND = 5,
  STOP = 6,
  /** integrateVelocities over the thread's awake bodies (a step split by island) */
  VELOCITIES = 7,
  /** integratePositions over the thread's awake bodies */
  POSITIONS = 8,
  /** every substep of the thread's islands, restitution and the impulses kept (contacts alone) */
  ISLANDS = 9,
}

/** @internal The columns the passes read or write, by owner: what a team shares and binds. */
export const TEAM_COLUMNS = {
  cc: ['data', 'ids', 'softness', 'restitution'],
  bodies: ['state', 'kind', 'invMass', 'invInertia', 'cx', 'cy'],
  contacts: [
    'bodyA',
    'bodyB',
    'shapeA',
    'shapeB',
    'normalX',
    'normalY',
    'pointCount',
    'pointX',
    'pointY',
    'separation',
    'normalImpulse',
    'tangentImpulse',
    'maxNormalImpulse',
    'approachSpeed',
  ],
  shapes: ['friction', 'restitution', 'radius'],
} as const;

/**
 * @internal A team's columns as posted to a worker: by owner and name (TEAM_COLUMNS), the order of
 * the constraints, and the awake bodies grouped by thread with their velocity updates.
 */
export interface TeamColumns {
  order: Int32Array;
  awake: Int32Array;
  update: Float64Array;
  owners: Record<keyof typeof TEAM_COLUMNS, Record<string, Float64Array | Int32Array | Uint8Array>>;
}

/** @internal the control block's length in Int32 for `threads` threads and `colors` colours */
export function controlLength(threads: number, colors: number): number {
  return bodyBoundsAt(threads, colors) + threads + 1;
}

/** @internal where the awake bodies' bounds by thread start in the control block */
export function bodyBoundsAt(threads: number, colors: number): number {
  // after a phase per colour and the overflow's
  return Control.PLAN + (colors + 1) * (threads + 1);
}

/** @internal What a thread of a team works with. */
export interface TeamThread {
  readonly control: Int32Array;
  readonly params: Float64Array;
  readonly thread: number;
  readonly threads: number;
  /** whether it may block in Atomics.wait: a browser page's main thread may not */
  readonly canSleep: boolean;
  readonly passes: ContactPasses;
  /** the columns it works on: views of the world's (a worker's hold the columns posted to it) */
  cc: ContactConstraints;
  bodies: BodyStore;
  contacts: ContactStore;
  shapes: ShapeStore;
  order: Int32Array;
  /** the awake bodies grouped by thread (a step split by island), and their velocity updates */
  awake: Int32Array;
  update: Float64Array;
}

/** spins at a barrier between looks at the clock */
const SPINS_BETWEEN_CLOCKS = 1 << 22;
/** how long a thread waits at a barrier for the others before it gives up */
const BARRIER_PATIENCE_MS = 5000;
/** spins of a waiting thread before it sleeps (Atomics.wait) */
const SPINS_BEFORE_SLEEP = 1 << 14;

/**
 * @internal Waits until every thread has arrived. Spins first: a pass's phases last microseconds,
 * less than a sleeping thread takes to wake. Then, where the thread may block (`canSleep`: not a
 * browser page's main thread), sleeps a millisecond at a time, so that a thread the system has not
 * given a core yet gets one. The generation is read before arriving, so a thread cannot miss the
 * round it arrives in.
 */
export function barrier(team: TeamThread): void {
  const { control, threads, canSleep } = team;
  const generation = Atomics.load(control, Control.GENERATION);
  if (Atomics.add(control, Control.ARRIVED, 1) === threads - 1) {
    Atomics.store(control, Control.ARRIVED, 0);
    Atomics.add(control, Control.GENERATION, 1);
    Atomics.notify(control, Control.GENERATION);
    return;
  }
  let spins = 0;
  let deadline = 0;
  while (Atomics.load(control, Control.GENERATION) === generation) {
    if (++spins < SPINS_BEFORE_SLEEP) continue;
    if (canSleep) Atomics.wait(control, Control.GENERATION, generation, 1);
    else if (spins < SPINS_BETWEEN_CLOCKS) continue;
    // a thread that died or hangs would hold the others here for good
    spins = 0;
    const now = Date.now();
    if (deadline === 0) deadline = now + BARRIER_PATIENCE_MS;
    else if (now > deadline) {
      throw team.passes.error(
        `a thread of the world's team did not reach a barrier within ${BARRIER_PATIENCE_MS} ms: the step cannot finish`,
      );
    }
  }
}

/**
 * @internal A worker's wait for the next pass after `seen`: spins a while, then sleeps; woken with no
 * new pass (SolverTeam.rouse), it spins again.
 */
export function awaitPass(control: Int32Array, seen: number): number {
  for (;;) {
    for (let i = 0; i < SPINS_BEFORE_SLEEP; i++) {
      const epoch = Atomics.load(control, Control.EPOCH);
      if (epoch !== seen) return epoch;
    }
    Atomics.wait(control, Control.EPOCH, seen);
  }
}

/** @internal Runs the thread's share of the pass: of every phase of the plan, or of all constraints. */
export function runPass(team: TeamThread, pass: Pass): void {
  if (pass === Pass.PREPARE || pass === Pass.STORE) {
    // each constraint on its own: one even share of them per thread
    const count = team.control[Control.COUNT];
    const from = Math.floor((count * team.thread) / team.threads);
    const to = Math.floor((count * (team.thread + 1)) / team.threads);
    if (pass === Pass.STORE) team.passes.store(team.cc, team.contacts, from, to);
    else if (prepareShare(team, from, to)) Atomics.store(team.control, Control.HEAVY, 1);
    barrier(team);
    return;
  }
  if (pass === Pass.VELOCITIES || pass === Pass.POSITIONS) {
    integrateShare(team, pass);
    barrier(team);
    return;
  }
  if (pass === Pass.ISLANDS) {
    stepIslands(team);
    barrier(team);
    return;
  }
  const { control, params, passes, cc } = team;
  const state = team.bodies.state;
  const phases = control[Control.PHASES];
  const stride = team.threads + 1;
  for (let p = 0; p < phases; p++) {
    const at = Control.PLAN + p * stride + team.thread;
    const from = control[at];
    const to = control[at + 1];
    if (from < to) {
      if (pass === Pass.SOLVE) {
        const useBias = params[Param.USE_BIAS] === 1;
        passes.solve(cc, state, params[Param.INV_H], useBias, params[Param.MAX_PUSH_SPEED], from, to);
      } else if (pass === Pass.WARM_START) {
        passes.warmStart(cc, state, from, to);
      } else {
        passes.restitution(cc, state, params[Param.THRESHOLD], from, to);
      }
    }
    barrier(team);
  }
}

function integrateShare(team: TeamThread, pass: Pass): void {
  const { control, params } = team;
  const at = bodyBoundsAt(team.threads, team.passes.colors) + team.thread;
  const h = params[Param.H];
  const maxSpeed = params[Param.MAX_LINEAR_SPEED];
  if (pass === Pass.VELOCITIES) {
    team.passes.integrateVelocities(
      team.bodies,
      team.awake,
      control[at],
      control[at + 1],
      team.update,
      h,
      maxSpeed,
    );
  } else {
    const last = params[Param.LAST] === 1;
    team.passes.integratePositions(team.bodies, team.awake, control[at], control[at + 1], h, maxSpeed, last);
  }
}

/**
 * The solve of a step whose constraints are contacts alone, split by island: the thread's islands
 * through the same sequence as the step's on one thread (world/solve.ts), with no joint pass between.
 */
function stepIslands(team: TeamThread): void {
  const { control, params, passes, cc, bodies, awake, update } = team;
  const state = bodies.state;
  // the plan's one phase (SolverTeam.planIslands)
  const from = control[Control.PLAN + team.thread];
  const to = control[Control.PLAN + team.thread + 1];
  const at = bodyBoundsAt(team.threads, passes.colors) + team.thread;
  const first = control[at];
  const end = control[at + 1];
  const h = params[Param.H];
  const invH = params[Param.INV_H];
  const maxSpeed = params[Param.MAX_LINEAR_SPEED];
  const push = params[Param.MAX_PUSH_SPEED];
  const subSteps = params[Param.SUBSTEPS];
  for (let i = 0; i < subSteps; i++) {
    passes.integrateVelocities(bodies, awake, first, end, update, h, maxSpeed);
    passes.warmStart(cc, state, from, to);
    passes.solve(cc, state, invH, true, push, from, to);
    passes.integratePositions(bodies, awake, first, end, h, maxSpeed, i === subSteps - 1);
    passes.solve(cc, state, invH, false, push, from, to);
  }
  passes.restitution(cc, state, params[Param.THRESHOLD], from, to);
  passes.store(cc, team.contacts, from, to);
}

function prepareShare(team: TeamThread, from: number, to: number): boolean {
  const frictionMin = team.params[Param.FRICTION_MIN] === 1;
  return team.passes.prepare(
    team.cc,
    team.order,
    from,
    to,
    team.contacts,
    team.bodies,
    team.shapes,
    frictionMin,
  );
}
