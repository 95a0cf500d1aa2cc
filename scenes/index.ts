/** Scene builders shared by tests, examples and benchmarks, and the registry the benchmark runs. */
import { cardHouse } from './card-house';
import { concaveRain } from './concave-rain';
import { bulletsAtPlanks, highDrop, spinningBar } from './continuous';
import { freeFall } from './free-fall';
import { bridge, carOnHills, newtonsCradle, pendulum, ragdoll, ragdolls, slingshot } from './joint-scenes';
import { chain, jointGrid } from './joints';
import { manyPyramids, pyramid } from './pyramids';
import { rain } from './rain';
import { highMassRatio, mixedShapesStack, verticalStack } from './stacks';
import { tumbler } from './tumbler';
import type { Scene } from './types';

export { bodyCentroid, bodyMass, shapeArea } from './mass';
export { createRandom, type Random } from './random';
export { addBlob, addCloth, type BlobOptions, type ClothOptions, cloth, softBlobs } from './soft-bodies';
export type * from './types';
export {
  bridge,
  bulletsAtPlanks,
  cardHouse,
  carOnHills,
  chain,
  concaveRain,
  freeFall,
  highDrop,
  highMassRatio,
  jointGrid,
  manyPyramids,
  mixedShapesStack,
  newtonsCradle,
  pendulum,
  pyramid,
  ragdoll,
  ragdolls,
  rain,
  slingshot,
  spinningBar,
  tumbler,
  verticalStack,
};

/** Every scene by name; `quick` gives a smaller version for fast runs. */
export const sceneBuilders: Record<string, (quick?: boolean) => Scene> = {
  pyramid: (quick) => pyramid({ base: quick ? 20 : 40 }),
  'large-pyramid': (quick) => pyramid({ base: quick ? 30 : 100 }),
  'many-pyramids': (quick) => manyPyramids({ count: quick ? 5 : 20, base: 10 }),
  /** the size of a matter.js demo's pyramid (120 boxes): the matter-API comparison's scene */
  'pyramid-15': () => pyramid({ base: 15 }),
  rain: (quick) => rain({ count: quick ? 300 : 1000 }),
  tumbler: (quick) => tumbler({ count: quick ? 200 : 500 }),
  'concave-rain': (quick) => concaveRain({ count: quick ? 200 : 500 }),
  'joint-grid': (quick) => jointGrid({ size: quick ? 20 : 40 }),
  chain: () => chain({ links: 100 }),
  'vertical-stack': () => verticalStack({ count: 20 }),
  'card-house': () => cardHouse({ levels: 3 }),
  'mass-ratio': () => highMassRatio(),
  'mixed-stack': () => mixedShapesStack(),
  bullets: () => bulletsAtPlanks(),
  'spinning-bar': () => spinningBar(),
  'high-drop': () => highDrop(),
};

/** the scenes `npm run bench` runs by default: the Box2D v3 benchmark set */
export const benchmarkScenes = [
  'pyramid',
  'large-pyramid',
  'many-pyramids',
  'rain',
  'tumbler',
  'joint-grid',
  'chain',
];
