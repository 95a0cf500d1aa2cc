/**
 * Tuning constants of the solver, in metres and seconds. Lengths and speeds are scaled by the
 * world's `lengthUnitsPerMeter`, so a world in pixels (say 50 units per metre) behaves the same.
 * @internal
 */
export interface Settings {
  /** overlap tolerated before position correction, keeps contacts persistent */
  linearSlop: number;
  /** contact points are created this far apart (speculative contacts) */
  speculativeDistance: number;
  /**
   * a contact's manifold is kept while its shapes moved less than this relative to each other since it
   * was computed (settled piles: most contacts)
   */
  manifoldTolerance: number;
  /** fat AABB margin of moving proxies in the broad phase */
  aabbMargin: number;
  /** largest speed at which the soft contact pushes overlapping shapes apart */
  contactPushMaxSpeed: number;
  /** bodies slower than this (and turning slower, see island.ts) for timeToSleep fall asleep */
  sleepSpeed: number;
  /**
   * largest speed at which a joint's position correction moves its bodies (a rigid joint pulled
   * together, a violated limit pushed back), as contactPushMaxSpeed bounds the contacts'
   */
  jointPushMaxSpeed: number;
  /** most a tree joint's position error is corrected by in one substep (JointTree.stabilize) */
  jointCorrectionMax: number;
  /** normal approach speed above which restitution is applied */
  restitutionThreshold: number;
  /** largest linear speed a body may reach */
  maxLinearSpeed: number;
  /** the world's length unit: how many make a metre (the scale of every length above) */
  lengthUnitsPerMeter: number;
}

export const CONTACT_HERTZ = 30;
export const CONTACT_DAMPING_RATIO = 10;
export const JOINT_HERTZ = 60;
export const JOINT_DAMPING_RATIO = 2;
export const TIME_TO_SLEEP = 0.5;
/** fastest turn (rad/s) at which a joint's position correction turns its bodies (see jointPushMaxSpeed) */
export const JOINT_PUSH_MAX_TURN = 3;
/** most a tree joint's angle error is corrected by in one substep (radians; see jointCorrectionMax) */
export const JOINT_CORRECTION_MAX_TURN = 0.15;
/** a tree joint's angle error left to its velocity bias (radians; the linear one is linearSlop) */
export const JOINT_SLOP_TURN = (2 / 180) * Math.PI;
/** largest rotation of a body in one substep, radians; keeps the (cos, sin) integration accurate */
export const MAX_ROTATION_PER_SUBSTEP = 0.25 * Math.PI;

/** @internal */
export function makeSettings(lengthUnitsPerMeter: number): Settings {
  const u = lengthUnitsPerMeter;
  const linearSlop = 0.005 * u;
  return {
    lengthUnitsPerMeter: u,
    linearSlop,
    speculativeDistance: 4 * linearSlop,
    manifoldTolerance: linearSlop / 500,
    aabbMargin: 0.1 * u,
    contactPushMaxSpeed: 3 * u,
    jointPushMaxSpeed: 3 * u,
    jointCorrectionMax: 0.2 * u,
    sleepSpeed: 0.05 * u,
    restitutionThreshold: 1 * u,
    maxLinearSpeed: 400 * u,
  };
}
