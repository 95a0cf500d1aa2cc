import { FulcrumError } from '../core/errors';
import type { BodyStore } from '../store/body-store';
import {
  applyRestitution,
  type ContactConstraints,
  solveContacts,
  warmStartContacts,
} from './contact-solver';
import { COLORS, type GraphColoring } from './graph-color';

/**
 * @internal The contact passes of a step spread over several threads (`new World({ workers })`,
 * src/parallel/team.ts): each colour's constraints split between the threads, a barrier between
 * colours. The step calls it in place of warmStartContacts, solveContacts and applyRestitution.
 */
export interface ContactTeam {
  /** Moves the body columns the passes write into shared memory (where they are not yet). */
  shareBodies(bodies: BodyStore): void;
  /** Shares this step's constraints and plans their colours; false: this step stays on one thread. */
  begin(cc: ContactConstraints, coloring: GraphColoring): boolean;
  warmStart(): void;
  solve(invH: number, useBias: boolean, maxPushSpeed: number): void;
  restitution(threshold: number): void;
}

/**
 * @internal What a team's threads run, handed to them rather than imported by src/parallel: the team's
 * code, loaded on demand, then shares no module with the core, and bundlers do not split the core
 * into more chunks for it.
 */
export interface ContactPasses {
  warmStart: typeof warmStartContacts;
  solve: typeof solveContacts;
  restitution: typeof applyRestitution;
  /** colours of the colouring, its overflow not counted */
  colors: number;
  error(message: string): Error;
}

/** @internal */
export const CONTACT_PASSES: Readonly<ContactPasses> = Object.freeze({
  warmStart: warmStartContacts,
  solve: solveContacts,
  restitution: applyRestitution,
  colors: COLORS,
  error: (message: string) => new FulcrumError(message),
});
