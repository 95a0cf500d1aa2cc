import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkAngle, checkNonNegativeForce, checkRate } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { motorImpulse } from '../solver/axial-rows';
import type { JointContext } from '../solver/joint-context';
import { relativeAngle, unwindAngle } from '../solver/joint-math';
import { BodyState } from '../store/body-store';
import {
  ANCHOR_KEYS,
  type AnchorDef,
  anchorsOf,
  BASE_KEYS,
  type BaseDef,
  currentAngle,
  type JointKind,
  jointBodies,
  optionalBoolean,
  optionalNumber,
  type SpringDef,
} from './joint-def';
import { SLIDER_KEYS, SliderJoint, type SliderOptions, sliderOptions } from './slider-joint';

/** A prismatic joint (see PrismaticJoint); `referenceAngle` defaults to the bodies' angle now. */
export interface PrismaticJointDef extends BaseDef, AnchorDef, SpringDef {
  type: 'prismatic';
  axis: Vec2;
  referenceAngle?: number;
  enableLimit?: boolean;
  lower?: number;
  upper?: number;
  enableMotor?: boolean;
  motorSpeed?: number;
  maxMotorForce?: number;
}

/** @internal */
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
    options: PrismaticOptions,
  ) {
    super(world, bodyA, bodyB, localAnchorA, localAnchorB, collideConnected, userData, slider);
    this.o = options;
  }

  setMaxMotorForce(force: number): void {
    checkNonNegativeForce('force', force);
    this.changing();
    this.o.maxMotorForce = force;
  }

  getReactionTorque(): number {
    this.check();
    return this.angularImpulse * this.invH;
  }

  /** @internal motor, spring and limits push along the axis: one axial row (limits: see Joint) */
  override axialRows(): number {
    return this.o.enableMotor || this.s.enableSpring || this.s.enableLimit ? 1 : 0;
  }

  /** @internal */
  protected axisEntry(): number {
    return this.axialEntry0;
  }

  /** @internal */
  protected override axisMotor(ctx: JointContext, speed: number, mass: number): number {
    const o = this.o;
    if (!o.enableMotor) return 0;
    const old = this.axialImpulse;
    this.axialImpulse = motorImpulse(old, speed, o.motorSpeed, mass, o.maxMotorForce * ctx.h);
    return this.axialImpulse - old;
  }

  /** @internal the axis rows (see Joint.solveAxial) */
  override solveAxial(
    ctx: JointContext,
    _row: number,
    speed: number,
    mass: number,
    useBias: boolean,
  ): number {
    return this.solveAxisRows(ctx, speed, mass, useBias);
  }

  /** @internal the perpendicular and angular rows */
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
    this.updateAxis(ctx.state);
    this.fillPerpRow(jA, jB, err, j, 0);
    this.fillAngleRow(ctx.state, jA, jB, err, j, 1, this.angle0);
    return this.fillAxisLimitRow(ctx, jA, jB, err, j, 2, limits);
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.perpImpulse = keep * this.perpImpulse - solution[o];
    this.angularImpulse = keep * this.angularImpulse - solution[o + 1];
    this.addLimitImpulse(solution, o + 2, keep);
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareSlider(ctx);
    this.angle0 = unwindAngle(
      relativeAngle(ctx.qc[this.a], ctx.qs[this.a], ctx.qc[this.b], ctx.qs[this.b]) - this.o.referenceAngle,
    );
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
    state[this.a * BodyState.STRIDE + BodyState.W] -= this.iA * this.angularImpulse;
    state[this.b * BodyState.STRIDE + BodyState.W] += this.iB * this.angularImpulse;
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    this.solveSlider(ctx, useBias);
    // no rotation relative to A
    const k = this.iA + this.iB;
    if (k > 0 && !this.inTree) {
      const sa = this.a * BodyState.STRIDE;
      const sb = this.b * BodyState.STRIDE;
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias) {
        const C =
          this.angle0 +
          relativeAngle(
            state[sa + BodyState.DQC],
            state[sa + BodyState.DQS],
            state[sb + BodyState.DQC],
            state[sb + BodyState.DQS],
          );
        const soft = ctx.jointSoftness;
        bias = Math.max(-ctx.jointPushMaxTurn, Math.min(soft.biasRate * C, ctx.jointPushMaxTurn));
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
      }
      const impulse =
        (-massScale * (state[sb + BodyState.W] - state[sa + BodyState.W] + bias)) / k -
        impulseScale * this.angularImpulse;
      this.angularImpulse += impulse;
      state[sa + BodyState.W] -= this.iA * impulse;
      state[sb + BodyState.W] += this.iB * impulse;
    }
  }
}

/** @internal The prismatic joint's kind (see registry.ts): its keys, defaults and validation. */
export const prismaticKind: JointKind<PrismaticJointDef, PrismaticJoint> = Object.freeze({
  className: 'PrismaticJoint',
  jointClass: PrismaticJoint,
  keys: Object.freeze([
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    ...SLIDER_KEYS,
    'referenceAngle',
    'enableMotor',
    'motorSpeed',
    'maxMotorForce',
  ]),
  build(world: World, def: PrismaticJointDef): PrismaticJoint {
    const { a, b, collide } = jointBodies(world, def);
    const { la, lb } = anchorsOf(def, a, b);
    // no spring unless asked for
    const slider = sliderOptions(def, a, false, 0, 0);
    return new PrismaticJoint(world, a, b, la, lb, collide, def.userData, slider, {
      referenceAngle: optionalNumber(checkAngle, 'referenceAngle', def.referenceAngle, currentAngle(a, b)),
      enableMotor: optionalBoolean('enableMotor', def.enableMotor, false),
      motorSpeed: optionalNumber(checkRate, 'motorSpeed', def.motorSpeed, 0),
      maxMotorForce: optionalNumber(checkNonNegativeForce, 'maxMotorForce', def.maxMotorForce, 0),
    });
  },
});
