import { checkNonNegativeRate } from '../../core/limits';
import type { Vec2 } from '../../math/vec2';
import type { Body } from '../body';
import { S } from '../body-store';
import { makeSoftness, type Softness } from '../softness';
import type { World } from '../world';
import { Joint } from './joint';
import type { JointContext } from './joint-context';
import { relativeAngle, solve22, solved } from './joint-math';

export interface WeldOptions {
  referenceAngle: number;
  /** 0 = rigid */
  linearHertz: number;
  /** 0 = rigid */
  angularHertz: number;
  dampingRatio: number;
}

/**
 * Glues two bodies together at an anchor and at their relative angle. Rigid by default; with
 * linearHertz / angularHertz it bends and stretches like a damped spring of that frequency.
 */
export class WeldJoint extends Joint {
  readonly type = 'weld' as const;
  /** @internal */
  o: WeldOptions;
  private linearX = 0;
  private linearY = 0;
  private angularImpulse = 0;
  private angle0 = 0;
  private axialMass = 0;
  private readonly linearSoft: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  private readonly angularSoft: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };

  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    localAnchorA: Vec2,
    localAnchorB: Vec2,
    collideConnected: boolean,
    userData: unknown,
    options: WeldOptions,
  ) {
    super(world, bodyA, bodyB, localAnchorA, localAnchorB, collideConnected, userData);
    this.o = options;
  }

  /** 0 makes that part rigid. */
  setStiffness(linearHertz: number, angularHertz: number, dampingRatio: number): void {
    checkNonNegativeRate('linearHertz', linearHertz);
    checkNonNegativeRate('angularHertz', angularHertz);
    checkNonNegativeRate('dampingRatio', dampingRatio);
    this.changing();
    this.o.linearHertz = linearHertz;
    this.o.angularHertz = angularHertz;
    this.o.dampingRatio = dampingRatio;
  }

  getReactionForce(): Vec2 {
    this.check();
    return { x: this.linearX * this.invH, y: this.linearY * this.invH };
  }

  getReactionTorque(): number {
    this.check();
    return this.angularImpulse * this.invH;
  }

  /** @internal a rigid weld's point and angle rows */
  override treeRows(): number {
    return this.o.linearHertz === 0 && this.o.angularHertz === 0 ? 3 : 0;
  }

  /** @internal */
  override treeFill(
    state: Float64Array,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
  ): void {
    this.updateAnchors(state);
    this.fillPointRows(jA, jB, err, j);
    this.fillAngleRow(state, jA, jB, err, j, 2, this.angle0);
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.linearX = keep * this.linearX - solution[o];
    this.linearY = keep * this.linearY - solution[o + 1];
    this.angularImpulse = keep * this.angularImpulse - solution[o + 2];
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareBase(ctx);
    const k = this.iA + this.iB;
    this.axialMass = k > 0 ? 1 / k : 0;
    this.angle0 =
      relativeAngle(ctx.qc[this.a], ctx.qs[this.a], ctx.qc[this.b], ctx.qs[this.b]) - this.o.referenceAngle;
    const j = ctx.jointSoftness;
    if (this.o.linearHertz > 0) makeSoftness(this.o.linearHertz, this.o.dampingRatio, ctx.h, this.linearSoft);
    else Object.assign(this.linearSoft, j);
    if (this.o.angularHertz > 0)
      makeSoftness(this.o.angularHertz, this.o.dampingRatio, ctx.h, this.angularSoft);
    else Object.assign(this.angularSoft, j);
  }

  /** @internal */
  forgetImpulses(): void {
    this.linearX = 0;
    this.linearY = 0;
    this.angularImpulse = 0;
  }

  /** @internal */
  warmStart(ctx: JointContext): void {
    const state = ctx.state;
    this.updateAnchors(state);
    const sa = this.a * S.STRIDE;
    const sb = this.b * S.STRIDE;
    const px = this.linearX;
    const py = this.linearY;
    state[sa + S.VX] -= this.mA * px;
    state[sa + S.VY] -= this.mA * py;
    state[sa + S.W] -= this.iA * (this.rAx * py - this.rAy * px + this.angularImpulse);
    state[sb + S.VX] += this.mB * px;
    state[sb + S.VY] += this.mB * py;
    state[sb + S.W] += this.iB * (this.rBx * py - this.rBy * px + this.angularImpulse);
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    if (this.inTree) return;
    const state = ctx.state;
    const sa = this.a * S.STRIDE;
    const sb = this.b * S.STRIDE;
    const mA = this.mA;
    const iA = this.iA;
    const mB = this.mB;
    const iB = this.iB;
    let wA = state[sa + S.W];
    let wB = state[sb + S.W];
    // a soft weld keeps its spring in the relax pass too; a rigid one only corrects with bias
    const springy = this.o.angularHertz > 0;
    {
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias || springy) {
        const C =
          this.angle0 +
          relativeAngle(state[sa + S.DQC], state[sa + S.DQS], state[sb + S.DQC], state[sb + S.DQS]);
        bias = this.angularSoft.biasRate * C;
        massScale = this.angularSoft.massScale;
        impulseScale = this.angularSoft.impulseScale;
      }
      const impulse = -massScale * this.axialMass * (wB - wA + bias) - impulseScale * this.angularImpulse;
      this.angularImpulse += impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    this.updateAnchors(state);
    const rAx = this.rAx;
    const rAy = this.rAy;
    const rBx = this.rBx;
    const rBy = this.rBy;
    let vAx = state[sa + S.VX];
    let vAy = state[sa + S.VY];
    let vBx = state[sb + S.VX];
    let vBy = state[sb + S.VY];
    let biasX = 0;
    let biasY = 0;
    let massScale = 1;
    let impulseScale = 0;
    if (useBias || this.o.linearHertz > 0) {
      biasX = this.linearSoft.biasRate * this.sepX;
      biasY = this.linearSoft.biasRate * this.sepY;
      massScale = this.linearSoft.massScale;
      impulseScale = this.linearSoft.impulseScale;
    }
    const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
    const k12 = -rAy * rAx * iA - rBy * rBx * iB;
    const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
    solve22(k11, k12, k22, vBx - wB * rBy - vAx + wA * rAy + biasX, vBy + wB * rBx - vAy - wA * rAx + biasY);
    const px = -massScale * solved.x - impulseScale * this.linearX;
    const py = -massScale * solved.y - impulseScale * this.linearY;
    this.linearX += px;
    this.linearY += py;
    vAx -= mA * px;
    vAy -= mA * py;
    wA -= iA * (rAx * py - rAy * px);
    vBx += mB * px;
    vBy += mB * py;
    wB += iB * (rBx * py - rBy * px);
    state[sa + S.VX] = vAx;
    state[sa + S.VY] = vAy;
    state[sa + S.W] = wA;
    state[sb + S.VX] = vBx;
    state[sb + S.VY] = vBy;
    state[sb + S.W] = wB;
  }
}
