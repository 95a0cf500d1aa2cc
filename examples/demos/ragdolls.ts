import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { ragdolls } from '../../scenes/index';
import { type Body, Shape } from '../../src/index';
import type { Demo } from '../demo';

const COUNT = 6;

export const ragdollsDemo: Demo = {
  id: 'ragdolls',
  title: 'Ragdolls',
  description:
    'Capsule limbs on revolute joints with angle limits at the hips, knees, shoulders, elbows and neck (scenes/joint-scenes.ts), dropped onto a flight of steps. Drag a ragdoll by any limb; "Toss" throws them all up again.',
  view: { center: { x: 1, y: 4 }, halfHeight: 6 },
  create: (ctx) => {
    const scene = ragdolls({ count: COUNT });
    const { world, bodies } = buildFulcrumWorld(scene);
    // a flight of steps under the right half of the row
    const ground = bodies[0];
    for (let i = 0; i < 5; i++) {
      const height = 0.5 * (i + 1);
      ground.createShape(Shape.box(0.6, height / 2, { x: 4.6 + 1.2 * i, y: 0.5 + height / 2 }), {
        friction: 0.8,
      });
    }
    // each ragdoll's bodies follow its pelvis in the scene's order
    const dolls: Body[][] = [];
    bodies.forEach((body, i) => {
      const tag = scene.bodies[i].tag;
      if (tag === 'pelvis') dolls.push([]);
      if (dolls.length > 0 && tag !== 'ground') dolls[dolls.length - 1].push(body);
    });
    const palette = [0xd9695f, 0x6fb3d9, 0xe3cf6a, 0x8fcf7a, 0xc792ea, 0xf08a6c];
    dolls.forEach((parts, i) => {
      for (const part of parts) ctx.render.setBodyStyle(part, { color: palette[i % palette.length] });
    });
    let tosses = 0;
    ctx.button('Toss', () => {
      tosses++;
      dolls.forEach((parts, i) => {
        // a deterministic spread of throws: alternate left and right
        const side = (i + tosses) % 2 === 0 ? 1 : -1;
        for (const part of parts) {
          part.setAwake(true);
          part.setLinearVelocity({ x: side * (1.5 + (i % 3)), y: 8 + (i % 2) });
          part.setAngularVelocity(side * 2);
        }
      });
    });
    return { world, dolls };
  },
};
