import type { MatterBody } from './body';
import { Bounds, type MatterBounds } from './bounds';
import type { MatterVector } from './vector';
import { Vertices } from './vertices';

/** A record of `Query.ray` and `Query.collides`: which body (part) the query met. */
export interface MatterQueryCollision {
  collided: boolean;
  bodyA: MatterBody;
  bodyB: MatterBody;
  parentA: MatterBody;
  parentB: MatterBody;
}

/** Whether the segment p-q crosses or touches the convex polygon `vertices` (or lies inside it). */
function segmentMeetsPolygon(p: MatterVector, q: MatterVector, vertices: readonly MatterVector[]): boolean {
  if (Vertices.contains(vertices, p) || Vertices.contains(vertices, q)) return true;
  const n = vertices.length;
  for (let i = 0; i < n; i++) {
    const a = vertices[i];
    const b = vertices[(i + 1) % n];
    const d1 = (q.x - p.x) * (a.y - p.y) - (q.y - p.y) * (a.x - p.x);
    const d2 = (q.x - p.x) * (b.y - p.y) - (q.y - p.y) * (b.x - p.x);
    const d3 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    const d4 = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
    if (d1 * d2 <= 0 && d3 * d4 <= 0) return true;
  }
  return false;
}

/** Whether two convex polygons overlap (separating axes of both). */
function polygonsOverlap(a: readonly MatterVector[], b: readonly MatterVector[]): boolean {
  for (const [p, q] of [
    [a, b],
    [b, a],
  ]) {
    for (let i = 0; i < p.length; i++) {
      const u = p[i];
      const v = p[(i + 1) % p.length];
      const nx = v.y - u.y;
      const ny = u.x - v.x;
      let minP = Number.POSITIVE_INFINITY;
      let maxP = Number.NEGATIVE_INFINITY;
      for (const w of p) {
        const d = w.x * nx + w.y * ny;
        minP = Math.min(minP, d);
        maxP = Math.max(maxP, d);
      }
      let minQ = Number.POSITIVE_INFINITY;
      let maxQ = Number.NEGATIVE_INFINITY;
      for (const w of q) {
        const d = w.x * nx + w.y * ny;
        minQ = Math.min(minQ, d);
        maxQ = Math.max(maxQ, d);
      }
      if (maxP < minQ || maxQ < minP) return false;
    }
  }
  return true;
}

/** The parts of `body` that stand for it in a query: its parts, or itself when it has none. */
function partsOf(body: MatterBody): MatterBody[] {
  return body.parts.length > 1 ? body.parts.slice(1) : [body];
}

/** matter.js's `Query`, on bodies' current vertices. A plain, mutable module object. */
export const Query = {
  /** The collisions of `body` with each of `bodies` it overlaps (one record per body). */
  collides(body: MatterBody, bodies: readonly MatterBody[]): MatterQueryCollision[] {
    const out: MatterQueryCollision[] = [];
    for (const other of bodies) {
      if (other === body || !Bounds.overlaps(other.bounds, body.bounds)) continue;
      search: for (const a of partsOf(other)) {
        for (const b of partsOf(body)) {
          if (Bounds.overlaps(a.bounds, b.bounds) && polygonsOverlap(a.vertices, b.vertices)) {
            out.push({ collided: true, bodyA: a, bodyB: b, parentA: other, parentB: body });
            break search;
          }
        }
      }
    }
    return out;
  },

  /**
   * The bodies a ray from `start` to `end` meets, `rayWidth` wide (default 1e-100: a line), one
   * record per body with the part it met as `bodyA` (and `bodyB`).
   */
  ray(
    bodies: readonly MatterBody[],
    start: MatterVector,
    end: MatterVector,
    rayWidth = 1e-100,
  ): MatterQueryCollision[] {
    const out: MatterQueryCollision[] = [];
    const dx = end.x - start.x;
    const dy = end.y - start.y;
    const length = Math.sqrt(dx * dx + dy * dy) || 1;
    const half = rayWidth / 2;
    const nx = (-dy / length) * half;
    const ny = (dx / length) * half;
    const band = [
      { x: start.x - nx, y: start.y - ny },
      { x: end.x - nx, y: end.y - ny },
      { x: end.x + nx, y: end.y + ny },
      { x: start.x + nx, y: start.y + ny },
    ];
    const wide = rayWidth > 1e-9;
    const bandBounds = Bounds.create(band);
    for (const body of bodies) {
      if (!Bounds.overlaps(body.bounds, bandBounds)) continue;
      for (const part of partsOf(body)) {
        if (!Bounds.overlaps(part.bounds, bandBounds)) continue;
        const hit = wide
          ? polygonsOverlap(band, part.vertices)
          : segmentMeetsPolygon(start, end, part.vertices);
        if (hit) {
          out.push({ collided: true, bodyA: part, bodyB: part, parentA: body, parentB: body });
          break;
        }
      }
    }
    return out;
  },

  /** The bodies whose bounds overlap `bounds` (or, with `outside`, do not). */
  region(bodies: readonly MatterBody[], bounds: MatterBounds, outside = false): MatterBody[] {
    return bodies.filter((body) => Bounds.overlaps(body.bounds, bounds) !== outside);
  },

  /** The bodies with a part that contains `point`. */
  point(bodies: readonly MatterBody[], point: MatterVector): MatterBody[] {
    return bodies.filter(
      (body) =>
        Bounds.contains(body.bounds, point) &&
        partsOf(body).some(
          (part) => Bounds.contains(part.bounds, point) && Vertices.contains(part.vertices, point),
        ),
    );
  },
};
