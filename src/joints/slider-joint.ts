import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkBoolean, FulcrumError } from '../core/errors';
import { checkCoordinate, checkHertz, checkNonNegativeRate, checkRate } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { limitImpulse } from '../solver/axial-rows';
import type { JointContext } from '../solver/joint-context';
import { makeSoftness, type Softness, springImpulse } from '../solver/softness';
import { BodyState } from '../store/body-store';
import { Joint } from './joint';
import { checkOrder, optionalBoolean, optionalNumber, unitAxis } from './joint-def';

/** @internal The options of a slider's definition (prismatic, wheel), as given. */
export interface SliderDef {
  axis: Vec2;
  enableLimit?: boolean;
  lower?: number;
  upper?: number;
  enableSpring?: boolean;
  hertz?: number;
  dampingRatio?: number;
}

/** @internal The keys of SliderDef. */
export const SLIDER_KEYS: readonly string[] = Object.freeze([
  'axis',
  'enableLimit',
  'lower',
  'upper',
  'enableSpring',
  'hertz',
  'dampingRatio',
]);

/**
 * @internal The slider's options from a definition, checked, with the spring's defaults of the
 * joint's type. The axis is turned into body A's frame.
 */
export function sliderOptions(
  def: SliderDef,
  bodyA: Body,
  enableSpring: boolean,
  hertz: number,
  dampingRatio: number,
): SliderOptions {
  const axis = bodyA.getLocalVector(unitAxis(def.axis));
  const lower = optionalNumber(checkCoordinate, 'lower', def.lower, 0);
  const upper = optionalNumber(checkCoordinate, 'upper', def.upper, 0);
  checkOrder('lower', lower, 'upper', upper);
  return {
    localAxisX: axis.x,
    localAxisY: axis.y,
    enableLimit: optionalBoolean('enableLimit', def.enableLimit, false),
    lower,
    upper,
    enableSpring: optionalBoolean('enableSpring', def.enableSpring, enableSpring),
    hertz: optionalNumber(checkHertz, 'hertz', def.hertz, hertz),
    dampingRatio: optionalNumber(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, dampingRatio),
  };
}

/** @internal */
export interface SliderOptions {
  /** unit axis in body A's frame */
  localAxisX: number;
  localAxisY: number;
  enableLimit: boolean;
  lower: number;
  upper: number;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
}

/**
 * Shared part of the prismatic and wheel joints: body B's anchor moves along an axis fixed in body A
 * (no motion across it), within optional limits, with an optional spring towards translation 0.
 */
