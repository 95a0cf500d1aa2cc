/**
 * The script a world's team starts in each of its workers (`new World({ workers })`): it waits for a
 * pass, solves its share of every colour of it on the shared columns, and waits again. Runs on Node's
 * worker_threads (its parentPort) and in a Web Worker (its global scope).
 * @module
 */

import { serveInWorker, type WorkerSink } from '../core/worker-scope';
import { ContactConstraints } from '../solver/contact-solver';
import { CONTACT_PASSES } from '../solver/contact-team';
import type { BodyStore } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';
import { awaitPass, barrier, Control, Pass, runPass, type TeamColumns, type TeamThread } from './control';

/** @internal The first message a worker gets. */
export interface TeamStart {
  control: Int32Array;
  params: Float64Array;
  thread: number;
  threads: number;
}

/** @internal The messages a worker gets: its start, then the columns each time they move. */
export type TeamMessage = { start: TeamStart } | { columns: TeamColumns };

function serve(port: WorkerSink): (message: TeamMessage) => void {
  let team: TeamThread | null = null;
  let seen = 0;
  // Runs passes until one asks for the event loop (new columns) or the end; a worker spends its life
  // here, between passes spinning or asleep in Atomics.wait.
  const work = (team: TeamThread): void => {
    const control = team.control;
    for (;;) {
      seen = awaitPass(control, seen);
      const pass = control[Control.PASS] as Pass;
      if (pass === Pass.BIND || pass === Pass.STOP) return;
      runPass(team, pass);
    }
  };
  return (message) => {
    if ('start' in message) {
      const { control, params, thread, threads } = message.start;
      // the stores hold only the columns the passes read, as posted (TEAM_COLUMNS)
      team = {
        control,
        params,
        thread,
        threads,
        canSleep: true,
        passes: CONTACT_PASSES,
        cc: new ContactConstraints(),
        bodies: {} as BodyStore,
        contacts: {} as ContactStore,
        shapes: {} as ShapeStore,
        order: new Int32Array(0),
        awake: new Int32Array(0),
        update: new Float64Array(0),
      };
      seen = Atomics.load(control, Control.EPOCH);
      port.postMessage('ready');
      work(team);
      return;
    }
    if (team === null) throw new Error('fulcrum: a solver worker got columns before its start');
    const { owners, order, awake, update } = message.columns;
    Object.assign(team.cc, owners.cc);
    Object.assign(team.bodies, owners.bodies);
    Object.assign(team.contacts, owners.contacts);
    Object.assign(team.shapes, owners.shapes);
    team.order = order;
    team.awake = awake;
    team.update = update;
    // tells the calling thread that this worker works on the new columns
    barrier(team);
    work(team);
  };
}

serveInWorker('fulcrum: solver-worker', serve);
