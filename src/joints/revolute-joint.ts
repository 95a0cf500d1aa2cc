import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkBoolean, FulcrumError } from '../core/errors';
import {
  checkAngle,
  checkHertz,
  checkNonNegativeForce,
  checkNonNegativeRate,
  checkRate,
} from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { limitImpulse, motorImpulse } from '../solver/axial-rows';
import { HingeField } from '../solver/hinge-batch';
import type { JointContext } from '../solver/joint-context';
import { relativeAngle, unwindAngle } from '../solver/joint-math';
import { CLOSURE_REGULARIZATION } from '../solver/joint-tree';
import { makeSoftness, type Softness, springImpulse } from '../solver/softness';
import { BodyState } from '../store/body-store';
import { Joint } from './joint';
import {
  ANCHOR_KEYS,
  type AnchorDef,
  anchorsOf,
  BASE_KEYS,
  type BaseDef,
  checkOrder,
  currentAngle,
  type JointKind,
  jointBodies,
  optionalBoolean,
  optionalNumber,
  SPRING_KEYS,
  type SpringDef,
} from './joint-def';

/** the Jacobian of B's turn relative to A (A's block, then B's) */
const TURN_JACOBIAN: readonly number[] = Object.freeze([0, 0, -1, 0, 0, 1]);

/** A revolute joint (see RevoluteJoint); `referenceAngle` defaults to the bodies' angle now. */
export interface RevoluteJointDef extends BaseDef, AnchorDef, SpringDef {
  type: 'revolute';
  referenceAngle?: number;
  enableLimit?: boolean;
  lowerAngle?: number;
  upperAngle?: number;
  enableMotor?: boolean;
  motorSpeed?: number;
  maxMotorTorque?: number;
}

/** @internal */
export interface RevoluteOptions {
  referenceAngle: number;
  enableLimit: boolean;
  lowerAngle: number;
  upperAngle: number;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorTorque: number;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
}

/**
 * A hinge: the anchors of both bodies stay together and the bodies turn freely about them, within
 * optional angle limits, driven by an optional motor (speed, torque limit) and an optional rotational
 * spring towards the reference angle.
 */
