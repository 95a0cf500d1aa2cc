import { parseSvgPath } from '../geometry/svg-path';
import type { MatterVector } from './vector';

/** matter.js's `Svg`: the points of an SVG path, for `Bodies.fromVertices`. A plain, mutable module object. */
export const Svg = {
  /**
   * The points along `path` (an SVG path element, or its `d` string), no farther apart than about
   * `sampleLength` (default 15): curves are cut into chords that stray at most a tenth of that from
   * them, and no SVGPathElement or browser is needed.
   */
  pathToVertices(
    path: string | { getAttribute(name: string): string | null },
    sampleLength = 15,
  ): MatterVector[] {
    const d = typeof path === 'string' ? path : (path.getAttribute('d') ?? '');
    const points: MatterVector[] = [];
    for (const subpath of parseSvgPath(d, { tolerance: sampleLength / 10 })) {
      for (const p of subpath.points) points.push({ x: p.x, y: p.y });
    }
    return points;
  },
};
