import { Shape } from './shapes';
import { parseSvgPath, type SvgPathOptions } from './svg-path';
import type { Chain, Concave } from './types';

/**
 * The shapes of an SVG path, ready for `body.createShape`, one per subpath in order (parsed as by
 * `parseSvgPath` with the same options):
 * - a closed subpath (ended by `Z`) is a solid `Shape.concave` for a body of any type (a convex
 *   outline gives one piece);
 * - an open subpath is ground: a `Shape.chain` for a static or kinematic body, facing up (toward +y,
 *   its points reversed if they run the other way), so a terrain drawn in either direction is walked
 *   on from above. A path whose ends have the same x (a wall, a bowl) keeps the way it runs.
 * The shapes' checks apply: a closed outline that crosses itself, or points closer than 0.005 m after
 * scaling, throw a FulcrumError.
 */
export function svgShapes(d: string, options?: SvgPathOptions): (Concave | Chain)[] {
  return parseSvgPath(d, options).map(({ points, closed }) => {
    if (closed) return Shape.concave(points);
    // a chain faces right of the way its points run; the up components of those normals, each
    // times its segment's length, add up to how far the run goes from right to left
    const facing = points[0].x - points[points.length - 1].x;
    return Shape.chain(facing >= 0 ? points : [...points].reverse());
  });
}
