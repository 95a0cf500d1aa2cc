import type { Batch, Reply } from './protocol';

/**
 * The calling thread's end of a worker, whatever the platform: post batches, hear replies, hear that
 * the worker failed or went away, and end it.
 */
export interface WorkerPort {
  post(batch: Batch, transfer: Transferable[]): void;
  /** Whether the world waits for a reply: on Node, an idle worker does not keep the process alive. */
  hold(waiting: boolean): void;
  terminate(): void;
}

export interface PortListener {
  reply(reply: Reply): void;
  /** the worker threw, could not start, or exited without being asked to */
  failure(error: Error): void;
}

interface NodeWorker {
  postMessage(message: unknown, transfer: Transferable[]): void;
  on(event: 'message', listener: (reply: Reply) => void): void;
  on(event: 'error' | 'messageerror', listener: (error: Error) => void): void;
  on(event: 'exit', listener: (code: number) => void): void;
  ref(): void;
  unref(): void;
  terminate(): Promise<number>;
}

interface WebWorker {
  postMessage(message: unknown, transfer: Transferable[]): void;
  onmessage: ((event: { data: Reply }) => void) | null;
  onerror: ((event: { message?: string; error?: unknown; preventDefault?(): void }) => void) | null;
  onmessageerror: (() => void) | null;
  terminate(): void;
}

function isNode(): boolean {
  const g = globalThis as { process?: { versions?: { node?: string } } };
  return typeof g.process?.versions?.node === 'string';
}

/** Node's worker_threads Worker running the script at `url`. */
async function startNode(url: URL | string | undefined, listener: PortListener): Promise<WorkerPort> {
  // a specifier in a variable, so that bundlers for the browser leave it alone
  const threads = 'node:worker_threads';
  const { Worker } = (await import(/* @vite-ignore */ threads)) as {
    Worker: new (url: URL | string) => NodeWorker;
  };
  const worker = new Worker(url ?? new URL('./worker-entry.js', import.meta.url));
  let ending = false;
  worker.on('message', (reply) => listener.reply(reply));
  worker.on('error', (error) => listener.failure(error));
  worker.on('messageerror', (error) => listener.failure(error));
  worker.on('exit', (code) => {
    if (!ending) listener.failure(new Error(`the worker exited with code ${code}`));
  });
  worker.unref();
  return {
    post: (batch, transfer) => worker.postMessage(batch, transfer),
    hold: (waiting) => (waiting ? worker.ref() : worker.unref()),
    terminate: () => {
      ending = true;
      void worker.terminate();
    },
  };
}

/** A module Web Worker running the script at `url`. */
function startWeb(url: URL | string | undefined, listener: PortListener): WorkerPort {
  const WorkerClass = (
    globalThis as unknown as { Worker: new (url: URL | string, options: object) => WebWorker }
  ).Worker;
  // written out in full when no url is given, so that bundlers (Vite, webpack, Parcel) find the script
  const worker =
    url === undefined
      ? new WorkerClass(new URL('./worker-entry.js', import.meta.url), { type: 'module' })
      : new WorkerClass(url, { type: 'module' });
  worker.onmessage = (event) => listener.reply(event.data);
  worker.onerror = (event) => {
    event.preventDefault?.();
    const error =
      event.error instanceof Error ? event.error : new Error(event.message ?? 'the worker failed');
    listener.failure(error);
  };
  worker.onmessageerror = () => listener.failure(new Error('a reply from the worker could not be read'));
  return {
    post: (batch, transfer) => worker.postMessage(batch, transfer),
    hold: () => {},
    terminate: () => worker.terminate(),
  };
}

/**
 * Starts the worker that runs a WorkerWorld's World: a worker_threads Worker on Node, a module Web
 * Worker elsewhere (browsers, Deno, Bun). `url` is its script, by default the package's
 * worker-entry.js beside this module.
 */
export async function startWorker(
  url: URL | string | undefined,
  listener: PortListener,
): Promise<WorkerPort> {
  if (isNode() && typeof (globalThis as { Worker?: unknown }).Worker !== 'function') {
    return startNode(url, listener);
  }
  return startWeb(url, listener);
}
