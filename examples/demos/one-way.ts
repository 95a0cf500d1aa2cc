import { type Body, Shape, World } from '../../src/index';
import type { Demo } from '../demo';
import { drawnPosition, onKeys } from '../lib';

const JUMP_SPEED = 11;
const RUN_SPEED = 5;

export const oneWayDemo: Demo = {
  id: 'one-way',
  title: 'One-way platforms',
  description:
    'Each platform is a one-sided chain: bodies pass up through it from below and land on it from above. The green box jumps with the up arrow (or space) and runs with left and right; the lift is a kinematic chain.',
  view: { center: { x: 0, y: 5 }, halfHeight: 7 },
  create: (ctx) => {
    const world = new World();
    // floor and walls: one loop, clockwise so that it holds what is inside
    world.createBody().createShape(
      Shape.chain(
        [
          { x: -12, y: 0 },
          { x: -12, y: 16 },
          { x: 12, y: 16 },
          { x: 12, y: 0 },
        ],
        { loop: true },
      ),
      { friction: 0.8 },
    );
    // platforms, each drawn right to left so that it faces up
    const planks: { body: Body; half: number }[] = [];
    for (const [x, y, half] of [
      [-6, 2.5, 3],
      [4, 3, 2.5],
      [-1, 5.5, 2.5],
      [-8, 7.5, 2],
      [6, 8, 3],
      [0, 10.5, 2],
    ]) {
      const platform = world.createBody({ position: { x, y } });
      platform.createShape(
        Shape.chain([
          { x: half, y: 0 },
          { x: -half, y: 0 },
        ]),
        { friction: 0.8 },
      );
      planks.push({ body: platform, half });
    }
    const lift = world.createBody({ type: 'kinematic', position: { x: 9.5, y: 2 } });
    lift.createShape(
      Shape.chain([
        { x: 1.5, y: 0 },
        { x: -1.5, y: 0 },
      ]),
    );
    planks.push({ body: lift, half: 1.5 });
    // each platform drawn as a plank under its chain: light passes up through it, feet land on it
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        render.setWorldTransform();
        const context = render.context;
        for (const { body, half } of planks) {
          const p = drawnPosition(ctx.runner, body);
          const wood = context.createLinearGradient(0, p.y, 0, p.y - 0.3);
          wood.addColorStop(0, body === lift ? '#7d8fb3' : '#b98a55');
          wood.addColorStop(1, body === lift ? '#4a5670' : '#6e4f2e');
          context.fillStyle = wood;
          context.fillRect(p.x - half, p.y - 0.3, 2 * half, 0.3);
        }
        render.setScreenTransform();
      }),
    );
    const player = world.createBody({ type: 'dynamic', position: { x: -6, y: 0.5 }, fixedRotation: true });
    player.createShape(Shape.box(0.4, 0.5), { friction: 0.8 });
    ctx.render.setBodyStyle(player, { color: 0x8fc46a });
    // balls that bounce up through the platforms
    const balls: Body[] = [];
    for (let i = 0; i < 8; i++) {
      const ball = world.createBody({ type: 'dynamic', position: { x: -10 + 2.6 * i, y: 0.4 } });
      ball.createShape(Shape.circle(0.3), { restitution: 0.6 });
      ctx.render.setBodyStyle(ball, { color: 0x6fb3d9 });
      balls.push(ball);
    }

    let run = 0;
    let jump = false;
    let steps = 0;
    if (!ctx.preview)
      ctx.track(
        onKeys(['ArrowLeft', 'ArrowRight', 'ArrowUp', ' ', 'a', 'd', 'w'], (key, down) => {
          if (key === 'ArrowUp' || key === ' ' || key === 'w') jump = down;
          else if (key === 'ArrowLeft' || key === 'a') run = down ? -1 : 0;
          else run = down ? 1 : 0;
        }),
      );
    let jumpOnce = false;
    ctx.button('Jump', () => {
      jumpOnce = true;
    });
    ctx.track(
      world.on('preStep', () => {
        steps++;
        // the lift goes up and down every 4 s
        lift.setLinearVelocity({ x: 0, y: Math.floor(steps / 240) % 2 === 0 ? 2 : -2 });
        const v = player.linearVelocity;
        const standing = Math.abs(v.y) < 0.05;
        player.setLinearVelocity({
          x: run * RUN_SPEED,
          y: (jump || jumpOnce) && standing ? JUMP_SPEED : v.y,
        });
        jumpOnce = false;
        // every second, the ball that is lowest is kicked up through the platforms above it
        if (steps % 60 === 0) {
          const ball = balls.reduce((low, b) => (b.position.y < low.position.y ? b : low));
          ball.setLinearVelocity({ x: ((steps / 60) % 3) - 1, y: 13 });
        }
      }),
    );
    ctx.setStatus('← → run, ↑ or space jump');
    return { world, player, balls, lift };
  },
};
