// A room worker's script. Node 20 workers do not take the TypeScript hooks (tsx) their process
// registered, so this registers tsx in the worker, then runs the TypeScript source: the pool and its
// workers then run the very same Fulcrum code, which snapshots need to restore.
import { parentPort } from 'node:worker_threads';
import { register } from 'tsx/esm/api';

register();
const { serveRooms } = await import('./room-worker.ts');
serveRooms(parentPort);
