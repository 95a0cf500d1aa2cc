import { createRandom } from '../../scenes/index';
import { type Body, type Filter, Shape, World } from '../../src/index';
import type { Demo } from '../demo';
import { regularPolygon } from '../lib';

const GROUND = 1;
const RED = 2;
const BLUE = 4;
const GREEN = 8;
const GHOST = 16;

interface Kind {
  name: string;
  color: number;
  filter: Partial<Filter>;
}

const kinds: Kind[] = [
  {
    name: 'red: ground, red, green',
    color: 0xd9695f,
    filter: { categoryBits: RED, maskBits: GROUND | RED | GREEN },
  },
  {
    name: 'blue: ground, blue, green',
    color: 0x6fb3d9,
    filter: { categoryBits: BLUE, maskBits: GROUND | BLUE | GREEN },
  },
  { name: 'green: everything', color: 0x8ccf7e, filter: { categoryBits: GREEN, maskBits: 0xffff } },
  {
    name: 'yellow: group -1, never each other',
    color: 0xe3cf6a,
    filter: { categoryBits: GHOST, maskBits: 0xffff, groupIndex: -1 },
  },
];

export const filteringDemo: Demo = {
  id: 'filtering',
  title: 'Collision filtering',
  description:
    'Category and mask bits: red and blue pass through each other but both land on green; yellow shapes share group -1 and never touch each other. A contact needs both shapes to accept the other.',
  view: { center: { x: 0, y: 7 }, halfHeight: 9 },
  create: (ctx) => {
    const world = new World();
    const random = createRandom(5);
    const ground = world.createBody({ position: { x: 0, y: 0 } });
    const groundFilter = { categoryBits: GROUND, maskBits: 0xffff };
    ground.createShape(Shape.box(12, 0.5, { x: 0, y: -0.5 }), { filter: groundFilter });
    ground.createShape(Shape.box(0.5, 6, { x: -12.5, y: 5 }), { filter: groundFilter });
    ground.createShape(Shape.box(0.5, 6, { x: 12.5, y: 5 }), { filter: groundFilter });

    const live: Body[] = [];
    let steps = 0;
    const spawn = (y = 15) => {
      const kind = kinds[random.int(kinds.length)];
      const body = world.createBody({
        type: 'dynamic',
        position: { x: random.range(-9, 9), y },
        linearVelocity: { x: 0, y: -5 },
        angle: random.range(0, 3),
      });
      const size = random.range(0.4, 0.8);
      const shape = random.int(3);
      const geometry =
        shape === 0
          ? Shape.circle(size)
          : shape === 1
            ? Shape.box(size, size * 0.6)
            : Shape.polygon(regularPolygon(5 + random.int(3), size));
      body.createShape(geometry, { filter: kind.filter, density: 1, friction: 0.5 });
      ctx.render.setBodyStyle(body, { color: kind.color });
      live.push(body);
      if (live.length > 90) world.destroyBody(live.shift()!);
    };
    for (let i = 0; i < 12; i++) spawn(3 + i * 1.8);
    ctx.track(
      world.on('postStep', () => {
        if (++steps % 15 === 0) spawn();
      }),
    );
    ctx.track(
      ctx.render.on('overlay', ({ context }) => {
        context.font = '13px system-ui, sans-serif';
        kinds.forEach((kind, i) => {
          context.fillStyle = `#${kind.color.toString(16).padStart(6, '0')}`;
          context.fillRect(12, 14 + i * 20, 12, 12);
          context.fillStyle = '#d8dce4';
          context.fillText(kind.name, 30, 24 + i * 20);
        });
      }),
    );
    return { world };
  },
};
