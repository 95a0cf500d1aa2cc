/** @internal A worker of a team, on Node's worker_threads or a module Web Worker. */
export interface Thread {
  post(message: unknown): void;
  /** Posts `message` and resolves with the worker's first reply (or rejects if it fails first). */
  ask(message: unknown): Promise<unknown>;
  end(): void;
}

interface NodeWorker {
  postMessage(message: unknown): void;
  once(event: 'message', listener: (reply: unknown) => void): void;
  once(event: 'error', listener: (error: Error) => void): void;
  unref(): void;
  terminate(): Promise<number>;
}

interface WebWorker {
  postMessage(message: unknown): void;
  onmessage: ((event: { data: unknown }) => void) | null;
  onerror: ((event: { message?: string }) => void) | null;
  terminate(): void;
}

function isNode(): boolean {
  const g = globalThis as { process?: { versions?: { node?: string } }; Worker?: unknown };
  return typeof g.process?.versions?.node === 'string' && typeof g.Worker !== 'function';
}

/** @internal Starts a worker running the script at `url`. */
export async function startThread(url: URL | string): Promise<Thread> {
  if (isNode()) {
    // a specifier in a variable, so that bundlers for the browser leave it alone
    const threads = 'node:worker_threads';
    const { Worker } = (await import(/* @vite-ignore */ threads)) as {
      Worker: new (url: URL | string) => NodeWorker;
    };
    // Node takes a file:// address only as a URL object (a string must be a path)
    const worker = new Worker(typeof url === 'string' && url.startsWith('file:') ? new URL(url) : url);
    // a team's workers do not keep the process alive: the world holds no pending work of its own
    worker.unref();
    return {
      post: (message) => worker.postMessage(message),
      ask: (message) =>
        new Promise((resolve, reject) => {
          worker.once('message', resolve);
          worker.once('error', reject);
          worker.postMessage(message);
        }),
      end: () => void worker.terminate(),
    };
  }
  const WorkerClass = (
    globalThis as unknown as { Worker: new (url: URL | string, options: object) => WebWorker }
  ).Worker;
  const worker = new WorkerClass(url, { type: 'module' });
  return {
    post: (message) => worker.postMessage(message),
    ask: (message) =>
      new Promise((resolve, reject) => {
        worker.onmessage = (event) => resolve(event.data);
        worker.onerror = (event) => reject(new Error(event.message ?? 'a solver worker failed'));
        worker.postMessage(message);
      }),
    end: () => worker.terminate(),
  };
}
