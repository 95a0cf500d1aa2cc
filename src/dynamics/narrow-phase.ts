import { collideReach } from '../geometry/collide-reach';
import { collidePacked } from '../geometry/manifold';
import {
  lastSeparatingAxis,
  referenceOwnerOfId,
  setReferenceHint,
  setSeparatingAxisHint,
  VERTEX_PAIR_MIN_GAP,
} from '../geometry/manifold-polygon';
import { Pack } from '../geometry/packed';
import type { Manifold, ManifoldPoint } from '../geometry/types';
import { BodyFlag, BodyKind } from './body-store';
import { ContactFlag } from './contact-store';
import { ShapeFlag, shouldShapesCollide } from './shape-store';
import type { WorldCore } from './world-core';

/** A manifold point of its own class, so that its fields stay unboxed doubles (see ScratchPoint). */
class Point implements ManifoldPoint {
  x = 0;
  y = 0;
  separation = 0;
  id = 0;
}

const manifold: Manifold = { normalX: 0, normalY: 0, pointCount: 0, points: [new Point(), new Point()] };

/** Creates contacts for the new overlapping pairs the broad phase found, in (shapeA, shapeB) order. */
export function createNewContacts(core: WorldCore): void {
  const pairs = core.newPairs;
  pairs.clear();
  core.broadPhase.updatePairs(core.pairs, pairs);
  const shapes = core.shapes;
  const kind = core.bodies.kind;
  const data = pairs.data;
  for (let i = 0, n = pairs.length; i < n; i += 2) {
    const a = data[i];
    const b = data[i + 1];
    const bodyA = shapes.body[a];
    const bodyB = shapes.body[b];
    if (bodyA === bodyB) continue;
    if (kind[bodyA] !== BodyKind.DYNAMIC && kind[bodyB] !== BodyKind.DYNAMIC) continue;
    if ((shapes.flags[a] & shapes.flags[b] & ShapeFlag.SENSOR) !== 0) continue;
    if (!shouldShapesCollide(shapes, a, b)) continue;
    if (!core.jointsAllowCollision(bodyA, bodyB)) continue;
    core.createContact(a, b);
  }
}

/**
 * Updates the manifold of every contact with an awake body, keeps the impulses of points whose
 * feature id survived (warm starting), records begin/end touching, wakes sleeping bodies that an
 * awake body starts to touch, and destroys contacts whose fat AABBs no longer overlap.
 */
