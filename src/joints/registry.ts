import { type DistanceJoint, type DistanceJointDef, distanceKind } from './distance-joint';
import type { JointKind } from './joint-def';
import { type MotorJoint, type MotorJointDef, motorKind } from './motor-joint';
import { type MouseJoint, type MouseJointDef, mouseKind } from './mouse-joint';
import { type PrismaticJoint, type PrismaticJointDef, prismaticKind } from './prismatic-joint';
import { type RevoluteJoint, type RevoluteJointDef, revoluteKind } from './revolute-joint';
import { type WeldJoint, type WeldJointDef, weldKind } from './weld-joint';
import { type WheelJoint, type WheelJointDef, wheelKind } from './wheel-joint';

/*
 * The joint types. Each type's file holds its class, its definition, and its kind (keys, defaults,
 * validation, the builder); here they are listed, once as types (JointTypes: World.createJoint maps
 * a definition's `type` to its joint class through it) and once as values (JOINT_KINDS: createJoint
 * and the snapshot read them). A new joint type is its file and a line in each.
 */

/** Each joint type's definition (`World.createJoint`'s argument) and the joint it makes. */
export interface JointTypes {
  distance: { def: DistanceJointDef; joint: DistanceJoint };
  revolute: { def: RevoluteJointDef; joint: RevoluteJoint };
  prismatic: { def: PrismaticJointDef; joint: PrismaticJoint };
  weld: { def: WeldJointDef; joint: WeldJoint };
  wheel: { def: WheelJointDef; joint: WheelJoint };
  mouse: { def: MouseJointDef; joint: MouseJoint };
  motor: { def: MotorJointDef; joint: MotorJoint };
}

export type JointType = keyof JointTypes;

/** A joint's definition, one of the types' (the `type` tells which). */
export type JointDef = JointTypes[JointType]['def'];

/** @internal Each type's kind, in the order an unknown type's error lists them. */
export const JOINT_KINDS: {
  readonly [T in JointType]: JointKind<JointTypes[T]['def'], JointTypes[T]['joint']>;
} = Object.freeze({
  distance: distanceKind,
  revolute: revoluteKind,
  prismatic: prismaticKind,
  weld: weldKind,
  wheel: wheelKind,
  mouse: mouseKind,
  motor: motorKind,
});
