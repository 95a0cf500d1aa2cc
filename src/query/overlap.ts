import type { ShapeHandle } from '../api/shape';
import type { World } from '../api/world';
import type { IntList } from '../broad-phase/int-list';
import { checkKnownKeys, FulcrumError, fail } from '../core/errors';
import { computeShapeBounds } from '../geometry/bounds';
import { shapeDistance } from '../geometry/distance';
import { testPoint } from '../geometry/raycast';
import { makeProxy } from '../geometry/shape-proxy';
import type { AABB } from '../math/aabb';
import { checkGeometry, checkPoint, resolveTransform } from './args';
import { passesQueryFilter, resolveQueryFilter } from './filter';

/*
 * Overlap queries over the broad-phase trees (static, kinematic and dynamic, sleeping bodies
 * included). Results are shape handles sorted by shape slot. Sensors are reported unless
 * filter.includeSensors is false.
 */

const ALL_TREES = 7;
const AABB_KEYS = ['lowerBound', 'upperBound'] as const;

/** Handles of the selected slots, ascending. */
function handles(world: World, selected: IntList): ShapeHandle[] {
  selected.sort();
  const result: ShapeHandle[] = new Array(selected.length);
  for (let i = 0; i < selected.length; i++) result[i] = world.handles.shapes[selected.data[i]]!;
  return result;
}

/** Shapes whose tight AABB (as `shape.getAABB()` reports it) overlaps or touches the box. */
export function queryAABB(world: World, aabb: unknown, queryFilter?: unknown): ShapeHandle[] {
  if (typeof aabb !== 'object' || aabb === null) fail('aabb', aabb, 'an object { lowerBound, upperBound }');
  checkKnownKeys('aabb', aabb, AABB_KEYS);
  const box = aabb as AABB;
  const lower = checkPoint('aabb.lowerBound', box.lowerBound);
  const upper = checkPoint('aabb.upperBound', box.upperBound);
  const minX = lower.x;
  const minY = lower.y;
  const maxX = upper.x;
  const maxY = upper.y;
  if (minX > maxX || minY > maxY) {
    throw new FulcrumError(
      `aabb.upperBound must not be below aabb.lowerBound, got lowerBound { x: ${minX}, y: ${minY} } and upperBound { x: ${maxX}, y: ${maxY} }`,
    );
  }
  const core = world.core;
  const { filter, found, selected } = world.handles.queryMemory;
  resolveQueryFilter(queryFilter, true, filter);
  const shapes = core.shapes;
  found.clear();
  selected.clear();
  core.broadPhase.query(minX, minY, maxX, maxY, ALL_TREES, found);
  for (let i = 0; i < found.length; i++) {
    const s = found.data[i];
    if (!passesQueryFilter(shapes, s, filter)) continue;
    // the trees hold fat boxes: keep the shapes whose tight box overlaps
    if (shapes.minX[s] > maxX || shapes.minY[s] > maxY || shapes.maxX[s] < minX || shapes.maxY[s] < minY)
      continue;
    selected.push(s);
  }
  return handles(world, selected);
}

/** Shapes that contain the point (inside or on the surface; segments contain nothing). */
export function queryPoint(world: World, point: unknown, queryFilter?: unknown): ShapeHandle[] {
  const p = checkPoint('point', point);
  const x = p.x;
  const y = p.y;
  const core = world.core;
  const { filter, found, selected, xf } = world.handles.queryMemory;
  resolveQueryFilter(queryFilter, true, filter);
  const shapes = core.shapes;
  found.clear();
  selected.clear();
  core.broadPhase.query(x, y, x, y, ALL_TREES, found);
  for (let i = 0; i < found.length; i++) {
    const s = found.data[i];
    if (!passesQueryFilter(shapes, s, filter)) continue;
    if (testPoint(shapes.geometry[s]!, core.fillTransform(shapes.body[s], xf), x, y)) selected.push(s);
  }
  return handles(world, selected);
}

/** Shapes whose surface overlaps or touches `geometry` placed at `transform`. */
export function overlapShape(
  world: World,
  geometry: unknown,
  transform: unknown,
  queryFilter?: unknown,
): ShapeHandle[] {
  const core = world.core;
  const m = world.handles.queryMemory;
  const { filter, found, selected, xf, queryXf, bounds, proxyA, proxyB, distance } = m;
  const g = checkGeometry('geometry', geometry);
  resolveTransform('transform', transform, queryXf);
  resolveQueryFilter(queryFilter, true, filter);
  const shapes = core.shapes;
  computeShapeBounds(g, queryXf, bounds, m.packed);
  found.clear();
  selected.clear();
  core.broadPhase.query(bounds.minX, bounds.minY, bounds.maxX, bounds.maxY, ALL_TREES, found);
  makeProxy(g, proxyB);
  for (let i = 0; i < found.length; i++) {
    const s = found.data[i];
    if (!passesQueryFilter(shapes, s, filter)) continue;
    makeProxy(shapes.geometry[s]!, proxyA);
    shapeDistance(m.gjk, proxyA, core.fillTransform(shapes.body[s], xf), proxyB, queryXf, false, distance);
    if (distance.distance <= proxyA.radius + proxyB.radius) selected.push(s);
  }
  return handles(world, selected);
}
