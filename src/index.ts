/**
 * `fulcrum`: the engine (worlds, bodies, shapes, joints, events, queries, snapshots).
 * @module fulcrum
 */

export {
  Body,
  type BodyDef,
  type BodyType,
  type ContactData,
  type ContactPointData,
  type MassData,
} from './api/body';
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
export { type FrictionMixing, World, type WorldDef } from './api/world';
export { FulcrumError } from './core/errors';
export { Shape } from './geometry/shapes';
export { parseSvgPath, type SvgPathOptions, type SvgSubpath } from './geometry/svg-path';
export { svgShapes } from './geometry/svg-shapes';
export type { Capsule, Chain, Circle, Concave, Geometry, Polygon, Segment } from './geometry/types';
export { DistanceJoint, type DistanceJointDef } from './joints/distance-joint';
export { Joint } from './joints/joint';
export { MotorJoint, type MotorJointDef } from './joints/motor-joint';
export { MouseJoint, type MouseJointDef } from './joints/mouse-joint';
export { PrismaticJoint, type PrismaticJointDef } from './joints/prismatic-joint';
export type { JointDef, JointType } from './joints/registry';
export { RevoluteJoint, type RevoluteJointDef } from './joints/revolute-joint';
export { WeldJoint, type WeldJointDef } from './joints/weld-joint';
export { WheelJoint, type WheelJointDef } from './joints/wheel-joint';
export type { AABB } from './math/aabb';
export type { Rot, Transform, Vec2 } from './math/vec2';
export type { CastHit, QueryFilter, QueryTransform } from './query/index';
