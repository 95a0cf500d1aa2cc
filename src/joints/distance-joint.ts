import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkBoolean, FulcrumError } from '../core/errors';
import { checkCoordinates, checkHertz, checkLength, checkNonNegativeRate } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import type { JointContext } from '../solver/joint-context';
import { CLOSURE_REGULARIZATION } from '../solver/joint-tree';
import { makeSoftness, type Softness, springImpulse } from '../solver/softness';
import { BodyState } from '../store/body-store';
import { Joint } from './joint';
import {
  BASE_KEYS,
  type BaseDef,
  checkOrder,
  type JointKind,
  jointBodies,
  optionalBoolean,
  optionalNumber,
  SPRING_KEYS,
  type SpringDef,
} from './joint-def';

/** A distance joint (see DistanceJoint): anchors in the bodies' frames; `length` defaults to their distance now. */
export interface DistanceJointDef extends BaseDef, SpringDef {
  type: 'distance';
  localAnchorA?: Vec2;
  localAnchorB?: Vec2;
  length?: number;
  minLength?: number;
  maxLength?: number;
}

/** @internal */
export interface DistanceOptions {
  length: number;
  minLength: number;
  maxLength: number;
  enableSpring: boolean;
  hertz: number;
  dampingRatio: number;
}

/**
 * Keeps the anchors `length` apart. Rigid by default; with `enableSpring` it is a damped spring
 * (Hooke's law) towards `length`, and `minLength`/`maxLength` bound it like a rope or a stop.
 * Stiffness k (N/m) and damping c (N·s/m) map to hertz f and ratio z by k = m (2 pi f)^2 and
 * c = 2 m z (2 pi f), with m the effective mass along the joint.
 */
export class DistanceJoint extends Joint {
  readonly type = 'distance' as const;
  /** @internal */
  o: DistanceOptions;
  private impulse = 0;
  private lowerImpulse = 0;
  private upperImpulse = 0;
  private readonly spring: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  private ux = 0;
  private uy = 0;

