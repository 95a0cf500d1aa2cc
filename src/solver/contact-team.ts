import type { BodyStore } from '../store/body-store';
import type { ContactConstraints } from './contact-solver';
import type { GraphColoring } from './graph-color';

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
