import { IndexBound } from '../core/index-bound';
import { Pack } from '../geometry/packed';
import { collidePacked } from '../narrow-phase/manifold';
import { referenceOwnerOfId, VERTEX_PAIR_MIN_GAP } from '../narrow-phase/manifold-polygon';
import { BodyFlag } from '../store/body-store';
import { ContactFlag, ManifoldCache } from '../store/contact-store';
import { WarningCode } from '../store/event-buffers';
import { WarningRearm } from './contact-limit';
import type { WorldCore } from './world-core';

/**
 * Creates contacts for the new overlapping pairs the broad phase found, WorldCore.shouldPair allowed
 * and the contact limit admitted, in (shapeA, shapeB) order, and records the warnings of a crowd.
 * A world holds at most IndexBound.MAX contacts: pairs beyond that are left out, like filtered ones,
 * until their proxies move again.
 * @internal
 */
export function createNewContacts(core: WorldCore): void {
  const pairs = core.newPairs;
  const limiter = core.contactLimiter;
  pairs.clear();
  limiter.requeue(core.broadPhase);
  core.broadPhase.updatePairs(core.pairs, core, pairs, limiter);
  core.contacts.reserve(Math.min(pairs.length >> 1, IndexBound.MAX - core.contacts.liveCount));
  const data = pairs.data;
  for (let i = 0, n = pairs.length; i < n; i += 2) {
    if (core.contacts.liveCount >= IndexBound.MAX) break;
    core.createContact(data[i], data[i + 1]);
  }
  limiter.settle(pairs);
  warnOfCrowds(core);
}

/**
 * Records a warning when shapes start to pass through shapes they overlap for want of room under the
 * contact limit, or proxies to wait for the pair search; again only after WarningRearm.STEPS steps
 * without it (a crowd coming apart passes the pair search's budget on and off).
 * (The crowded count walks the waiting shapes: none in a scene under the limit.)
 */
function warnOfCrowds(core: WorldCore): void {
  const limiter = core.contactLimiter;
  const crowded = limiter.waiting.length === 0 ? 0 : limiter.crowdedCount;
  if (crowded === 0) limiter.quietLimit = Math.min(limiter.quietLimit + 1, WarningRearm.STEPS);
  else {
    if (limiter.quietLimit >= WarningRearm.STEPS) {
      core.events.recordWarning(WarningCode.CONTACT_LIMIT, crowded, limiter.limit, limiter.firstCrowded());
    }
    limiter.quietLimit = 0;
  }
  const broad = core.broadPhase;
  const deferred = broad.deferredCount;
  if (deferred === 0) limiter.quietSearch = Math.min(limiter.quietSearch + 1, WarningRearm.STEPS);
  else {
    if (limiter.quietSearch >= WarningRearm.STEPS) {
      core.events.recordWarning(
        WarningCode.PAIR_SEARCH,
        deferred,
        broad.searchBudget,
        broad.firstDeferredShape(),
      );
    }
    limiter.quietSearch = 0;
  }
}

