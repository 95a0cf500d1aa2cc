import { makeRot } from '../math/rot';
/**
 * matter.js's `Vector`: plain `{ x, y }` arithmetic. A module object, not a class, and mutable: plugins
 * replace its functions by path (`Matter.after('Vector.add', ...)`).
 */
export interface MatterVector {
  x: number;
  y: number;
}

export const Vector = {
  create(x?: number, y?: number): MatterVector {
    return { x: x || 0, y: y || 0 };
  },

  clone(vector: MatterVector): MatterVector {
    return { x: vector.x, y: vector.y };
  },

  magnitude(vector: MatterVector): number {
    return Math.sqrt(vector.x * vector.x + vector.y * vector.y);
  },

  magnitudeSquared(vector: MatterVector): number {
    return vector.x * vector.x + vector.y * vector.y;
  },

  /** `vector` turned by `angle` (radians, clockwise on a y-down screen), into `output` if given. */
  rotate(vector: MatterVector, angle: number, output?: MatterVector): MatterVector {
    const { c, s } = makeRot(angle);
    const out = output ?? { x: 0, y: 0 };
    const x = vector.x * c - vector.y * s;
    out.y = vector.x * s + vector.y * c;
    out.x = x;
    return out;
  },

  /** `vector` turned by `angle` about `point`, into `output` if given. */
  rotateAbout(vector: MatterVector, angle: number, point: MatterVector, output?: MatterVector): MatterVector {
    const { c, s } = makeRot(angle);
    const dx = vector.x - point.x;
    const dy = vector.y - point.y;
    const out = output ?? { x: 0, y: 0 };
    out.x = point.x + dx * c - dy * s;
    out.y = point.y + dx * s + dy * c;
    return out;
  },

  /** The unit vector along `vector`; the zero vector for a zero one. */
  normalise(vector: MatterVector): MatterVector {
    const length = Math.sqrt(vector.x * vector.x + vector.y * vector.y);
    return length === 0 ? { x: 0, y: 0 } : { x: vector.x / length, y: vector.y / length };
  },

  dot(a: MatterVector, b: MatterVector): number {
    return a.x * b.x + a.y * b.y;
  },

  /** The z of the cross product of a and b. */
  cross(a: MatterVector, b: MatterVector): number {
    return a.x * b.y - a.y * b.x;
  },

  /** The z of the cross product of (b - a) and (c - a). */
  cross3(a: MatterVector, b: MatterVector, c: MatterVector): number {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  },

  add(a: MatterVector, b: MatterVector, output?: MatterVector): MatterVector {
    const out = output ?? { x: 0, y: 0 };
    out.x = a.x + b.x;
    out.y = a.y + b.y;
    return out;
  },

  sub(a: MatterVector, b: MatterVector, output?: MatterVector): MatterVector {
    const out = output ?? { x: 0, y: 0 };
    out.x = a.x - b.x;
    out.y = a.y - b.y;
    return out;
  },

  mult(vector: MatterVector, scalar: number): MatterVector {
    return { x: vector.x * scalar, y: vector.y * scalar };
  },

  div(vector: MatterVector, scalar: number): MatterVector {
    return { x: vector.x / scalar, y: vector.y / scalar };
  },

  /** `vector` turned a quarter turn: (-y, x), or (y, -x) when `negate` is true. */
  perp(vector: MatterVector, negate?: boolean): MatterVector {
    return negate === true ? { x: vector.y, y: -vector.x } : { x: -vector.y, y: vector.x };
  },

  neg(vector: MatterVector): MatterVector {
    return { x: -vector.x, y: -vector.y };
  },

  /** The angle of the line from a to b (output only: matter's Math.atan2, the engine never reads it). */
  angle(a: MatterVector, b: MatterVector): number {
    return Math.atan2(b.y - a.y, b.x - a.x);
  },

  /** Scratch vectors some programs borrow, as matter.js offers them. */
  _temp: [
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
  ] as MatterVector[],
};