  /** @internal */
  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    localAnchorA: Vec2,
    localAnchorB: Vec2,
    collideConnected: boolean,
    userData: unknown,
    options: DistanceOptions,
  ) {
    super(world, bodyA, bodyB, localAnchorA, localAnchorB, collideConnected, userData);
    this.o = options;
  }

  /** Current distance between the anchors. */
  get currentLength(): number {
    const a = this.anchorA;
    const b = this.anchorB;
    return Math.sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
  }

  get length(): number {
    return this.o.length;
  }

  setLength(length: number): void {
    checkLength('length', length);
    this.changing();
    this.o.length = length;
  }

  setLengthRange(minLength: number, maxLength: number): void {
    checkLength('minLength', minLength);
    if (maxLength !== Number.POSITIVE_INFINITY) checkLength('maxLength', maxLength);
    if (minLength > maxLength)
      throw new FulcrumError(`minLength must be <= maxLength, got ${minLength} > ${maxLength}`);
    this.changing();
    this.o.minLength = minLength;
    this.o.maxLength = maxLength;
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
    const f = (this.impulse + this.lowerImpulse - this.upperImpulse) * this.invH;
    return { x: f * this.ux, y: f * this.uy };
  }

  getReactionTorque(): number {
    this.check();
    return 0;
  }

  /** Whether the joint is a rigid rod (no spring, or a range of zero width). */
  private isRigid(): boolean {
    return !this.o.enableSpring || this.o.minLength === this.o.maxLength;
  }

  /** @internal */
  override canCloseLoop(): boolean {
    return true;
  }

  /** @internal the rod's row */
  override treeRows(): number {
    return this.isRigid() ? 1 : 0;
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
    const length = Math.sqrt(this.sepX * this.sepX + this.sepY * this.sepY);
    // at zero length the axis keeps its last direction
    if (length > 1e-12) {
      this.ux = this.sepX / length;
      this.uy = this.sepY / length;
    }
    const ux = this.ux;
    const uy = this.uy;
    const m = 9 * j;
    jA[m] = -ux;
    jA[m + 1] = -uy;
    jA[m + 2] = -(this.rAx * uy - this.rAy * ux);
    jB[m] = ux;
    jB[m + 1] = uy;
    jB[m + 2] = this.rBx * uy - this.rBy * ux;
    err[3 * j] = length - this.o.length;
    this.clearTreeRows(jA, jB, err, j, 1);
    return 1;
  }

  /** @internal */
  override treeAddImpulse(solution: Float64Array, o: number, keep: number): void {
    this.impulse = keep * this.impulse - solution[o];
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareBase(ctx);
    const o = this.o;
    makeSoftness(o.enableSpring ? o.hertz : 0, o.dampingRatio, ctx.h, this.spring);
    if (this.isRigid()) {
      this.lowerImpulse = 0;
      this.upperImpulse = 0;
    }
    this.setAxis();
  }

  private setAxis(): void {
    const dx = this.dcx + this.rBx - this.rAx;
    const dy = this.dcy + this.rBy - this.rAy;
    const len = Math.sqrt(dx * dx + dy * dy);
    if (len > 1e-12) {
      this.ux = dx / len;
      this.uy = dy / len;
    } else {
      this.ux = 1;
      this.uy = 0;
    }
  }

  /** @internal */
  forgetImpulses(): void {
    this.impulse = 0;
    this.lowerImpulse = 0;
    this.upperImpulse = 0;
  }

  /** @internal */
  warmStart(ctx: JointContext): void {
    const state = ctx.state;
    this.updateAnchors(state);
    const len = Math.sqrt(this.sepX * this.sepX + this.sepY * this.sepY);
    if (len > 1e-12) {
      this.ux = this.sepX / len;
      this.uy = this.sepY / len;
    }
    this.apply(state, this.impulse + this.lowerImpulse - this.upperImpulse);
  }

  /** Applies an impulse along the axis and returns nothing; reads and writes the velocities. */
  private apply(state: Float64Array, impulse: number): void {
    const px = impulse * this.ux;
    const py = impulse * this.uy;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    state[sa + BodyState.VX] -= this.mA * px;
    state[sa + BodyState.VY] -= this.mA * py;
    state[sa + BodyState.W] -= this.iA * (this.rAx * py - this.rAy * px);
    state[sb + BodyState.VX] += this.mB * px;
    state[sb + BodyState.VY] += this.mB * py;
    state[sb + BodyState.W] += this.iB * (this.rBx * py - this.rBy * px);
  }

  /** Relative velocity of the anchors along the axis. */
  private axialSpeed(state: Float64Array): number {
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    const wA = state[sa + BodyState.W];
    const wB = state[sb + BodyState.W];
    const dvx = state[sb + BodyState.VX] - wB * this.rBy - state[sa + BodyState.VX] + wA * this.rAy;
    const dvy = state[sb + BodyState.VY] + wB * this.rBx - state[sa + BodyState.VY] - wA * this.rAx;
    return dvx * this.ux + dvy * this.uy;
  }

  /** @internal */
  solve(ctx: JointContext, useBias: boolean): void {
    const state = ctx.state;
    const o = this.o;
    this.updateAnchors(state);
    const length = Math.sqrt(this.sepX * this.sepX + this.sepY * this.sepY);
    if (length > 1e-12) {
      this.ux = this.sepX / length;
      this.uy = this.sepY / length;
    }
    const crA = this.rAx * this.uy - this.rAy * this.ux;
    const crB = this.rBx * this.uy - this.rBy * this.ux;
    const k = this.mA + this.mB + this.iA * crA * crA + this.iB * crB * crB;
    const axialMass = k > 0 ? 1 / k : 0;
    const soft = ctx.jointSoftness;

    if (o.enableSpring && o.minLength < o.maxLength) {
      if (o.hertz > 0) {
        const C = length - o.length;
        const impulse = springImpulse(
          this.spring,
          o.hertz,
          ctx.h,
          this.mA + this.mB,
          k,
          this.axialSpeed(state),
          C,
          this.impulse,
        );
        this.impulse += impulse;
        this.apply(state, impulse);
      }
      if (o.minLength > 0) {
        const C = length - o.minLength;
        let bias = 0;
        let massScale = 1;
        let impulseScale = 0;
        if (C > 0) bias = C * ctx.invH;
        else if (useBias) {
          bias = Math.max(soft.biasRate * C, -ctx.jointPushMaxSpeed);
          massScale = soft.massScale;
          impulseScale = soft.impulseScale;
        }
        const old = this.lowerImpulse;
        const next = Math.max(
          old - massScale * axialMass * (this.axialSpeed(state) + bias) - impulseScale * old,
          0,
        );
        this.lowerImpulse = next;
        this.apply(state, next - old);
      }
      if (Number.isFinite(o.maxLength)) {
        const C = o.maxLength - length;
        let bias = 0;
        let massScale = 1;
        let impulseScale = 0;
        if (C > 0) bias = C * ctx.invH;
        else if (useBias) {
          bias = Math.max(soft.biasRate * C, -ctx.jointPushMaxSpeed);
          massScale = soft.massScale;
          impulseScale = soft.impulseScale;
        }
        const old = this.upperImpulse;
        const next = Math.max(
          old - massScale * axialMass * (-this.axialSpeed(state) + bias) - impulseScale * old,
          0,
        );
        this.upperImpulse = next;
        this.apply(state, old - next);
      }
    } else if (!this.inTree) {
      // rigid rod
      const C = length - o.length;
      let bias = 0;
      let massScale = 1;
      let impulseScale = 0;
      if (useBias) {
        // bounded, as a contact's push is (see the revolute joint's point rows)
        bias = Math.max(-ctx.jointPushMaxSpeed, Math.min(soft.biasRate * C, ctx.jointPushMaxSpeed));
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
      }
      // a rod that closes a loop of the tree moves the bodies as the tree lets them (see JointTree)
      const mass = this.closure ? 1 / (this.closureMass[0] + CLOSURE_REGULARIZATION * k) : axialMass;
      const impulse = -massScale * mass * (this.axialSpeed(state) + bias) - impulseScale * this.impulse;
      this.impulse += impulse;
      if (this.closure) {
        const closureImpulse = ctx.tree.closureImpulse;
        closureImpulse[0] = impulse;
        closureImpulse[1] = 0;
        ctx.tree.applyClosure(this.closureIndex, state);
      } else {
        this.apply(state, impulse);
      }
    }
  }
}

