import type { World } from '../api/world';
import type { BroadPhaseRayCastVisitor } from '../broad-phase/broad-phase';
import { rayCastGeometry } from '../geometry/raycast';
import { makeRayHit } from '../geometry/types';
import { makeTransform } from '../math/vec2';
import type { WorldCore } from '../world/world-core';
import { checkPoint } from './args';
import { makeResolvedQueryFilter, passesQueryFilter, resolveQueryFilter } from './filter';
import { type CastHit, makeCastHit } from './hit';

/*
 * World ray casts. The ray is origin + f * translation, f in [0, 1], and each shape follows the rule
 * of geometry/raycast.ts: a ray starting strictly inside a solid shape does not hit it, a zero-length
 * ray hits nothing, a grazing (tangent) ray hits. Sensors are skipped unless filter.includeSensors.
 * Ties: among hits at the same fraction the smaller shape slot comes first.
 */

/**
 * What both visitors share: the ray, its filter, and the test of one shape against the ray. A world
 * keeps one of each visitor (QueryMemory), set up by each cast.
 */
abstract class ShapeRayVisitor implements BroadPhaseRayCastVisitor {
  core: WorldCore | null = null;
  ox = 0;
  oy = 0;
  tx = 0;
  ty = 0;
  readonly filter = makeResolvedQueryFilter();
  /** the hit of the last shape tested */
  readonly hit = makeRayHit();
  readonly xf = makeTransform();

  abstract rayCastProxy(proxyKey: number, s: number, maxFraction: number): number;

  /** Tests shape `s` against the ray; on a hit fills `hit`. */
  protected castShapeSlot(s: number): boolean {
    const core = this.core!;
    const shapes = core.shapes;
    if (!passesQueryFilter(shapes, s, this.filter)) return false;
    core.fillTransform(shapes.body[s], this.xf);
    return rayCastGeometry(shapes.geometry[s]!, this.xf, this.ox, this.oy, this.tx, this.ty, this.hit);
  }
}

/** @internal Keeps the closest hit and clips the ray to it. */
export class ClosestVisitor extends ShapeRayVisitor {
  slot = -1;
  fraction = 0;
  px = 0;
  py = 0;
  nx = 0;
  ny = 0;

  rayCastProxy(_proxyKey: number, s: number, maxFraction: number): number {
    if (!this.castShapeSlot(s)) return -1;
    const hit = this.hit;
    const f = hit.fraction;
    if (f > maxFraction) return -1;
    if (this.slot === -1 || f < this.fraction || (f === this.fraction && s < this.slot)) {
      this.slot = s;
      this.fraction = f;
      this.px = hit.pointX;
      this.py = hit.pointY;
      this.nx = hit.normalX;
      this.ny = hit.normalY;
    }
    return f; // 0 stops the cast: nothing can come before a hit at the origin
  }
}

/** @internal Records every hit without clipping: per hit, slot and five numbers. */
export class AllVisitor extends ShapeRayVisitor {
  count = 0;
  slots = new Int32Array(16);
  values = new Float64Array(16 * 5);

  rayCastProxy(_proxyKey: number, s: number, _maxFraction: number): number {
    if (!this.castShapeSlot(s)) return -1;
    const hit = this.hit;
    if (this.count === this.slots.length) {
      const slots = new Int32Array(this.count * 2);
      slots.set(this.slots);
      this.slots = slots;
      const values = new Float64Array(this.count * 10);
      values.set(this.values);
      this.values = values;
    }
    const i = this.count++;
    this.slots[i] = s;
    const v = this.values;
    v[5 * i] = hit.fraction;
    v[5 * i + 1] = hit.pointX;
    v[5 * i + 2] = hit.pointY;
    v[5 * i + 3] = hit.normalX;
    v[5 * i + 4] = hit.normalY;
    return -1; // keep the whole ray
  }
}

/** The closest shape hit by the ray, or null. */
export function castRay(
  world: World,
  origin: unknown,
  translation: unknown,
  queryFilter?: unknown,
): CastHit | null {
  const o = checkPoint('origin', origin);
  const t = checkPoint('translation', translation);
  const core = world.core;
  const v = world.handles.queryMemory.closest;
  resolveQueryFilter(queryFilter, false, v.filter);
  v.core = core;
  v.ox = o.x;
  v.oy = o.y;
  v.tx = t.x;
  v.ty = t.y;
  v.slot = -1;
  if (v.tx !== 0 || v.ty !== 0) core.broadPhase.rayCast(v.ox, v.oy, v.tx, v.ty, 1, v);
  v.core = null;
  if (v.slot === -1) return null;
  return makeCastHit(world.handles.shapes[v.slot]!, v.px, v.py, v.nx, v.ny, v.fraction);
}

/** Every shape hit by the ray, sorted by fraction, then by shape slot. */
export function castRayAll(
  world: World,
  origin: unknown,
  translation: unknown,
  queryFilter?: unknown,
): CastHit[] {
  const o = checkPoint('origin', origin);
  const t = checkPoint('translation', translation);
  const core = world.core;
  const v = world.handles.queryMemory.all;
  resolveQueryFilter(queryFilter, false, v.filter);
  v.core = core;
  v.ox = o.x;
  v.oy = o.y;
  v.tx = t.x;
  v.ty = t.y;
  v.count = 0;
  if (v.tx !== 0 || v.ty !== 0) core.broadPhase.rayCast(v.ox, v.oy, v.tx, v.ty, 1, v);
  v.core = null;
  const result: CastHit[] = [];
  const values = v.values;
  for (let i = 0; i < v.count; i++) {
    const k = 5 * i;
    result.push(
      makeCastHit(
        world.handles.shapes[v.slots[i]]!,
        values[k + 1],
        values[k + 2],
        values[k + 3],
        values[k + 4],
        values[k],
      ),
    );
  }
  result.sort((a, b) => a.fraction - b.fraction || a.shape.slot - b.shape.slot);
  return result;
}
