/** @internal Where a worker script posts its answers: a Web Worker's global scope or Node's parentPort. */
export interface WorkerSink {
  postMessage(message: unknown, transfer?: Transferable[]): void;
}

interface WebWorkerScope extends WorkerSink {
  onmessage: ((event: { data: unknown }) => void) | null;
}

interface NodeParentPort extends WorkerSink {
  on(event: 'message', listener: (message: unknown) => void): void;
}

/**
 * @internal Feeds the messages this worker gets to the handler `serve` makes for its sink, whichever
 * the platform: a browser's Web Worker (its global scope) or Node's worker_threads (its parentPort).
 * `script` names the script in the error thrown when it runs on a main thread.
 */
export function serveInWorker<M>(script: string, serve: (sink: WorkerSink) => (message: M) => void): void {
  const scope = globalThis as unknown as { WorkerGlobalScope?: unknown } & WebWorkerScope;
  if (typeof scope.WorkerGlobalScope === 'function' && scope instanceof (scope.WorkerGlobalScope as never)) {
    const handle = serve(scope);
    scope.onmessage = (event) => handle(event.data as M);
    return;
  }
  // Node: a specifier in a variable, so that bundlers for the browser leave it alone
  const threads = 'node:worker_threads';
  import(/* @vite-ignore */ threads).then((module: { parentPort: NodeParentPort | null }) => {
    const port = module.parentPort;
    if (port === null) throw new Error(`${script} runs in a worker, not on the main thread`);
    const handle = serve(port);
    port.on('message', (message) => handle(message as M));
  });
}
