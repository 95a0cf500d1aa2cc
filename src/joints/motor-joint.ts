import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkAngle, checkCoordinates, checkNonNegativeForce } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import type { JointContext } from '../solver/joint-context';
import { relativeAngle, unwindAngle } from '../solver/joint-math';
import { BodyState } from '../store/body-store';
import { Joint } from './joint';
import {
  BASE_KEYS,
  type BaseDef,
  checkFraction,
  currentAngle,
  type JointKind,
  jointBodies,
  optionalNumber,
} from './joint-def';

/**
 * A motor joint (see MotorJoint); the offsets default to B's place and angle relative to A now, the
 * force and torque to 1, the correction factor to 0.3.
 */
export interface MotorJointDef extends BaseDef {
  type: 'motor';
  linearOffset?: Vec2;
  angularOffset?: number;
  maxForce?: number;
  maxTorque?: number;
  correctionFactor?: number;
}

/** @internal */
export interface MotorOptions {
  /** wanted position of B's centre in A's frame */
  linearOffsetX: number;
  linearOffsetY: number;
  /** wanted angle of B relative to A */
  angularOffset: number;
  maxForce: number;
  maxTorque: number;
  /** fraction of the position error removed per second of step, 0..1 */
  correctionFactor: number;
}

/** Drives B towards an offset from A with limited force and torque: moving platforms, top-down friction. */
export class MotorJoint extends Joint {
  readonly type = 'motor' as const;
  /** @internal */
  o: MotorOptions;
  private linearX = 0;
  private linearY = 0;
  private angularImpulse = 0;
  private angle0 = 0;
  private offsetX = 0;
  private offsetY = 0;

  /** @internal */
  constructor(
    world: World,
    bodyA: Body,
    bodyB: Body,
    collideConnected: boolean,
    userData: unknown,
    options: MotorOptions,
  ) {
    super(world, bodyA, bodyB, { x: 0, y: 0 }, { x: 0, y: 0 }, collideConnected, userData);
    this.o = options;
  }

  /** Wanted position of B's centre in A's frame. */
  setLinearOffset(offset: Vec2): void {
    const o = checkCoordinates('offset', offset);
    this.changing();
    this.o.linearOffsetX = o.x;
    this.o.linearOffsetY = o.y;
  }

  setAngularOffset(angle: number): void {
    checkAngle('angle', angle);
    this.changing();
    this.o.angularOffset = angle;
  }

  setMaxForce(force: number): void {
    checkNonNegativeForce('force', force);
    this.changing();
    this.o.maxForce = force;
  }

  setMaxTorque(torque: number): void {
    checkNonNegativeForce('torque', torque);
    this.changing();
    this.o.maxTorque = torque;
  }

  getReactionForce(): Vec2 {
    this.check();
    return { x: this.linearX * this.invH, y: this.linearY * this.invH };
  }

  getReactionTorque(): number {
    this.check();
    return this.angularImpulse * this.invH;
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    // anchors at the centres of mass
    this.localAnchorAx = ctx.lcx[this.slotA];
    this.localAnchorAy = ctx.lcy[this.slotA];
    this.localAnchorBx = ctx.lcx[this.slotB];
    this.localAnchorBy = ctx.lcy[this.slotB];
    this.prepareBase(ctx);
    const c = ctx.qc[this.a];
    const s = ctx.qs[this.a];
    // wanted centre offset in world orientation at the step's start (A's turn during the step is small)
    const ox = this.o.linearOffsetX - ctx.lcx[this.a];
    const oy = this.o.linearOffsetY - ctx.lcy[this.a];
    this.offsetX = c * ox - s * oy;
    this.offsetY = s * ox + c * oy;
    this.angle0 = unwindAngle(relativeAngle(c, s, ctx.qc[this.b], ctx.qs[this.b]) - this.o.angularOffset);
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
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    state[sa + BodyState.VX] -= this.mA * this.linearX;
    state[sa + BodyState.VY] -= this.mA * this.linearY;
    state[sa + BodyState.W] -= this.iA * this.angularImpulse;
    state[sb + BodyState.VX] += this.mB * this.linearX;
    state[sb + BodyState.VY] += this.mB * this.linearY;
    state[sb + BodyState.W] += this.iB * this.angularImpulse;
  }

