export type { QueryTransform } from './args';
export { castShape } from './cast-shape';
export type { QueryFilter } from './filter';
export type { CastHit } from './hit';
export { overlapShape, queryAABB, queryPoint } from './overlap';
export { castRay, castRayAll } from './ray-cast';
