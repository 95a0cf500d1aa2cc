/**
 * The script a WorkerWorld starts in its worker: a WorldHost fed the batches that arrive, on Node's
 * worker_threads (its parentPort) or in a browser's Web Worker (its global scope), whichever this
 * runs in. An error that escapes the host ends the worker, and the WorkerWorld reports it.
 * @module
 */

import { WorldHost } from './host';
import type { Batch, Reply } from './protocol';

interface MessageSink {
  postMessage(message: Reply, transfer: Transferable[]): void;
}

interface WebWorkerScope extends MessageSink {
  onmessage: ((event: { data: Batch }) => void) | null;
}

interface NodeParentPort extends MessageSink {
  on(event: 'message', listener: (batch: Batch) => void): void;
}

function serve(sink: MessageSink): (batch: Batch) => void {
  const host = new WorldHost();
  return (batch) => {
    const { reply, transfer } = host.handle(batch);
    sink.postMessage(reply, transfer);
  };
}

function start(): void {
  const scope = globalThis as unknown as { WorkerGlobalScope?: unknown } & WebWorkerScope;
  if (typeof scope.WorkerGlobalScope === 'function' && scope instanceof (scope.WorkerGlobalScope as never)) {
    const handle = serve(scope);
    scope.onmessage = (event) => handle(event.data);
    return;
  }
  // Node: a specifier in a variable, so that bundlers for the browser leave it alone
  const threads = 'node:worker_threads';
  import(/* @vite-ignore */ threads).then((module: { parentPort: NodeParentPort | null }) => {
    const port = module.parentPort;
    if (port === null)
      throw new Error('fulcrum/worker: worker-entry runs in a worker, not on the main thread');
    port.on('message', serve(port));
  });
}

start();
