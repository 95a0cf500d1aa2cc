import type { WorkerWorld } from '../worker/worker-world';
import type { AnyWorld, DrawSource } from './draw-source';
import { WorkerDrawSource } from './worker-source';
import { WorldDrawSource } from './world-source';

/** Whether `world` runs in a worker (tells the two kinds apart without loading fulcrum/worker). */
export function isWorkerWorld(world: AnyWorld): world is WorkerWorld {
  return !('core' in world);
}

/** The drawing source of a world on this thread or in a worker. */
export function drawSourceOf(world: AnyWorld): DrawSource {
  return isWorkerWorld(world) ? new WorkerDrawSource(world) : new WorldDrawSource(world);
}
