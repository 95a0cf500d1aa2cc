import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { cloth } from '../../scenes/index';
import { type Body, Shape } from '../../src/index';
import type { Demo } from '../demo';
import { drawnPosition } from '../lib';

const COLUMNS = 18;
const ROWS = 13;
const SPACING = 0.4;

export const clothDemo: Demo = {
  id: 'cloth',
  title: 'Cloth',
  description:
    'A sheet of 234 small circles, each tied to its neighbours by soft distance joints (springs along the rows and columns, softer ones across the diagonals), pinned at seven points of its top edge (scenes/soft-bodies.ts). Balls drop into it; drag the cloth or a ball.',
  view: { center: { x: 0, y: 4.6 }, halfHeight: 5.4 },
  flags: { joints: false },
  create: (ctx) => {
    const scene = cloth({ columns: COLUMNS, rows: ROWS, spacing: SPACING, topLeft: { x: -3.4, y: 9 } });
    const { world, bodies } = buildFulcrumWorld(scene);
    const nodes = bodies.slice(1);
    for (const node of nodes)
      ctx.render.setBodyStyle(node, { color: node.type === 'static' ? 0xe6a04b : 0x6fb3d9 });
    const balls: Body[] = [];
    const drop = () => {
      const i = balls.length;
      const ball = world.createBody({
        type: 'dynamic',
        position: { x: -2 + ((i * 1.7) % 4), y: 11 },
        bullet: true,
      });
      ball.createShape(Shape.circle(0.35 + 0.1 * (i % 3)), { density: 3, friction: 0.5 });
      ctx.render.setBodyStyle(ball, { color: 0xd9695f });
      balls.push(ball);
    };
    drop();
    ctx.button('Drop a ball', drop);
    const at = (row: number, column: number) => nodes[row * COLUMNS + column];
    ctx.track(
      ctx.render.on('afterDraw', ({ context, pixel }) => {
        // the weave: a line along every row and column, under the circles' outlines
        context.strokeStyle = 'rgba(111, 179, 217, 0.55)';
        context.lineWidth = 1.5 * pixel;
        context.beginPath();
        for (let row = 0; row < ROWS; row++) {
          for (let column = 0; column < COLUMNS; column++) {
            const p = drawnPosition(ctx.runner, at(row, column));
            if (column + 1 < COLUMNS) {
              const q = drawnPosition(ctx.runner, at(row, column + 1));
              context.moveTo(p.x, p.y);
              context.lineTo(q.x, q.y);
            }
            if (row + 1 < ROWS) {
              const q = drawnPosition(ctx.runner, at(row + 1, column));
              context.moveTo(p.x, p.y);
              context.lineTo(q.x, q.y);
            }
          }
        }
        context.stroke();
      }),
    );
    return { world, nodes, balls };
  },
};
