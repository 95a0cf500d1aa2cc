import type { JointContext } from './joint-context';

/**
 * The accumulated impulse of a one-sided limit row after one solve: `old` the impulse so far, `C`
 * the room left before the limit (negative when past it), `speed` the row's speed towards more
 * room, `mass` its effective mass, `maxPush` the fastest a violated limit is pushed back. Ahead of
 * the limit the row lets the bodies close the gap within the substep (speculative); past it, it
 * pushes back softly, at the joints' softness, and no faster than maxPush.
 * @internal
 */
export function limitImpulse(
  ctx: JointContext,
  useBias: boolean,
  old: number,
  C: number,
  speed: number,
  mass: number,
  maxPush: number,
): number {
  let bias = 0;
  let massScale = 1;
  let impulseScale = 0;
  if (C > 0) bias = C * ctx.invH;
  else if (useBias) {
    const soft = ctx.jointSoftness;
    bias = Math.max(soft.biasRate * C, -maxPush);
    massScale = soft.massScale;
    impulseScale = soft.impulseScale;
  }
  return Math.max(old - massScale * mass * (speed + bias) - impulseScale * old, 0);
}

/** The accumulated impulse of a motor row after one solve: towards `target`, within ±`max`. */
export function motorImpulse(old: number, speed: number, target: number, mass: number, max: number): number {
  return Math.max(-max, Math.min(old - mass * (speed - target), max));
}
