import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { tumbler } from '../../scenes/index';
import type { Demo } from '../demo';

export const tumblerDemo: Demo = {
  id: 'tumbler',
  title: 'Tumbler',
  description:
    'A kinematic drum turns at a steady rate with 400 boxes inside (scenes/tumbler.ts): kinematic bodies push dynamic ones but nothing pushes them.',
  view: { center: { x: 0, y: 10 }, halfHeight: 12.5 },
  fitWidth: 11.2,
  create: () => {
    const { world } = buildFulcrumWorld(tumbler({ count: 400, angularVelocity: 0.5 }));
    return { world };
  },
};
