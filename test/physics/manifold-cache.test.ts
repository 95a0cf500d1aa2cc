import { describe, expect, it } from 'vitest';
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { tumbler } from '../../scenes/tumbler';
import { Pack } from '../../src/geometry/packed';
import { makeManifold } from '../../src/geometry/types';
import { Shape, World } from '../../src/index';
import { CollideContext } from '../../src/narrow-phase/collide-context';
import { collidePacked } from '../../src/narrow-phase/manifold';
import { referenceOwnerOfId } from '../../src/narrow-phase/manifold-polygon';
import { ContactFlag, ManifoldCache } from '../../src/store/contact-store';
import { groundWorld, pyramid } from '../helpers/world';

const fresh = makeManifold();
const context = new CollideContext();

interface Deviation {
  /** contacts whose manifold the narrow phase kept, and all touching ones */
  kept: number;
  touching: number;
  /** largest difference between a kept manifold and one computed afresh at the same poses */
  point: number;
  separation: number;
  normal: number;
  countMismatch: number;
  /** contacts apart whose empty manifold the narrow phase kept, and those a fresh one gave points */
  keptEmpty: number;
  emptyMismatch: number;
}

/** the bodies' poses before a step: the ones its narrow phase saw */
interface Poses {
  px: Float64Array;
  py: Float64Array;
  qc: Float64Array;
  qs: Float64Array;
}

function transformOf(poses: Poses, b: number) {
  return { p: { x: poses.px[b], y: poses.py[b] }, q: { c: poses.qc[b], s: poses.qs[b] } };
}

/**
 * Compares every touching contact's manifold after a step with one computed afresh from the poses
 * the step's narrow phase saw. A manifold the narrow phase kept is told apart by its record: one
 * computed in that step stored the very pose the bodies were at.
 */
function compare(world: World, poses: Poses, out: Deviation): void {
  const core = world.core;
  const contacts = core.contacts;
  const shapes = core.shapes;
  const cache = contacts.manifoldCache;
  for (let c = 0; c < contacts.slotCount; c++) {
    if (contacts.alive[c] === 0) continue;
    if ((contacts.flags[c] & ContactFlag.SENSOR) !== 0) continue;
    const empty = contacts.pointCount[c] === 0;
    // an empty manifold is kept only from a collide call (CACHED): others were not looked at
    if (empty && (contacts.flags[c] & ContactFlag.CACHED) === 0) continue;
    if (!empty) out.touching++;
    const a = contacts.bodyA[c];
    const b = contacts.bodyB[c];
    const o = c * ManifoldCache.STRIDE;
    const fromA = shapes.originExtent[contacts.shapeB[c]] <= shapes.originExtent[contacts.shapeA[c]];
    const [f, g] = fromA ? [a, b] : [b, a];
    const dx = poses.px[g] - poses.px[f];
    const dy = poses.py[g] - poses.py[f];
    const tx = poses.qc[f] * dx + poses.qs[f] * dy;
    const ty = poses.qc[f] * dy - poses.qs[f] * dx;
    if (tx === cache[o + ManifoldCache.TX] && ty === cache[o + ManifoldCache.TY]) continue;
    if (empty) out.keptEmpty++;
    else out.kept++;
    const sa = contacts.shapeA[c];
    const sb = contacts.shapeB[c];
    context.referenceHint = referenceOwnerOfId(contacts.pointId[2 * c]);
    context.axisHint = contacts.separatingAxis[c];
    context.reach = core.settings.speculativeDistance;
    collidePacked(
      shapes.kind[sa],
      shapes.kind[sb],
      shapes.packed,
      sa * Pack.STRIDE,
      transformOf(poses, a),
      sb * Pack.STRIDE,
      transformOf(poses, b),
      fresh,
      context,
    );
    if (empty) {
      if (fresh.pointCount > 0) out.emptyMismatch++;
      continue;
    }
    if (fresh.pointCount !== contacts.pointCount[c]) {
      out.countMismatch++;
      continue;
    }
    out.normal = Math.max(
      out.normal,
      Math.hypot(fresh.normalX - contacts.normalX[c], fresh.normalY - contacts.normalY[c]),
    );
    for (let j = 0; j < fresh.pointCount; j++) {
      const k = 2 * c + j;
      // the fresh manifold may list the same two points the other way round
      const p = fresh.points[j];
      const q = fresh.points[fresh.pointCount - 1 - j];
      const near = Math.min(
        Math.hypot(p.x - contacts.pointX[k], p.y - contacts.pointY[k]),
        Math.hypot(q.x - contacts.pointX[k], q.y - contacts.pointY[k]),
      );
      const sep = Math.min(
        Math.abs(p.separation - contacts.separation[k]),
        Math.abs(q.separation - contacts.separation[k]),
      );
      out.point = Math.max(out.point, near);
      out.separation = Math.max(out.separation, sep);
    }
  }
}

