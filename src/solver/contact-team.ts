import { FulcrumError } from '../core/errors';
import type { BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';
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
 * src/parallel/team.ts): each colour's constraints split between the threads, a barrier between
 * colours. The step calls it in place of warmStartContacts, solveContacts and applyRestitution.
 */
export interface ContactTeam {
  /** the threads that solve, the calling one included */
  readonly threads: number;
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
  warmStart: typeof warmStartContacts;
  solve: typeof solveContacts;
  restitution: typeof applyRestitution;
  store: typeof storeImpulses;
  /** colours of the colouring, its overflow not counted */
  colors: number;
  error(message: string): Error;
}

/** @internal */
export const CONTACT_PASSES: Readonly<ContactPasses> = Object.freeze({
  prepare: prepareContacts,
  warmStart: warmStartContacts,
  solve: solveContacts,
  restitution: applyRestitution,
  store: storeImpulses,
  colors: COLORS,
  error: (message: string) => new FulcrumError(message),
});
