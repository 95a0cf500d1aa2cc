import { type Body, World } from '../../src/index';
import type { Demo } from '../demo';
import { box, ground } from '../lib';

export const pyramidDemo: Demo = {
  id: 'pyramid',
  title: 'Pyramid',
  description:
    'Twenty rows of one-metre boxes drop into place and stand as a pyramid. Drag a box with the mouse or a finger; drag empty space to pan; wheel or pinch to zoom.',
  view: { center: { x: 0, y: 9.5 }, halfHeight: 12 },
  fitWidth: 11,
  create: () => {
    const world = new World();
    ground(world, 30);
    const base = 20;
    const boxes: Body[] = [];
    for (let row = 0; row < base; row++) {
      const count = base - row;
      for (let i = 0; i < count; i++) {
        // each row starts 5 cm above the one below, so the pyramid settles as it appears
        const position = { x: i - (count - 1) / 2, y: 0.5 + row * 1.05 };
        boxes.push(box(world, position, 0.5, 0.5));
      }
    }
    return { world, boxes };
  },
};