export abstract class SliderJoint extends Joint {
  /** @internal */
  s: SliderOptions;
  /** @internal the subclass's options: both joints have a motor */
  abstract o: { enableMotor: boolean; motorSpeed: number };
  /** @internal */
  protected perpImpulse = 0;
  /** @internal */
  protected springImpulse = 0;
  /** @internal */
  protected lowerImpulse = 0;
  /** @internal */
  protected upperImpulse = 0;
  /** @internal */
  protected axialImpulse = 0;
  private readonly spring: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  private axis0x = 1;
  private axis0y = 0;
  // current axis and Jacobian terms (updated by updateAxis)
  /** @internal */
  protected ux = 1;
  /** @internal */
  protected uy = 0;
  /** @internal */
  protected a1 = 0;
  /** @internal */
  protected a2 = 0;
  /** @internal */
  protected axialPosition = 0;
  /** @internal */
  protected axialMass = 0;

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
  ) {
    super(world, bodyA, bodyB, localAnchorA, localAnchorB, collideConnected, userData);
    this.s = slider;
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

  /** Translation of B's anchor along the axis from A's anchor (m). */
  get translation(): number {
    this.check();
    const a = this.anchorA;
    const b = this.anchorB;
    const axis = this.bodyA.getWorldVector({ x: this.s.localAxisX, y: this.s.localAxisY });
    return (b.x - a.x) * axis.x + (b.y - a.y) * axis.y;
  }

  enableLimit(enable: boolean): void {
    checkBoolean('enable', enable);
    this.changing();
    this.s.enableLimit = enable;
  }

  setLimits(lower: number, upper: number): void {
    checkCoordinate('lower', lower);
    checkCoordinate('upper', upper);
    if (lower > upper) throw new FulcrumError(`lower must be <= upper, got ${lower} > ${upper}`);
    this.changing();
    this.s.lower = lower;
    this.s.upper = upper;
  }

  enableSpring(enable: boolean): void {
    checkBoolean('enable', enable);
    this.changing();
    this.s.enableSpring = enable;
  }

  setSpring(hertz: number, dampingRatio: number): void {
    checkHertz('hertz', hertz);
    checkNonNegativeRate('dampingRatio', dampingRatio);
    this.changing();
    this.s.hertz = hertz;
    this.s.dampingRatio = dampingRatio;
  }

  /** @internal */
  prepareSlider(ctx: JointContext): void {
    this.prepareBase(ctx);
    const c = ctx.qc[this.a];
    const s = ctx.qs[this.a];
    this.axis0x = c * this.s.localAxisX - s * this.s.localAxisY;
    this.axis0y = s * this.s.localAxisX + c * this.s.localAxisY;
    makeSoftness(this.s.enableSpring ? this.s.hertz : 0, this.s.dampingRatio, ctx.h, this.spring);
    if (!this.s.enableSpring) this.springImpulse = 0;
    if (!this.s.enableLimit) {
      this.lowerImpulse = 0;
      this.upperImpulse = 0;
    }
  }

  /** @internal Current axis (turned with A), translation and the axial effective mass. */
  protected updateAxis(state: Float64Array): void {
    this.updateAnchors(state);
    const sa = this.a * BodyState.STRIDE;
    const c = state[sa + BodyState.DQC];
    const s = state[sa + BodyState.DQS];
    this.ux = c * this.axis0x - s * this.axis0y;
    this.uy = s * this.axis0x + c * this.axis0y;
    const dx = this.sepX + this.rAx;
    const dy = this.sepY + this.rAy;
    this.a1 = dx * this.uy - dy * this.ux;
    this.a2 = this.rBx * this.uy - this.rBy * this.ux;
    this.axialPosition = this.sepX * this.ux + this.sepY * this.uy;
    const k = this.mA + this.mB + this.iA * this.a1 * this.a1 + this.iB * this.a2 * this.a2;
    this.axialMass = k > 0 ? 1 / k : 0;
  }

  /** @internal */
  protected axialSpeed(state: Float64Array): number {
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    return (
      (state[sb + BodyState.VX] - state[sa + BodyState.VX]) * this.ux +
      (state[sb + BodyState.VY] - state[sa + BodyState.VY]) * this.uy +
      this.a2 * state[sb + BodyState.W] -
      this.a1 * state[sa + BodyState.W]
    );
  }

  /** @internal */
  protected applyAxial(state: Float64Array, impulse: number): void {
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    state[sa + BodyState.VX] -= this.mA * impulse * this.ux;
    state[sa + BodyState.VY] -= this.mA * impulse * this.uy;
    state[sa + BodyState.W] -= this.iA * impulse * this.a1;
    state[sb + BodyState.VX] += this.mB * impulse * this.ux;
    state[sb + BodyState.VY] += this.mB * impulse * this.uy;
    state[sb + BodyState.W] += this.iB * impulse * this.a2;
  }

  /** @internal The tree's entry of the axis row (see Joint.axialEntry0), -1 when it is not weighed there. */
  protected abstract axisEntry(): number;

  /** @internal Perpendicular impulse: P along perp = (-uy, ux), with its angular terms. */
  protected applyPerp(state: Float64Array, impulse: number): void {
    const px = -this.uy;
    const py = this.ux;
    const dx = this.sepX + this.rAx;
    const dy = this.sepY + this.rAy;
    const s1 = dx * py - dy * px;
    const s2 = this.rBx * py - this.rBy * px;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    state[sa + BodyState.VX] -= this.mA * impulse * px;
    state[sa + BodyState.VY] -= this.mA * impulse * py;
    state[sa + BodyState.W] -= this.iA * impulse * s1;
    state[sb + BodyState.VX] += this.mB * impulse * px;
    state[sb + BodyState.VY] += this.mB * impulse * py;
    state[sb + BodyState.W] += this.iB * impulse * s2;
  }

  /** @internal the rows along the axis (spring, limits, and the subclass's motor) */
  override iteratesInTree(): boolean {
    return this.s.enableSpring || this.s.enableLimit || this.o.enableMotor;
  }

  /** @internal the row along the axis */
  override axialJacobian(state: Float64Array, _row: number, jA: Float64Array, jB: Float64Array): void {
    this.updateAxis(state);
    jA[0] = -this.ux;
    jA[1] = -this.uy;
    jA[2] = -this.a1;
    jB[0] = this.ux;
    jB[1] = this.uy;
    jB[2] = this.a2;
  }

  /**
   * Writes the perpendicular row (no motion of B's anchor across the axis) as row `row` of tree joint
   * `j`, and zeros the rows after it; anchors and axis must be current (updateAxis).
   * @internal
   */
  protected fillPerpRow(jA: Float64Array, jB: Float64Array, err: Float64Array, j: number, row: number): void {
    const px = -this.uy;
    const py = this.ux;
    const dx = this.sepX + this.rAx;
    const dy = this.sepY + this.rAy;
    const m = 9 * j + 3 * row;
    jA[m] = -px;
    jA[m + 1] = -py;
    jA[m + 2] = -(dx * py - dy * px);
    jB[m] = px;
    jB[m + 1] = py;
    jB[m + 2] = this.rBx * py - this.rBy * px;
    err[3 * j + row] = this.sepX * px + this.sepY * py;
    this.clearTreeRows(jA, jB, err, j, row + 1);
  }

  /** the axis row's Jacobian (A's block, then B's) for fillLimitRow */
  private readonly axisJacobian = new Float64Array(6);

  /**
   * Writes the limit the bodies reach along the axis within the substep, if any, as row `row` of tree
   * joint `j` (see Joint.fillLimitRow); the axis must be current (updateAxis). Returns the row count.
   * @internal
   */
  protected fillAxisLimitRow(
    ctx: JointContext,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    row: number,
    limits: boolean,
  ): number {
    const o = this.s;
    if (!limits || !o.enableLimit) {
      this.treeLimit = 0;
      return row;
    }
    const jac = this.axisJacobian;
    jac[0] = -this.ux;
    jac[1] = -this.uy;
    jac[2] = -this.a1;
    jac[3] = this.ux;
    jac[4] = this.uy;
    jac[5] = this.a2;
    return this.fillLimitRow(
      ctx,
      jA,
      jB,
      err,
      j,
      row,
      jac,
      ctx.jointPushMaxSpeed * ctx.h,
      this.axialPosition - o.lower,
      o.upper - this.axialPosition,
      this.lowerImpulse,
      this.upperImpulse,
    );
  }

  /** @internal Adds the tree's impulse on the limit row at `solution[o]` (see treeAddImpulse). */
  protected addLimitImpulse(solution: Float64Array, o: number, keep: number): void {
    if (this.treeLimit === 1) this.lowerImpulse = keep * this.lowerImpulse - solution[o];
    else if (this.treeLimit === -1) this.upperImpulse = keep * this.upperImpulse - solution[o];
  }

  /** @internal Forgets the slider's own impulses (axial, perpendicular). */
  protected forgetSliderImpulses(): void {
    this.perpImpulse = 0;
    this.springImpulse = 0;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
    this.axialImpulse = 0;
  }

  /** @internal Warm starts the slider's own impulses (axial, perpendicular). */
  protected warmStartSlider(state: Float64Array): void {
    this.updateAxis(state);
    this.applyAxial(state, this.springImpulse + this.axialImpulse + this.lowerImpulse - this.upperImpulse);
    this.applyPerp(state, this.perpImpulse);
  }

  /** @internal The impulse of a motor along the axis after one solve (a prismatic's; none by default). */
  protected axisMotor(_ctx: JointContext, _speed: number, _mass: number): number {
    return 0;
  }

  /**
   * The rows along the axis given its speed and mass (see Joint.solveAxial): motor, spring, then
   * limits; returns their impulse. Needs the axis current (updateAxis).
   * @internal
   */
  protected solveAxisRows(ctx: JointContext, speed: number, mass: number, useBias: boolean): number {
    if (mass === 0) return 0;
    const o = this.s;
    const invMass = 1 / mass;
    let total = this.axisMotor(ctx, speed, mass);
    speed += total * invMass;
    if (o.enableSpring && o.hertz > 0) {
      const impulse = springImpulse(
        this.spring,
        o.hertz,
        ctx.h,
        this.mA + this.mB,
        invMass,
        speed,
        this.axialPosition,
        this.springImpulse,
      );
      this.springImpulse += impulse;
      speed += impulse * invMass;
      total += impulse;
    }
    // a limit the tree holds this substep is its row (Joint.fillLimitRow)
    if (o.enableLimit && this.treeLimit === 0) {
      const maxPush = ctx.jointPushMaxSpeed;
      const oldLower = this.lowerImpulse;
      this.lowerImpulse = limitImpulse(
        ctx,
        useBias,
        oldLower,
        this.axialPosition - o.lower,
        speed,
        mass,
        maxPush,
      );
      const lower = this.lowerImpulse - oldLower;
      speed += lower * invMass;
      const oldUpper = this.upperImpulse;
      this.upperImpulse = limitImpulse(
        ctx,
        useBias,
        oldUpper,
        o.upper - this.axialPosition,
        -speed,
        mass,
        maxPush,
      );
      total += lower - (this.upperImpulse - oldUpper);
    }
    return total;
  }

  /**
   * The rows along the axis (unless the tree solves them: TreeAxials), then the perpendicular
   * constraint unless the tree owns it.
   * @internal
   */
  protected solveSlider(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    this.updateAxis(state);
    if (this.axisEntry() < 0) {
      this.applyAxial(state, this.solveAxisRows(ctx, this.axialSpeed(state), this.axialMass, useBias));
    }
    if (this.inTree) return;
    // no motion across the axis
    const px = -this.uy;
    const py = this.ux;
    const dx = this.sepX + this.rAx;
    const dy = this.sepY + this.rAy;
    const s1 = dx * py - dy * px;
    const s2 = this.rBx * py - this.rBy * px;
    const k = this.mA + this.mB + this.iA * s1 * s1 + this.iB * s2 * s2;
    if (k > 0) {
      const sa = this.a * BodyState.STRIDE;
      const sb = this.b * BodyState.STRIDE;
      const cdot =
        (state[sb + BodyState.VX] - state[sa + BodyState.VX]) * px +
        (state[sb + BodyState.VY] - state[sa + BodyState.VY]) * py +
        s2 * state[sb + BodyState.W] -
        s1 * state[sa + BodyState.W];
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias) {
        const soft = ctx.jointSoftness;
        // bounded, as a contact's push is (see the revolute joint's point rows)
        const max = ctx.jointPushMaxSpeed;
        bias = Math.max(-max, Math.min(soft.biasRate * (this.sepX * px + this.sepY * py), max));
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
      }
      const impulse = (-massScale * (cdot + bias)) / k - impulseScale * this.perpImpulse;
      this.perpImpulse += impulse;
      this.applyPerp(state, impulse);
    }
  }

  /** Force on B from the axial and perpendicular impulses (N). */
  getReactionForce(): Vec2 {
    this.check();
    const axial =
      (this.springImpulse + this.axialImpulse + this.lowerImpulse - this.upperImpulse) * this.invH;
    const perp = this.perpImpulse * this.invH;
    return { x: axial * this.ux - perp * this.uy, y: axial * this.uy + perp * this.ux };
  }
}
