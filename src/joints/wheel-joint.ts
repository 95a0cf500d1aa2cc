import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkNonNegativeForce, checkRate } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { motorImpulse } from '../solver/axial-rows';
import type { JointContext } from '../solver/joint-context';
import { BodyState } from '../store/body-store';
import {
  ANCHOR_KEYS,
  type AnchorDef,
  anchorsOf,
  BASE_KEYS,
  type BaseDef,
  type JointKind,
  jointBodies,
  optionalBoolean,
  optionalNumber,
  type SpringDef,
} from './joint-def';
import { SLIDER_KEYS, SliderJoint, type SliderOptions, sliderOptions } from './slider-joint';

/** A wheel joint (see WheelJoint): its suspension spring is on by default, at 1 Hz, damping ratio 0.7. */
export interface WheelJointDef extends BaseDef, AnchorDef, SpringDef {
  type: 'wheel';
  axis: Vec2;
  enableMotor?: boolean;
  motorSpeed?: number;
  maxMotorTorque?: number;
  enableLimit?: boolean;
  lower?: number;
  upper?: number;
}

/** @internal */
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

  /** @internal */
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

  setMaxMotorTorque(torque: number): void {
    checkNonNegativeForce('torque', torque);
    this.changing();
    this.o.maxMotorTorque = torque;
  }

  getReactionTorque(): number {
    this.check();
    return this.motorImpulse * this.invH;
  }

  /** @internal row 0 the motor's (B turns relative to A), row 1 along the axis (spring, limits) */
  override axialRows(): number {
    return (this.o.enableMotor ? 1 : 0) | (this.s.enableSpring || this.s.enableLimit ? 2 : 0);
  }

  /** @internal */
  override axialJacobian(state: Float64Array, row: number, jA: Float64Array, jB: Float64Array): void {
    if (row === 1) {
      super.axialJacobian(state, row, jA, jB);
      return;
    }
    jA[0] = 0;
    jA[1] = 0;
    jA[2] = -1;
    jB[0] = 0;
    jB[1] = 0;
    jB[2] = 1;
  }

  /** @internal */
  protected axisEntry(): number {
    return this.axialEntry1;
  }

  /** @internal row 0 the motor, row 1 the axis rows (see Joint.solveAxial) */
  override solveAxial(ctx: JointContext, row: number, speed: number, mass: number, useBias: boolean): number {
    if (row === 1) return this.solveAxisRows(ctx, speed, mass, useBias);
    const o = this.o;
    if (!o.enableMotor || mass === 0) return 0;
    const old = this.motorImpulse;
    this.motorImpulse = motorImpulse(old, speed, o.motorSpeed, mass, o.maxMotorTorque * ctx.h);
    return this.motorImpulse - old;
  }

  /** @internal the perpendicular row */
  override treeRows(): number {
    return 1;
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
    this.updateAxis(ctx.state);
    this.fillPerpRow(jA, jB, err, j, 0);
    return this.fillAxisLimitRow(ctx, jA, jB, err, j, 1, limits);
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.perpImpulse = keep * this.perpImpulse - solution[o];
    this.addLimitImpulse(solution, o + 1, keep);
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
    state[this.a * BodyState.STRIDE + BodyState.W] -= this.iA * this.motorImpulse;
    state[this.b * BodyState.STRIDE + BodyState.W] += this.iB * this.motorImpulse;
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    const k = this.iA + this.iB;
    // the motor here unless the tree solves it (TreeAxials)
    if (this.o.enableMotor && k > 0 && this.axialEntry0 < 0) {
      const sa = this.a * BodyState.STRIDE;
      const sb = this.b * BodyState.STRIDE;
      const impulse = this.solveAxial(
        ctx,
        0,
        state[sb + BodyState.W] - state[sa + BodyState.W],
        1 / k,
        useBias,
      );
      state[sa + BodyState.W] -= this.iA * impulse;
      state[sb + BodyState.W] += this.iB * impulse;
    }
    this.solveSlider(ctx, useBias);
  }
}

/** @internal The wheel joint's kind (see registry.ts): its keys, defaults and validation. */
export const wheelKind: JointKind<WheelJointDef, WheelJoint> = Object.freeze({
  className: 'WheelJoint',
  jointClass: WheelJoint,
  keys: Object.freeze([
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    ...SLIDER_KEYS,
    'enableMotor',
    'motorSpeed',
    'maxMotorTorque',
  ]),
  build(world: World, def: WheelJointDef): WheelJoint {
    const { a, b, collide } = jointBodies(world, def);
    const { la, lb } = anchorsOf(def, a, b);
    // a suspension: the spring on by default
    const slider = sliderOptions(def, a, true, 1, 0.7);
    return new WheelJoint(world, a, b, la, lb, collide, def.userData, slider, {
      enableMotor: optionalBoolean('enableMotor', def.enableMotor, false),
      motorSpeed: optionalNumber(checkRate, 'motorSpeed', def.motorSpeed, 0),
      maxMotorTorque: optionalNumber(checkNonNegativeForce, 'maxMotorTorque', def.maxMotorTorque, 0),
    });
  },
});
