import { IntList } from '../collision/int-list';
import { computeShapeBounds } from '../geometry/bounds';
import { makeProxy, makeShapeProxy } from '../geometry/shape-proxy';
import { getSweepTransform, makeSweep } from '../geometry/sweep';
import { makeTOIOutput, type TOIInput, timeOfImpact } from '../geometry/toi';
import { makeBounds } from '../math/aabb';
import { makeTransform } from '../math/vec2';
import { SHAPE_SENSOR, shouldShapesCollide } from './shape-store';
import type { WorldCore } from './world-core';

const input: TOIInput = {
  proxyA: makeShapeProxy(),
  sweepA: makeSweep(),
  proxyB: makeShapeProxy(),
  sweepB: makeSweep(),
  maxFraction: 1,
};
const output = makeTOIOutput();
const candidates = new IntList(64);
const start = makeTransform();
const bounds = makeBounds();
const xf = makeTransform();
const STATIC_TREE_MASK = 1;

/**
 * Continuous collision of one fast body against static shapes: the body's motion over the step
 * (centre from (c1x, c1y) to its current centre, rotation from (q1c, q1s) to its current rotation)
 * is swept against every static shape its swept box touches, and the body is moved back to the
 * earliest time of impact. Its velocity is kept; next step's speculative contact stops it there.
 */
export function solveContinuous(
  core: WorldCore,
  b: number,
  c1x: number,
  c1y: number,
  q1c: number,
  q1s: number,
): void {
  const bodies = core.bodies;
  const shapes = core.shapes;
  const sweep = input.sweepB;
  sweep.localCenterX = bodies.lcx[b];
  sweep.localCenterY = bodies.lcy[b];
  sweep.c1X = c1x;
  sweep.c1Y = c1y;
  sweep.c2X = bodies.cx[b];
  sweep.c2Y = bodies.cy[b];
  sweep.q1C = q1c;
  sweep.q1S = q1s;
  sweep.q2C = bodies.qc[b];
  sweep.q2S = bodies.qs[b];
  getSweepTransform(sweep, 0, start);
  const slop = core.settings.linearSlop;
  let minFraction = 1;
  for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
    if ((shapes.flags[s] & SHAPE_SENSOR) !== 0) continue;
    const g = shapes.geometry[s]!;
    // swept box: the shape's box at the start of the step united with its box now
    computeShapeBounds(g, start, bounds);
    const minX = Math.min(bounds.minX, shapes.minX[s]);
    const minY = Math.min(bounds.minY, shapes.minY[s]);
    const maxX = Math.max(bounds.maxX, shapes.maxX[s]);
    const maxY = Math.max(bounds.maxY, shapes.maxY[s]);
    candidates.clear();
    core.broadPhase.query(minX, minY, maxX, maxY, STATIC_TREE_MASK, candidates);
    if (candidates.length === 0) continue;
    makeProxy(g, input.proxyB);
    for (let i = 0; i < candidates.length; i++) {
      const other = candidates.data[i];
      if ((shapes.flags[other] & SHAPE_SENSOR) !== 0 || !shouldShapesCollide(shapes, s, other)) continue;
      const ob = shapes.body[other];
      makeProxy(shapes.geometry[other]!, input.proxyA);
      const sa = input.sweepA;
      sa.localCenterX = 0;
      sa.localCenterY = 0;
      sa.c1X = sa.c2X = bodies.px[ob];
      sa.c1Y = sa.c2Y = bodies.py[ob];
      sa.q1C = sa.q2C = bodies.qc[ob];
      sa.q1S = sa.q2S = bodies.qs[ob];
      input.maxFraction = minFraction;
      timeOfImpact(input, output, slop);
      // a pair already touching at the start (fraction 0) is the contact solver's business
      if (
        (output.state === 'hit' || output.state === 'failed') &&
        output.fraction > 0 &&
        output.fraction < minFraction
      ) {
        minFraction = output.fraction;
      }
    }
  }
  if (minFraction < 1) {
    getSweepTransform(sweep, minFraction, xf);
    bodies.qc[b] = xf.q.c;
    bodies.qs[b] = xf.q.s;
    bodies.px[b] = xf.p.x;
    bodies.py[b] = xf.p.y;
    bodies.updateCenter(b);
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) core.refreshShapeBounds(s);
  }
}
