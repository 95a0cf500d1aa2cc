import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { cardHouse } from '../../scenes/index';
import type { Demo } from '../demo';
import { ball } from '../lib';

export const cardHouseDemo: Demo = {
  id: 'card-house',
  title: 'Card house',
  description:
    'Four storeys of 2 cm cards leaning on each other, held up by friction alone (scenes/card-house.ts), and a ball rolling in to test it. Drop more balls, or pull a card out.',
  view: { center: { x: -1, y: 2.3 }, halfHeight: 3.2 },
  fitWidth: 5,
  create: (ctx) => {
    const { world } = buildFulcrumWorld(cardHouse({ levels: 4 }));
    ball(world, { x: -6, y: 0.15 }, 0.15, { density: 3 }).setLinearVelocity({ x: 1.2, y: 0 });
    ctx.button('Drop a ball', () => {
      ball(world, { x: (Math.random() - 0.5) * 2, y: 6 }, 0.2, { density: 4 });
    });
    return { world };
  },
};
