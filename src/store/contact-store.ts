import { growF64, growI32, growU8 } from '../core/grow';
import { SlotStore } from '../core/slot-store';

export enum ContactFlag {
  TOUCHING = 1,
  SENSOR = 2,
  /** touching began or ended during this step's narrow phase (cleared each step) */
  STARTED = 4,
  /** the contact's manifold record holds the last computed manifold and the pose it was computed at */
  CACHED = 8,
  /** the contact counts against shape A's, or shape B's, contact limit (see contact-limit.ts) */
  COUNTS_A = 16,
  COUNTS_B = 32,
}

/**
 * Layout of a contact's record in `ContactStore.manifoldCache` (doubles): the bodies' relative pose
 * when the manifold was last computed, and the manifold's normal and points in body A's frame. The
 * pose is that of the body whose shape reaches less far from its origin, seen from the other's frame
 * (the shapes fix which one: see updateContacts). While the pose stays within the world's
 * manifoldTolerance of it, no point of the two shapes moved further than that relative to the other,
 * and the narrow phase keeps the manifold.
 */
export enum ManifoldCache {
  TX = 0,
  TY = 1,
  RC = 2,
  RS = 3,
  NX = 4,
  NY = 5,
  X0 = 6,
  Y0 = 7,
  X1 = 8,
  Y1 = 9,
  /**
   * for a manifold without points: a lower bound of the shapes' distance when it was computed, or -1
   * (see CollideContext.separatedDistance)
   */
  GAP = 10,
  STRIDE = 11,
}

/**
 * Contacts between pairs of shapes whose fat AABBs overlap, with their manifold and the impulses
 * kept for warm starting. Each contact sits in two intrusive doubly linked lists, one per body:
 * edge key = contact * 2 + side (side 0 is in body A's list, side 1 in body B's).
 * @internal
 */
export class ContactStore extends SlotStore {
  shapeA = new Int32Array(0);
  shapeB = new Int32Array(0);
  bodyA = new Int32Array(0);
  bodyB = new Int32Array(0);
  flags = new Uint8Array(0);
  edgePrev = new Int32Array(0);
  edgeNext = new Int32Array(0);
  // manifold
  normalX = new Float64Array(0);
  normalY = new Float64Array(0);
  pointCount = new Uint8Array(0);
  /** per point, two slots per contact (index contact * 2 + point) */
  pointX = new Float64Array(0);
  pointY = new Float64Array(0);
  separation = new Float64Array(0);
  pointId = new Int32Array(0);
  normalImpulse = new Float64Array(0);
  tangentImpulse = new Float64Array(0);
  /** largest normal impulse of the last step and the approach speed before it (for hit events) */
  maxNormalImpulse = new Float64Array(0);
  approachSpeed = new Float64Array(0);
  /** edge that separated the pair's cores at the last narrow phase (a speed hint; see manifold-polygon) */
  separatingAxis = new Uint8Array(0);
  /** per contact, the manifold kept with the pose it holds for (see MC; valid with ContactFlag.CACHED) */
  manifoldCache = new Float64Array(0);

  protected growColumns(capacity: number): void {
    this.shapeA = growI32(this.shapeA, capacity);
    this.shapeB = growI32(this.shapeB, capacity);
    this.bodyA = growI32(this.bodyA, capacity);
    this.bodyB = growI32(this.bodyB, capacity);
    this.flags = growU8(this.flags, capacity);
    this.edgePrev = growI32(this.edgePrev, capacity * 2);
    this.edgeNext = growI32(this.edgeNext, capacity * 2);
    this.normalX = growF64(this.normalX, capacity);
    this.normalY = growF64(this.normalY, capacity);
    this.pointCount = growU8(this.pointCount, capacity);
    this.pointX = growF64(this.pointX, capacity * 2);
    this.pointY = growF64(this.pointY, capacity * 2);
    this.separation = growF64(this.separation, capacity * 2);
    this.pointId = growI32(this.pointId, capacity * 2);
    this.normalImpulse = growF64(this.normalImpulse, capacity * 2);
    this.tangentImpulse = growF64(this.tangentImpulse, capacity * 2);
    this.maxNormalImpulse = growF64(this.maxNormalImpulse, capacity * 2);
    this.approachSpeed = growF64(this.approachSpeed, capacity * 2);
    this.separatingAxis = growU8(this.separatingAxis, capacity);
    this.manifoldCache = growF64(this.manifoldCache, capacity * ManifoldCache.STRIDE);
  }

  protected resetSlot(slot: number): void {
    this.flags[slot] = 0;
    this.pointCount[slot] = 0;
    this.separatingAxis[slot] = 0;
    this.normalX[slot] = 0;
    this.normalY[slot] = 0;
    for (let k = slot * 2; k < slot * 2 + 2; k++) {
      this.normalImpulse[k] = 0;
      this.tangentImpulse[k] = 0;
      this.maxNormalImpulse[k] = 0;
      this.approachSpeed[k] = 0;
      this.pointId[k] = 0;
      this.edgePrev[k] = -1;
      this.edgeNext[k] = -1;
    }
  }

  /** Links side `side` of contact `c` at the head of the list that starts at `head`; returns the new head. */
  linkEdge(c: number, side: number, head: number): number {
    const e = c * 2 + side;
    this.edgePrev[e] = -1;
    this.edgeNext[e] = head;
    if (head !== -1) this.edgePrev[head] = e;
    return e;
  }

  /** Unlinks side `side` of contact `c`; returns the list head after removal. */
  unlinkEdge(c: number, side: number, head: number): number {
    const e = c * 2 + side;
    const prev = this.edgePrev[e];
    const next = this.edgeNext[e];
    if (prev !== -1) this.edgeNext[prev] = next;
    if (next !== -1) this.edgePrev[next] = prev;
    this.edgePrev[e] = -1;
    this.edgeNext[e] = -1;
    return head === e ? next : head;
  }
}
