import { IntList } from '../broad-phase/int-list';
import { makeShapeProxy } from '../geometry/shape-proxy';
import { makeSweep } from '../geometry/sweep';
import { makeTOIOutput, type TOIInput, TOIMemory } from '../geometry/toi';
import { makeRayHit } from '../geometry/types';
import { makeBounds } from '../math/aabb';
import { makeTransform } from '../math/vec2';

/**
 * A world's working memory for continuous collision (continuous.ts; WorldCore.work.continuous): the
 * sweeps' inputs, results and scratch, written before they are read, and the bullets deferred within
 * a step, which solveBullets empties before the step ends.
 * @internal
 */
export class ContinuousMemory {
  readonly toi = new TOIMemory();
  readonly input: TOIInput = {
    proxyA: makeShapeProxy(),
    sweepA: makeSweep(),
    proxyB: makeShapeProxy(),
    sweepB: makeSweep(),
    maxFraction: 1,
  };
  readonly output = makeTOIOutput();
  /** the fast shape's proxy: input.proxyB, but while the disc is swept */
  readonly shapeProxy = this.input.proxyB;
  /** a small disc at the fast shape's centroid, swept when the whole shape starts out touching */
  readonly discProxy = makeShapeProxy();
  readonly candidates = new IntList(64);
  readonly start = makeTransform();
  readonly bounds = makeBounds();
  readonly xf = makeTransform();
  /** the other body's transform and the ray's hit, for discCentreRunsIn */
  readonly otherXf = makeTransform();
  /** a shape's centroid in its body's frame */
  readonly centre = { x: 0, y: 0 };
  readonly centreHit = makeRayHit();
  /** the swept box of a shape, as minX, minY, maxX, maxY */
  readonly sweptBox = new Float64Array(4);
  /**
   * The start of the step of the body handed to solveContinuous or deferBullet: centre x, y and
   * rotation cos, sin. Written by the caller (doubles passed to a call that V8 does not inline are
   * put on the heap).
   */
  readonly sweepStart = new Float64Array(4);
  /** Fast bullets of the current step waiting for solveBullets: slot, and start centre and rotation. */
  bulletCount = 0;
  bulletSlots = new Int32Array(16);
  bulletStarts = new Float64Array(16 * 4);
}
