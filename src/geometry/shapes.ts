import { fail } from '../core/errors';
import { checkAngle, checkCoordinates, checkRange, checkSize, Limits } from '../core/limits';
import { makeRot } from '../math/rot';
import type { Vec2 } from '../math/vec2';
import { LINEAR_SLOP } from './constants';
import { decomposeOutline } from './decompose';
import { computeHull } from './hull';
import {
  type Capsule,
  type Chain,
  type Circle,
  type Concave,
  MAX_CHAIN_POINTS,
  type Polygon,
  type Segment,
  ShapeKind,
} from './types';

function frozenPoint(x: number, y: number): Vec2 {
  return Object.freeze({ x, y });
}

function optionalPoint(argument: string, value: unknown): Vec2 {
  return value === undefined ? frozenPoint(0, 0) : Object.freeze(checkCoordinates(argument, value));
}

/** Builds the frozen polygon from counter-clockwise hull vertices: edge normals and area centroid. */
function makePolygon(vertices: readonly Vec2[], radius: number, centroid?: Vec2): Polygon {
  const count = vertices.length;
  const normals: Vec2[] = [];
  for (let i = 0; i < count; i++) {
    const a = vertices[i];
    const b = vertices[i + 1 === count ? 0 : i + 1];
    const ex = b.x - a.x;
    const ey = b.y - a.y;
    const len = Math.sqrt(ex * ex + ey * ey);
    normals.push(frozenPoint(ey / len, -ex / len));
  }
  return Object.freeze({
    type: 'polygon',
    kind: ShapeKind.POLYGON,
    count,
    vertices: Object.freeze(vertices.map((v) => frozenPoint(v.x, v.y))),
    normals: Object.freeze(normals),
    centroid: centroid ?? areaCentroid(vertices),
    radius,
  });
}

/** Area centroid of a counter-clockwise polygon, summed relative to its first vertex for precision. */
function areaCentroid(vertices: readonly Vec2[]): Vec2 {
  const o = vertices[0];
  let area = 0;
  let cx = 0;
  let cy = 0;
  for (let i = 1; i + 1 < vertices.length; i++) {
    const ax = vertices[i].x - o.x;
    const ay = vertices[i].y - o.y;
    const bx = vertices[i + 1].x - o.x;
    const by = vertices[i + 1].y - o.y;
    const triangleArea = 0.5 * (ax * by - ay * bx);
    area += triangleArea;
    cx += (triangleArea * (ax + bx)) / 3;
    cy += (triangleArea * (ay + by)) / 3;
  }
  return frozenPoint(o.x + cx / area, o.y + cy / area);
}

/** The points of an outline, each checked: by index, not map(), which skips the holes of a sparse array. */
function checkPoints(points: readonly Vec2[]): Vec2[] {
  if (!Array.isArray(points)) fail('points', points, 'an array of at least 3 vectors { x, y }');
  const checked: Vec2[] = [];
  for (let i = 0; i < points.length; i++) checked.push(checkCoordinates(`points[${i}]`, points[i]));
  return checked;
}

function checkApart(p1: Vec2, p2: Vec2, value: unknown): void {
  const dx = p2.x - p1.x;
  const dy = p2.y - p1.y;
  if (dx * dx + dy * dy < LINEAR_SLOP * LINEAR_SLOP) {
    fail('p2', value, `at least ${LINEAR_SLOP} m away from p1 (${p1.x}, ${p1.y})`);
  }
}

/**
 * One frozen segment of a chain: point1 to point2 (checked like Shape.segment's ends), with the
 * neighbours before and after it (null at an open end).
 */
export function makeChainSegment(
  point1: Vec2,
  point2: Vec2,
  ghost1: Vec2 | null,
  ghost2: Vec2 | null,
): Segment {
  const a = checkCoordinates('p1', point1);
  const b = checkCoordinates('p2', point2);
  checkApart(a, b, point2);
  const g1 = ghost1 === null ? null : checkCoordinates('ghost1', ghost1);
  const g2 = ghost2 === null ? null : checkCoordinates('ghost2', ghost2);
  if (g1 !== null) checkApart(g1, a, point1);
  if (g2 !== null) checkApart(b, g2, ghost2);
  return Object.freeze({
    type: 'segment',
    kind: ShapeKind.SEGMENT,
    point1: Object.freeze(a),
    point2: Object.freeze(b),
    oneSided: true,
    ghost1: g1 === null ? null : Object.freeze(g1),
    ghost2: g2 === null ? null : Object.freeze(g2),
  });
}

