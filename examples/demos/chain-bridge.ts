import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { bridge } from '../../scenes/index';
import { type Body, Shape } from '../../src/index';
import type { Demo } from '../demo';

const PLANKS = 20;
const LINKS = 10;
const LINK = 0.4;
const PIVOT = { x: -3, y: 8 };

export const chainBridgeDemo: Demo = {
  id: 'chain-bridge',
  title: 'Chain and bridge',
  description:
    'A rope bridge of twenty planks on revolute joints carries five boxes (scenes/joint-scenes.ts); a chain of capsule links swings a heavy ball into them. Drag the planks, the boxes or the ball.',
  view: { center: { x: 0, y: 4.2 }, halfHeight: 6.8 },
  fitWidth: 10.6,
  create: (ctx) => {
    const scene = bridge({ planks: PLANKS });
    const { world, bodies } = buildFulcrumWorld(scene);
    const ground = bodies[0];
    // the posts the bridge hangs from, and a beam for the chain
    ground.createShape(Shape.box(0.25, 2.25, { x: -PLANKS / 2 - 0.25, y: 2.75 }));
    ground.createShape(Shape.box(0.25, 2.25, { x: PLANKS / 2 + 0.25, y: 2.75 }));
    bodies.forEach((body, i) => {
      const tag = scene.bodies[i].tag;
      if (tag === 'plank') ctx.render.setBodyStyle(body, { color: 0xb07a45 });
      else if (tag === 'load') ctx.render.setBodyStyle(body, { color: 0x6fb3d9 });
    });
    // the chain: capsules on revolute joints, starting level so it swings down
    const pivot = world.createBody({ position: PIVOT });
    pivot.createShape(Shape.circle(0.12));
    let previous: Body = pivot;
    const links: Body[] = [];
    for (let i = 0; i < LINKS; i++) {
      const link = world.createBody({
        type: 'dynamic',
        position: { x: PIVOT.x + LINK * (i + 0.5), y: PIVOT.y },
      });
      link.createShape(Shape.capsule({ x: -LINK / 2, y: 0 }, { x: LINK / 2, y: 0 }, 0.06), { density: 4 });
      ctx.render.setBodyStyle(link, { color: 0x9aa3b5 });
      world.createJoint({
        type: 'revolute',
        bodyA: previous,
        bodyB: link,
        anchor: { x: PIVOT.x + LINK * i, y: PIVOT.y },
      });
      links.push(link);
      previous = link;
    }
    const end = PIVOT.x + LINK * LINKS;
    const ball = world.createBody({ type: 'dynamic', position: { x: end + 0.5, y: PIVOT.y } });
    ball.createShape(Shape.circle(0.5), { density: 6, friction: 0.4 });
    ctx.render.setBodyStyle(ball, { color: 0xd9695f });
    world.createJoint({ type: 'revolute', bodyA: previous, bodyB: ball, anchor: { x: end, y: PIVOT.y } });
    return { world, links, ball };
  },
};
