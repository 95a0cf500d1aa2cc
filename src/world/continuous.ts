import { packedBounds } from '../geometry/bounds';
import { minExtent } from '../geometry/extent';
import { frontOffsetAt, isOneSided, Pack } from '../geometry/packed';
import { rayCastGeometry } from '../geometry/raycast';
import { makeProxy, type ShapeProxy } from '../geometry/shape-proxy';
import { getSweepTransform } from '../geometry/sweep';
import { timeOfImpact } from '../geometry/toi';
import { type Geometry, ShapeKind } from '../geometry/types';
import type { Vec2 } from '../math/vec2';
import { BodyFlag } from '../store/body-store';
import { ShapeFlag, shouldShapesCollide } from '../store/shape-store';
import type { WorldCore } from './world-core';

const STATIC_TREE_MASK = 1;
/** static, kinematic and dynamic trees */
const ALL_TREES_MASK = 7;

/**
 * Continuous collision of one fast body against static shapes: the body's motion over the step
 * (centre and rotation from `sweepStart` to its current ones) is swept against every static shape its
 * swept box touches, and the body is moved back to the earliest time of impact. Its velocity is kept;
 * next step's speculative contact stops it there.
 * @internal
 */
export function solveContinuous(core: WorldCore, b: number): void {
  sweepAgainst(core, b, core.work.continuous.sweepStart, 0, STATIC_TREE_MASK);
}

/**
 * Records a fast bullet (starting at `sweepStart`) whose continuous collision must wait until every
 * other awake body has its final transform; `solveBullets` handles it and moves its proxies.
 * Allocation free once warmed up.
 */
export function deferBullet(core: WorldCore, b: number): void {
  const m = core.work.continuous;
  const count = m.bulletCount;
  if (count === m.bulletSlots.length) {
    const slots = new Int32Array(2 * count);
    slots.set(m.bulletSlots);
    m.bulletSlots = slots;
    const starts = new Float64Array(8 * count);
    starts.set(m.bulletStarts);
    m.bulletStarts = starts;
  }
  m.bulletCount = count + 1;
  m.bulletSlots[count] = b;
  m.bulletStarts.set(m.sweepStart, 4 * count);
}

/**
 * Continuous collision of the deferred bullets (in the order they were deferred, ascending slot)
 * against static shapes and the shapes of kinematic and dynamic non-bullet bodies, which are taken
 * at their final transform of the step (a conservative approximation: they do not sweep). Bullets do
 * not sweep against each other. Then moves the bullets' proxies.
 * @internal
 */
export function solveBullets(core: WorldCore): void {
  const bodies = core.bodies;
  const shapes = core.shapes;
  const broad = core.broadPhase;
  const m = core.work.continuous;
  for (let i = 0; i < m.bulletCount; i++) {
    const b = m.bulletSlots[i];
    const k = 4 * i;
    sweepAgainst(core, b, m.bulletStarts, k, ALL_TREES_MASK);
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
      broad.placeProxy(shapes.proxyKey[s], shapes, s);
    }
  }
  m.bulletCount = 0;
}

