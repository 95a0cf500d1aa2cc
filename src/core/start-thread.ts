/**
 * @internal A worker thread, whatever the platform: a worker_threads Worker on Node, a module Web
 * Worker elsewhere (browsers, Deno, Bun). fulcrum/worker's world worker and a multi-core step's
 * solver workers start this way.
 */
export interface ThreadPort {
  post(message: unknown, transfer?: Transferable[]): void;
  /** whether the worker keeps Node's process alive (it does not until held); nothing elsewhere */
  hold(keep: boolean): void;
  end(): void;
}

/** @internal What a thread tells its owner. */
export interface ThreadListener {
  message(data: unknown): void;
  /** the worker threw, sent what could not be read, or exited without `end` */
  failure(error: Error): void;
}

/** @internal What `new Worker(...)` makes, as far as a thread uses it. */
export interface WebWorkerLike {
  postMessage(message: unknown, transfer: Transferable[]): void;
  onmessage: ((event: { data: unknown }) => void) | null;
  onerror: ((event: { message?: string; error?: unknown; preventDefault?(): void }) => void) | null;
  onmessageerror: (() => void) | null;
  terminate(): void;
}

/**
 * @internal The script a thread runs: its address; or, for a script of the package's own, its address
 * and a function that makes the Web Worker with `new Worker(new URL('./x.js', import.meta.url), ...)`
 * written out in full beside the script, which is how bundlers find a worker's script.
 */
export type ThreadScript = URL | string | { url: URL; web: () => WebWorkerLike };

interface NodeWorker {
  postMessage(message: unknown, transfer: Transferable[]): void;
  on(event: 'message', listener: (data: unknown) => void): void;
  on(event: 'error' | 'messageerror', listener: (error: Error) => void): void;
  on(event: 'exit', listener: (code: number) => void): void;
  ref(): void;
  unref(): void;
  terminate(): Promise<number>;
}

function onNode(): boolean {
  const g = globalThis as { process?: { versions?: { node?: string } }; Worker?: unknown };
  return typeof g.process?.versions?.node === 'string' && typeof g.Worker !== 'function';
}

async function startNode(url: URL | string, listener: ThreadListener): Promise<ThreadPort> {
  // a specifier in a variable, so that bundlers for the browser leave it alone
  const threads = 'node:worker_threads';
  const { Worker } = (await import(/* @vite-ignore */ threads)) as {
    Worker: new (url: URL | string) => NodeWorker;
  };
  // Node takes a file:// address only as a URL object (a string must be a path)
  const worker = new Worker(typeof url === 'string' && url.startsWith('file:') ? new URL(url) : url);
  let ending = false;
  worker.on('message', (data) => listener.message(data));
  worker.on('error', (error) => listener.failure(error));
  worker.on('messageerror', (error) => listener.failure(error));
  worker.on('exit', (code) => {
    if (!ending) listener.failure(new Error(`the worker exited with code ${code}`));
  });
  worker.unref();
  return {
    post: (message, transfer = []) => worker.postMessage(message, transfer),
    hold: (keep) => (keep ? worker.ref() : worker.unref()),
    end: () => {
      ending = true;
      void worker.terminate();
    },
  };
}

function startWeb(worker: WebWorkerLike, listener: ThreadListener): ThreadPort {
  worker.onmessage = (event) => listener.message(event.data);
  worker.onerror = (event) => {
    event.preventDefault?.();
    const error =
      event.error instanceof Error ? event.error : new Error(event.message ?? 'the worker failed');
    listener.failure(error);
  };
  worker.onmessageerror = () => listener.failure(new Error('a message from the worker could not be read'));
  return {
    post: (message, transfer = []) => worker.postMessage(message, transfer),
    hold: () => {},
    end: () => worker.terminate(),
  };
}

/** @internal Starts a worker running `script`; its messages and failures go to `listener`. */
export async function startThread(script: ThreadScript, listener: ThreadListener): Promise<ThreadPort> {
  const own = typeof script === 'object' && !(script instanceof URL);
  if (onNode()) return startNode(own ? script.url : script, listener);
  if (own) return startWeb(script.web(), listener);
  const WorkerClass = (
    globalThis as unknown as { Worker: new (url: URL | string, options: object) => WebWorkerLike }
  ).Worker;
  return startWeb(new WorkerClass(script, { type: 'module' }), listener);
}
