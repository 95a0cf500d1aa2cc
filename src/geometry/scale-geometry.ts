import { FulcrumError } from '../core/errors';
import type { Vec2 } from '../math/vec2';
import { makeChainSegment, Shape } from './shapes';
import type { Geometry, Segment } from './types';

/**
 * A linear map of a body's local frame, [[m00, m01], [m10, m11]], and whether it is a uniform scale
 * by `uniform` (then the m's are `uniform` and 0 exactly): only a uniform scale keeps a circle a
 * circle and a rounded shape's radius one radius.
 */
export interface LocalScale {
  m00: number;
  m01: number;
  m10: number;
  m11: number;
  /** the factor of a uniform scale, or NaN when the map is not one */
  uniform: number;
}

/**
 * The local map of a scale by `sx`, `sy` along the world's axes, for a body turned by (c, s):
 * Rᵀ diag(sx, sy) R. Equal factors give the uniform scale exactly.
 */
export function localScale(sx: number, sy: number, c: number, s: number): LocalScale {
  if (sx === sy) return { m00: sx, m01: 0, m10: 0, m11: sx, uniform: sx };
  const off = (sy - sx) * s * c;
  return {
    m00: sx * c * c + sy * s * s,
    m01: off,
    m10: off,
    m11: sx * s * s + sy * c * c,
    uniform: Number.NaN,
  };
}

function map(m: LocalScale, p: Vec2): Vec2 {
  return { x: m.m00 * p.x + m.m01 * p.y, y: m.m10 * p.x + m.m11 * p.y };
}

/**
 * A chain's segment under `m`, checked like Shape.segment. A mirroring map (negative determinant)
 * also reverses the segment, so that its front stays on the side the map carried it to.
 */
function scaleChainSegment(g: Segment, m: LocalScale): Segment {
  const mirror = m.m00 * m.m11 - m.m01 * m.m10 < 0;
  const p1 = map(m, mirror ? g.point2 : g.point1);
  const p2 = map(m, mirror ? g.point1 : g.point2);
  const g1 = mirror ? g.ghost2 : g.ghost1;
  const g2 = mirror ? g.ghost1 : g.ghost2;
  return makeChainSegment(p1, p2, g1 === null ? null : map(m, g1), g2 === null ? null : map(m, g2));
}

/**
 * The geometry `g` under the local map `m`, built and validated by the Shape factories. Throws a
 * FulcrumError naming `argument` when the map cannot apply: a circle, a capsule or a rounded polygon
 * under a map that is not a uniform scale, or a shape the map flattens below the engine's sizes.
 */
export function scaleGeometry(g: Geometry, m: LocalScale, argument: string): Geometry {
  const uniform = Math.abs(m.uniform);
  const rounded = g.type === 'circle' || g.type === 'capsule' || (g.type === 'polygon' && g.radius > 0);
  if (rounded && Number.isNaN(uniform)) {
    throw new FulcrumError(
      `${argument}: a ${g.type === 'polygon' ? 'rounded polygon' : g.type} can only be scaled by the same factor along x and y`,
    );
  }
  try {
    switch (g.type) {
      case 'circle':
        return Shape.circle(g.radius * uniform, map(m, g.center));
      case 'capsule':
        return Shape.capsule(map(m, g.center1), map(m, g.center2), g.radius * uniform);
      case 'segment':
        return g.oneSided ? scaleChainSegment(g, m) : Shape.segment(map(m, g.point1), map(m, g.point2));
      case 'polygon':
        return Shape.polygon(
          g.vertices.map((v) => map(m, v)),
          g.radius > 0 ? g.radius * uniform : undefined,
        );
    }
  } catch (error) {
    if (!(error instanceof FulcrumError)) throw error;
    throw new FulcrumError(
      `${argument}: the ${g.type} it scales would not be a valid shape (${error.message})`,
    );
  }
}
