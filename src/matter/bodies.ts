import { checkSize } from '../core/limits';
import { Shape } from '../geometry/shapes';
import { makeRot } from '../math/rot';
import { Body, type BodyOptions, type MatterBody } from './body';
import { Common } from './common';
import type { MatterVector } from './vector';
import { Vertices } from './vertices';

export type BodiesOptions = Omit<BodyOptions, 'chamfer'> & {
  chamfer?: { radius?: number | number[]; quality?: number; qualityMin?: number; qualityMax?: number };
};

function length(x: number, y: number): number {
  return Math.sqrt(x * x + y * y);
}

/**
 * The corners of the polygon that, rounded by `radius`, is `points` chamfered by `radius` (each arc's
 * centre: on the corner's bisector, `radius` from both edges), about the chamfered outline's centroid;
 * null where an arc would run past the middle of an edge (matter's outline then folds on itself).
 */
function insetCorners(
  points: readonly MatterVector[],
  radius: number,
  centre: MatterVector,
): MatterVector[] | null {
  const n = points.length;
  const corners: MatterVector[] = [];
  for (let i = 0; i < n; i++) {
    const prev = points[(i + n - 1) % n];
    const v = points[i];
    const next = points[(i + 1) % n];
    const inLength = length(prev.x - v.x, prev.y - v.y);
    const outLength = length(next.x - v.x, next.y - v.y);
    const ax = (prev.x - v.x) / inLength;
    const ay = (prev.y - v.y) / inLength;
    const bx = (next.x - v.x) / outLength;
    const by = (next.y - v.y) / outLength;
    const cos = Math.max(-1, Math.min(1, ax * bx + ay * by));
    const sin = Math.abs(ax * by - ay * bx);
    if (sin === 0) return null;
    const reach = (radius * (1 + cos)) / sin;
    if (reach > inLength / 2 + 1e-9 * inLength || reach > outLength / 2 + 1e-9 * outLength) return null;
    const bisectorLength = length(ax + bx, ay + by);
    const toCentre = radius / Math.sqrt((1 - cos) / 2);
    corners.push({
      x: v.x + ((ax + bx) / bisectorLength) * toCentre - centre.x,
      y: v.y + ((ay + by) / bisectorLength) * toCentre - centre.y,
    });
  }
  return corners;
}

function finish(
  options: BodiesOptions | undefined,
  defaults: BodiesOptions,
  points: MatterVector[],
): MatterBody {
  const settings = Common.extend({}, defaults, options) as BodiesOptions;
  let vertices = points;
  const chamfer = settings.chamfer;
  if (chamfer)
    vertices = Vertices.chamfer(
      points,
      chamfer.radius,
      chamfer.quality,
      chamfer.qualityMin,
      chamfer.qualityMax,
    );
  const body = Body.create({
    ...settings,
    vertices,
    chamfer: chamfer ? { radius: chamfer.radius ?? 8 } : null,
  });
  // one chamfer radius on every corner of a convex outline the engine holds as one polygon: it
  // simulates the rounded polygon of exactly that shape (a rounded box, a capsule, a circle) rather
  // than the many-cornered outline matter draws
  const given = chamfer?.radius ?? 8;
  const radius = Array.isArray(given) ? (given.every((r) => r === given[0]) ? given[0] : 0) : given;
  if (chamfer && radius > 0 && points.length <= 8 && Vertices.isConvex(points.slice())) {
    const corners = insetCorners(points, radius, Vertices.centre(vertices));
    if (corners) {
      Object.defineProperty(body, '_rounded', {
        value: { corners, radius },
        writable: true,
        enumerable: false,
        configurable: true,
      });
    }
  }
  return body;
}

/** matter.js's `Bodies`: factories of common bodies, at world positions in pixels. A plain, mutable module object. */
export const Bodies = {
  /** A `width` by `height` rectangle centred on (x, y). */
  rectangle(x: number, y: number, width: number, height: number, options?: BodiesOptions): MatterBody {
    return finish(options, { label: 'Rectangle Body', position: { x, y } }, [
      { x: 0, y: 0 },
      { x: width, y: 0 },
      { x: width, y: height },
      { x: 0, y: height },
    ]);
  },

  /** A trapezoid `width` wide at its base, its top `slope` times narrower on each side. */
  trapezoid(
    x: number,
    y: number,
    width: number,
    height: number,
    slope: number,
    options?: BodiesOptions,
  ): MatterBody {
    const top = slope * width * 0.5;
    const points =
      slope < 1
        ? [
            { x: 0, y: 0 },
            { x: top, y: -height },
            { x: width - top, y: -height },
            { x: width, y: 0 },
          ]
        : [
            { x: 0, y: 0 },
            { x: width / 2, y: -height },
            { x: width, y: 0 },
          ];
    return finish(options, { label: 'Trapezoid Body', position: { x, y } }, points);
  },

  /**
   * A circle of `radius` centred on (x, y). It collides as a true circle in Fulcrum; its `vertices`
   * are a polygon of up to `maxSides` (default 25) sides, as matter draws and queries it.
   */
  circle(x: number, y: number, radius: number, options?: BodiesOptions, maxSides = 25): MatterBody {
    checkSize('radius', radius);
    const sides = Math.ceil(Math.max(10, Math.min(maxSides, radius)));
    const body = Bodies.polygon(x, y, sides % 2 === 1 ? sides + 1 : sides, radius, {
      label: 'Circle Body',
      ...options,
      circleRadius: radius,
    });
    return body;
  },

  /** A regular polygon of `sides` sides (3 or more) inscribed in a circle of `radius`, centred on (x, y). */
  polygon(x: number, y: number, sides: number, radius: number, options?: BodiesOptions): MatterBody {
    if (sides < 3) return Bodies.circle(x, y, radius, options);
    const step = (2 * Math.PI) / sides;
    const points: MatterVector[] = [];
    for (let i = 0; i < sides; i++) {
      const a = step * 0.5 + step * i;
      // to 0.001 px, as matter writes them (through a path string): the same vertices, the same centre
      const { c, s } = makeRot(a);
      points.push({ x: Number((radius * c).toFixed(3)), y: Number((radius * s).toFixed(3)) });
    }
    return finish(options, { label: 'Polygon Body', position: { x, y } }, points);
  },

  /**
   * A body from one outline or several (`vertexSets`), centred on (x, y). A concave outline is split
   * into convex parts by the engine itself (no poly-decomp needed): the result is a compound body
   * whose parts are the pieces, as matter.js builds it.
   */
  fromVertices(
    x: number,
    y: number,
    vertexSets: MatterVector[] | MatterVector[][],
    options?: BodiesOptions,
  ): MatterBody {
    const sets = (Array.isArray(vertexSets[0]) ? vertexSets : [vertexSets]) as MatterVector[][];
    const { chamfer: _chamfer, ...settings } = options ?? {};
    const parts: MatterBody[] = [];
    for (const set of sets) {
      const points = set.map((p) => ({ x: p.x, y: p.y }));
      if (Vertices.isConvex(points) || Vertices.isConvex(points.slice().reverse())) {
        parts.push(Body.create({ ...settings, vertices: points, position: Vertices.centre(points) }));
        continue;
      }
      for (const piece of Shape.decompose(points)) {
        const vertices = piece.vertices.map((v) => ({ x: v.x, y: v.y }));
        parts.push(Body.create({ ...settings, vertices, position: Vertices.centre(vertices) }));
      }
    }
    const body = parts.length === 1 ? parts[0] : Body.create({ ...settings, parts });
    Body.setPosition(body, { x, y });
    return body;
  },
};
