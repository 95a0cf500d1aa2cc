/**
 * A little solar system with no world gravity: each step a preStep handler pulls every body towards
 * the sun and the two planets (F = G m M / r², body.applyForce). Press and drag to throw a rock: the
 * dotted line shows where it will go; each rock leaves a trail of its path. A rock that falls into
 * the sun burns up; one flung away for good is let go.
 */
import { createRandom } from '../../scenes/index';
import { type Body, Shape, type Vec2, World } from '../../src/index';
import type { Demo } from '../demo';
import { capturePointer, drawnPosition, regularPolygon, stepHook } from '../lib';

/** gravitational constant of this little universe, m^3 / (kg s^2) */
const G = 1;
export const SUN_MASS = 6000;
const SUN_RADIUS = 3.5;
/** a throw's speed per metre of drag, 1/s */
export const FLING = 3;
/** the trail: one point every TRAIL_EVERY steps, TRAIL_POINTS of them */
const TRAIL_EVERY = 2;
const TRAIL_POINTS = 70;
/** a rock farther than this from the sun is let go, m */
const AWAY = 150;
/** how far along its step's path a body's pull is taken, as a share of the step (see preStep) */
const LOOK_AHEAD = 0.35;
/** steps of the thrown path's preview */
const PREVIEW_STEPS = 240;

interface Attractor {
  body: Body;
  /** the mass its gravity acts with, kg */
  mass: number;
}

interface Rock {
  body: Body;
  outline: readonly Vec2[];
  color: string;
  /** the trail's points, x and y, oldest overwritten first */
  trail: Float32Array;
  trailCount: number;
  trailHead: number;
}

/** The speed of a circular orbit of radius r about the sun. */
export function orbitSpeed(r: number): number {
  return Math.sqrt((G * SUN_MASS) / r);
}

const rockColors = ['#b7a58c', '#9d8f80', '#c2916a', '#8f9aa6', '#a8866a'];

