import type { JointContext } from './joint-context';

/**
 * A joint as the solvers see it: the slots of its two bodies, the per-step state each solver keeps on
 * it, and the rows it gives each solver (plain Gauss-Seidel, the hinge batch, hinge paths, the joint
 * tree). The joints (joints/joint.ts, and one file per type) implement it and say what each member
 * does: the solvers know joints through this interface only, not through the public handles.
 * @internal
 */
export interface SolverJoint {
  readonly slotA: number;
  readonly slotB: number;
  /** whether contacts between the two bodies are made */
  readonly collideConnected: boolean;
  /** anchors in the bodies' frames, relative to their origins */
  readonly localAnchorAx: number;
  readonly localAnchorAy: number;
  readonly localAnchorBx: number;
  readonly localAnchorBy: number;

  // Which solver takes the joint this step, and its place there.
  inTree: boolean;
  batchIndex: number;
  carriedSlot: number;
  onPath: boolean;
  closure: boolean;
  closureIndex: number;
  readonly closureMass: Float64Array;
  axialEntry0: number;
  axialEntry1: number;
  treeLimit: number;

  // Plain Gauss-Seidel.
  prepare(ctx: JointContext): void;
  warmStartGuarded(ctx: JointContext): void;
  solve(ctx: JointContext, useBias: boolean): void;
  forgetImpulses(): void;

  // The hinge batch and hinge paths.
  isPlainHinge(): boolean;
  isFreeHinge(): boolean;
  packHinge(ctx: JointContext, data: Float64Array, ids: Int32Array, anchors: Float64Array, i: number): void;
  unpackHinge(data: Float64Array, base: number, invH: number): void;

  // The joint tree.
  treeRows(): number;
  canCloseLoop(): boolean;
  iteratesInTree(): boolean;
  treeFill(
    ctx: JointContext,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    limits: boolean,
  ): number;
  treeAddImpulse(solution: Float64Array, o: number, keep: number): void;
  axialRows(): number;
  axialJacobian(state: Float64Array, row: number, jA: Float64Array, jB: Float64Array): void;
  solveAxial(ctx: JointContext, row: number, speed: number, mass: number, useBias: boolean): number;
}
