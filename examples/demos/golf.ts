import { type Body, Shape, type Vec2, World } from '../../src/index';
import type { Demo } from '../demo';

const TEE: Vec2 = { x: -11, y: 0.15 };
const HOLE_X = 7;
const BALL_RADIUS = 0.15;
/** impulse per metre of pull-back, N s/m */
const POWER = 0.35;
const MAX_PULL = 5;

/** The golf green: ground with a bump and a cup, and the cup's sensor. Exported for the tests. */
export function buildGolf(world: World): { ball: Body; cup: ReturnType<Body['createShape']> } {
  const green = world.createBody({ position: { x: 0, y: 0 } });
  const grass = { friction: 0.8 };
  green.createShape(Shape.box(11.25, 0.5, { x: -4.75, y: -0.5 }), grass); // x in [-16, 6.5]
  green.createShape(Shape.box(4.25, 0.5, { x: 11.75, y: -0.5 }), grass); // x in [7.5, 16]
  green.createShape(Shape.box(0.5, 0.25, { x: HOLE_X, y: -1.25 }), grass); // the cup's bottom
  green.createShape(Shape.box(0.5, 3, { x: -16.5, y: 2 }), grass);
  green.createShape(Shape.box(0.5, 3, { x: 16.5, y: 2 }), grass);
  green.createShape(
    Shape.polygon(
      [
        { x: -5, y: -0.05 },
        { x: 1, y: -0.05 },
        { x: -1.5, y: 0.25 },
        { x: -2.5, y: 0.25 },
      ],
      0.05,
    ),
    grass,
  );
  // the cup: a sensor that reports the ball falling in
  const cup = green.createShape(Shape.box(0.45, 0.3, { x: HOLE_X, y: -0.7 }), { isSensor: true });
  const ball = world.createBody({
    type: 'dynamic',
    position: TEE,
    bullet: true,
    linearDamping: 0.2,
    angularDamping: 0.2,
  });
  ball.createShape(Shape.circle(BALL_RADIUS), { density: 2, friction: 0.8, restitution: 0.3 });
  return { ball, cup };
}

export const golfDemo: Demo = {
  id: 'golf',
  title: 'Golf green',
  description:
    'Pull back from the ball and let go to putt. The cup is a sensor shape: its sensorBegin event tells the ball is in. A first putt is on its way.',
  view: { center: { x: -1.5, y: 1.5 }, halfHeight: 6.5 },
  create: (ctx) => {
    const world = new World();
    const { ball, cup } = buildGolf(world);
    ctx.render.setBodyStyle(ball, { color: 0xf4f4f4 });
    ball.setLinearVelocity({ x: 8, y: 0 });
    let strokes = 1;
    let holes = 0;
    let sunkAt = -1;
    let steps = 0;
    let aim: Vec2 | null = null;
    const state = { strokes: () => strokes, holes: () => holes };
    ctx.setStatus('strokes 1');
    ctx.pointer.filter = (body) => body.type === 'dynamic' && body !== ball;

    const still = () => {
      const v = ball.linearVelocity;
      return v.x * v.x + v.y * v.y < 0.05;
    };
    ctx.track(
      ctx.pointer.on('down', (e) => {
        const p = ball.position;
        const dx = e.point.x - p.x;
        const dy = e.point.y - p.y;
        if (sunkAt < 0 && still() && dx * dx + dy * dy < 1.5 * 1.5) {
          aim = e.point;
          e.handled = true;
        }
      }),
    );
    ctx.track(
      ctx.pointer.on('move', (e) => {
        if (aim) aim = e.point;
      }),
    );
    ctx.track(
      ctx.pointer.on('up', (e) => {
        if (!aim) return;
        aim = null;
        const p = ball.position;
        let dx = p.x - e.point.x;
        let dy = p.y - e.point.y;
        const length = Math.hypot(dx, dy);
        if (length < 0.2) return;
        const scale = Math.min(length, MAX_PULL) / length;
        dx *= scale * POWER;
        dy *= scale * POWER;
        ball.applyLinearImpulse({ x: dx, y: dy });
        strokes++;
        ctx.setStatus(`strokes ${strokes}`);
      }),
    );
    ctx.track(
      world.on('sensorBegin', (e) => {
        if (e.sensorShape === cup && e.visitorShape.body === ball && sunkAt < 0) {
          sunkAt = steps;
          holes++;
          ctx.setStatus(`In the hole in ${strokes} stroke${strokes === 1 ? '' : 's'}!`);
        }
      }),
    );
    ctx.track(
      world.on('postStep', () => {
        steps++;
        if (sunkAt >= 0 && steps - sunkAt > 120) {
          sunkAt = -1;
          strokes = 0;
          ball.setTransform(TEE, 0);
          ball.setLinearVelocity({ x: 0, y: 0 });
          ball.setAngularVelocity(0);
          ctx.setStatus('strokes 0: pull back from the ball to putt');
        }
      }),
    );
    ctx.track(
      ctx.render.on('afterDraw', ({ context, pixel }) => {
        // the flag
        context.strokeStyle = '#d8dce4';
        context.lineWidth = 2 * pixel;
        context.beginPath();
        context.moveTo(HOLE_X, -0.3);
        context.lineTo(HOLE_X, 3);
        context.stroke();
        context.fillStyle = '#d9695f';
        context.beginPath();
        context.moveTo(HOLE_X, 3);
        context.lineTo(HOLE_X + 1.2, 2.7);
        context.lineTo(HOLE_X, 2.4);
        context.fill();
        if (aim) {
          const p = ball.position;
          context.strokeStyle = '#e6a04b';
          context.setLineDash([6 * pixel, 4 * pixel]);
          context.beginPath();
          context.moveTo(p.x, p.y);
          context.lineTo(2 * p.x - aim.x, 2 * p.y - aim.y);
          context.stroke();
          context.setLineDash([]);
        }
      }),
    );
    return { world, ball, state };
  },
};
