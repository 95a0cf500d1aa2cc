/**
 * `fulcrum`: the engine (worlds, bodies, shapes, joints, events, queries, snapshots).
 * @module fulcrum
 */
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
  WarningEvent,
  WorldEventMap,
  WorldEvents,
} from './dynamics/events';
export type {
  DistanceJointDef,
  JointDef,
  MotorJointDef,
  MouseJointDef,
  PrismaticJointDef,
  RevoluteJointDef,
  WeldJointDef,
  WheelJointDef,
} from './dynamics/joints/create-joint';
export { DistanceJoint } from './dynamics/joints/distance-joint';
export { Joint, type JointType } from './dynamics/joints/joint';
export { MotorJoint } from './dynamics/joints/motor-joint';
export { MouseJoint } from './dynamics/joints/mouse-joint';
export { PrismaticJoint } from './dynamics/joints/prismatic-joint';
export { RevoluteJoint } from './dynamics/joints/revolute-joint';
export { WeldJoint } from './dynamics/joints/weld-joint';
export { WheelJoint } from './dynamics/joints/wheel-joint';
export { type Filter, type RayCastResult, type ShapeDef, ShapeHandle } from './dynamics/shape';
export { World, type WorldDef } from './dynamics/world';
export { Shape } from './geometry/shapes';
export type { Capsule, Circle, Geometry, Polygon, Segment } from './geometry/types';
export type { AABB } from './math/aabb';
export type { Rot, Transform, Vec2 } from './math/vec2';
export type { CastHit, QueryFilter, QueryTransform } from './query/index';
