import type { MatterBounds } from './bounds';
import type { MatterVertex } from './vertices';

/**
 * A simulated body's parts' vertices and bounds, written from the last read-back's pose only when a
 * program next reads (or replaces) them: a program that draws nothing pays nothing for them. Once a
 * program has read them, they are written at every read-back as matter writes them (`eager`): a
 * program may keep the arrays and read them later without going through the body. The fields are
 * accessors from the body's creation on (`defineVertexFields`): made accessors later, the objects
 * would drop to V8's slow dictionary properties.
 */
/** What this module uses of a matter body (body.ts's MatterBody has it). */
export interface PosedPart {
  _pose: PartPoses | null;
  _vertices: MatterVertex[];
  _bounds: MatterBounds;
}

export class PartPoses {
  /** whether the parts' fields show the pose below */
  posed = true;
  /** whether a program has read the fields: then each read-back writes them at once */
  eager = false;
  /** the parts whose fields wait for this pose, in the order of `outlines` */
  parts: PosedPart[] = [];
  /** each part's outline in the body's frame (x, y of each vertex in turn) */
  outlines: Float64Array[] = [];
  /** the body's position and rotation at the read-back, and its velocity (bounds are widened by it, as matter's) */
  x = 0;
  y = 0;
  c = 1;
  s = 0;
  vx = 0;
  vy = 0;

  /** Writes the pose into the parts' vertices and bounds. */
  write(): void {
    this.posed = true;
    const { x: cx, y: cy, c, s, vx, vy, parts, outlines } = this;
    for (let k = 0; k < parts.length; k++) {
      const part = parts[k];
      const outline = outlines[k];
      const vertices = part._vertices;
      let minX = Number.POSITIVE_INFINITY;
      let minY = Number.POSITIVE_INFINITY;
      let maxX = Number.NEGATIVE_INFINITY;
      let maxY = Number.NEGATIVE_INFINITY;
      for (let i = 0, n = outline.length >> 1; i < n; i++) {
        const px = outline[2 * i];
        const py = outline[2 * i + 1];
        const x = cx + c * px - s * py;
        const y = cy + s * px + c * py;
        const vertex = vertices[i];
        vertex.x = x;
        vertex.y = y;
        if (x < minX) minX = x;
        if (x > maxX) maxX = x;
        if (y < minY) minY = y;
        if (y > maxY) maxY = y;
      }
      const bounds = part._bounds;
      bounds.min.x = vx < 0 ? minX + vx : minX;
      bounds.max.x = vx > 0 ? maxX + vx : maxX;
      bounds.min.y = vy < 0 ? minY + vy : minY;
      bounds.max.y = vy > 0 ? maxY + vy : maxY;
    }
  }

  /** A program reads or replaces a part's fields: they show the latest pose from now on. */
  read(): void {
    this.eager = true;
    if (!this.posed) this.write();
  }

  /** Makes `parts` (with these outlines) wait for this pose, and lets the parts it had go (written). */
  attach(parts: PosedPart[], outlines: Float64Array[]): void {
    this.detach();
    this.parts = parts;
    this.outlines = outlines;
    for (const part of parts) part._pose = this;
  }

  /** Writes any pending pose and lets the parts go: their fields are plain values again. */
  detach(): void {
    if (!this.posed) this.write();
    for (const part of this.parts) if (part._pose === this) part._pose = null;
    this.parts = [];
    this.outlines = [];
  }
}

function getVertices(this: PosedPart): MatterVertex[] {
  const pose = this._pose;
  if (pose !== null) pose.read();
  return this._vertices;
}

function setVertices(this: PosedPart, vertices: MatterVertex[]): void {
  const pose = this._pose;
  if (pose !== null) pose.read();
  this._vertices = vertices;
}

function getBounds(this: PosedPart): MatterBounds {
  const pose = this._pose;
  if (pose !== null) pose.read();
  return this._bounds;
}

function setBounds(this: PosedPart, bounds: MatterBounds): void {
  const pose = this._pose;
  if (pose !== null) pose.read();
  this._bounds = bounds;
}

/** Gives a new body its `vertices` and `bounds` fields (enumerable, as matter's) over hidden ones. */
export function defineVertexFields(body: object, vertices: MatterVertex[], bounds: MatterBounds): void {
  Object.defineProperty(body, '_pose', { value: null, writable: true, enumerable: false });
  Object.defineProperty(body, '_vertices', { value: vertices, writable: true, enumerable: false });
  Object.defineProperty(body, '_bounds', { value: bounds, writable: true, enumerable: false });
  Object.defineProperty(body, 'vertices', {
    get: getVertices,
    set: setVertices,
    enumerable: true,
    configurable: true,
  });
  Object.defineProperty(body, 'bounds', {
    get: getBounds,
    set: setBounds,
    enumerable: true,
    configurable: true,
  });
}
