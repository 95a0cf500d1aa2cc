import type { World } from '../api/world';
import { computeShapeBounds } from '../geometry/bounds';
import { frontOffsetAt, isOneSided, Pack } from '../geometry/packed';
import { shapeCast } from '../geometry/shape-cast';
import { makeProxy } from '../geometry/shape-proxy';
import { checkGeometry, checkPoint, resolveTransform } from './args';
import { passesQueryFilter, resolveQueryFilter } from './filter';
import { type CastHit, makeCastHit } from './hit';

const ALL_TREES = 7;

/**
 * Moves `geometry` from `transform` along `translation` (no rotation) and returns the first shape it
 * touches: fraction of the translation, contact point on the hit shape and that shape's outward
 * normal. A shape that already overlaps or touches at the start is hit at fraction 0 with normal
 * (0, 0). Sensors are skipped unless filter.includeSensors; ties go to the smaller shape slot.
 * Candidates come from the box swept by the shape, so very long diagonal casts test more shapes.
 */
export function castShape(
  world: World,
  geometry: unknown,
  transform: unknown,
  translation: unknown,
  queryFilter?: unknown,
): CastHit | null {
  const core = world.core;
  const m = world.handles.queryMemory;
  const input = m.castInput;
  const output = m.castOutput;
  const filter = m.filter;
  const found = m.found;
  const bounds = m.bounds;
  const g = checkGeometry('geometry', geometry);
  resolveTransform('transform', transform, input.transformB);
  const t = checkPoint('translation', translation);
  const tx = t.x;
  const ty = t.y;
  resolveQueryFilter(queryFilter, false, filter);
  const shapes = core.shapes;
  computeShapeBounds(g, input.transformB, bounds, m.packed);
  found.clear();
  core.broadPhase.query(
    bounds.minX + Math.min(tx, 0),
    bounds.minY + Math.min(ty, 0),
    bounds.maxX + Math.max(tx, 0),
    bounds.maxY + Math.max(ty, 0),
    ALL_TREES,
    found,
  );
  makeProxy(g, input.proxyB);
  // the cast shape's centre (the mean of its points): a chain's segment it starts behind lets it pass
  const proxy = input.proxyB;
  let lx = 0;
  let ly = 0;
  for (let i = 0; i < proxy.count; i++) {
    lx += proxy.x[i] / proxy.count;
    ly += proxy.y[i] / proxy.count;
  }
  const xfB = input.transformB;
  const centreX = xfB.p.x + xfB.q.c * lx - xfB.q.s * ly;
  const centreY = xfB.p.y + xfB.q.s * lx + xfB.q.c * ly;
  input.translationX = tx;
  input.translationY = ty;
  let best = -1;
  let fraction = 1;
  let px = 0;
  let py = 0;
  let nx = 0;
  let ny = 0;
  for (let i = 0; i < found.length; i++) {
    const s = found.data[i];
    if (!passesQueryFilter(shapes, s, filter)) continue;
    core.fillTransform(shapes.body[s], input.transformA);
    const base = s * Pack.STRIDE;
    if (
      isOneSided(shapes.kind[s], shapes.packed, base) &&
      frontOffsetAt(shapes.packed, base, input.transformA, centreX, centreY) < 0
    )
      continue;
    makeProxy(shapes.geometry[s]!, input.proxyA);
    input.maxFraction = fraction;
    shapeCast(m.gjk, input, output);
    if (!output.hit) continue;
    const f = output.fraction;
    if (best === -1 || f < fraction || (f === fraction && s < best)) {
      best = s;
      fraction = f;
      px = output.pointX;
      py = output.pointY;
      nx = output.normalX;
      ny = output.normalY;
    }
  }
  if (best === -1) return null;
  return makeCastHit(world.handles.shapes[best]!, px, py, nx, ny, fraction);
}