export class RevoluteJoint extends Joint {
  readonly type = 'revolute' as const;
  /** @internal */
  o: RevoluteOptions;
  private linearX = 0;
  private linearY = 0;
  private springImpulse = 0;
  private motorImpulse = 0;
  private lowerImpulse = 0;
  private upperImpulse = 0;
  private angle0 = 0;
  private axialMass = 0;
  private readonly spring: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };

  /** @internal */
  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    localAnchorA: Vec2,
    localAnchorB: Vec2,
    collideConnected: boolean,
    userData: unknown,
    options: RevoluteOptions,
  ) {
    super(world, bodyA, bodyB, localAnchorA, localAnchorB, collideConnected, userData);
    this.o = options;
  }

  /** Angle of B relative to A, minus the reference angle (radians). */
  get angle(): number {
    this.check();
    const a = this.bodyA.rotation;
    const b = this.bodyB.rotation;
    return unwindAngle(relativeAngle(a.c, a.s, b.c, b.s) - this.o.referenceAngle);
  }

  get motorSpeed(): number {
    return this.o.motorSpeed;
  }

  enableMotor(enable: boolean): void {
    checkBoolean('enable', enable);
    this.changing();
    this.o.enableMotor = enable;
  }

  setMotorSpeed(speed: number): void {
    checkRate('speed', speed);
    this.changing();
    this.o.motorSpeed = speed;
  }

  setMaxMotorTorque(torque: number): void {
    checkNonNegativeForce('torque', torque);
    this.changing();
    this.o.maxMotorTorque = torque;
  }

  enableLimit(enable: boolean): void {
    checkBoolean('enable', enable);
    this.changing();
    this.o.enableLimit = enable;
  }

  setLimits(lowerAngle: number, upperAngle: number): void {
    checkAngle('lowerAngle', lowerAngle);
    checkAngle('upperAngle', upperAngle);
    if (lowerAngle > upperAngle) {
      throw new FulcrumError(`lowerAngle must be <= upperAngle, got ${lowerAngle} > ${upperAngle}`);
    }
    this.changing();
    this.o.lowerAngle = lowerAngle;
    this.o.upperAngle = upperAngle;
  }

  enableSpring(enable: boolean): void {
    checkBoolean('enable', enable);
    this.changing();
    this.o.enableSpring = enable;
  }

  setSpring(hertz: number, dampingRatio: number): void {
    checkHertz('hertz', hertz);
    checkNonNegativeRate('dampingRatio', dampingRatio);
    this.changing();
    this.o.hertz = hertz;
    this.o.dampingRatio = dampingRatio;
  }

  getReactionForce(): Vec2 {
    this.check();
    if (this.batchIndex >= 0) {
      // the hinge batch keeps the impulse until the hinge leaves it (see HingeBatch)
      const batch = this.core.hingeBatch;
      const base = this.batchIndex * HingeField.STRIDE;
      return {
        x: batch.data[base + HingeField.LX] * batch.invH,
        y: batch.data[base + HingeField.LY] * batch.invH,
      };
    }
    return { x: this.linearX * this.invH, y: this.linearY * this.invH };
  }

  getReactionTorque(): number {
    this.check();
    return (this.springImpulse + this.motorImpulse + this.lowerImpulse - this.upperImpulse) * this.invH;
  }

  /** @internal spring, motor and limits turn B relative to A: one axial row */
  override axialRows(): number {
    const o = this.o;
    return o.enableMotor || o.enableSpring || o.enableLimit ? 1 : 0;
  }

  /** @internal */
  override iteratesInTree(): boolean {
    return this.o.enableLimit || this.o.enableMotor || this.o.enableSpring;
  }

  /** @internal */
  override canCloseLoop(): boolean {
    return true;
  }

  /** @internal the point rows */
  override treeRows(): number {
    return 2;
  }

  /** @internal */
  override treeFill(
    ctx: JointContext,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    limits: boolean,
  ): number {
    const state = ctx.state;
    this.updateAnchors(state);
    this.fillPointRows(jA, jB, err, j);
    if (!limits || !this.o.enableLimit || this.iA + this.iB === 0) {
      this.treeLimit = 0;
      return 2;
    }
    const angle = this.currentAngle(state);
    return this.fillLimitRow(
      ctx,
      jA,
      jB,
      err,
      j,
      2,
      TURN_JACOBIAN,
      ctx.jointPushMaxTurn * ctx.h,
      angle - this.o.lowerAngle,
      this.o.upperAngle - angle,
      this.lowerImpulse,
      this.upperImpulse,
    );
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.linearX = keep * this.linearX - solution[o];
    this.linearY = keep * this.linearY - solution[o + 1];
    if (this.treeLimit === 1) this.lowerImpulse = keep * this.lowerImpulse - solution[o + 2];
    else if (this.treeLimit === -1) this.upperImpulse = keep * this.upperImpulse - solution[o + 2];
  }

  /** @internal */
  override isPlainHinge(): boolean {
    return !this.inTree && !this.closure && this.isFreeHinge();
  }

  /** @internal */
  override isFreeHinge(): boolean {
    const o = this.o;
    return !o.enableLimit && !o.enableMotor && !o.enableSpring;
  }

  /** @internal */
  override packHinge(
    ctx: JointContext,
    data: Float64Array,
    ids: Int32Array,
    anchors: Float64Array,
    i: number,
  ): void {
    super.packHinge(ctx, data, ids, anchors, i);
    const base = i * HingeField.STRIDE;
    // as prepare does for disabled rows
    this.springImpulse = 0;
    this.motorImpulse = 0;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
    data[base + HingeField.LX] = this.linearX;
    data[base + HingeField.LY] = this.linearY;
    this.batchIndex = i;
  }

  /** @internal */
  override unpackHinge(data: Float64Array, base: number, invH: number): void {
    this.linearX = data[base + HingeField.LX];
    this.linearY = data[base + HingeField.LY];
    this.invH = invH;
    this.batchIndex = -1;
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareBase(ctx);
    const k = this.iA + this.iB;
    this.axialMass = k > 0 ? 1 / k : 0;
    // only limits and springs read the angle (computing it boxes a double per joint and step)
    if (this.o.enableLimit || this.o.enableSpring)
      this.angle0 = unwindAngle(
        relativeAngle(ctx.qc[this.a], ctx.qs[this.a], ctx.qc[this.b], ctx.qs[this.b]) - this.o.referenceAngle,
      );
    makeSoftness(this.o.enableSpring ? this.o.hertz : 0, this.o.dampingRatio, ctx.h, this.spring);
    if (!this.o.enableSpring) this.springImpulse = 0;
    if (!this.o.enableMotor) this.motorImpulse = 0;
    if (!this.o.enableLimit) {
      this.lowerImpulse = 0;
      this.upperImpulse = 0;
    }
  }

  /** @internal */
  forgetImpulses(): void {
    this.linearX = 0;
    this.linearY = 0;
    this.springImpulse = 0;
    this.motorImpulse = 0;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
  }

  /** @internal */
  warmStart(ctx: JointContext): void {
    const state = ctx.state;
    this.updateAnchors(state);
    this.core.work.pointRows.applyTurnImpulse(
      state,
      this.a * BodyState.STRIDE,
      this.b * BodyState.STRIDE,
      this.mA,
      this.iA,
      this.mB,
      this.iB,
      this.rAx,
      this.rAy,
      this.rBx,
      this.rBy,
      this.linearX,
      this.linearY,
      this.springImpulse + this.motorImpulse + this.lowerImpulse - this.upperImpulse,
    );
  }

  /** Current joint angle from the angle at the step's start and the rotations since. */
  private currentAngle(state: Float64Array): number {
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    return (
      this.angle0 +
      relativeAngle(
        state[sa + BodyState.DQC],
        state[sa + BodyState.DQS],
        state[sb + BodyState.DQC],
        state[sb + BodyState.DQS],
      )
    );
  }

  /** B's angular velocity relative to A's. */
  private relativeTurn(state: Float64Array): number {
    return state[this.b * BodyState.STRIDE + BodyState.W] - state[this.a * BodyState.STRIDE + BodyState.W];
  }

  /** @internal spring, motor and limits, in that order, on B's turn relative to A (see Joint) */
  override solveAxial(
    ctx: JointContext,
    _row: number,
    speed: number,
    mass: number,
    useBias: boolean,
  ): number {
    if (mass === 0) return 0;
    const o = this.o;
    const invMass = 1 / mass;
    let total = 0;
    if (o.enableSpring) {
      const impulse = springImpulse(
        this.spring,
        o.hertz,
        ctx.h,
        this.iA + this.iB,
        invMass,
        speed,
        this.currentAngle(ctx.state),
        this.springImpulse,
      );
      this.springImpulse += impulse;
      speed += impulse * invMass;
      total += impulse;
    }
    if (o.enableMotor) {
      const old = this.motorImpulse;
      this.motorImpulse = motorImpulse(old, speed, o.motorSpeed, mass, o.maxMotorTorque * ctx.h);
      const impulse = this.motorImpulse - old;
      speed += impulse * invMass;
      total += impulse;
    }
    // a limit the tree holds this substep is its row (Joint.fillLimitRow)
    if (o.enableLimit && this.treeLimit === 0) {
      const angle = this.currentAngle(ctx.state);
      const maxPush = ctx.jointPushMaxTurn;
      // lower limit: angle - lower >= 0
      const oldLower = this.lowerImpulse;
      this.lowerImpulse = limitImpulse(ctx, useBias, oldLower, angle - o.lowerAngle, speed, mass, maxPush);
      const lower = this.lowerImpulse - oldLower;
      speed += lower * invMass;
      // upper limit: upper - angle >= 0, pushing the other way
      const oldUpper = this.upperImpulse;
      this.upperImpulse = limitImpulse(ctx, useBias, oldUpper, o.upperAngle - angle, -speed, mass, maxPush);
      total += lower - (this.upperImpulse - oldUpper);
    }
    return total;
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    // the axial rows here unless the tree solves them (TreeAxials)
    if (this.axialEntry0 < 0 && this.axialRows() !== 0) {
      const impulse = this.solveAxial(ctx, 0, this.relativeTurn(state), this.axialMass, useBias);
      state[sa + BodyState.W] -= this.iA * impulse;
      state[sb + BodyState.W] += this.iB * impulse;
    }
    // point-to-point, unless the tree solver owns it
    if (!this.inTree) this.solvePoint(ctx, useBias);
  }

  /**
   * The point rows (see solver/point-rows.ts), with the bodies' own masses or, closing a loop of the
   * tree, through it. A method of its own, called with no doubles: in solve, with the axial rows,
   * they left solveAxial out of V8's inlining budget, a call that boxes its doubles (a grid of
   * motored hinges took 1.19x the instructions a step).
   */
  private solvePoint(ctx: JointContext, useBias: boolean): void {
    const rows = this.core.work.pointRows;
    const state = ctx.state;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    const mA = this.mA;
    const iA = this.iA;
    const mB = this.mB;
    const iB = this.iB;
    this.updateAnchors(state);
    const rAx = this.rAx;
    const rAy = this.rAy;
    const rBx = this.rBx;
    const rBy = this.rBy;
    const wA = state[sa + BodyState.W];
    const wB = state[sb + BodyState.W];
    const cdotX = rows.speedX(state[sa + BodyState.VX], wA, rAy, state[sb + BodyState.VX], wB, rBy);
    const cdotY = rows.speedY(state[sa + BodyState.VY], wA, rAx, state[sb + BodyState.VY], wB, rBx);
    let biasX = 0;
    let biasY = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (useBias) {
      const soft = ctx.jointSoftness;
      biasX = soft.biasRate * this.sepX;
      biasY = soft.biasRate * this.sepY;
      // bounded, as a contact's push is: joints torn apart in a loop that cannot close (or limits
      // against pins) otherwise pull at any speed, and the relax pass cannot take all of it back
      const f = rows.pullBound(biasX, biasY, ctx.jointPushMaxSpeed);
      biasX *= f;
      biasY *= f;
      massScale = soft.massScale;
      impulseScale = soft.impulseScale;
    }
    let k11 = rows.massDiagonal(mA + mB, iA, rAy, iB, rBy);
    let k12 = rows.massCoupling(iA, rAx, rAy, iB, rBx, rBy);
    let k22 = rows.massDiagonal(mA + mB, iA, rAx, iB, rBx);
    if (this.closure) {
      // through the tree, plus a little of the local mass: the tree may not let the hinge move at all
      // in some direction (two pinned bars), where K alone would be singular
      const k = this.closureMass;
      k11 = k[0] + CLOSURE_REGULARIZATION * k11;
      k12 = k[1] + CLOSURE_REGULARIZATION * k12;
      k22 = k[3] + CLOSURE_REGULARIZATION * k22;
    }
    const det = rows.inverseDeterminant(k11, k12, k22);
    const bx = cdotX + biasX;
    const by = cdotY + biasY;
    const px = rows.softImpulse(massScale, impulseScale, rows.solveX(det, k12, k22, bx, by), this.linearX);
    const py = rows.softImpulse(massScale, impulseScale, rows.solveY(det, k11, k12, bx, by), this.linearY);
    this.linearX += px;
    this.linearY += py;
    if (this.closure) {
      const impulse = ctx.tree.closureImpulse;
      impulse[0] = px;
      impulse[1] = py;
      ctx.tree.applyClosure(this.closureIndex, state);
      return;
    }
    rows.applyImpulse(state, sa, sb, mA, iA, mB, iB, rAx, rAy, rBx, rBy, px, py);
  }
}

