import { growF64, growI32, growU8, growU32 } from '../core/grow';
import { SlotStore } from '../core/slot-store';
import { maxExtentFrom } from '../geometry/extent';
import { Pack, packGeometry } from '../geometry/packed';
import { type Geometry, ShapeKind } from '../geometry/types';

export enum ShapeFlag {
  SENSOR = 1,
  CONTACT_EVENTS = 2,
  SENSOR_EVENTS = 4,
  HIT_EVENTS = 8,
}

/** @internal Shape data in columns indexed by shape slot; geometry objects are immutable and shared. */
export class ShapeStore extends SlotStore {
  body = new Int32Array(0);
  /** next shape of the same body (-1 ends the list) */
  next = new Int32Array(0);
  kind = new Uint8Array(0);
  flags = new Uint8Array(0);
  density = new Float64Array(0);
  friction = new Float64Array(0);
  restitution = new Float64Array(0);
  /** rounding radius of the geometry (circle and capsule radius, polygon radius, 0 for segments) */
  radius = new Float64Array(0);
  /** largest distance of any point of the shape from its body's origin */
  originExtent = new Float64Array(0);
  /** largest distance of any point of the shape from its own centroid: its size for the contact limit */
  centroidExtent = new Float64Array(0);
  /** the contacts that count against this shape's contact limit (see world/contact-limit.ts) */
  contactLoad = new Int32Array(0);
  categoryBits = new Uint32Array(0);
  maskBits = new Uint32Array(0);
  groupIndex = new Int32Array(0);
  proxyKey = new Int32Array(0);
  /** tight world AABB, refreshed when the body moves */
  minX = new Float64Array(0);
  minY = new Float64Array(0);
  maxX = new Float64Array(0);
  maxY = new Float64Array(0);
  geometry: (Geometry | undefined)[] = [];
  /** each shape's geometry packed (see packed.ts), Pack.STRIDE doubles per slot */
  packed = new Float64Array(0);

  /** Writes the columns that follow from shape `s`'s geometry (its proxy and mass are the caller's). */
  setGeometry(s: number, geometry: Geometry): void {
    this.geometry[s] = geometry;
    packGeometry(geometry, this.packed, s * Pack.STRIDE);
    this.kind[s] = geometry.kind;
    this.radius[s] = geometry.kind === ShapeKind.SEGMENT ? 0 : geometry.radius;
    this.originExtent[s] = maxExtentFrom(geometry, 0, 0);
  }

  protected growColumns(capacity: number): void {
    this.body = growI32(this.body, capacity);
    this.next = growI32(this.next, capacity);
    this.kind = growU8(this.kind, capacity);
    this.flags = growU8(this.flags, capacity);
    this.density = growF64(this.density, capacity);
    this.friction = growF64(this.friction, capacity);
    this.restitution = growF64(this.restitution, capacity);
    this.radius = growF64(this.radius, capacity);
    this.originExtent = growF64(this.originExtent, capacity);
    this.centroidExtent = growF64(this.centroidExtent, capacity);
    this.contactLoad = growI32(this.contactLoad, capacity);
    this.categoryBits = growU32(this.categoryBits, capacity);
    this.maskBits = growU32(this.maskBits, capacity);
    this.groupIndex = growI32(this.groupIndex, capacity);
    this.proxyKey = growI32(this.proxyKey, capacity);
    this.minX = growF64(this.minX, capacity);
    this.minY = growF64(this.minY, capacity);
    this.maxX = growF64(this.maxX, capacity);
    this.maxY = growF64(this.maxY, capacity);
    this.packed = growF64(this.packed, capacity * Pack.STRIDE);
  }

  protected resetSlot(slot: number): void {
    this.body[slot] = -1;
    this.next[slot] = -1;
    this.flags[slot] = 0;
    this.proxyKey[slot] = -1;
    this.contactLoad[slot] = 0;
    this.geometry[slot] = undefined;
  }
}

/** @internal Collision filtering rule: a shared non-zero group decides; otherwise categories and masks must agree. */
export function shouldShapesCollide(store: ShapeStore, a: number, b: number): boolean {
  const ga = store.groupIndex[a];
  if (ga !== 0 && ga === store.groupIndex[b]) return ga > 0;
  return (
    (store.categoryBits[a] & store.maskBits[b]) !== 0 && (store.categoryBits[b] & store.maskBits[a]) !== 0
  );
}
