import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { newtonsCradle } from '../../scenes/index';
import type { Demo } from '../demo';

const COUNT = 5;
const STRING = 2;
const TOP = 4;

export const newtonsCradleDemo: Demo = {
  id: 'newtons-cradle',
  title: "Newton's cradle",
  description:
    'Five steel balls on 2 m distance joints (scenes/joint-scenes.ts), restitution 1, hanging 2 cm apart so each impact is solved on its own and the momentum passes down the row. Lift one, two or three balls and let go.',
  view: { center: { x: 0, y: 2.5 }, halfHeight: 2.6 },
  fitWidth: 2.8,
  flags: { sleeping: false },
  create: (ctx) => {
    const { world, bodies } = buildFulcrumWorld(newtonsCradle({ count: COUNT }));
    const balls = bodies.slice(1);
    const pivots = balls.map((_, i) => (i - (COUNT - 1) / 2) * 0.52);
    for (const ball of balls) ctx.render.setBodyStyle(ball, { color: 0xc9ced8 });
    /** lifts the first `n` balls to the horizontal and lets the rest hang still */
    const lift = (n: number) => {
      balls.forEach((ball, i) => {
        const x = pivots[i];
        ball.setTransform(i < n ? { x: x - STRING, y: TOP } : { x, y: TOP - STRING }, 0);
        ball.setLinearVelocity({ x: 0, y: 0 });
        ball.setAngularVelocity(0);
        ball.setAwake(true);
      });
    };
    ctx.button('Lift one', () => lift(1));
    ctx.button('Lift two', () => lift(2));
    ctx.button('Lift three', () => lift(3));
    ctx.track(
      ctx.render.on('afterDraw', ({ context, pixel }) => {
        // the frame the strings hang from
        context.strokeStyle = '#8a92a3';
        context.lineWidth = 6 * pixel;
        context.lineCap = 'round';
        context.beginPath();
        context.moveTo(pivots[0] - 0.6, TOP);
        context.lineTo(pivots[COUNT - 1] + 0.6, TOP);
        context.stroke();
        context.lineCap = 'butt';
      }),
    );
    return { world, balls };
  },
};
