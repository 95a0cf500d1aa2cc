import { Limits } from '../core/limits';
import type { Vec2 } from '../math/vec2';
import { LINEAR_SLOP } from './constants';

/** Largest vertex count of a convex polygon. */
export const MAX_POLYGON_VERTICES = 8;

/**
 * The most points of an outline that Shape.decompose and Shape.concave split: checking that it is
 * simple and triangulating it take time quadratic in the count (1.4 ms for a 1024-point gear, 7 ms
 * for a 1024-point star of 512 spikes).
 */
export const MAX_OUTLINE_POINTS = 1024;

/** The most points of a chain (`Shape.chain`): a chain is one shape per link. */
export const MAX_CHAIN_POINTS = 65536;

/** Numeric shape kinds, used for dispatch inside the engine. The public API shows the string `type`. */
export enum ShapeKind {
  CIRCLE = 0,
  CAPSULE = 1,
  SEGMENT = 2,
  POLYGON = 3,
}

/** All geometry is in the body's local frame (metres), immutable once built by `Shape.*`. */
export interface Circle {
  readonly type: 'circle';
  readonly kind: ShapeKind.CIRCLE;
  readonly center: Vec2;
  readonly radius: number;
}

export interface Capsule {
  readonly type: 'capsule';
  readonly kind: ShapeKind.CAPSULE;
  readonly center1: Vec2;
  readonly center2: Vec2;
  readonly radius: number;
}

/**
 * A segment with no thickness; only on static or kinematic bodies. `Shape.segment` makes it
 * two-sided. The segments of a chain (`Shape.chain`) are one-sided: they collide only with shapes
 * whose centre is on their front side, to the right of the way from point1 to point2, and they know
 * their neighbours (`ghost1` before point1, `ghost2` after point2, null at an open chain's ends) so
 * that a body sliding or rolling over the seam between two of them meets one surface.
 */
export interface Segment {
  readonly type: 'segment';
  readonly kind: ShapeKind.SEGMENT;
  readonly point1: Vec2;
  readonly point2: Vec2;
  readonly oneSided: boolean;
  readonly ghost1: Vec2 | null;
  readonly ghost2: Vec2 | null;
}

/**
 * Convex polygon, counter-clockwise, no three collinear vertices, 3..8 vertices.
 * `radius` > 0 rounds it (the surface is the core polygon inflated by radius).
 */
export interface Polygon {
  readonly type: 'polygon';
  readonly kind: ShapeKind.POLYGON;
  readonly count: number;
  readonly vertices: readonly Vec2[];
  /** outward unit normal of edge i (from vertex i to vertex i+1) */
  readonly normals: readonly Vec2[];
  readonly centroid: Vec2;
  readonly radius: number;
}

export type Geometry = Circle | Capsule | Segment | Polygon;

/**
 * A simple outline split into convex polygons by `Shape.concave`. It is not a `Geometry`: a body takes
 * it whole, `body.createShape(concave, def)` making one shape per piece (all with `def`) and returning
 * their handles. The pieces do not overlap and their union is the outline, so the body's mass, centre
 * of mass and inertia are the outline's.
 */
export interface Concave {
  readonly type: 'concave';
  /** the outline as cleaned: repeated and collinear points dropped, counter-clockwise */
  readonly outline: readonly Vec2[];
  /** convex pieces, each with 3 to MAX_POLYGON_VERTICES vertices, all of them points of `outline` */
  readonly pieces: readonly Polygon[];
}

/**
 * A chain of one-sided segments through `points` (`Shape.chain`), closed into a loop or open. It is
 * not a `Geometry`: a static or kinematic body takes it whole, `body.createShape(chain, def)` making
 * one shape per segment (all with `def`) and returning their handles in order. The segments face
 * right of the way the points run: a counter-clockwise loop is solid inside, like a polygon, and
 * ground drawn from right to left (y up) is collided from above.
 */
export interface Chain {
  readonly type: 'chain';
  readonly points: readonly Vec2[];
  readonly loop: boolean;
  readonly segments: readonly Segment[];
}

/** Mass properties of one shape: inertia is about the shape's own centre of mass. */
export interface MassData {
  mass: number;
  centerX: number;
  centerY: number;
  /** rotational inertia about (centerX, centerY) */
  inertia: number;
}

/**
 * One contact point. The point is in world coordinates, halfway between the two surfaces.
 * `separation` < 0 means overlap. `id` names the features that made the point so that the
 * solver can warm start it next step: same features, same id.
 */
export interface ManifoldPoint {
  x: number;
  y: number;
  separation: number;
  id: number;
}

/** Contact manifold between shape A and shape B: the normal is a world unit vector from A to B. */
export interface Manifold {
  normalX: number;
  normalY: number;
  pointCount: number;
  readonly points: [ManifoldPoint, ManifoldPoint];
}

export function makeManifold(): Manifold {
  return {
    normalX: 0,
    normalY: 0,
    pointCount: 0,
    points: [
      { x: 0, y: 0, separation: 0, id: 0 },
      { x: 0, y: 0, separation: 0, id: 0 },
    ],
  };
}

/** Result of a ray cast: world or local depending on the caller's frame. */
export interface RayHit {
  /** fraction of the translation at which the ray hits, in [0, 1] */
  fraction: number;
  pointX: number;
  pointY: number;
  normalX: number;
  normalY: number;
}

export function makeRayHit(): RayHit {
  return { fraction: 0, pointX: 0, pointY: 0, normalX: 0, normalY: 0 };
}

