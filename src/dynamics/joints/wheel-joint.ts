import { checkBoolean } from '../../core/errors';
import { checkNonNegativeForce, checkRate } from '../../core/limits';
import type { Vec2 } from '../../math/vec2';
import type { Body } from '../body';
import { S } from '../body-store';
import type { World } from '../world';
import type { JointContext } from './joint-context';
import { SliderJoint, type SliderOptions } from './slider-joint';

export interface WheelOptions {
  enableMotor: boolean;
  motorSpeed: number;
  maxMotorTorque: number;
}

/**
 * A wheel on a suspension: B's anchor slides along an axis fixed in A on a spring (with optional
 * limits) and B turns freely, driven by an optional motor.
 */
export class WheelJoint extends SliderJoint {
  readonly type = 'wheel' as const;
  /** @internal */
  o: WheelOptions;
  private motorImpulse = 0;

  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    localAnchorA: Vec2,
    localAnchorB: Vec2,
    collideConnected: boolean,
    userData: unknown,
    slider: SliderOptions,
    options: WheelOptions,
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

  setMaxMotorTorque(torque: number): void {
    checkNonNegativeForce('torque', torque);
    this.changing();
    this.o.maxMotorTorque = torque;
  }

  getReactionForce(): Vec2 {
    this.check();
    return this.sliderForce();
  }

  getReactionTorque(): number {
    this.check();
    return this.motorImpulse * this.invH;
  }

  /** @internal */
  protected hasMotor(): boolean {
    return this.o.enableMotor;
  }

  /** @internal the motor turns the wheel relative to A: its mass through the tree (see JointTree) */
  override hasAxialRow(): boolean {
    return this.o.enableMotor;
  }

  /** @internal the perpendicular row */
  override treeRows(): number {
    return 1;
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
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.perpImpulse = keep * this.perpImpulse - solution[o];
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareSlider(ctx);
    if (!this.o.enableMotor) this.motorImpulse = 0;
  }

  /** @internal */
  forgetImpulses(): void {
    this.forgetSliderImpulses();
    this.motorImpulse = 0;
  }

  /** @internal */
  warmStart(ctx: JointContext): void {
    const state = ctx.state;
    this.warmStartSlider(state);
    state[this.a * S.STRIDE + S.W] -= this.iA * this.motorImpulse;
    state[this.b * S.STRIDE + S.W] += this.iB * this.motorImpulse;
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    const o = this.o;
    const k = this.iA + this.iB;
    if (o.enableMotor && k > 0) {
      const sa = this.a * S.STRIDE;
      const sb = this.b * S.STRIDE;
      const max = o.maxMotorTorque * ctx.h;
      const old = this.motorImpulse;
      const mass = this.treeAxialMass > 0 ? this.treeAxialMass : 1 / k;
      this.motorImpulse = Math.max(
        -max,
        Math.min(old - mass * (state[sb + S.W] - state[sa + S.W] - o.motorSpeed), max),
      );
      const impulse = this.motorImpulse - old;
      state[sa + S.W] -= this.iA * impulse;
      state[sb + S.W] += this.iB * impulse;
    }
    this.solveSlider(ctx, useBias);
  }
}