/** @internal The distance joint's kind (see registry.ts): its keys, defaults and validation. */
export const distanceKind: JointKind<DistanceJointDef, DistanceJoint> = Object.freeze({
  className: 'DistanceJoint',
  jointClass: DistanceJoint,
  keys: Object.freeze([
    ...BASE_KEYS,
    'localAnchorA',
    'localAnchorB',
    'length',
    'minLength',
    'maxLength',
    ...SPRING_KEYS,
  ]),
  build(world: World, def: DistanceJointDef): DistanceJoint {
    const { a, b, collide } = jointBodies(world, def);
    const la =
      def.localAnchorA === undefined ? { x: 0, y: 0 } : checkCoordinates('localAnchorA', def.localAnchorA);
    const lb =
      def.localAnchorB === undefined ? { x: 0, y: 0 } : checkCoordinates('localAnchorB', def.localAnchorB);
    const pa = a.getWorldPoint(la);
    const pb = b.getWorldPoint(lb);
    const current = Math.sqrt((pb.x - pa.x) * (pb.x - pa.x) + (pb.y - pa.y) * (pb.y - pa.y));
    const length = optionalNumber(checkLength, 'length', def.length, current);
    const minLength = optionalNumber(checkLength, 'minLength', def.minLength, 0);
    const maxLength =
      def.maxLength === undefined || def.maxLength === Number.POSITIVE_INFINITY
        ? Number.POSITIVE_INFINITY
        : checkLength('maxLength', def.maxLength);
    checkOrder('minLength', minLength, 'maxLength', maxLength);
    return new DistanceJoint(world, a, b, la, lb, collide, def.userData, {
      length,
      minLength,
      maxLength,
      enableSpring: optionalBoolean('enableSpring', def.enableSpring, false),
      hertz: optionalNumber(checkHertz, 'hertz', def.hertz, 0),
      dampingRatio: optionalNumber(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 0),
    });
  },
});