/**
 * Updates the manifold of every contact with an awake body, keeps the impulses of points whose
 * feature id survived (warm starting), records begin/end touching, wakes sleeping bodies that an
 * awake body starts to touch, and destroys contacts whose fat AABBs no longer overlap.
 * @internal
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
  // the columns in locals: the loop calls out (collide, events), and V8 reloads every property
  // read after a call; nothing called here resizes them
  const alive = contacts.alive;
  const contactBodyA = contacts.bodyA;
  const contactBodyB = contacts.bodyB;
  const contactShapeA = contacts.shapeA;
  const contactShapeB = contacts.shapeB;
  const contactFlags = contacts.flags;
  const pointCount = contacts.pointCount;
  const pointId = contacts.pointId;
  const pointX = contacts.pointX;
  const pointY = contacts.pointY;
  const separation = contacts.separation;
  const normalImpulse = contacts.normalImpulse;
  const tangentImpulse = contacts.tangentImpulse;
  const normalX = contacts.normalX;
  const normalY = contacts.normalY;
  const separatingAxis = contacts.separatingAxis;
  const minX = shapes.minX;
  const minY = shapes.minY;
  const maxX = shapes.maxX;
  const maxY = shapes.maxY;
  const shapeKind = shapes.kind;
  const proxyKey = shapes.proxyKey;
  const packed = shapes.packed;
  const manifold = core.work.manifold;
  const points = manifold.points;
  const bodyPx = bodies.px;
  const bodyPy = bodies.py;
  const bodyQc = bodies.qc;
  const bodyQs = bodies.qs;
  const cache = contacts.manifoldCache;
  const originExtent = shapes.originExtent;
  const tolerance = core.settings.manifoldTolerance;
  const context = core.work.collide;
  for (let c = 0, n = contacts.slotCount; c < n; c++) {
    if (alive[c] === 0) continue;
    const bodyA = contactBodyA[c];
    const bodyB = contactBodyB[c];
    const awakeA = (flagsB[bodyA] & BodyFlag.AWAKE) !== 0;
    const awakeB = (flagsB[bodyB] & BodyFlag.AWAKE) !== 0;
    if (!awakeA && !awakeB) continue;
    const shapeA = contactShapeA[c];
    const shapeB = contactShapeB[c];
    // gap between the shapes' tight boxes (negative when they overlap)
    const gap = Math.max(
      minX[shapeA] - maxX[shapeB],
      minX[shapeB] - maxX[shapeA],
      minY[shapeA] - maxY[shapeB],
      minY[shapeB] - maxY[shapeA],
    );
    // the fat boxes hold the tight ones: they can only have come apart if the tight ones are apart
    if (gap > 0 && !broad.fatBoxesOverlap(proxyKey[shapeA], proxyKey[shapeB])) {
      core.destroyContact(c, true);
      continue;
    }
    let flags = contactFlags[c];
    const sensor = (flags & ContactFlag.SENSOR) !== 0;
    const k0 = c * 2;
    const reach = sensor ? 0 : speculative;
    if (gap > reach + VERTEX_PAIR_MIN_GAP) {
      // the shapes are further apart than the boxes, and a point's separation is at most the vertex-pair
      // tolerance below the shapes' distance (manifold-polygon.ts): the manifold would be empty, and
      // if it was empty already, nothing changes (a hanging grid's diagonal neighbours, every step)
      if (pointCount[c] === 0) {
        contactFlags[c] = flags & ~ContactFlag.CACHED;
        continue;
      }
      manifold.pointCount = 0;
      flags &= ~ContactFlag.CACHED;
    } else {
      const ax = bodyPx[bodyA];
      const ay = bodyPy[bodyA];
      const ac = bodyQc[bodyA];
      const as = bodyQs[bodyA];
      const bx = bodyPx[bodyB];
      const by = bodyPy[bodyB];
      const bc = bodyQc[bodyB];
      const bs = bodyQs[bodyB];
      // the pose of the body whose shape reaches less far from its origin (a small box on a long
      // ground: the box's turn moves little), seen from the other's frame, and the rotation of B
      // relative to A (for either, a change of the pair bounds the change of the other)
      const extentA = originExtent[shapeA];
      const extentB = originExtent[shapeB];
      const fromA = extentB <= extentA;
      const fc = fromA ? ac : bc;
      const fs = fromA ? as : bs;
      const dx = fromA ? bx - ax : ax - bx;
      const dy = fromA ? by - ay : ay - by;
      const tx = fc * dx + fs * dy;
      const ty = fc * dy - fs * dx;
      const rc = ac * bc + as * bs;
      const rs = ac * bs - as * bc;
      const o = c * ManifoldCache.STRIDE;
      if ((flags & ContactFlag.CACHED) !== 0) {
        // how far any point of that shape moved, relative to the other, since the manifold was
        // computed: at most the translation plus its extent times the rotation's change
        const moved =
          Math.abs(tx - cache[o + ManifoldCache.TX]) +
          Math.abs(ty - cache[o + ManifoldCache.TY]) +
          (fromA ? extentB : extentA) *
            (Math.abs(rc - cache[o + ManifoldCache.RC]) + Math.abs(rs - cache[o + ManifoldCache.RS]));
        // shapes found apart stay apart (the manifold empty) while they came closer by less than
        // their distance then, less the reach (the vertex-pair tolerance as for `gap` above)
        if (pointCount[c] === 0 && moved < cache[o + ManifoldCache.GAP] - reach - VERTEX_PAIR_MIN_GAP)
          continue;
        if (moved < tolerance && pointCount[c] > 0) {
          // the manifold holds: carried along with body A, separations and impulses kept
          const count = pointCount[c];
          if (!sensor && count > 0) {
            const lnx = cache[o + ManifoldCache.NX];
            const lny = cache[o + ManifoldCache.NY];
            normalX[c] = ac * lnx - as * lny;
            normalY[c] = as * lnx + ac * lny;
            for (let j = 0; j < count; j++) {
              const lx = cache[o + ManifoldCache.X0 + 2 * j];
              const ly = cache[o + ManifoldCache.Y0 + 2 * j];
              pointX[k0 + j] = ax + ac * lx - as * ly;
              pointY[k0 + j] = ay + as * lx + ac * ly;
            }
          }
          continue;
        }
      }
      context.reach = reach;
      context.referenceHint = pointCount[c] > 0 ? referenceOwnerOfId(pointId[k0]) : -1;
      context.axisHint = separatingAxis[c];
      context.separatingAxis = 0;
      context.separatedDistance = -1;
      collidePacked(
        shapeKind[shapeA],
        shapeKind[shapeB],
        packed,
        shapeA * Pack.STRIDE,
        core.fillTransform(bodyA, core.xfA),
        shapeB * Pack.STRIDE,
        core.fillTransform(bodyB, core.xfB),
        manifold,
        context,
      );
      separatingAxis[c] = context.separatingAxis;
      // keep the manifold in A's frame with the pose it holds for
      cache[o + ManifoldCache.TX] = tx;
      cache[o + ManifoldCache.TY] = ty;
      cache[o + ManifoldCache.RC] = rc;
      cache[o + ManifoldCache.RS] = rs;
      // collide leaves the normal of a manifold without points as it was, the last one computed:
      // 0 keeps the snapshot free of it (it is never read)
      const nx = manifold.pointCount > 0 ? manifold.normalX : 0;
      const ny = manifold.pointCount > 0 ? manifold.normalY : 0;
      cache[o + ManifoldCache.NX] = ac * nx + as * ny;
      cache[o + ManifoldCache.NY] = ac * ny - as * nx;
      for (let j = 0; j < manifold.pointCount; j++) {
        const px = points[j].x - ax;
        const py = points[j].y - ay;
        cache[o + ManifoldCache.X0 + 2 * j] = ac * px + as * py;
        cache[o + ManifoldCache.Y0 + 2 * j] = ac * py - as * px;
      }
      if (manifold.pointCount === 0) cache[o + ManifoldCache.GAP] = context.separatedDistance;
      flags |= ContactFlag.CACHED;
    }
    contactFlags[c] = flags;
    const count = manifold.pointCount;
    if (!sensor) {
      // Carry the impulses of surviving points over (warm starting): same feature id, or else the old
      // point nearest to the new one. The position fallback keeps the impulses when the manifold
      // swaps its reference face between the two shapes (nearly parallel faces under load do), which
      // renames the features but not the physical points; losing them makes large piles jitter.
      const oldCount = pointCount[c];
      const oldId0 = pointId[k0];
      const oldId1 = pointId[k0 + 1];
      const ox0 = pointX[k0];
      const oy0 = pointY[k0];
      const ox1 = pointX[k0 + 1];
      const oy1 = pointY[k0 + 1];
      const n0 = normalImpulse[k0];
      const t0 = tangentImpulse[k0];
      const n1 = normalImpulse[k0 + 1];
      const t1 = tangentImpulse[k0 + 1];
      const sameNormal = normalX[c] * manifold.normalX + normalY[c] * manifold.normalY > 0.99;
      for (let j = 0; j < count; j++) {
        const p = points[j];
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
        pointX[k] = p.x;
        pointY[k] = p.y;
        separation[k] = p.separation;
        pointId[k] = p.id;
        normalImpulse[k] = match === 0 ? n0 : match === 1 ? n1 : 0;
        tangentImpulse[k] = match === 0 ? t0 : match === 1 ? t1 : 0;
      }
      // the normal of a manifold without points is not read (and not always written by collide)
      if (count > 0) {
        normalX[c] = manifold.normalX;
        normalY[c] = manifold.normalY;
      }
    }
    pointCount[c] = count;
    const touching = count > 0;
    const wasTouching = (flags & ContactFlag.TOUCHING) !== 0;
    if (touching === wasTouching) continue;
    if (touching) {
      contactFlags[c] = flags | ContactFlag.TOUCHING;
      events.recordBegin(contacts, c, shapes);
      if (!sensor) {
        if (!awakeA) core.wake(bodyA);
        if (!awakeB) core.wake(bodyB);
      }
    } else {
      contactFlags[c] = flags & ~ContactFlag.TOUCHING;
      events.recordEnd(contacts, c, shapes, false);
    }
  }
}
