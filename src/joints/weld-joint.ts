import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkAngle, checkHertz, checkNonNegativeRate } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import type { JointContext } from '../solver/joint-context';
import { relativeAngle, solveSymmetric33, unwindAngle } from '../solver/joint-math';
import { makeSoftness, type Softness, springInvMass } from '../solver/softness';
import { BodyState } from '../store/body-store';
import { Joint } from './joint';
import {
  ANCHOR_KEYS,
  type AnchorDef,
  anchorsOf,
  BASE_KEYS,
  type BaseDef,
  currentAngle,
  type JointKind,
  jointBodies,
  optionalNumber,
} from './joint-def';

/** A weld joint (see WeldJoint): rigid unless given frequencies; `referenceAngle` defaults to the bodies' angle now. */
export interface WeldJointDef extends BaseDef, AnchorDef {
  type: 'weld';
  referenceAngle?: number;
  linearHertz?: number;
  angularHertz?: number;
  dampingRatio?: number;
}

/** @internal */
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
  private readonly linearSoft: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  private readonly angularSoft: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  /** the block solve's impulse (see solve) */
  private readonly blockImpulse = new Float64Array(3);

  /** @internal */
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
    checkHertz('linearHertz', linearHertz);
    checkHertz('angularHertz', angularHertz);
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
    ctx: JointContext,
    jA: Float64Array,
    jB: Float64Array,
    err: Float64Array,
    j: number,
    _limits: boolean,
  ): number {
    const state = ctx.state;
    this.updateAnchors(state);
    this.fillPointRows(jA, jB, err, j);
    this.fillAngleRow(state, jA, jB, err, j, 2, this.angle0);
    return 3;
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
    this.angle0 = unwindAngle(
      relativeAngle(ctx.qc[this.a], ctx.qs[this.a], ctx.qc[this.b], ctx.qs[this.b]) - this.o.referenceAngle,
    );
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
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    const px = this.linearX;
    const py = this.linearY;
    state[sa + BodyState.VX] -= this.mA * px;
    state[sa + BodyState.VY] -= this.mA * py;
    state[sa + BodyState.W] -= this.iA * (this.rAx * py - this.rAy * px + this.angularImpulse);
    state[sb + BodyState.VX] += this.mB * px;
    state[sb + BodyState.VY] += this.mB * py;
    state[sb + BodyState.W] += this.iB * (this.rBx * py - this.rBy * px + this.angularImpulse);
  }

  /**
   * @internal The point and angle rows as one block. Solved one after the other, a soft weld's
   * linear and angular springs push against each other through the body's turn (the point rows
   * turn it by r × impulse): a 5 kg box on a 1.5 Hz weld gained energy without bound at damping
   * ratios under 0.05.
   *
   * Each row is a spring of its own (implicit Euler, as the soft step's single rows): row i gets
   * the compliance Γ_ii = W_i / a2 (a2 = massScale / impulseScale of its Softness), W_i the inverse
   * mass that sets its stiffness, and the impulse is Δλ = -(K + Γ)⁻¹ (J v + bias + Γ λ), K the rows'
   * inverse effective mass. With W_i = K_ii and a single row this is the soft step's
   * Δλ = -massScale (J v + bias) / K - impulseScale λ. A spring's W_i is its bodies' own masses
   * (springInvMass: a true spring); Γ must be diagonal (a coupled compliance with rows of different
   * stiffness is not conservative either). A rigid row is soft only in the biased pass, with the
   * joints' softness and W_i = K_ii; in the relax pass it has no bias and no compliance.
   */
  solve(ctx: JointContext, useBias: boolean): void {
    if (this.inTree) return;
    const state = ctx.state;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    const mA = this.mA;
    const iA = this.iA;
    const mB = this.mB;
    const iB = this.iB;
    const vAx = state[sa + BodyState.VX];
    const vAy = state[sa + BodyState.VY];
    const wA = state[sa + BodyState.W];
    const vBx = state[sb + BodyState.VX];
    const vBy = state[sb + BodyState.VY];
    const wB = state[sb + BodyState.W];
    this.updateAnchors(state);
    const rAx = this.rAx;
    const rAy = this.rAy;
    const rBx = this.rBx;
    const rBy = this.rBy;
    // bias and 1 / a2 (see above) of the point rows and of the angle row
    let biasX = 0;
    let biasY = 0;
    let cLinear = 0;
    if (this.o.linearHertz > 0 || useBias) {
      const soft = this.linearSoft;
      biasX = soft.biasRate * this.sepX;
      biasY = soft.biasRate * this.sepY;
      cLinear = soft.impulseScale / soft.massScale;
      if (this.o.linearHertz === 0) {
        // a rigid weld's pull is bounded, as a contact's push is (see the revolute joint)
        const b2 = biasX * biasX + biasY * biasY;
        const maxPush = ctx.jointPushMaxSpeed;
        if (b2 > maxPush * maxPush) {
          const f = maxPush / Math.sqrt(b2);
          biasX *= f;
          biasY *= f;
        }
      }
    }
    let biasW = 0;
    let cAngular = 0;
    if (this.o.angularHertz > 0 || useBias) {
      const soft = this.angularSoft;
      const C =
        this.angle0 +
        relativeAngle(
          state[sa + BodyState.DQC],
          state[sa + BodyState.DQS],
          state[sb + BodyState.DQC],
          state[sb + BodyState.DQS],
        );
      biasW = soft.biasRate * C;
      if (this.o.angularHertz === 0) {
        biasW = Math.max(-ctx.jointPushMaxTurn, Math.min(biasW, ctx.jointPushMaxTurn));
      }
      cAngular = soft.impulseScale / soft.massScale;
    }
    // K of the rows (B's anchor velocity minus A's, B's turn minus A's), then K + Γ
    const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
    const k12 = -rAy * rAx * iA - rBy * rBx * iB;
    const k13 = -rAy * iA - rBy * iB;
    const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
    const k23 = rAx * iA + rBx * iB;
    const k33 = iA + iB;
    // Γ: a spring's rows take their stiffness from the bodies' own masses (springInvMass), a rigid
    // row's correction from its effective mass (the joints' softness, as every rigid row's)
    const hertz = this.o.linearHertz;
    const g11 = cLinear * (hertz > 0 ? springInvMass(hertz, ctx.h, mA + mB, k11) : k11);
    const g22 = cLinear * (hertz > 0 ? springInvMass(hertz, ctx.h, mA + mB, k22) : k22);
    const g33 = cAngular * k33;
    const lx = this.linearX;
    const ly = this.linearY;
    const lw = this.angularImpulse;
    const out = this.blockImpulse;
    // bodies that cannot turn (fixed rotation) leave the angle row out: it alone would be singular
    const turns = k33 > 0;
    solveSymmetric33(
      k11 + g11,
      k12,
      k13,
      k22 + g22,
      k23,
      turns ? k33 + g33 : 1,
      vBx - wB * rBy - vAx + wA * rAy + biasX + g11 * lx,
      vBy + wB * rBx - vAy - wA * rAx + biasY + g22 * ly,
      turns ? wB - wA + biasW + g33 * lw : 0,
      out,
    );
    const px = -out[0];
    const py = -out[1];
    const pw = -out[2];
    this.linearX = lx + px;
    this.linearY = ly + py;
    this.angularImpulse = lw + pw;
    state[sa + BodyState.VX] = vAx - mA * px;
    state[sa + BodyState.VY] = vAy - mA * py;
    state[sa + BodyState.W] = wA - iA * (rAx * py - rAy * px + pw);
    state[sb + BodyState.VX] = vBx + mB * px;
    state[sb + BodyState.VY] = vBy + mB * py;
    state[sb + BodyState.W] = wB + iB * (rBx * py - rBy * px + pw);
  }
}

/** @internal The weld joint's kind (see registry.ts): its keys, defaults and validation. */
export const weldKind: JointKind<WeldJointDef, WeldJoint> = Object.freeze({
  className: 'WeldJoint',
  jointClass: WeldJoint,
  keys: Object.freeze([
    ...BASE_KEYS,
    ...ANCHOR_KEYS,
    'referenceAngle',
    'linearHertz',
    'angularHertz',
    'dampingRatio',
  ]),
  build(world: World, def: WeldJointDef): WeldJoint {
    const { a, b, collide } = jointBodies(world, def);
    const { la, lb } = anchorsOf(def, a, b);
    return new WeldJoint(world, a, b, la, lb, collide, def.userData, {
      referenceAngle: optionalNumber(checkAngle, 'referenceAngle', def.referenceAngle, currentAngle(a, b)),
      linearHertz: optionalNumber(checkHertz, 'linearHertz', def.linearHertz, 0),
      angularHertz: optionalNumber(checkHertz, 'angularHertz', def.angularHertz, 0),
      dampingRatio: optionalNumber(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 1),
    });
  },
});
