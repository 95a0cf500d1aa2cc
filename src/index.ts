export { FulcrumError } from './core/errors';
export { stateHash } from './debug/state-hash';
export { Body, type BodyDef, type BodyType } from './dynamics/body';
export type {
  BodyEvent,
  ContactBeginEvent,
  ContactEndEvent,
  ContactHitEvent,
  SensorEvent,
  StepEvent,
  WorldEventMap,
  WorldEvents,
} from './dynamics/events';
export { type Filter, type RayCastResult, type ShapeDef, ShapeHandle } from './dynamics/shape';
export { World, type WorldDef } from './dynamics/world';
export { Shape } from './geometry/shapes';
export type { Capsule, Circle, Geometry, Polygon, Segment } from './geometry/types';
export type { AABB } from './math/aabb';
export type { Rot, Transform, Vec2 } from './math/vec2';
