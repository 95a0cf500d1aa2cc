/** Every demo of the gallery, in the order of the list. The URL's hash names the demo: #pyramid. */
import type { Demo } from './demo';
import { bulletsDemo } from './demos/bullets';
import { carDemo } from './demos/car';
import { cardHouseDemo } from './demos/card-house';
import { chainBridgeDemo } from './demos/chain-bridge';
import { clothDemo } from './demos/cloth';
import { concaveRainDemo } from './demos/concave-rain';
import { filteringDemo } from './demos/filtering';
import { golfDemo } from './demos/golf';
import { heavyLoadsDemo } from './demos/heavy-loads';
import { newtonsCradleDemo } from './demos/newtons-cradle';
import { oneWayDemo } from './demos/one-way';
import { p5Demo } from './demos/p5-sketch';
import { phaserDemo } from './demos/phaser';
import { pixiDemo } from './demos/pixi';
import { planetsDemo } from './demos/planets';
import { pyramidDemo } from './demos/pyramid';
import { ragdollsDemo } from './demos/ragdolls';
import { rayCastDemo } from './demos/ray-cast';
import { slingshotDemo } from './demos/slingshot/demo';
import { softBodyDemo } from './demos/soft-body';
import { stressDemo } from './demos/stress';
import { stressWorkerDemo } from './demos/stress-worker';
import { svgTerrainDemo } from './demos/svg-terrain';
import { tumblerDemo } from './demos/tumbler';

export const demos: readonly Demo[] = [
  pyramidDemo,
  cardHouseDemo,
  slingshotDemo,
  newtonsCradleDemo,
  chainBridgeDemo,
  heavyLoadsDemo,
  ragdollsDemo,
  carDemo,
  svgTerrainDemo,
  concaveRainDemo,
  oneWayDemo,
  clothDemo,
  softBodyDemo,
  planetsDemo,
  golfDemo,
  filteringDemo,
  bulletsDemo,
  rayCastDemo,
  tumblerDemo,
  stressDemo,
  stressWorkerDemo,
  pixiDemo,
  p5Demo,
  phaserDemo,
];

export function findDemo(id: string): Demo | undefined {
  return demos.find((d) => d.id === id);
}
