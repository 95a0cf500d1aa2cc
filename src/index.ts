/**
 * `fulcrum`: the engine (worlds, bodies, shapes, joints, events, queries, snapshots).
 * @module fulcrum
 */

export { Body, type BodyDef, type BodyType } from './api/body';
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
} from './api/events';
export { type Filter, type RayCastResult, type ShapeDef, ShapeHandle } from './api/shape';
export { stateHash } from './api/state-hash';
export { World, type WorldDef } from './api/world';
export { FulcrumError } from './core/errors';
export { Shape } from './geometry/shapes';
export { parseSvgPath, type SvgPathOptions, type SvgSubpath } from './geometry/svg-path';
export type { Capsule, Circle, Concave, Geometry, Polygon, Segment } from './geometry/types';
export type {
  DistanceJointDef,
  JointDef,
  MotorJointDef,
  MouseJointDef,
  PrismaticJointDef,
  RevoluteJointDef,
  WeldJointDef,
  WheelJointDef,
} from './joints/create-joint';
export { DistanceJoint } from './joints/distance-joint';
export { Joint, type JointType } from './joints/joint';
export { MotorJoint } from './joints/motor-joint';
export { MouseJoint } from './joints/mouse-joint';
export { PrismaticJoint } from './joints/prismatic-joint';
export { RevoluteJoint } from './joints/revolute-joint';
export { WeldJoint } from './joints/weld-joint';
export { WheelJoint } from './joints/wheel-joint';
export type { AABB } from './math/aabb';
export type { Rot, Transform, Vec2 } from './math/vec2';
export type { CastHit, QueryFilter, QueryTransform } from './query/index';
