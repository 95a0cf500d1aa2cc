import { startThread, type WebWorkerLike } from '../core/start-thread';
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

/**
 * Starts the worker that runs a WorkerWorld's World: a worker_threads Worker on Node, a module Web
 * Worker elsewhere (browsers, Deno, Bun). `url` is its script, by default the package's
 * worker-entry.js beside this module.
 */
export async function startWorker(
  url: URL | string | undefined,
  listener: PortListener,
): Promise<WorkerPort> {
  const thread = await startThread(
    url ?? {
      url: new URL('./worker-entry.js', import.meta.url),
      // `new Worker` written out in full (minifiers keep the global's name), so that bundlers (Vite,
      // webpack, Parcel) find the script and bundle it as a worker
      web: () =>
        new Worker(new URL('./worker-entry.js', import.meta.url), {
          type: 'module',
        }) as unknown as WebWorkerLike,
    },
    { message: (data) => listener.reply(data as Reply), failure: (error) => listener.failure(error) },
  );
  return {
    post: (batch, transfer) => thread.post(batch, transfer),
    hold: (waiting) => thread.hold(waiting),
    terminate: () => thread.end(),
  };
}