  /** @internal */
  solve(ctx: JointContext, _useBias: boolean): void {
    const state = ctx.state;
    const o = this.o;
    const sa = this.a * BodyState.STRIDE;
    const sb = this.b * BodyState.STRIDE;
    const correction = o.correctionFactor * ctx.invH;
    const k = this.iA + this.iB;
    if (k > 0) {
      const C =
        this.angle0 +
        relativeAngle(
          state[sa + BodyState.DQC],
          state[sa + BodyState.DQS],
          state[sb + BodyState.DQC],
          state[sb + BodyState.DQS],
        );
      const max = o.maxTorque * ctx.h;
      const old = this.angularImpulse;
      const cdot = state[sb + BodyState.W] - state[sa + BodyState.W] + correction * C;
      this.angularImpulse = Math.max(-max, Math.min(old - cdot / k, max));
      const impulse = this.angularImpulse - old;
      state[sa + BodyState.W] -= this.iA * impulse;
      state[sb + BodyState.W] += this.iB * impulse;
    }
    const m = this.mA + this.mB;
    if (m > 0) {
      this.updateAnchors(state);
      const cx = this.sepX - this.offsetX;
      const cy = this.sepY - this.offsetY;
      const cdotX = state[sb + BodyState.VX] - state[sa + BodyState.VX] + correction * cx;
      const cdotY = state[sb + BodyState.VY] - state[sa + BodyState.VY] + correction * cy;
      const oldX = this.linearX;
      const oldY = this.linearY;
      let ix = oldX - cdotX / m;
      let iy = oldY - cdotY / m;
      const max = o.maxForce * ctx.h;
      const len2 = ix * ix + iy * iy;
      if (len2 > max * max) {
        const scale = max / Math.sqrt(len2);
        ix *= scale;
        iy *= scale;
      }
      this.linearX = ix;
      this.linearY = iy;
      state[sa + BodyState.VX] -= this.mA * (ix - oldX);
      state[sa + BodyState.VY] -= this.mA * (iy - oldY);
      state[sb + BodyState.VX] += this.mB * (ix - oldX);
      state[sb + BodyState.VY] += this.mB * (iy - oldY);
    }
  }
}

/** `p` in `body`'s frame, unchecked: B's centre may lie beyond the range getLocalPoint accepts */
function localPointOf(body: Body, p: Vec2): Vec2 {
  const q = body.rotation;
  const o = body.position;
  const dx = p.x - o.x;
  const dy = p.y - o.y;
  return { x: q.c * dx + q.s * dy, y: -q.s * dx + q.c * dy };
}

/** @internal The motor joint's kind (see registry.ts): its keys, defaults and validation. */
export const motorKind: JointKind<MotorJointDef, MotorJoint> = Object.freeze({
  className: 'MotorJoint',
  jointClass: MotorJoint,
  keys: Object.freeze([
    ...BASE_KEYS,
    'linearOffset',
    'angularOffset',
    'maxForce',
    'maxTorque',
    'correctionFactor',
  ]),
  build(world: World, def: MotorJointDef): MotorJoint {
    const { a, b, collide } = jointBodies(world, def);
    const offset =
      def.linearOffset === undefined
        ? localPointOf(a, b.worldCenter)
        : checkCoordinates('linearOffset', def.linearOffset);
    return new MotorJoint(world, a, b, collide, def.userData, {
      linearOffsetX: offset.x,
      linearOffsetY: offset.y,
      angularOffset: optionalNumber(checkAngle, 'angularOffset', def.angularOffset, currentAngle(a, b)),
      maxForce: optionalNumber(checkNonNegativeForce, 'maxForce', def.maxForce, 1),
      maxTorque: optionalNumber(checkNonNegativeForce, 'maxTorque', def.maxTorque, 1),
      correctionFactor: optionalNumber(checkFraction, 'correctionFactor', def.correctionFactor, 0.3),
    });
  },
});
