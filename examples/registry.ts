/** Every demo of the gallery, in the order of the list. The URL's hash names the demo: #pyramid. */
import type { Demo } from './demo';
import { bulletsDemo } from './demos/bullets';
import { cardHouseDemo } from './demos/card-house';
import { filteringDemo } from './demos/filtering';
import { golfDemo } from './demos/golf';
import { pixiDemo } from './demos/pixi';
import { planetsDemo } from './demos/planets';
import { pyramidDemo } from './demos/pyramid';
import { rayCastDemo } from './demos/ray-cast';
import { stressDemo } from './demos/stress';
import { tumblerDemo } from './demos/tumbler';

export const demos: readonly Demo[] = [
  pyramidDemo,
  cardHouseDemo,
  planetsDemo,
  golfDemo,
  filteringDemo,
  bulletsDemo,
  rayCastDemo,
  tumblerDemo,
  stressDemo,
  pixiDemo,
];

export function findDemo(id: string): Demo | undefined {
  return demos.find((d) => d.id === id);
}
