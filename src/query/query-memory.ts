import { IntList } from '../broad-phase/int-list';
import { makeDistanceOutput } from '../geometry/distance';
import { Pack } from '../geometry/packed';
import { makeShapeCastInput, makeShapeCastOutput } from '../geometry/shape-cast';
import { makeShapeProxy } from '../geometry/shape-proxy';
import { GjkMemory } from '../geometry/simplex';
import { makeBounds } from '../math/aabb';
import { makeTransform } from '../math/vec2';
import { makeResolvedQueryFilter } from './filter';
import { AllVisitor, ClosestVisitor } from './ray-cast';

/**
 * A world's working memory for its queries (held by its WorldHandles, as the queries belong to the
 * public layer): every query writes what it uses before it reads it, so one serves all the queries
 * of a world, and queries of different worlds share nothing. None of it is allocated per query.
 * @internal
 */
export class QueryMemory {
  readonly filter = makeResolvedQueryFilter();
  /** the broad phase's candidates, and the shapes an overlap query keeps of them */
  readonly found = new IntList(64);
  readonly selected = new IntList(64);
  /** a candidate shape's transform, and the transform of overlapShape's shape */
  readonly xf = makeTransform();
  readonly queryXf = makeTransform();
  /** the box of the query's shape, and that shape packed to work it out */
  readonly bounds = makeBounds();
  readonly packed = new Float64Array(Pack.STRIDE);
  /** overlapShape: a candidate's proxy (A), the query shape's (B), their distance */
  readonly proxyA = makeShapeProxy();
  readonly proxyB = makeShapeProxy();
  readonly distance = makeDistanceOutput();
  readonly gjk = new GjkMemory();
  /** castShape's cast of the query shape (B) against each candidate (A) */
  readonly castInput = makeShapeCastInput();
  readonly castOutput = makeShapeCastOutput();
  /** the ray casts' visitors */
  readonly closest = new ClosestVisitor();
  readonly all = new AllVisitor();
}
