import { createRandom } from '../../scenes/index';
import { type Body, Shape, World } from '../../src/index';
import type { Demo } from '../demo';

const WALL_X = 6;
const SPEED = 150;

export const bulletsDemo: Demo = {
  id: 'bullets',
  title: 'Bullets vs thin walls',
  description: `Balls 10 cm wide fly at ${SPEED} m/s, 2.5 m per step, at walls 4 cm thick. Continuous collision stops every fast body at static walls (top); bodies marked bullet also stop at thin dynamic planks (bottom). The counters show how many got through: none should.`,
  view: { center: { x: 0, y: 5.5 }, halfHeight: 8.5 },
  create: (ctx) => {
    const world = new World();
    const random = createRandom(3);
    const frame = world.createBody({ position: { x: 0, y: 0 } });
    frame.createShape(Shape.box(13, 0.5, { x: 0, y: -0.5 }));
    frame.createShape(Shape.box(13, 0.25, { x: 0, y: 5.25 })); // shelf between the two lanes
    frame.createShape(Shape.box(0.02, 2.5, { x: WALL_X, y: 8 })); // upper lane: thin static wall
    frame.createShape(Shape.box(0.5, 6, { x: 13.5, y: 5.5 }));
    frame.createShape(Shape.box(0.5, 6, { x: -13.5, y: 5.5 }));
    // lower lane: a row of thin dynamic planks standing on the ground
    const planks: Body[] = [];
    for (let i = 0; i < 4; i++) {
      const plank = world.createBody({ type: 'dynamic', position: { x: WALL_X + i * 1.5, y: 2 } });
      plank.createShape(Shape.box(0.02, 2), { density: 200, friction: 0.9 });
      planks.push(plank);
    }
    const counts = { fired: 0, throughWall: 0, throughPlanks: 0 };
    const flying: { body: Body; lane: 'wall' | 'planks'; born: number }[] = [];
    let steps = 0;
    const fire = () => {
      const lane = counts.fired % 2 === 0 ? 'wall' : 'planks';
      const y = lane === 'wall' ? random.range(6, 10) : random.range(0.5, 3.5);
      const body = world.createBody({
        type: 'dynamic',
        position: { x: -12, y },
        linearVelocity: { x: SPEED, y: 0 },
        bullet: lane === 'planks',
        gravityScale: 0,
      });
      body.createShape(Shape.circle(0.05), { density: 5, restitution: 0.1 });
      ctx.render.setBodyStyle(body, { color: lane === 'wall' ? 0xe3cf6a : 0xf08a6c });
      flying.push({ body, lane, born: steps });
      counts.fired++;
    };
    ctx.track(
      world.on('postStep', () => {
        steps++;
        if (steps % 12 === 0) fire();
        for (let i = flying.length - 1; i >= 0; i--) {
          const f = flying[i];
          const x = f.body.position.x;
          // a bullet past the first plank got through it, if that plank still stands
          const upright = Math.abs(planks[0].angle) < 0.2;
          const through = f.lane === 'wall' ? x > WALL_X + 0.5 : upright && x > planks[0].position.x + 0.5;
          if (through) {
            if (f.lane === 'wall') counts.throughWall++;
            else counts.throughPlanks++;
          }
          if (through || steps - f.born > 90) {
            world.destroyBody(f.body);
            flying.splice(i, 1);
          }
        }
        ctx.setStatus(
          `fired ${counts.fired}, through the static wall ${counts.throughWall}, through the planks ${counts.throughPlanks}`,
        );
      }),
    );
    ctx.track(
      ctx.render.on('afterDraw', ({ context, pixel }) => {
        // a streak behind each ball: how far it flies in one step
        context.lineWidth = 2 * pixel;
        for (const f of flying) {
          const p = f.body.position;
          const v = f.body.linearVelocity;
          context.strokeStyle = f.lane === 'wall' ? 'rgba(227, 207, 106, 0.6)' : 'rgba(240, 138, 108, 0.6)';
          context.beginPath();
          context.moveTo(p.x, p.y);
          context.lineTo(p.x - v.x / 60, p.y - v.y / 60);
          context.stroke();
        }
      }),
    );
    ctx.button('Stand the planks up', () => {
      planks.forEach((p, i) => {
        p.setTransform({ x: WALL_X + i * 1.5, y: 2 }, 0);
        p.setLinearVelocity({ x: 0, y: 0 });
        p.setAngularVelocity(0);
      });
    });
    return { world, counts };
  },
};
