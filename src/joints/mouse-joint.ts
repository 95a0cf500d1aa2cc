import type { Body } from '../api/body';
import type { World } from '../api/world';
import { checkCoordinates, checkHertz, checkNonNegativeForce, checkNonNegativeRate } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import type { JointContext } from '../solver/joint-context';
import { makeSoftness, type Softness } from '../solver/softness';
import { BodyState } from '../store/body-store';
import { Joint } from './joint';
import { type JointKind, optionalNumber } from './joint-def';

/**
 * A mouse joint (see MouseJoint): one body and a target; `maxForce` defaults to 1000 times the
 * body's mass (at least 1 kg), the spring to 5 Hz, damping ratio 0.7.
 */
export interface MouseJointDef {
  type: 'mouse';
  body: Body;
  target: Vec2;
  maxForce?: number;
  hertz?: number;
  dampingRatio?: number;
  userData?: unknown;
}

/** @internal */
export interface MouseOptions {
  targetX: number;
  targetY: number;
  maxForce: number;
  hertz: number;
  dampingRatio: number;
}

/**
 * Pulls a point of one body towards a target with a soft spring (hertz, damping ratio) whose force is
 * capped at maxForce: dragging with the mouse or a finger. It acts on one body, which is both bodyA
 * and bodyB of the joint.
 */
export class MouseJoint extends Joint {
  readonly type = 'mouse' as const;
  /** @internal */
  o: MouseOptions;
  private impulseX = 0;
  private impulseY = 0;
  private readonly soft: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  private cBx = 0;
  private cBy = 0;

  /** @internal */
  constructor(world: World, body: Body, localAnchor: Vec2, userData: unknown, options: MouseOptions) {
    super(world, body, body, localAnchor, localAnchor, true, userData);
    this.o = options;
  }

  get body(): Body {
    return this.bodyB;
  }

  get target(): Vec2 {
    return { x: this.o.targetX, y: this.o.targetY };
  }

  /** Moves the target (world point) and wakes the body. */
  setTarget(target: Vec2): void {
    this.check();
    const t = checkCoordinates('target', target);
    this.o.targetX = t.x;
    this.o.targetY = t.y;
    this.core.wake(this.slotB);
  }

  getReactionForce(): Vec2 {
    this.check();
    return { x: this.impulseX * this.invH, y: this.impulseY * this.invH };
  }

  getReactionTorque(): number {
    this.check();
    return 0;
  }

  /** @internal */
  prepare(ctx: JointContext): void {
    this.prepareBase(ctx);
    this.cBx = ctx.cx[this.b];
    this.cBy = ctx.cy[this.b];
    makeSoftness(this.o.hertz, this.o.dampingRatio, ctx.h, this.soft);
  }

  /** @internal */
  forgetImpulses(): void {
    this.impulseX = 0;
    this.impulseY = 0;
  }

  /** @internal */
  warmStart(ctx: JointContext): void {
    const state = ctx.state;
    this.updateAnchors(state);
    const sb = this.b * BodyState.STRIDE;
    state[sb + BodyState.VX] += this.mB * this.impulseX;
    state[sb + BodyState.VY] += this.mB * this.impulseY;
    state[sb + BodyState.W] += this.iB * (this.rBx * this.impulseY - this.rBy * this.impulseX);
  }

  /** @internal */
  solve(ctx: JointContext, _useBias: boolean): void {
    const rows = this.core.work.pointRows;
    const state = ctx.state;
    this.updateAnchors(state);
    const sb = this.b * BodyState.STRIDE;
    const mB = this.mB;
    const iB = this.iB;
    const rBx = this.rBx;
    const rBy = this.rBy;
    let vx = state[sb + BodyState.VX];
    let vy = state[sb + BodyState.VY];
    let w = state[sb + BodyState.W];
    // the spring acts in both passes: it is a soft force, not an error to be relaxed away
    const cx = this.cBx + state[sb + BodyState.DPX] + rBx - this.o.targetX;
    const cy = this.cBy + state[sb + BodyState.DPY] + rBy - this.o.targetY;
    const cdotX = vx - w * rBy;
    const cdotY = vy + w * rBx;
    const k11 = mB + rBy * rBy * iB;
    const k12 = -rBy * rBx * iB;
    const k22 = mB + rBx * rBx * iB;
    const det = rows.inverseDeterminant(k11, k12, k22);
    const bx = cdotX + this.soft.biasRate * cx;
    const by = cdotY + this.soft.biasRate * cy;
    const oldX = this.impulseX;
    const oldY = this.impulseY;
    let ix = oldX - this.soft.massScale * rows.solveX(det, k12, k22, bx, by) - this.soft.impulseScale * oldX;
    let iy = oldY - this.soft.massScale * rows.solveY(det, k11, k12, bx, by) - this.soft.impulseScale * oldY;
    const max = this.o.maxForce * ctx.h;
    const len2 = ix * ix + iy * iy;
    if (len2 > max * max) {
      const scale = max / Math.sqrt(len2);
      ix *= scale;
      iy *= scale;
    }
    this.impulseX = ix;
    this.impulseY = iy;
    const px = ix - oldX;
    const py = iy - oldY;
    vx += mB * px;
    vy += mB * py;
    w += iB * (rBx * py - rBy * px);
    state[sb + BodyState.VX] = vx;
    state[sb + BodyState.VY] = vy;
    state[sb + BodyState.W] = w;
  }
}

/** @internal The mouse joint's kind (see registry.ts): its keys, defaults and validation. */
export const mouseKind: JointKind<MouseJointDef, MouseJoint> = Object.freeze({
  className: 'MouseJoint',
  jointClass: MouseJoint,
  keys: Object.freeze(['type', 'body', 'target', 'maxForce', 'hertz', 'dampingRatio', 'userData']),
  build(world: World, def: MouseJointDef): MouseJoint {
    world.checkBody('body', def.body);
    const body = def.body;
    const target = checkCoordinates('target', def.target);
    const mass = body.mass;
    return new MouseJoint(world, body, body.getLocalPoint(target), def.userData, {
      targetX: target.x,
      targetY: target.y,
      maxForce: optionalNumber(checkNonNegativeForce, 'maxForce', def.maxForce, 1000 * Math.max(mass, 1)),
      hertz: optionalNumber(checkHertz, 'hertz', def.hertz, 5),
      dampingRatio: optionalNumber(checkNonNegativeRate, 'dampingRatio', def.dampingRatio, 0.7),
    });
  },
});