function measure(world: World, steps: number): Deviation {
  const out: Deviation = {
    kept: 0,
    touching: 0,
    point: 0,
    separation: 0,
    normal: 0,
    countMismatch: 0,
    keptEmpty: 0,
    emptyMismatch: 0,
  };
  const bodies = world.core.bodies;
  for (let i = 0; i < steps; i++) {
    const poses = {
      px: bodies.px.slice(),
      py: bodies.py.slice(),
      qc: bodies.qc.slice(),
      qs: bodies.qs.slice(),
    };
    world.step(1 / 60);
    if (i >= 60) compare(world, poses, out);
  }
  return out;
}

/**
 * A kept manifold is one whose shapes moved less than `tolerance` relative to each other: a signed
 * distance changes by at most that, a clipped point (where one shape's edge crosses the other's
 * side plane) by at most about twice that at the shallow angles here, and the normal turns by at
 * most the tolerance over the turning shape's extent (at least 0.7 m for these boxes) radians.
 */
function expectWithin(d: Deviation, tolerance: number): void {
  expect(d.separation).toBeLessThan(tolerance);
  expect(d.point).toBeLessThan(2 * tolerance);
  expect(d.normal).toBeLessThan(tolerance / 0.7);
}

describe('manifold cache', () => {
  it('a settled pyramid keeps most manifolds, each within the tolerance of a fresh one', () => {
    const { world } = groundWorld({ enableSleep: false });
    pyramid(world, 10);
    const tolerance = world.core.settings.manifoldTolerance;
    const d = measure(world, 300);
    expect(d.kept / d.touching).toBeGreaterThan(0.8);
    expect(d.countMismatch).toBe(0);
    expectWithin(d, tolerance);
  });

  it('boxes riding a moving, turning platform: kept manifolds follow the bodies', () => {
    const world = new World({ enableSleep: false });
    const platform = world.createBody({ type: 'kinematic', position: { x: 0, y: 0 } });
    platform.createShape(Shape.box(4, 0.25));
    platform.setLinearVelocity({ x: 1.5, y: 0.5 });
    platform.setAngularVelocity(0.05);
    for (let i = 0; i < 3; i++) {
      const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.75 + i } });
      box.createShape(Shape.box(0.5, 0.5), { friction: 0.8 });
    }
    const tolerance = world.core.settings.manifoldTolerance;
    const d = measure(world, 240);
    expect(d.kept).toBeGreaterThan(0);
    expect(d.countMismatch).toBe(0);
    expectWithin(d, tolerance);
  });

  it('boxes tumbling in a turning drum: pairs found apart keep their empty manifold only while a fresh one is empty too', () => {
    // the drum's walls reach over most boxes' boxes: the narrow phase skips a pair apart by d along
    // an edge normal until it came closer by d less the contact reach (see updateContacts)
    const { world } = buildFulcrumWorld(tumbler({ count: 200 }), { enableSleep: false });
    const d = measure(world, 240);
    // measured: 58,239 kept empty (159 without the skip, by the tolerance alone), none wrong
    expect(d.keptEmpty).toBeGreaterThan(10_000);
    expect(d.emptyMismatch).toBe(0);
  });
});