/** Factories of immutable geometry in a body's local frame. Every argument is validated. */
export const Shape = Object.freeze({
  circle(radius: number, center?: Vec2): Circle {
    checkSize('radius', radius);
    return Object.freeze({
      type: 'circle',
      kind: ShapeKind.CIRCLE,
      center: optionalPoint('center', center),
      radius,
    });
  },

  /** A rectangle with half extents, centred on `center`, rotated by `angle` radians. */
  box(halfWidth: number, halfHeight: number, center?: Vec2, angle?: number): Polygon {
    checkSize('halfWidth', halfWidth);
    checkSize('halfHeight', halfHeight);
    const c = optionalPoint('center', center);
    const q = makeRot(angle === undefined ? 0 : checkAngle('angle', angle));
    const corners = [
      [-halfWidth, -halfHeight],
      [halfWidth, -halfHeight],
      [halfWidth, halfHeight],
      [-halfWidth, halfHeight],
    ];
    const vertices = corners.map(([x, y]) => ({ x: c.x + q.c * x - q.s * y, y: c.y + q.s * x + q.c * y }));
    return makePolygon(vertices, 0, c);
  },

  /**
   * A convex polygon through `points` (in any order, up to 8 corners); `radius` rounds the corners (the
   * surface is the polygon inflated by radius). Repeated points and points within 0.005 m of the line
   * of their neighbours are dropped. A point farther inside is refused with a FulcrumError: the outline
   * is concave, and `Shape.concave` is the shape for it.
   */
  polygon(points: readonly Vec2[], radius?: number): Polygon {
    const r = radius === undefined ? 0 : checkRange('radius', radius, 0, Limits.COORDINATE);
    return makePolygon(computeHull(checkPoints(points), 'points'), r);
  },

  /**
   * Splits a simple outline (any winding, 3 to 1024 points, no edge crossing or touching another) into
   * convex polygons of at most 8 vertices that do not overlap and whose union is the outline. The
   * outline is cleaned first: points within 0.005 m of the point before and points within 0.005 m of
   * the line of their neighbours are dropped. A self-intersecting or degenerate outline throws a
   * FulcrumError that names the points at fault.
   */
  decompose(points: readonly Vec2[]): Polygon[] {
    const { pieces } = decomposeOutline(checkPoints(points), 'points');
    return pieces.map((piece) => makePolygon(piece, 0));
  },

  /**
   * A concave shape: the outline and its convex pieces (see `decompose`). `body.createShape(concave,
   * def)` attaches every piece with `def` and returns their handles; the body's mass, centre of mass
   * and inertia are then the outline's.
   */
  concave(points: readonly Vec2[]): Concave {
    const { outline, pieces } = decomposeOutline(checkPoints(points), 'points');
    return Object.freeze({
      type: 'concave',
      outline: Object.freeze(outline.map((p) => frozenPoint(p.x, p.y))),
      pieces: Object.freeze(pieces.map((piece) => makePolygon(piece, 0))),
    });
  },

  /** The set of points within `radius` of the segment p1-p2. */
  capsule(p1: Vec2, p2: Vec2, radius: number): Capsule {
    const a = checkCoordinates('p1', p1);
    const b = checkCoordinates('p2', p2);
    checkSize('radius', radius);
    checkApart(a, b, p2);
    return Object.freeze({
      type: 'capsule',
      kind: ShapeKind.CAPSULE,
      center1: Object.freeze(a),
      center2: Object.freeze(b),
      radius,
    });
  },

  /** A two-sided segment without thickness (static or kinematic bodies only). */
  segment(p1: Vec2, p2: Vec2): Segment {
    const a = checkCoordinates('p1', p1);
    const b = checkCoordinates('p2', p2);
    checkApart(a, b, p2);
    return Object.freeze({
      type: 'segment',
      kind: ShapeKind.SEGMENT,
      point1: Object.freeze(a),
      point2: Object.freeze(b),
      oneSided: false,
      ghost1: null,
      ghost2: null,
    });
  },

  /**
   * A chain of one-sided segments through `points` (2 to 65,536 of them, 3 or more for a loop, each
   * at least 0.005 m from the one before), closed from the last point back to the first when `loop`
   * is true. The segments face right of the way the points run (a counter-clockwise loop is solid
   * inside, like a polygon; ground drawn right to left, y up, is walked on from above), shapes on
   * their back side pass through them (one-way platforms), and bodies slide and roll over the seams
   * between them as over one surface. `body.createShape(chain, def)` attaches one shape per segment
   * to a static or kinematic body and returns their handles.
   */
  chain(points: readonly Vec2[], options?: { loop?: boolean }): Chain {
    if (options !== undefined && (typeof options !== 'object' || options === null)) {
      fail('options', options, 'an object { loop?: boolean } or undefined');
    }
    const loop = options?.loop ?? false;
    if (typeof loop !== 'boolean') fail('options.loop', loop, 'a boolean');
    const least = loop ? 3 : 2;
    if (!Array.isArray(points) || points.length < least || points.length > MAX_CHAIN_POINTS) {
      fail(
        'points',
        points,
        `an array of ${least} to ${MAX_CHAIN_POINTS} vectors { x, y }${loop ? ' (a loop)' : ''}`,
      );
    }
    const p = checkPoints(points).map((v) => frozenPoint(v.x, v.y));
    const n = p.length;
    const links = loop ? n : n - 1;
    for (let i = 0; i < links; i++) {
      const a = p[i];
      const b = p[(i + 1) % n];
      const dx = b.x - a.x;
      const dy = b.y - a.y;
      if (dx * dx + dy * dy < LINEAR_SLOP * LINEAR_SLOP) {
        fail(
          `points[${(i + 1) % n}]`,
          b,
          `at least ${LINEAR_SLOP} m away from points[${i}] (${a.x}, ${a.y})`,
        );
      }
    }
    const segments: Segment[] = [];
    for (let i = 0; i < links; i++) {
      const before = loop || i > 0 ? p[(i - 1 + n) % n] : null;
      const after = loop || i + 2 < n ? p[(i + 2) % n] : null;
      segments.push(makeChainSegment(p[i], p[(i + 1) % n], before, after));
    }
    return Object.freeze({
      type: 'chain',
      points: Object.freeze(p),
      loop,
      segments: Object.freeze(segments),
    });
  },
});