/** @internal The revolute joint's kind (see registry.ts): its keys, defaults and validation. */
export const revoluteKind: JointKind<RevoluteJointDef, RevoluteJoint> = Object.freeze({
  className: 'RevoluteJoint',
  jointClass: RevoluteJoint,
  keys: Object.freeze([
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    ...SPRING_KEYS,
    'referenceAngle',
    'enableLimit',
    'lowerAngle',
    'upperAngle',
    'enableMotor',
    'motorSpeed',
    'maxMotorTorque',
  ]),
  build(world: World, def: RevoluteJointDef): RevoluteJoint {
    const { a, b, collide } = jointBodies(world, def);
    const { la, lb } = anchorsOf(def, a, b);
    const lowerAngle = optionalNumber(checkAngle, 'lowerAngle', def.lowerAngle, 0);
    const upperAngle = optionalNumber(checkAngle, 'upperAngle', def.upperAngle, 0);
    checkOrder('lowerAngle', lowerAngle, 'upperAngle', upperAngle);
    return new RevoluteJoint(world, a, b, la, lb, collide, def.userData, {
      referenceAngle: optionalNumber(checkAngle, 'referenceAngle', def.referenceAngle, currentAngle(a, b)),
      enableLimit: optionalBoolean('enableLimit', def.enableLimit, false),
      lowerAngle,
      upperAngle,
      enableMotor: optionalBoolean('enableMotor', def.enableMotor, false),
      motorSpeed: optionalNumber(checkRate, 'motorSpeed', def.motorSpeed, 0),
      maxMotorTorque: optionalNumber(checkNonNegativeForce, 'maxMotorTorque', def.maxMotorTorque, 0),
      enableSpring: optionalBoolean('enableSpring', def.enableSpring, false),
      hertz: optionalNumber(checkHertz, 'hertz', def.hertz, 0),
      dampingRatio: optionalNumber(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 0),
    });
  },
});
