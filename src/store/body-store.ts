import { growF64, growI32, growU8 } from '../core/grow';
import { SlotStore } from '../core/slot-store';

/*
 * Layouts, kinds and flags that hot loops use are enums, not module-level consts: a bundler (esbuild,
 * as in tsup's build of dist/) writes enum members into the code as numbers, where V8 (Node 20) loads a
 * module-level const from its context, checks its tag and adds it with an overflow check at every
 * use. Measured on the bundled engine: 15-27 % of a step (pyramid 0.77x, joint grid 0.73x).
 */
export enum BodyKind {
  STATIC = 0,
  KINEMATIC = 1,
  DYNAMIC = 2,
}

export enum BodyFlag {
  AWAKE = 1,
  FIXED_ROTATION = 2,
  BULLET = 4,
  ALLOW_SLEEP = 8,
  /** mass and rotational inertia given by Body.setMassData, not worked out from the shapes */
  MASS_SET = 16,
  /** the centre of mass given by Body.setMassData too */
  CENTER_SET = 32,
}

/**
 * Solver state of a body, 8 doubles (one cache line) per body slot:
 * linear velocity, angular velocity, a pad, then the translation of the centre of mass and the
 * rotation (cos, sin) accumulated since the start of the step. Static bodies keep zeros and (1, 0).
 */
export enum BodyState {
  STRIDE = 8,
  VX = 0,
  VY = 1,
  W = 2,
  DPX = 4,
  DPY = 5,
  DQC = 6,
  DQS = 7,
}

/**
 * Hot body data in typed-array columns indexed by body slot. Slots are reused through a free list;
 * a generation counter per slot lets handles detect that their body was destroyed.
 * @internal
 */
export class BodyStore extends SlotStore {
  kind = new Uint8Array(0);
  flags = new Uint8Array(0);
  /** counts the changes of any body's AWAKE flag after its creation (sleep, wake, type changes) */
  awakeEpoch = 0;
  state: Float64Array = new Float64Array(0);
  // origin transform
  px = new Float64Array(0);
  py = new Float64Array(0);
  qc = new Float64Array(0);
  qs = new Float64Array(0);
  // centre of mass: world and local
  cx = new Float64Array(0);
  cy = new Float64Array(0);
  lcx = new Float64Array(0);
  lcy = new Float64Array(0);
  mass = new Float64Array(0);
  /** what Body.setMassData gave (read where the flags MASS_SET and CENTER_SET say so) */
  givenMass = new Float64Array(0);
  givenInertia = new Float64Array(0);
  givenLcx = new Float64Array(0);
  givenLcy = new Float64Array(0);
  invMass = new Float64Array(0);
  inertia = new Float64Array(0);
  invInertia = new Float64Array(0);
  linearDamping = new Float64Array(0);
  angularDamping = new Float64Array(0);
  gravityScale = new Float64Array(0);
  fx = new Float64Array(0);
  fy = new Float64Array(0);
  torque = new Float64Array(0);
  sleepTime = new Float64Array(0);
  /** largest distance of any shape point from the centre of mass; smallest half-extent */
  maxExtent = new Float64Array(0);
  minExtent = new Float64Array(0);
  /** sleeping island the body belongs to (-1 when awake) and the next body of that island */
  sleepIsland = new Int32Array(0);
  islandNext = new Int32Array(0);
  /** heads of the body's intrusive lists: shapes, contact edges and joint edges (-1 = empty) */
  shapeHead = new Int32Array(0);
  contactHead = new Int32Array(0);
  jointHead = new Int32Array(0);

  protected resetSlot(slot: number): void {
    this.kind[slot] = BodyKind.STATIC;
    this.flags[slot] = 0;
    const s = slot * BodyState.STRIDE;
    this.state.fill(0, s, s + BodyState.STRIDE);
    this.state[s + BodyState.DQC] = 1;
    this.px[slot] = 0;
    this.py[slot] = 0;
    this.qc[slot] = 1;
    this.qs[slot] = 0;
    this.cx[slot] = 0;
    this.cy[slot] = 0;
    this.lcx[slot] = 0;
    this.lcy[slot] = 0;
    this.mass[slot] = 0;
    this.givenMass[slot] = 0;
    this.givenInertia[slot] = 0;
    this.givenLcx[slot] = 0;
    this.givenLcy[slot] = 0;
    this.invMass[slot] = 0;
    this.inertia[slot] = 0;
    this.invInertia[slot] = 0;
    this.linearDamping[slot] = 0;
    this.angularDamping[slot] = 0;
    this.gravityScale[slot] = 1;
    this.fx[slot] = 0;
    this.fy[slot] = 0;
    this.torque[slot] = 0;
    this.sleepTime[slot] = 0;
    this.maxExtent[slot] = 0;
    this.minExtent[slot] = 0;
    this.sleepIsland[slot] = -1;
    this.islandNext[slot] = -1;
    this.shapeHead[slot] = -1;
    this.contactHead[slot] = -1;
    this.jointHead[slot] = -1;
  }

  protected growColumns(capacity: number): void {
    this.kind = growU8(this.kind, capacity);
    this.flags = growU8(this.flags, capacity);
    this.state = growF64(this.state, capacity * BodyState.STRIDE);
    this.px = growF64(this.px, capacity);
    this.py = growF64(this.py, capacity);
    this.qc = growF64(this.qc, capacity);
    this.qs = growF64(this.qs, capacity);
    this.cx = growF64(this.cx, capacity);
    this.cy = growF64(this.cy, capacity);
    this.lcx = growF64(this.lcx, capacity);
    this.lcy = growF64(this.lcy, capacity);
    this.mass = growF64(this.mass, capacity);
    this.givenMass = growF64(this.givenMass, capacity);
    this.givenInertia = growF64(this.givenInertia, capacity);
    this.givenLcx = growF64(this.givenLcx, capacity);
    this.givenLcy = growF64(this.givenLcy, capacity);
    this.invMass = growF64(this.invMass, capacity);
    this.inertia = growF64(this.inertia, capacity);
    this.invInertia = growF64(this.invInertia, capacity);
    this.linearDamping = growF64(this.linearDamping, capacity);
    this.angularDamping = growF64(this.angularDamping, capacity);
    this.gravityScale = growF64(this.gravityScale, capacity);
    this.fx = growF64(this.fx, capacity);
    this.fy = growF64(this.fy, capacity);
    this.torque = growF64(this.torque, capacity);
    this.sleepTime = growF64(this.sleepTime, capacity);
    this.maxExtent = growF64(this.maxExtent, capacity);
    this.minExtent = growF64(this.minExtent, capacity);
    this.sleepIsland = growI32(this.sleepIsland, capacity);
    this.islandNext = growI32(this.islandNext, capacity);
    this.shapeHead = growI32(this.shapeHead, capacity);
    this.contactHead = growI32(this.contactHead, capacity);
    this.jointHead = growI32(this.jointHead, capacity);
  }

  isAwake(slot: number): boolean {
    return (this.flags[slot] & BodyFlag.AWAKE) !== 0;
  }

  /** Recomputes the world centre of mass from the origin transform and the local centre. */
  updateCenter(slot: number): void {
    const c = this.qc[slot];
    const s = this.qs[slot];
    const lx = this.lcx[slot];
    const ly = this.lcy[slot];
    this.cx[slot] = c * lx - s * ly + this.px[slot];
    this.cy[slot] = s * lx + c * ly + this.py[slot];
  }
}