/** Sweeps body `b` from the start pose at `at` in `starts` (see sweepStart) against the trees of `treeMask`. */
function sweepAgainst(core: WorldCore, b: number, starts: Float64Array, at: number, treeMask: number): void {
  // nothing to hit (a world without ground): no sweep and no box to work out
  if (core.broadPhase.isEmpty(treeMask)) return;
  const bodies = core.bodies;
  const shapes = core.shapes;
  const m = core.work.continuous;
  const input = m.input;
  const output = m.output;
  const shapeProxy = m.shapeProxy;
  const discProxy = m.discProxy;
  const candidates = m.candidates;
  const start = m.start;
  const bounds = m.bounds;
  const sweptBox = m.sweptBox;
  const sweep = input.sweepB;
  sweep.localCenterX = bodies.lcx[b];
  sweep.localCenterY = bodies.lcy[b];
  sweep.c1X = starts[at];
  sweep.c1Y = starts[at + 1];
  sweep.c2X = bodies.cx[b];
  sweep.c2Y = bodies.cy[b];
  sweep.q1C = starts[at + 2];
  sweep.q1S = starts[at + 3];
  sweep.q2C = bodies.qc[b];
  sweep.q2S = bodies.qs[b];
  getSweepTransform(sweep, 0, start);
  const slop = core.settings.linearSlop;
  let minFraction = 1;
  for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
    if ((shapes.flags[s] & ShapeFlag.SENSOR) !== 0) continue;
    const g = shapes.geometry[s]!;
    // swept box: the shape's box at the start of the step united with its box now
    packedBounds(shapes.packed, s * Pack.STRIDE, start, bounds);
    sweptBox[0] = Math.min(bounds.minX, shapes.minX[s]);
    sweptBox[1] = Math.min(bounds.minY, shapes.minY[s]);
    sweptBox[2] = Math.max(bounds.maxX, shapes.maxX[s]);
    sweptBox[3] = Math.max(bounds.maxY, shapes.maxY[s]);
    candidates.clear();
    core.broadPhase.queryBox(sweptBox, 0, treeMask, candidates);
    if (candidates.length === 0) continue;
    makeProxy(g, shapeProxy);
    let discReady = false;
    for (let i = 0; i < candidates.length; i++) {
      const other = candidates.data[i];
      if ((shapes.flags[other] & ShapeFlag.SENSOR) !== 0 || !shouldShapesCollide(shapes, s, other)) continue;
      const ob = shapes.body[other];
      if (ob === b || (bodies.flags[ob] & BodyFlag.BULLET) !== 0 || !core.jointsAllowCollision(b, ob))
        continue;
      const otherBase = other * Pack.STRIDE;
      if (
        isOneSided(shapes.kind[other], shapes.packed, otherBase) &&
        skipsChainSegment(core, b, g, otherBase, ob)
      )
        continue;
      makeProxy(shapes.geometry[other]!, input.proxyA);
      const sa = input.sweepA;
      sa.localCenterX = 0;
      sa.localCenterY = 0;
      sa.c1X = sa.c2X = bodies.px[ob];
      sa.c1Y = sa.c2Y = bodies.py[ob];
      sa.q1C = sa.q2C = bodies.qc[ob];
      sa.q1S = sa.q2S = bodies.qs[ob];
      input.maxFraction = minFraction;
      timeOfImpact(m.toi, input, output, slop);
      if (output.state === 'overlapped' || (output.state === 'hit' && output.fraction === 0)) {
        // Touching at the start: that contact is the solver's business, but the shape may still be
        // turning or sliding through the other one (a spinning plank against a wall it already
        // touches). Sweep a disc of a quarter of the shape's thickness at its centroid instead,
        // so that at least the shape's core cannot cross.
        if (!discReady) {
          loadDisc(g, discProxy, m.centre);
          discReady = true;
        }
        input.proxyB = discProxy;
        timeOfImpact(m.toi, input, output, slop);
        input.proxyB = shapeProxy;
        if (output.state === 'hit' && output.fraction === 0 && discCentreRunsIn(core, other, ob)) {
          // the core touches already, and the step would take its centre in or through: nothing
          // but the solver's contact held a plank spinning against a thin wall, and it slipped
          // through (the disc pinned in front of the wall, the plank through it a step later); it
          // stays where it was this step, with its velocity, for the contact to stop
          minFraction = 0;
          input.maxFraction = 0;
        }
      }
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
    const xf = m.xf;
    getSweepTransform(sweep, minFraction, xf);
    bodies.qc[b] = xf.q.c;
    bodies.qs[b] = xf.q.s;
    bodies.px[b] = xf.p.x;
    bodies.py[b] = xf.p.y;
    bodies.updateCenter(b);
    core.poseEpoch++;
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) core.refreshShapeBounds(s);
  }
}

/**
 * Whether the centre of the disc of the body being swept (its sweep is input.sweepB; see loadDisc), which
 * touches shape `other` of body `ob` at the start of the step, runs into that shape on its way to
 * the end of the step (its straight path hits it): it goes in or through. Sliding or rolling along
 * the shape, past a seam between two of them, does not (a test on the normal to the nearest feature
 * froze thin bodies at seams, where that feature is a corner).
 */
