/**
 * `fulcrum/worker`: a Fulcrum world in a worker (worker_threads on Node, a Web Worker in browsers),
 * built and commanded from the calling thread, read there synchronously after each step.
 * @module fulcrum/worker
 */

export type {
  WorkerBodyEvent,
  WorkerContactBeginEvent,
  WorkerContactEndEvent,
  WorkerContactHitEvent,
  WorkerSensorEvent,
  WorkerStepEvent,
  WorkerWarningEvent,
  WorkerWorldEventMap,
} from './events';
export { WorkerBody, type WorkerContactData, WorkerJoint, WorkerShape } from './handles';
export {
  type BufferMode,
  type WorkerCastHit,
  type WorkerJointDef,
  type WorkerOptions,
  WorkerWorld,
  type WorkerWorldDef,
} from './worker-world';
