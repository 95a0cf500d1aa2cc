import { arcTangent2 } from '../math/arc-tangent';
import { makeRot } from '../math/rot';
import { type MatterVector, Vector } from './vector';

/** A vertex of a matter.js body: its world point, its index in the list, and its body. */
export interface MatterVertex extends MatterVector {
  index: number;
  body: unknown;
  isInternal: boolean;
}

/**
 * matter.js's `Vertices`: operations on vertex lists, in place where matter's are. Lists are
 * clockwise on a y-down screen (counter-clockwise in the coordinates' own sense), as matter keeps them.
 * A plain, mutable module object.
 */
export const Vertices = {
  /** Vertex objects for `points`, numbered in order and owned by `body`. */
  create(points: readonly MatterVector[], body?: unknown): MatterVertex[] {
    return points.map((p, index) => ({ x: p.x, y: p.y, index, body, isInternal: false }));
  },

  /** Vertices from a list of coordinates, `"x1 y1 x2 y2 ..."`, commas and `L`s allowed between them. */
  fromPath(path: string, body?: unknown): MatterVertex[] {
    const numbers = (path.match(/[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?/gi) ?? []).map(Number);
    const points: MatterVector[] = [];
    for (let i = 0; i + 1 < numbers.length; i += 2) points.push({ x: numbers[i], y: numbers[i + 1] });
    return Vertices.create(points, body);
  },

  /** The area centroid. */
  centre(vertices: readonly MatterVector[]): MatterVector {
    const n = vertices.length;
    let doubleArea = 0;
    let x = 0;
    let y = 0;
    for (let i = 0; i < n; i++) {
      const a = vertices[i];
      const b = vertices[(i + 1) % n];
      const cross = a.x * b.y - b.x * a.y;
      doubleArea += cross;
      x += (a.x + b.x) * cross;
      y += (a.y + b.y) * cross;
    }
    return { x: x / (3 * doubleArea), y: y / (3 * doubleArea) };
  },

  /** The mean of the vertices. */
  mean(vertices: readonly MatterVector[]): MatterVector {
    let x = 0;
    let y = 0;
    for (const v of vertices) {
      x += v.x;
      y += v.y;
    }
    return { x: x / vertices.length, y: y / vertices.length };
  },

  /** The area; `signed`, positive for a list clockwise on a y-down screen. */
  area(vertices: readonly MatterVector[], signed?: boolean): number {
    const n = vertices.length;
    let doubleArea = 0;
    for (let i = 0; i < n; i++) {
      const a = vertices[i];
      const b = vertices[(i + 1) % n];
      doubleArea += a.x * b.y - b.x * a.y;
    }
    return signed ? doubleArea / 2 : Math.abs(doubleArea) / 2;
  },

  /**
   * The moment of inertia of the polygon of mass `mass` about the origin of its coordinates (matter
   * calls it with the vertices centred on their centroid).
   */
  inertia(vertices: readonly MatterVector[], mass: number): number {
    const n = vertices.length;
    let sum = 0;
    let weight = 0;
    for (let i = 0; i < n; i++) {
      const a = vertices[i];
      const b = vertices[(i + 1) % n];
      const cross = Math.abs(a.x * b.y - b.x * a.y);
      sum += cross * (a.x * a.x + a.y * a.y + a.x * b.x + a.y * b.y + b.x * b.x + b.y * b.y);
      weight += cross;
    }
    return (mass / 6) * (sum / weight);
  },

  /** Moves every vertex by `vector` times `scalar` (default 1), in place. */
  translate<T extends MatterVector[]>(vertices: T, vector: MatterVector, scalar?: number): T {
    const k = scalar ?? 1;
    const dx = vector.x * k;
    const dy = vector.y * k;
    for (const v of vertices) {
      v.x += dx;
      v.y += dy;
    }
    return vertices;
  },

  /** Turns every vertex by `angle` about `point`, in place. */
  rotate<T extends MatterVector[]>(vertices: T, angle: number, point: MatterVector): T {
    if (angle === 0) return vertices;
    for (const v of vertices) Vector.rotateAbout(v, angle, point, v);
    return vertices;
  },

  /** Whether `point` is inside the convex polygon (on its edge counts). */
  contains(vertices: readonly MatterVector[], point: MatterVector): boolean {
    const n = vertices.length;
    for (let i = 0; i < n; i++) {
      const a = vertices[i === 0 ? n - 1 : i - 1];
      const b = vertices[i];
      if ((b.x - a.x) * (point.y - a.y) - (b.y - a.y) * (point.x - a.x) < 0) return false;
    }
    return true;
  },

  /** Scales every vertex about `point` (default: the centroid), in place. */
  scale<T extends MatterVector[]>(vertices: T, scaleX: number, scaleY: number, point?: MatterVector): T {
    if (scaleX === 1 && scaleY === 1) return vertices;
    const o = point ?? Vertices.centre(vertices);
    for (const v of vertices) {
      v.x = o.x + (v.x - o.x) * scaleX;
      v.y = o.y + (v.y - o.y) * scaleY;
    }
    return vertices;
  },

  /**
   * Rounds each corner with an arc of `radius` (one number, or one per corner; default 8) cut into
   * `quality` steps (-1, the default, picks it from the radius, between `qualityMin` 2 and
   * `qualityMax` 14). Returns new points.
   */
  chamfer(
    vertices: readonly MatterVector[],
    radius?: number | readonly number[],
    quality?: number,
    qualityMin?: number,
    qualityMax?: number,
  ): MatterVector[] {
    const radii = typeof radius === 'number' ? [radius] : radius && radius.length > 0 ? radius : [8];
    const n = vertices.length;
    const out: MatterVector[] = [];
    for (let i = 0; i < n; i++) {
      const prev = vertices[(i + n - 1) % n];
      const v = vertices[i];
      const next = vertices[(i + 1) % n];
      const r = radii[Math.min(i, radii.length - 1)];
      if (r === 0) {
        out.push({ x: v.x, y: v.y });
        continue;
      }
      // the arc's centre lies on the corner's bisector, `r` from both edges; it runs from the foot
      // of the centre on the edge in to its foot on the edge out
      const a = Vector.normalise({ x: prev.x - v.x, y: prev.y - v.y });
      const b = Vector.normalise({ x: next.x - v.x, y: next.y - v.y });
      // the corner's angle from its cosine and sine; the half-angle forms keep to + - * / and sqrt
      const cos = Math.max(-1, Math.min(1, a.x * b.x + a.y * b.y));
      const sin = Math.abs(a.x * b.y - a.y * b.x);
      const turn = arcTangent2(sin, cos);
      const reach = (r * (1 + cos)) / sin; // from the corner to each foot: r / tan(turn / 2)
      const bisector = Vector.normalise({ x: a.x + b.x, y: a.y + b.y });
      const toCentre = r / Math.sqrt((1 - cos) / 2); // r / sin(turn / 2)
      const cx = v.x + bisector.x * toCentre;
      const cy = v.y + bisector.y * toCentre;
      const fromX = v.x + a.x * reach - cx;
      const fromY = v.y + a.y * reach - cy;
      const sweep = Math.PI - turn; // the arc turns as far as the outline does at the corner
      const direction = a.x * b.y - a.y * b.x > 0 ? -1 : 1;
      // matter's count of arc points; Math.pow is not bit-exact everywhere, but only a value within a
      // rounding error of an even integer could change the count (the points themselves are exact)
      let steps = quality !== undefined && quality !== -1 ? quality : 1.75 * r ** 0.32;
      steps = Math.min(Math.max(steps, qualityMin || 2), qualityMax || 14);
      steps = Math.ceil(steps / 2) * 2; // even, as matter keeps it
      // the arc's ends are the feet themselves, on the edges exactly; its inner points turned about the centre
      out.push({ x: v.x + a.x * reach, y: v.y + a.y * reach });
      for (let j = 1; j < steps; j++) {
        const { c, s } = makeRot((direction * sweep * j) / steps);
        out.push({ x: cx + fromX * c - fromY * s, y: cy + fromX * s + fromY * c });
      }
      out.push({ x: v.x + b.x * reach, y: v.y + b.y * reach });
    }
    return out;
  },

  /**
   * Sorts the vertices clockwise on a y-down screen about their mean, in place. By the deterministic
   * arcTangent2 (matter's Vector.angle is Math.atan2): a compound body's hull is sorted here, and the
   * world steps its shapes.
   */
  clockwiseSort<T extends MatterVector[]>(vertices: T): T {
    const { x, y } = Vertices.mean(vertices);
    vertices.sort((p, q) => arcTangent2(p.y - y, p.x - x) - arcTangent2(q.y - y, q.x - x));
    return vertices;
  },

  /** true for a convex polygon, false for a concave one, null when it has no area or fewer than 3 points. */
  isConvex(vertices: readonly MatterVector[]): boolean | null {
    const n = vertices.length;
    if (n < 3) return null;
    let left = false;
    let right = false;
    for (let i = 0; i < n; i++) {
      const a = vertices[i];
      const b = vertices[(i + 1) % n];
      const c = vertices[(i + 2) % n];
      const z = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
      if (z < 0) left = true;
      else if (z > 0) right = true;
      if (left && right) return false;
    }
    return left || right ? true : null;
  },

  /** The convex hull of the points, as new points, clockwise on a y-down screen. */
  hull(vertices: readonly MatterVector[]): MatterVector[] {
    const points = [...vertices].sort((p, q) => p.x - q.x || p.y - q.y);
    const chain = (list: MatterVector[]): MatterVector[] => {
      const out: MatterVector[] = [];
      for (const p of list) {
        while (out.length >= 2 && Vector.cross3(out[out.length - 2], out[out.length - 1], p) <= 0) out.pop();
        out.push(p);
      }
      out.pop();
      return out;
    };
    const lower = chain(points);
    const upper = chain(points.reverse());
    return lower.concat(upper).map((p) => ({ x: p.x, y: p.y }));
  },
};