const KIND_OF_TYPE: Readonly<Record<string, number>> = Object.freeze({
  circle: ShapeKind.CIRCLE,
  capsule: ShapeKind.CAPSULE,
  segment: ShapeKind.SEGMENT,
  polygon: ShapeKind.POLYGON,
});

/** How far from the body's origin a vertex of Shape's may lie: a box of the largest size and offset, turned. */
const VERTEX_BOUND = 4 * Limits.COORDINATE;

function isFinitePoint(p: unknown): boolean {
  if (typeof p !== 'object' || p === null) return false;
  const v = p as { x?: unknown; y?: unknown };
  return (
    typeof v.x === 'number' &&
    typeof v.y === 'number' &&
    Math.abs(v.x) <= VERTEX_BOUND &&
    Math.abs(v.y) <= VERTEX_BOUND
  );
}

/** Points at least LINEAR_SLOP apart, as Shape.segment and Shape.chain require of a segment's ends. */
function areApart(a: Vec2, b: Vec2): boolean {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  return dx * dx + dy * dy >= LINEAR_SLOP * LINEAR_SLOP;
}

function isPointList(list: unknown, count: number): boolean {
  return Array.isArray(list) && list.length === count && list.every(isFinitePoint);
}

function isUnitList(list: unknown, count: number): boolean {
  return (
    isPointList(list, count) && (list as Vec2[]).every((n) => Math.abs(n.x * n.x + n.y * n.y - 1) <= 1e-9)
  );
}

function isLength(value: unknown, min: number): boolean {
  return typeof value === 'number' && value >= min && value <= Limits.COORDINATE;
}

/**
 * True for a concave shape as `Shape.concave` builds it: frozen, with a frozen outline of points and a
 * frozen list of polygon pieces that each pass isGeometry.
 */
export function isConcave(value: unknown): value is Concave {
  if (typeof value !== 'object' || value === null || !Object.isFrozen(value)) return false;
  const g = value as Record<string, unknown>;
  const outline = g.outline;
  const pieces = g.pieces;
  return (
    g.type === 'concave' &&
    Array.isArray(outline) &&
    Object.isFrozen(outline) &&
    outline.length >= 3 &&
    outline.length <= MAX_OUTLINE_POINTS &&
    isPointList(outline, outline.length) &&
    Array.isArray(pieces) &&
    Object.isFrozen(pieces) &&
    pieces.length >= 1 &&
    pieces.length <= outline.length - 2 &&
    pieces.every((piece) => isGeometry(piece) && piece.kind === ShapeKind.POLYGON)
  );
}

/**
 * True for a chain as `Shape.chain` builds it: frozen, with a frozen list of points and a frozen list of
 * one-sided segments that each pass isGeometry, as many as the chain has links.
 */
export function isChain(value: unknown): value is Chain {
  if (typeof value !== 'object' || value === null || !Object.isFrozen(value)) return false;
  const g = value as Record<string, unknown>;
  const points = g.points;
  const segments = g.segments;
  if (g.type !== 'chain' || typeof g.loop !== 'boolean' || !Array.isArray(points) || !Array.isArray(segments))
    return false;
  const links = g.loop ? points.length : points.length - 1;
  return (
    Object.isFrozen(points) &&
    Object.isFrozen(segments) &&
    points.length >= (g.loop ? 3 : 2) &&
    points.length <= MAX_CHAIN_POINTS &&
    segments.length === links &&
    segments.every((segment) => isGeometry(segment) && segment.kind === ShapeKind.SEGMENT && segment.oneSided)
  );
}

/**
 * True for geometry as `Shape.*` builds it: frozen, with a matching type and kind, coordinates and
 * sizes in the ranges Shape accepts (core/limits.ts), unit normals and at most MAX_POLYGON_VERTICES
 * vertices. The shape store packs it into a fixed-size record, so a
 * hand-made object that passed on type alone could write past it or bring NaN into the world.
 */
export function isGeometry(value: unknown): value is Geometry {
  if (typeof value !== 'object' || value === null || !Object.isFrozen(value)) return false;
  const g = value as Record<string, unknown>;
  if (typeof g.type !== 'string' || KIND_OF_TYPE[g.type] !== g.kind) return false;
  switch (g.kind) {
    case ShapeKind.CIRCLE:
      return isFinitePoint(g.center) && isLength(g.radius, Limits.MIN_SIZE);
    case ShapeKind.CAPSULE:
      return isFinitePoint(g.center1) && isFinitePoint(g.center2) && isLength(g.radius, Limits.MIN_SIZE);
    case ShapeKind.SEGMENT:
      return (
        isFinitePoint(g.point1) &&
        isFinitePoint(g.point2) &&
        areApart(g.point1 as Vec2, g.point2 as Vec2) &&
        typeof g.oneSided === 'boolean' &&
        (g.ghost1 === null ||
          (g.oneSided === true && isFinitePoint(g.ghost1) && areApart(g.ghost1 as Vec2, g.point1 as Vec2))) &&
        (g.ghost2 === null ||
          (g.oneSided === true && isFinitePoint(g.ghost2) && areApart(g.point2 as Vec2, g.ghost2 as Vec2)))
      );
    default: {
      const count = g.count;
      return (
        typeof count === 'number' &&
        Number.isInteger(count) &&
        count >= 3 &&
        count <= MAX_POLYGON_VERTICES &&
        isPointList(g.vertices, count) &&
        isUnitList(g.normals, count) &&
        isFinitePoint(g.centroid) &&
        isLength(g.radius, 0)
      );
    }
  }
}
