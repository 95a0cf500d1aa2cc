import { createRandom } from '../../scenes/index';
import { Shape, type Vec2, World } from '../../src/index';
import type { Demo } from '../demo';
import { regularPolygon } from '../lib';

const RAYS = 36;
const LENGTH = 30;

interface Hit {
  from: Vec2;
  to: Vec2;
  normal: Vec2 | null;
}

export const rayCastDemo: Demo = {
  id: 'ray-cast',
  title: 'Ray casting',
  description:
    'A turning lamp casts 36 rays with world.castRay (the closest hit and its normal), and a laser finds every shape on its line with world.castRayAll. Drag shapes into the light.',
  view: { center: { x: 0, y: 0 }, halfHeight: 12 },
  create: (ctx) => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const random = createRandom(9);
    const room = world.createBody({ position: { x: 0, y: 0 } });
    room.createShape(Shape.box(18, 0.5, { x: 0, y: -11 }));
    room.createShape(Shape.box(18, 0.5, { x: 0, y: 11 }));
    room.createShape(Shape.box(0.5, 11, { x: -18, y: 0 }));
    room.createShape(Shape.box(0.5, 11, { x: 18, y: 0 }));
    for (let i = 0; i < 26; i++) {
      const angle = random.range(0, 2 * Math.PI);
      const r = random.range(4, 9.5);
      const body = world.createBody({
        type: 'dynamic',
        position: { x: r * Math.cos(angle) * 1.5, y: r * Math.sin(angle) },
        angle: random.range(0, 3),
        linearVelocity: { x: random.range(-1, 1), y: random.range(-1, 1) },
        angularVelocity: random.range(-1, 1),
        linearDamping: 0.05,
      });
      const size = random.range(0.5, 1.2);
      const kind = i % 4;
      body.createShape(
        kind === 0
          ? Shape.circle(size)
          : kind === 1
            ? Shape.box(size, size * 0.5)
            : kind === 2
              ? Shape.capsule({ x: -size, y: 0 }, { x: size, y: 0 }, size * 0.4)
              : Shape.polygon(regularPolygon(3 + random.int(5), size)),
        { restitution: 0.8, friction: 0.1 },
      );
    }
    const lamp: Vec2 = { x: 0, y: 0 };
    let turn = 0;
    let rays: Hit[] = [];
    let laser: Vec2[] = [];
    let laserEnd: Vec2 = { x: 0, y: 0 };
    const cast = () => {
      rays = [];
      for (let i = 0; i < RAYS; i++) {
        const a = turn + (2 * Math.PI * i) / RAYS;
        const d = { x: LENGTH * Math.cos(a), y: LENGTH * Math.sin(a) };
        const hit = world.castRay(lamp, d);
        rays.push(
          hit
            ? { from: lamp, to: hit.point, normal: hit.normal }
            : { from: lamp, to: { x: lamp.x + d.x, y: lamp.y + d.y }, normal: null },
        );
      }
      // the laser: along a slowly turning line across the room, every hit
      const a = -turn * 0.5;
      const origin = { x: -17 * Math.cos(a), y: -10 * Math.sin(a) };
      const d = { x: 34 * Math.cos(a), y: 20 * Math.sin(a) };
      laser = world.castRayAll(origin, d).map((h) => h.point);
      laserEnd = { x: origin.x + d.x, y: origin.y + d.y };
      laser.unshift(origin);
    };
    cast();
    ctx.track(
      world.on('postStep', (e) => {
        turn += 0.4 * e.dt;
        cast();
      }),
    );
    ctx.track(
      ctx.render.on('afterDraw', ({ context, pixel }) => {
        context.lineWidth = pixel;
        context.strokeStyle = 'rgba(255, 230, 140, 0.55)';
        context.beginPath();
        for (const r of rays) {
          context.moveTo(r.from.x, r.from.y);
          context.lineTo(r.to.x, r.to.y);
        }
        context.stroke();
        context.fillStyle = '#ffe68c';
        context.strokeStyle = '#7fd3e6';
        context.beginPath();
        for (const r of rays) {
          if (!r.normal) continue;
          context.moveTo(r.to.x, r.to.y);
          context.lineTo(r.to.x + r.normal.x * 0.6, r.to.y + r.normal.y * 0.6);
        }
        context.stroke();
        for (const r of rays) {
          if (!r.normal) continue;
          context.beginPath();
          context.arc(r.to.x, r.to.y, 3 * pixel, 0, 2 * Math.PI);
          context.fill();
        }
        context.beginPath();
        context.arc(lamp.x, lamp.y, 6 * pixel, 0, 2 * Math.PI);
        context.fill();
        // the laser and all its hits
        context.strokeStyle = 'rgba(255, 80, 80, 0.8)';
        context.beginPath();
        context.moveTo(laser[0].x, laser[0].y);
        context.lineTo(laserEnd.x, laserEnd.y);
        context.stroke();
        context.fillStyle = '#ff5050';
        for (const p of laser.slice(1)) {
          context.beginPath();
          context.arc(p.x, p.y, 4 * pixel, 0, 2 * Math.PI);
          context.fill();
        }
      }),
    );
    return { world };
  },
};
