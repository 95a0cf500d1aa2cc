import { checkBoolean } from '../../core/errors';
import { checkNonNegativeForce, checkRate } from '../../core/limits';
import type { Vec2 } from '../../math/vec2';
import type { Body } from '../body';
import { S } from '../body-store';
import type { World } from '../world';
import type { JointContext } from './joint-context';
import { relativeAngle } from './joint-math';
import { SliderJoint, type SliderOptions } from './slider-joint';

export interface PrismaticOptions {
  referenceAngle: number;
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorForce: number;
}

/** A slider: B moves along an axis fixed in A without turning relative to A; limits, motor, spring. */
export class PrismaticJoint extends SliderJoint {
  readonly type = 'prismatic' as const;
  /** @internal */
  o: PrismaticOptions;
  private angularImpulse = 0;
  private angle0 = 0;

  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    localAnchorA: Vec2,
    localAnchorB: Vec2,
    collideConnected: boolean,
    userData: unknown,
    slider: SliderOptions,
    options: PrismaticOptions,
  ) {
    super(world, bodyA, bodyB, localAnchorA, localAnchorB, collideConnected, userData, slider);
    this.o = options;
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

  setMaxMotorForce(force: number): void {
    checkNonNegativeForce('force', force);
    this.changing();
    this.o.maxMotorForce = force;
  }

  getReactionForce(): Vec2 {
    this.check();
    return this.sliderForce();
  }

  getReactionTorque(): number {
    this.check();
    return this.angularImpulse * this.invH;
  }

  /** @internal */
  protected hasMotor(): boolean {
    return this.o.enableMotor;
  }

  /** @internal the motor and the limits push along the axis: their mass through the tree */
  override hasAxialRow(): boolean {
    return this.o.enableMotor || this.s.enableLimit;
  }

  /** @internal the row along the axis */
  override axialJacobian(state: Float64Array, jA: Float64Array, jB: Float64Array): void {
    this.updateAxis(state);
    jA[0] = -this.ux;
    jA[1] = -this.uy;
    jA[2] = -this.a1;
    jB[0] = this.ux;
    jB[1] = this.uy;
    jB[2] = this.a2;
  }

  /** @internal */
  protected override axisRowMass(): number {
    return this.treeAxialMass > 0 ? this.treeAxialMass : this.axialMass;
  }

  /** @internal the perpendicular and angular rows */
  override treeRows(): number {
    return 2;
  }

  /** @internal */
  override treeFill(
    state: Float64Array,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
  ): void {
    this.updateAxis(state);
    this.fillPerpRow(jA, jB, err, j, 0);
    this.fillAngleRow(state, jA, jB, err, j, 1, this.angle0);
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.perpImpulse = keep * this.perpImpulse - solution[o];
    this.angularImpulse = keep * this.angularImpulse - solution[o + 1];
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareSlider(ctx);
    this.angle0 =
      relativeAngle(ctx.qc[this.a], ctx.qs[this.a], ctx.qc[this.b], ctx.qs[this.b]) - this.o.referenceAngle;
    if (!this.o.enableMotor) this.axialImpulse = 0;
  }

  /** @internal */
  forgetImpulses(): void {
    this.forgetSliderImpulses();
    this.angularImpulse = 0;
  }

  /** @internal */
  warmStart(ctx: JointContext): void {
    const state = ctx.state;
    this.warmStartSlider(state);
    state[this.a * S.STRIDE + S.W] -= this.iA * this.angularImpulse;
    state[this.b * S.STRIDE + S.W] += this.iB * this.angularImpulse;
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    const o = this.o;
    if (o.enableMotor) {
      this.updateAxis(state);
      const max = o.maxMotorForce * ctx.h;
      const old = this.axialImpulse;
      this.axialImpulse = Math.max(
        -max,
        Math.min(old - this.axisRowMass() * (this.axialSpeed(state) - o.motorSpeed), max),
      );
      this.applyAxial(state, this.axialImpulse - old);
    }
    this.solveSlider(ctx, useBias);
    // no rotation relative to A
    const k = this.iA + this.iB;
    if (k > 0 && !this.inTree) {
      const sa = this.a * S.STRIDE;
      const sb = this.b * S.STRIDE;
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias) {
        const C =
          this.angle0 +
          relativeAngle(state[sa + S.DQC], state[sa + S.DQS], state[sb + S.DQC], state[sb + S.DQS]);
        const soft = ctx.jointSoftness;
        bias = soft.biasRate * C;
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
      }
      const impulse =
        (-massScale * (state[sb + S.W] - state[sa + S.W] + bias)) / k - impulseScale * this.angularImpulse;
      this.angularImpulse += impulse;
      state[sa + S.W] -= this.iA * impulse;
      state[sb + S.W] += this.iB * impulse;
    }
  }
}