export const planetsDemo: Demo = {
  id: 'planets',
  title: 'Planets',
  description:
    'No world gravity: every step a preStep handler pulls each body towards the sun and the two planets with F = G m M / r² through body.applyForce. Press and drag to throw a rock (the dotted line shows its path): thrown across the sun fast enough, it orbits. Rocks leave trails, collide, and burn up in the sun.',
  view: { center: { x: 0, y: 0 }, halfHeight: 24 },
  fitWidth: 21,
  fitAnchor: 'center',
  flags: { shapes: false, joints: false, sleeping: false },
  create: (ctx) => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const random = createRandom(11);
    const sun = world.createBody({ position: { x: 0, y: 0 } });
    sun.createShape(Shape.circle(SUN_RADIUS));
    const attractors: Attractor[] = [{ body: sun, mass: SUN_MASS }];
    const planets: { body: Body; radius: number; light: string; dark: string }[] = [];
    for (const [radius, size, mass, light, dark] of [
      [12, 1.3, 40, '#8fd0f5', '#1f5f9a'],
      [20, 1.8, 90, '#f2a275', '#8a3522'],
    ] as const) {
      const planet = world.createBody({
        type: 'dynamic',
        position: { x: radius, y: 0 },
        linearVelocity: { x: 0, y: orbitSpeed(radius) },
        angularVelocity: 0.5,
      });
      planet.createShape(Shape.circle(size), { density: mass / (Math.PI * size * size) });
      attractors.push({ body: planet, mass });
      planets.push({ body: planet, radius: size, light, dark });
    }
    const isPlanet = (body: Body) => body === planets[0].body || body === planets[1].body;

    const rocks: Rock[] = [];
    const addRock = (position: Vec2, velocity: Vec2, size: number): Rock => {
      const body = world.createBody({
        type: 'dynamic',
        position,
        linearVelocity: velocity,
        angle: random.range(0, 6),
        angularVelocity: random.range(-1, 1),
      });
      const outline = regularPolygon(5 + (rocks.length % 4), size);
      body.createShape(Shape.polygon(outline, 0.05), { density: 2, friction: 0.4, restitution: 0.3 });
      const rock: Rock = {
        body,
        outline,
        color: rockColors[rocks.length % rockColors.length],
        trail: new Float32Array(2 * TRAIL_POINTS),
        trailCount: 0,
        trailHead: 0,
      };
      rocks.push(rock);
      return rock;
    };
    // a loose ring of rocks between the planets
    for (let i = 0; i < 18; i++) {
      const angle = (2 * Math.PI * i) / 18 + random.range(-0.05, 0.05);
      const r = random.range(15, 17);
      const v = orbitSpeed(r);
      addRock(
        { x: r * Math.cos(angle), y: r * Math.sin(angle) },
        { x: -v * Math.sin(angle), y: v * Math.cos(angle) },
        random.range(0.5, 0.8),
      );
    }

    /** the pull of the attractors on a body of mass m at p, into `out` */
    const pull = (p: Vec2, m: number, self: Body | null, out: Vec2) => {
      out.x = 0;
      out.y = 0;
      for (const a of attractors) {
        if (a.body === self) continue;
        // planets feel the sun only; everything else feels all three
        if (self && isPlanet(self) && a.body !== sun) continue;
        const c = a.body.worldCenter;
        const dx = c.x - p.x;
        const dy = c.y - p.y;
        const r2 = Math.max(dx * dx + dy * dy, 1);
        const f = (G * m * a.mass) / r2 / Math.sqrt(r2);
        out.x += f * dx;
        out.y += f * dy;
      }
    };
    const force = { x: 0, y: 0 };
    const ahead = { x: 0, y: 0 };
    ctx.track(
      world.on('preStep', ({ dt }) => {
        for (const body of world.bodies) {
          if (body.type !== 'dynamic') continue;
          // A force holds for a whole step while the body crosses it: taken where the body starts, an
          // orbit gains energy every turn (a rock thrown at 6.5 m drifted out to 15.8 m in 600 steps).
          // Taken a third of the way along, it keeps (measured: 6.5 to 8.5 m; a circle is 6.5 to 7.5).
          const c = body.worldCenter;
          const v = body.linearVelocity;
          ahead.x = c.x + v.x * dt * LOOK_AHEAD;
          ahead.y = c.y + v.y * dt * LOOK_AHEAD;
          pull(ahead, body.mass, body, force);
          body.applyForce(force);
        }
      }),
    );

    // rocks that touch the sun burn up; rocks far away are let go
    const burning = new Set<Body>();
    const flares: { x: number; y: number; age: number }[] = [];
    ctx.track(
      world.on('contactBegin', (e) => {
        const a = e.shapeA.body;
        const b = e.shapeB.body;
        if (a === sun && !isPlanet(b)) burning.add(b);
        if (b === sun && !isPlanet(a)) burning.add(a);
      }),
    );
    let steps = 0;
    ctx.track(
      world.on('postStep', () => {
        steps++;
        for (let i = flares.length - 1; i >= 0; i--) if (++flares[i].age > 40) flares.splice(i, 1);
        for (let i = rocks.length - 1; i >= 0; i--) {
          const rock = rocks[i];
          const p = rock.body.position;
          if (burning.has(rock.body) || p.x * p.x + p.y * p.y > AWAY * AWAY) {
            if (burning.has(rock.body)) flares.push({ x: p.x, y: p.y, age: 0 });
            world.destroyBody(rock.body);
            rocks.splice(i, 1);
            continue;
          }
          if (steps % TRAIL_EVERY === 0) {
            rock.trail[2 * rock.trailHead] = p.x;
            rock.trail[2 * rock.trailHead + 1] = p.y;
            rock.trailHead = (rock.trailHead + 1) % TRAIL_POINTS;
            rock.trailCount = Math.min(TRAIL_POINTS, rock.trailCount + 1);
          }
        }
        burning.clear();
      }),
    );

    // the throw: press where the rock starts, drag the way and as far as it should fly
    let press: Vec2 | null = null;
    let hand: Vec2 | null = null;
    let thrown = 0;
    ctx.pointer.filter = () => false;
    ctx.track(
      ctx.pointer.on('down', (e) => {
        if (e.event.button !== 0) return;
        const p = e.point;
        if (p.x * p.x + p.y * p.y < (SUN_RADIUS + 1) * (SUN_RADIUS + 1)) return;
        press = p;
        hand = p;
        e.handled = true;
        capturePointer(ctx, e.event);
      }),
    );
    ctx.track(
      ctx.pointer.on('move', (e) => {
        if (press) hand = e.point;
      }),
    );
    ctx.track(
      ctx.pointer.on('up', (e) => {
        if (!press) return;
        const from = press;
        press = null;
        hand = null;
        addRock(from, { x: FLING * (e.point.x - from.x), y: FLING * (e.point.y - from.y) }, 0.9);
        thrown++;
      }),
    );

    // the picture: space, the sun's glow, trails, planets, rocks, the throw's preview
    const random2 = createRandom(5);
    const stars: number[] = [];
    for (let i = 0; i < 220; i++)
      stars.push(random2.range(-90, 90), random2.range(-50, 50), random2.range(0.2, 1));
    const preview = new Float32Array(2 * PREVIEW_STEPS);
    const previewPoint = { x: 0, y: 0 };
    const previewVelocity = { x: 0, y: 0 };
    const xf = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        const c = render.context;
        const pixel = 1 / render.camera.scale;
        render.setWorldTransform();
        c.fillStyle = '#05060d';
        c.fillRect(-400, -400, 800, 800);
        for (let i = 0; i < stars.length; i += 3) {
          c.fillStyle = `rgba(220, 230, 255, ${stars[i + 2] * 0.8})`;
          c.fillRect(
            stars[i],
            stars[i + 1],
            2 * pixel * stars[i + 2] + pixel,
            2 * pixel * stars[i + 2] + pixel,
          );
        }
        // the sun and its glow
        const glow = c.createRadialGradient(0, 0, SUN_RADIUS * 0.6, 0, 0, SUN_RADIUS * 3.2);
        glow.addColorStop(0, 'rgba(255, 210, 110, 0.55)');
        glow.addColorStop(1, 'rgba(255, 140, 40, 0)');
        c.fillStyle = glow;
        c.beginPath();
        c.arc(0, 0, SUN_RADIUS * 3.2, 0, 2 * Math.PI);
        c.fill();
        const face = c.createRadialGradient(-1, 1, 0.3, 0, 0, SUN_RADIUS);
        face.addColorStop(0, '#fff6c8');
        face.addColorStop(0.6, '#ffd25a');
        face.addColorStop(1, '#f08a24');
        c.fillStyle = face;
        c.beginPath();
        c.arc(0, 0, SUN_RADIUS, 0, 2 * Math.PI);
        c.fill();
        // trails, fading towards their oldest point
        c.lineCap = 'round';
        c.lineWidth = 2 * pixel;
        for (const rock of rocks) {
          const n = rock.trailCount;
          for (let k = 1; k < n; k++) {
            const i0 = (rock.trailHead - n + k - 1 + TRAIL_POINTS) % TRAIL_POINTS;
            const i1 = (i0 + 1) % TRAIL_POINTS;
            c.strokeStyle = `rgba(150, 190, 255, ${(0.5 * k) / n})`;
            c.beginPath();
            c.moveTo(rock.trail[2 * i0], rock.trail[2 * i0 + 1]);
            c.lineTo(rock.trail[2 * i1], rock.trail[2 * i1 + 1]);
            c.stroke();
          }
        }
        // planets, lit from the sun
        for (const planet of planets) {
          const p = drawnPosition(ctx.runner, planet.body);
          const d = Math.hypot(p.x, p.y) || 1;
          const lx = (-p.x / d) * planet.radius * 0.5;
          const ly = (-p.y / d) * planet.radius * 0.5;
          const g = c.createRadialGradient(p.x + lx, p.y + ly, planet.radius * 0.1, p.x, p.y, planet.radius);
          g.addColorStop(0, planet.light);
          g.addColorStop(1, planet.dark);
          c.fillStyle = g;
          c.beginPath();
          c.arc(p.x, p.y, planet.radius, 0, 2 * Math.PI);
          c.fill();
        }
        // rocks, their sunny side lighter
        for (const rock of rocks) {
          const t = ctx.runner.interpolate ? ctx.runner.interpolator.transformOf(rock.body, xf) : null;
          const p = t ? t.p : rock.body.position;
          const q = t ? t.q : { c: Math.cos(rock.body.angle), s: Math.sin(rock.body.angle) };
          // lit from the sun: the gradient runs, in the rock's own frame, from its sunny side to its night side
          const d = Math.hypot(p.x, p.y) || 1;
          const ux = -p.x / d;
          const uy = -p.y / d;
          const lx = q.c * ux + q.s * uy;
          const ly = -q.s * ux + q.c * uy;
          c.save();
          c.transform(q.c, q.s, -q.s, q.c, p.x, p.y);
          const shade = c.createLinearGradient(lx, ly, -lx, -ly);
          shade.addColorStop(0, rock.color);
          shade.addColorStop(1, '#2a2630');
          c.fillStyle = shade;
          c.strokeStyle = 'rgba(0, 0, 0, 0.45)';
          c.lineWidth = 1.5 * pixel;
          c.beginPath();
          for (const [k, v] of rock.outline.entries()) {
            if (k === 0) c.moveTo(v.x, v.y);
            else c.lineTo(v.x, v.y);
          }
          c.closePath();
          c.fill();
          c.stroke();
          c.restore();
        }
        for (const f of flares) {
          const r = 0.5 + f.age * 0.05;
          c.fillStyle = `rgba(255, 200, 90, ${1 - f.age / 40})`;
          c.beginPath();
          c.arc(f.x, f.y, r, 0, 2 * Math.PI);
          c.fill();
        }
        // the throw: the rock in the hand, the arrow of its speed and the dotted path it will take
        if (press && hand) {
          previewPoint.x = press.x;
          previewPoint.y = press.y;
          previewVelocity.x = FLING * (hand.x - press.x);
          previewVelocity.y = FLING * (hand.y - press.y);
          const dt = ctx.runner.dt;
          let count = 0;
          for (let k = 0; k < PREVIEW_STEPS; k++) {
            pull(previewPoint, 1, null, force);
            previewVelocity.x += force.x * dt;
            previewVelocity.y += force.y * dt;
            previewPoint.x += previewVelocity.x * dt;
            previewPoint.y += previewVelocity.y * dt;
            preview[2 * k] = previewPoint.x;
            preview[2 * k + 1] = previewPoint.y;
            count++;
            if (previewPoint.x * previewPoint.x + previewPoint.y * previewPoint.y < SUN_RADIUS * SUN_RADIUS)
              break;
          }
          c.fillStyle = 'rgba(255, 255, 255, 0.7)';
          for (let k = 2; k < count; k += 3) {
            c.beginPath();
            c.arc(preview[2 * k], preview[2 * k + 1], 1.8 * pixel, 0, 2 * Math.PI);
            c.fill();
          }
          c.strokeStyle = '#ffd25a';
          c.lineWidth = 3 * pixel;
          c.beginPath();
          c.moveTo(press.x, press.y);
          c.lineTo(hand.x, hand.y);
          c.stroke();
          c.fillStyle = rockColors[rocks.length % rockColors.length];
          c.beginPath();
          c.arc(press.x, press.y, 0.9, 0, 2 * Math.PI);
          c.fill();
        }
        render.setScreenTransform();
      }),
    );
    const advance = stepHook(ctx.runner);
    return {
      world,
      sun,
      rocks,
      thrown: () => thrown,
      /** the body of the rock thrown last */
      lastRock: () => rocks[rocks.length - 1]?.body ?? null,
      advance,
    };
  },
};
