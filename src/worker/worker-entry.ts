/**
 * The script a WorkerWorld starts in its worker: a WorldHost fed the batches that arrive, on Node's
 * worker_threads (its parentPort) or in a browser's Web Worker (its global scope), whichever this
 * runs in. An error that escapes the host ends the worker, and the WorkerWorld reports it.
 * @module
 */

import { serveInWorker, type WorkerSink } from '../core/worker-scope';
import { WorldHost } from './host';
import type { Batch } from './protocol';

function serve(sink: WorkerSink): (batch: Batch) => void {
  const host = new WorldHost();
  return (batch) => {
    const { reply, transfer } = host.handle(batch);
    sink.postMessage(reply, transfer);
  };
}

serveInWorker('fulcrum/worker: worker-entry', serve);
