import type { Softness } from './softness';

/** @internal What every joint needs from the step: the body columns and the substep's constants. */
export interface JointContext {
  /** solver state, BodyState.STRIDE doubles per body slot (velocities, step deltas) */
  state: Float64Array;
  invMass: Float64Array;
  invInertia: Float64Array;
  /** centres of mass and rotations at the start of the step */
  cx: Float64Array;
  cy: Float64Array;
  qc: Float64Array;
  qs: Float64Array;
  lcx: Float64Array;
  lcy: Float64Array;
  h: number;
  invH: number;
  /** speeds no warm start may throw a body past (linear, angular): twice the step's limits */
  warmSpeedLimit: number;
  warmTurnLimit: number;
  /**
   * the fastest a joint's position correction moves its bodies (a rigid joint pulled back together,
   * a violated limit pushed back), as the contacts' push is bounded: along a row (m/s), in angle (rad/s)
   */
  jointPushMaxSpeed: number;
  jointPushMaxTurn: number;
  /** the most a tree joint's position error is corrected by in one substep (JointTree.stabilize) */
  jointCorrectionMax: number;
  jointCorrectionMaxTurn: number;
  /** the position error of a tree joint left to its velocity bias (JointTree.stabilize) */
  jointSlop: number;
  jointSlopTurn: number;
  /** softness of rigid joints' position correction */
  jointSoftness: Softness;
  /** the exact solver of tree-shaped joints (closures apply their impulses through it) */
  tree: TreeForJoints;
  /** the world's pose epoch at this step (WorldCore.poseEpoch: data carried over holds while it does) */
  poseEpoch: number;
}

/**
 * @internal What joints call on the JointTree (solver/joint-tree.ts, which implements it) while it
 * solves them: named here so that joints and the context do not depend on the tree's module.
 */
export interface TreeForJoints {
  /** while set, the limits the tree holds stay as chosen (see Joint.fillLimitRow) */
  readonly keepLimits: boolean;
  /** records that row `row` of tree joint `j` is a limit the tree holds */
  markLimitRow(j: number, row: number): void;
  /** a closure's point impulse, in and out of applyClosure */
  readonly closureImpulse: Float64Array;
  /** applies `closureImpulse` of closure `c` through the tree to the bodies' velocities in `state` */
  applyClosure(c: number, state: Float64Array): void;
}
