import { startThread as startWorkerThread } from '../core/start-thread';

/** @internal A worker of a team, on Node's worker_threads or a module Web Worker. */
export interface Thread {
  post(message: unknown): void;
  /** Posts `message` and resolves with the worker's next message (or rejects if it fails first). */
  ask(message: unknown): Promise<unknown>;
  end(): void;
}

/**
 * @internal Starts a worker running the script at `url`. A failure while no `ask` waits is thrown: the
 * team's steps wait on the workers through shared memory, and would wait for ever on a dead one.
 */
export async function startThread(url: URL | string): Promise<Thread> {
  let waiting: { resolve(data: unknown): void; reject(error: Error): void } | null = null;
  const thread = await startWorkerThread(url, {
    message: (data) => {
      const asked = waiting;
      waiting = null;
      thread.hold(false);
      asked?.resolve(data);
    },
    failure: (error) => {
      const asked = waiting;
      waiting = null;
      thread.hold(false);
      if (asked === null) throw error;
      asked.reject(error);
    },
  });
  return {
    post: (message) => thread.post(message),
    // the worker keeps Node's process alive while an answer is awaited (a script that awaits
    // workersReady and nothing else would end there, its promise never settled), and only then
    ask: (message) =>
      new Promise((resolve, reject) => {
        waiting = { resolve, reject };
        thread.hold(true);
        thread.post(message);
      }),
    end: () => thread.end(),
  };
}