export function updateContacts(core: WorldCore): void {
  const contacts = core.contacts;
  const shapes = core.shapes;
  const bodies = core.bodies;
  const flagsB = bodies.flags;
  const broad = core.broadPhase;
  const speculative = core.settings.speculativeDistance;
  const matchDistance2 = 4 * speculative * speculative;
  const events = core.events;
  for (let c = 0, n = contacts.slotCount; c < n; c++) {
    if (contacts.alive[c] === 0) continue;
    const bodyA = contacts.bodyA[c];
    const bodyB = contacts.bodyB[c];
    const awakeA = (flagsB[bodyA] & BodyFlag.AWAKE) !== 0;
    const awakeB = (flagsB[bodyB] & BodyFlag.AWAKE) !== 0;
    if (!awakeA && !awakeB) continue;
    const shapeA = contacts.shapeA[c];
    const shapeB = contacts.shapeB[c];
    // gap between the shapes' tight boxes (negative when they overlap)
    const gap = Math.max(
      shapes.minX[shapeA] - shapes.maxX[shapeB],
      shapes.minX[shapeB] - shapes.maxX[shapeA],
      shapes.minY[shapeA] - shapes.maxY[shapeB],
      shapes.minY[shapeB] - shapes.maxY[shapeA],
    );
    // the fat boxes hold the tight ones: they can only have come apart if the tight ones are apart
    if (gap > 0 && !broad.fatBoxesOverlap(shapes.proxyKey[shapeA], shapes.proxyKey[shapeB])) {
      core.destroyContact(c, true);
      continue;
    }
    const flags = contacts.flags[c];
    const sensor = (flags & ContactFlag.SENSOR) !== 0;
    const k0 = c * 2;
    const reach = sensor ? 0 : speculative;
    if (gap > reach + VERTEX_PAIR_MIN_GAP) {
      // the shapes are further apart than the boxes, and a point's separation is at most the vertex-pair
      // tolerance below the shapes' distance (manifold-polygon.ts): the manifold would be empty
      manifold.pointCount = 0;
    } else {
      setReferenceHint(contacts.pointCount[c] > 0 ? referenceOwnerOfId(contacts.pointId[k0]) : -1);
      setSeparatingAxisHint(contacts.separatingAxis[c]);
      collideReach[0] = reach;
      collidePacked(
        shapes.kind[shapeA],
        shapes.kind[shapeB],
        shapes.packed,
        shapeA * Pack.STRIDE,
        core.fillTransform(bodyA, core.xfA),
        shapeB * Pack.STRIDE,
        core.fillTransform(bodyB, core.xfB),
        manifold,
      );
      contacts.separatingAxis[c] = lastSeparatingAxis();
    }
    const count = manifold.pointCount;
    if (!sensor) {
      // Carry the impulses of surviving points over (warm starting): same feature id, or else the old
      // point nearest to the new one. The position fallback keeps the impulses when the manifold
      // swaps its reference face between the two shapes (nearly parallel faces under load do), which
      // renames the features but not the physical points; losing them makes large piles jitter.
      const oldCount = contacts.pointCount[c];
      const oldId0 = contacts.pointId[k0];
      const oldId1 = contacts.pointId[k0 + 1];
      const ox0 = contacts.pointX[k0];
      const oy0 = contacts.pointY[k0];
      const ox1 = contacts.pointX[k0 + 1];
      const oy1 = contacts.pointY[k0 + 1];
      const n0 = contacts.normalImpulse[k0];
      const t0 = contacts.tangentImpulse[k0];
      const n1 = contacts.normalImpulse[k0 + 1];
      const t1 = contacts.tangentImpulse[k0 + 1];
      const sameNormal =
        contacts.normalX[c] * manifold.normalX + contacts.normalY[c] * manifold.normalY > 0.99;
      for (let j = 0; j < count; j++) {
        const p = manifold.points[j];
        const k = k0 + j;
        let match = -1;
        if (oldCount > 0 && p.id === oldId0) match = 0;
        else if (oldCount > 1 && p.id === oldId1) match = 1;
        else if (oldCount > 0 && sameNormal) {
          const d0 = (p.x - ox0) * (p.x - ox0) + (p.y - oy0) * (p.y - oy0);
          const d1 =
            oldCount > 1 ? (p.x - ox1) * (p.x - ox1) + (p.y - oy1) * (p.y - oy1) : Number.POSITIVE_INFINITY;
          if (Math.min(d0, d1) < matchDistance2) match = d0 <= d1 ? 0 : 1;
        }
        contacts.pointX[k] = p.x;
        contacts.pointY[k] = p.y;
        contacts.separation[k] = p.separation;
        contacts.pointId[k] = p.id;
        contacts.normalImpulse[k] = match === 0 ? n0 : match === 1 ? n1 : 0;
        contacts.tangentImpulse[k] = match === 0 ? t0 : match === 1 ? t1 : 0;
      }
      // the normal of a manifold without points is not read (and not always written by collide)
      if (count > 0) {
        contacts.normalX[c] = manifold.normalX;
        contacts.normalY[c] = manifold.normalY;
      }
    }
    contacts.pointCount[c] = count;
    const touching = count > 0;
    const wasTouching = (flags & ContactFlag.TOUCHING) !== 0;
    if (touching === wasTouching) continue;
    if (touching) {
      contacts.flags[c] = flags | ContactFlag.TOUCHING;
      events.recordBegin(contacts, c, shapes);
      if (!sensor) {
        if (!awakeA) core.wake(bodyA);
        if (!awakeB) core.wake(bodyB);
      }
    } else {
      contacts.flags[c] = flags & ~ContactFlag.TOUCHING;
      events.recordEnd(contacts, c, shapes);
    }
  }
}
