import { createRandom } from '../../scenes/index';
import { type Body, Shape, World } from '../../src/index';
import type { Demo } from '../demo';
import { regularPolygon } from '../lib';

/** gravitational constant of this little universe, m^3 / (kg s^2) */
const G = 1;

interface Attractor {
  body: Body;
  /** the mass its gravity acts with, kg */
  mass: number;
}

export const planetsDemo: Demo = {
  id: 'planets',
  title: 'Planets',
  description:
    'No world gravity: every step a preStep handler pulls each body towards the sun and the two planets with F = G m M / r² through body.applyForce. A ring of rocks orbits and collides.',
  view: { center: { x: 0, y: 0 }, halfHeight: 34 },
  create: (ctx) => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const random = createRandom(11);
    const sunMass = 6000;
    const sun = world.createBody({ position: { x: 0, y: 0 } });
    sun.createShape(Shape.circle(3));
    ctx.render.setBodyStyle(sun, { color: 0xf3c053 });
    const attractors: Attractor[] = [{ body: sun, mass: sunMass }];

    const orbit = (r: number) => Math.sqrt((G * sunMass) / r);
    for (const [radius, size, color, mass] of [
      [14, 1.2, 0x6fb3d9, 150],
      [26, 1.6, 0xd9695f, 300],
    ] as const) {
      const planet = world.createBody({
        type: 'dynamic',
        position: { x: radius, y: 0 },
        linearVelocity: { x: 0, y: orbit(radius) },
        angularVelocity: 0.5,
      });
      planet.createShape(Shape.circle(size), { density: mass / (Math.PI * size * size) });
      ctx.render.setBodyStyle(planet, { color });
      attractors.push({ body: planet, mass });
    }

    // a ring of rocks between the planets
    for (let i = 0; i < 160; i++) {
      const angle = (2 * Math.PI * i) / 160 + random.range(-0.01, 0.01);
      const r = random.range(18.5, 22);
      const v = orbit(r);
      const rock = world.createBody({
        type: 'dynamic',
        position: { x: r * Math.cos(angle), y: r * Math.sin(angle) },
        linearVelocity: { x: -v * Math.sin(angle), y: v * Math.cos(angle) },
        angle: random.range(0, 6),
      });
      const size = random.range(0.15, 0.35);
      rock.createShape(
        i % 3 === 0 ? Shape.circle(size) : Shape.polygon(regularPolygon(3 + (i % 4), size * 1.3), 0.02),
        { density: 2, friction: 0.4, restitution: 0.2 },
      );
    }

    ctx.track(
      world.on('preStep', () => {
        for (const body of world.bodies) {
          if (body.type !== 'dynamic') continue;
          const p = body.worldCenter;
          const m = body.mass;
          let fx = 0;
          let fy = 0;
          for (const a of attractors) {
            if (a.body === body) continue;
            // planets feel the sun only; everything else feels all three
            if (attractors.some((o) => o.body === body) && a.body !== sun) continue;
            const c = a.body.worldCenter;
            const dx = c.x - p.x;
            const dy = c.y - p.y;
            const r2 = Math.max(dx * dx + dy * dy, 1);
            const f = (G * m * a.mass) / r2 / Math.sqrt(r2);
            fx += f * dx;
            fy += f * dy;
          }
          body.applyForce({ x: fx, y: fy });
        }
      }),
    );
    return { world };
  },
};
