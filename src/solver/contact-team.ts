import { FulcrumError } from '../core/errors';
import type { BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';
import { integratePositions, integrateVelocities, VelocityUpdate } from './body-solver';
import {
  applyRestitution,
  type ContactConstraints,
  prepareContacts,
  solveContacts,
  storeImpulses,
  warmStartContacts,
} from './contact-solver';
import { COLORS, type GraphColoring } from './graph-color';

/**
 * @internal The contact passes of a step spread over several threads (`new World({ workers })`,
 * src/parallel/team.ts): each thread its own islands, or where the islands cannot be shared evenly,
 * each colour's constraints split between the threads, a barrier between colours. The step calls it in place of warmStartContacts, solveContacts and applyRestitution.
 */
export interface ContactTeam {
  /** the threads that solve, the calling one included */
  readonly threads: number;
  /**
   * Wakes the workers at the start of the solve if the last step used them, so that they are awake
   * (spinning) when the first pass comes, not still waking from sleep.
   */
  rouse(): void;
  /** Moves the body columns the passes write into shared memory (where they are not yet). */
  shareBodies(bodies: BodyStore): void;
  /**
   * Shares this step's constraints (reserved and counted, not yet prepared) and the columns their
   * preparation reads, and plans their colours; false: this step stays on one thread.
   */
  begin(
    cc: ContactConstraints,
    coloring: GraphColoring,
    contacts: ContactStore,
    bodies: BodyStore,
    shapes: ShapeStore,
  ): boolean;
  /**
   * Whether this step's constraints are grouped by the threads' islands (each group in colour order)
   * rather than in the colouring's order: the same arithmetic per body, but not the same order
   * across bodies, so the passes that go over all constraints in order stay in the colouring's.
   */
  readonly reordered: boolean;
  /**
   * In a step split by island (`reordered`), before prepareVelocityUpdate: groups `awake[0..count)` by
   * the thread of their islands into `awake`, with room in `update` for their velocity updates, so that
   * each thread integrates the bodies it solves. Returns false if a kinematic body is in a constraint:
   * the threads read it, so it moves between their passes (stepIslands may not be used).
   */
  groupBodies(awake: Int32Array, count: number): boolean;
  /** the awake bodies as groupBodies grouped them */
  readonly awake: Int32Array;
  /** their velocity updates, as prepareVelocityUpdate writes them for `awake` */
  readonly update: Float64Array;
  /** integrateVelocities over the threads, each its group (after groupBodies) */
  integrateVelocities(h: number, maxLinearSpeed: number): void;
  /** integratePositions over the threads, each its group */
  integratePositions(h: number, maxLinearSpeed: number, last: boolean): void;
  /**
   * A step split by island whose constraints are contacts alone (no joint acts between the passes):
   * each thread steps its islands through every substep (integrate velocities, warm start, solve,
   * integrate positions, relax), then restitution and the impulses kept, with one barrier in all.
   */
  stepIslands(
    h: number,
    invH: number,
    subSteps: number,
    maxLinearSpeed: number,
    maxPushSpeed: number,
    threshold: number,
  ): void;
  /** prepareContacts over the threads; returns ContactConstraints.heavyPair */
  prepare(frictionMin: boolean): boolean;
  warmStart(): void;
  solve(invH: number, useBias: boolean, maxPushSpeed: number): void;
  restitution(threshold: number): void;
  /** storeImpulses over the threads */
  store(): void;
  /** Ends the workers; the world steps on one thread from then on. */
  stop(): void;
}

/**
 * @internal What a team's threads run, handed to them rather than imported by src/parallel: the team's
 * code, loaded on demand, then shares no module with the core, and bundlers do not split the core
 * into more chunks for it.
 */
export interface ContactPasses {
  prepare: typeof prepareContacts;
  integrateVelocities: typeof integrateVelocities;
  integratePositions: typeof integratePositions;
  warmStart: typeof warmStartContacts;
  solve: typeof solveContacts;
  restitution: typeof applyRestitution;
  store: typeof storeImpulses;
  /** numbers per body of prepareVelocityUpdate's output (VelocityUpdate.STRIDE) */
  updateStride: number;
  /** colours of the colouring, its overflow not counted */
  colors: number;
  error(message: string): Error;
}

/** @internal */
export const CONTACT_PASSES: Readonly<ContactPasses> = Object.freeze({
  prepare: prepareContacts,
  integrateVelocities,
  integratePositions,
  warmStart: warmStartContacts,
  solve: solveContacts,
  restitution: applyRestitution,
  store: storeImpulses,
  updateStride: VelocityUpdate.STRIDE,
  colors: COLORS,
  error: (message: string) => new FulcrumError(message),
});