function discCentreRunsIn(core: WorldCore, other: number, ob: number): boolean {
  const bodies = core.bodies;
  const m = core.work.continuous;
  const otherXf = m.otherXf;
  const xf = m.xf;
  const start = m.start;
  const discProxy = m.discProxy;
  otherXf.p.x = bodies.px[ob];
  otherXf.p.y = bodies.py[ob];
  otherXf.q.c = bodies.qc[ob];
  otherXf.q.s = bodies.qs[ob];
  getSweepTransform(m.input.sweepB, 1, xf);
  const lx = discProxy.x[0];
  const ly = discProxy.y[0];
  const x0 = start.p.x + start.q.c * lx - start.q.s * ly;
  const y0 = start.p.y + start.q.s * lx + start.q.c * ly;
  const x1 = xf.p.x + xf.q.c * lx - xf.q.s * ly;
  const y1 = xf.p.y + xf.q.s * lx + xf.q.c * ly;
  return rayCastGeometry(core.shapes.geometry[other]!, otherXf, x0, y0, x1 - x0, y1 - y0, m.centreHit);
}

/**
 * Whether the sweep of shape `g` of body `b` skips the chain's one-sided segment packed at `base` of
 * body `ob`: when its centroid starts behind the segment (it passes through, as contacts let it), or
 * comes toward the segment's line by less than a quarter of the shape's thickness over the step.
 * A body sliding along a chain does not come toward it, and sweeping it would stop it at every seam
 * (the sweep's target distance finds the next segment's end in its way); a slow approach is the
 * speculative contact's.
 */
function skipsChainSegment(core: WorldCore, b: number, g: Geometry, base: number, ob: number): boolean {
  const bodies = core.bodies;
  const m = core.work.continuous;
  const centre = m.centre;
  shapeCentroid(g, centre);
  const otherXf = m.otherXf;
  otherXf.p.x = bodies.px[ob];
  otherXf.p.y = bodies.py[ob];
  otherXf.q.c = bodies.qc[ob];
  otherXf.q.s = bodies.qs[ob];
  const start = m.start;
  const x1 = start.p.x + start.q.c * centre.x - start.q.s * centre.y;
  const y1 = start.p.y + start.q.s * centre.x + start.q.c * centre.y;
  const offset1 = frontOffsetAt(core.shapes.packed, base, otherXf, x1, y1);
  if (offset1 < 0) return true;
  const c = bodies.qc[b];
  const s = bodies.qs[b];
  const x2 = bodies.px[b] + c * centre.x - s * centre.y;
  const y2 = bodies.py[b] + s * centre.x + c * centre.y;
  const offset2 = frontOffsetAt(core.shapes.packed, base, otherXf, x2, y2);
  return offset1 - offset2 < 0.25 * minExtent(g);
}

/** The centroid of `g` in its body's frame, to `out`. */
function shapeCentroid(g: Geometry, out: Vec2): void {
  if (g.kind === ShapeKind.CIRCLE) {
    out.x = g.center.x;
    out.y = g.center.y;
  } else if (g.kind === ShapeKind.CAPSULE) {
    out.x = 0.5 * (g.center1.x + g.center2.x);
    out.y = 0.5 * (g.center1.y + g.center2.y);
  } else if (g.kind === ShapeKind.POLYGON) {
    out.x = g.centroid.x;
    out.y = g.centroid.y;
  } else {
    out.x = 0.5 * (g.point1.x + g.point2.x);
    out.y = 0.5 * (g.point1.y + g.point2.y);
  }
}

/** A one-point proxy at the shape's centroid with a quarter of its smallest half-thickness as radius. */
function loadDisc(g: Geometry, out: ShapeProxy, centre: Vec2): void {
  shapeCentroid(g, centre);
  out.x[0] = centre.x;
  out.y[0] = centre.y;
  out.count = 1;
  out.radius = 0.25 * minExtent(g);
}
