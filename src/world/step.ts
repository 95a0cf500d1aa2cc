import { solveBullets } from './continuous';
import { collectAwakeBodies, finalizeBodies, solve, updateSleep } from './solve';
import { createNewContacts, updateContacts } from './update-contacts';
import type { WorldCore } from './world-core';

/**
 * One step of `dt` seconds, its stages in order (src/README.md names each one's file):
 * 1. contacts for the pairs the broad phase found new (update-contacts.ts `createNewContacts`);
 * 2. every contact's manifold updated, begins and ends recorded (`updateContacts`);
 * 3. the awake bodies, their contacts and joints gathered into the step's sets (solve.ts);
 * 4. the solve: substeps of integrate, warm start, solve, relax, restitution (solve.ts, solver/);
 * 5. bodies finalised: transforms, continuous collision of fast bodies, proxies moved (solve.ts,
 *    continuous.ts);
 * 6. sleep: islands at rest for long enough put to sleep (solve.ts, solver/island.ts).
 * The world is locked meanwhile: the public API refuses changes until the step returns or throws.
 */
export function stepWorld(core: WorldCore, dt: number): void {
  core.locked = true;
  core.events.clear();
  core.events.takePending(core.shapes);
  try {
    createNewContacts(core);
    updateContacts(core);
    if (dt > 0) {
      collectAwakeBodies(core);
      solve(core, dt);
      finalizeBodies(core, dt);
      if (core.enableContinuous) solveBullets(core);
      if (core.enableSleep) updateSleep(core);
    }
  } finally {
    core.locked = false;
  }
}
