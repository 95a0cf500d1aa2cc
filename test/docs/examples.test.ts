/**
 * The docs' code: every block in the guides is a file in docs/examples (included into the page), and
 * each one runs here and does what its page says. The browser-only examples (canvas, PixiJS) are
 * typechecked with the rest and run in Chromium by test/e2e/docs.e2e.test.ts.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';

const DOCS = resolve(__dirname, '../../docs');
const EXAMPLES = join(DOCS, 'examples');
/** Run in the browser by the e2e test. */
// run in the browser by the e2e tests, and script-tag.html by npm run pack:check against the packed package
const BROWSER_EXAMPLES = [
  'canvas-render.ts',
  'pixi-render.ts',
  'canvas.html',
  'script-tag.html',
  // run by test/e2e/worker-stress.test.ts, on a cross-origin isolated page
  'worker-render.ts',
];

// the examples print what they show; keep the test output to the results
beforeAll(() => {
  vi.spyOn(console, 'log').mockImplementation(() => {});
});
afterAll(() => {
  vi.restoreAllMocks();
});

const G = 10;

describe('docs examples', () => {
  it('worker: a world in a worker drops its ball as a World on this thread does, bit for bit', async () => {
    const { dropInAWorker } = await import('../../docs/examples/worker');
    const { workerScript } = await import('../helpers/worker-script');
    const result = await dropInAWorker({ url: workerScript() });
    expect(result.same).toBe(true);
    expect(result.y).toBe(result.twinY);
    // restitution 0.5 from 4 m up: it bounces, and after 2 s it is back near the ground (y = 1)
    expect(result.bounces).toBeGreaterThan(0);
    expect(result.y).toBeGreaterThan(0.99);
    expect(result.y).toBeLessThan(2.5);
  });

  it('worker joints: a hinge in a worker holds its bob’s weight, and four times it once the bob is scaled by 2', async () => {
    const { hangInAWorker } = await import('../../docs/examples/worker-joints');
    const { workerScript } = await import('../helpers/worker-script');
    const { before, after } = await hangInAWorker({ url: workerScript() });
    // at rest under the pivot, the hinge pulls the bob up with its weight
    expect(before.mass).toBeCloseTo(4 * Math.PI * 0.25 ** 2, 12);
    expect(before.force.y).toBeCloseTo(before.mass * G, 6);
    expect(before.force.x).toBeCloseTo(0, 9);
    expect(before.angle).toBeCloseTo(0, 9);
    // twice the radius, four times the area and the mass
    expect(after.geometry).toMatchObject({ type: 'circle', radius: 0.5 });
    expect(after.mass).toBeCloseTo(4 * before.mass, 12);
    expect(after.force.y).toBeCloseTo(after.mass * G, 6);
  });

  it('workers: a pyramid stepped by two threads is bit for bit the one stepped by one', async () => {
    const { pyramidOnTwoThreads } = await import('../../docs/examples/workers-step');
    const { workerScript } = await import('../helpers/worker-script');
    const result = await pyramidOnTwoThreads(workerScript('test/worker/fixtures/solver-source-entry.mjs'));
    expect(result.threads).toBe(2);
    expect(result.same).toBe(true);
    // the ground and 40 + 39 + ... + 1 boxes
    expect(result.bodies).toBe(1 + (40 * 41) / 2);
  });

  it('hello world: the ball comes to rest on the ground, half a metre up', async () => {
    const { ball, touches } = await import('../../docs/examples/hello-world');
    expect(ball.position.x).toBe(0);
    expect(ball.position.y).toBeCloseTo(0.5, 3); // the ground's top is y = 0, the radius 0.5
    expect(ball.isAwake).toBe(false);
    expect(touches).toBeGreaterThan(1); // restitution 0.5: it bounces before it settles
  });

  it('units: a world in pixels rests its 1 m crate at 25 px with a mass of 1 kg', async () => {
    const { crate, PX } = await import('../../docs/examples/units-pixels');
    expect(crate.mass).toBeCloseTo(1, 12);
    expect(crate.position.y).toBeCloseTo(0.5 * PX, 1);
  });

  it('units: screen and world coordinates round-trip, y flipped', async () => {
    const { toScreen, toWorld } = await import('../../docs/examples/units-screen');
    const view = { scale: 40, origin: { x: -10, y: 15 } };
    expect(toScreen(view, { x: -10, y: 15 })).toEqual({ x: 0, y: 0 });
    expect(toScreen(view, { x: 0, y: 0 })).toEqual({ x: 400, y: 600 });
    const back = toWorld(view, toScreen(view, { x: 1.25, y: -3.5 }));
    expect(back.x).toBeCloseTo(1.25, 12);
    expect(back.y).toBeCloseTo(-3.5, 12);
  });

  it('bodies and shapes: masses from density, the kinematic platform moves 1 m in 1 s', async () => {
    const { ball, box, pill, platform, wedge } = await import('../../docs/examples/bodies-and-shapes');
    expect(box.mass).toBeCloseTo(2 * (1 * 0.5), 12);
    expect(ball.mass).toBeCloseTo(Math.PI * 0.25, 12);
    expect(pill.mass).toBeCloseTo(1 * 0.5 + Math.PI * 0.25 * 0.25, 12); // rectangle + two half discs
    expect(wedge.mass).toBeGreaterThan(0.4); // the triangle (0.4 m²) plus its rounded rim
    expect(platform.position.x).toBeCloseTo(1, 9);
    for (const body of [ball, pill, wedge]) expect(body.position.y).toBeGreaterThan(0); // on the segment
  });

  it('compound: the hammer weighs 5 kg with its centre of mass 0.48 m up the handle', async () => {
    const { hammer } = await import('../../docs/examples/compound');
    expect(hammer.mass).toBeCloseTo(5, 12);
    expect(hammer.worldCenter.x).toBeCloseTo(0, 12);
    expect(hammer.worldCenter.y).toBeCloseTo(2 + (0 * 1 + 0.6 * 4) / 5, 12);
  });

  it('SVG paths: the valley drawn in pixels lands upright in metres, the crate rests at its bottom', async () => {
    const { box, crate, terrain } = await import('../../docs/examples/svg-path');
    expect(terrain.closed).toBe(false);
    expect(terrain.points[0]).toEqual({ x: 0, y: -2 });
    expect(terrain.points[terrain.points.length - 1]).toEqual({ x: 8, y: -2 });
    // the valley's floor: Q from (2, -2) by (4, -4) to (6, -2) is the parabola y = -3 + (x - 4)^2 / 4
    for (const p of terrain.points) {
      const y = p.x < 2 || p.x > 6 ? -2 : -3 + (p.x - 4) ** 2 / 4;
      expect(p.y).toBeCloseTo(y, 12);
    }
    expect(crate).toEqual({
      points: [
        { x: -0.4, y: 0.2 },
        { x: 0.4, y: 0.2 },
        { x: 0.4, y: -0.2 },
        { x: -0.4, y: -0.2 },
      ],
      closed: true,
    });
    // on the curve itself the crate's corners (x = 4 +- 0.4) would sit at -3 + 0.04 and its centre
    // 0.2 higher; the chords lie above the curve by at most the tolerance (1 px = 0.02 m), and the
    // contact margin (linear slop, 0.005 m) allows that much overlap
    expect(box.position.x).toBeCloseTo(4, 2);
    expect(box.position.y).toBeGreaterThanOrEqual(-2.76 - 0.005);
    expect(box.position.y).toBeLessThanOrEqual(-2.76 + 0.02);
    expect(box.isAwake).toBe(false);
  });

  it('svgShapes: the hills are a chain facing up, the crate lands on them', async () => {
    const { box, hills, pieces, segments } = await import('../../docs/examples/svg-shapes');
    expect(hills.type === 'chain' ? hills.points[0] : null).toEqual({ x: 8, y: -6 }); // reversed: it faces up
    expect(segments.length).toBeGreaterThan(3);
    expect(pieces).toHaveLength(1);
    // the crate (0.8 m square) came to rest on the hills: its centre 0.4 m above the chain's line
    // (a little more vertically, on the slope)
    const points = hills.type === 'chain' ? hills.points : [];
    const c = box.worldCenter;
    const i = points.findIndex((p, k) => k + 1 < points.length && p.x >= c.x && points[k + 1].x <= c.x);
    const [a, b] = [points[i], points[i + 1]];
    const lineY = a.y + ((b.y - a.y) * (c.x - a.x)) / (b.x - a.x);
    expect(c.y - lineY).toBeGreaterThan(0.395);
    expect(c.y - lineY).toBeLessThan(0.42);
    expect(Math.hypot(box.linearVelocity.x, box.linearVelocity.y)).toBeLessThan(0.01);
  });

  it('chains: the ball rolls over the hills, the box jumps onto the one-way platform, the marble stays in the loop', async () => {
    const { ball, jumper, marble, segments } = await import('../../docs/examples/chain');
    expect(segments).toHaveLength(160);
    expect(ball.position.x).toBeGreaterThan(-5);
    // on the curve y = 0.3 cos x: the centre 0.3 m along the normal from it
    const x = ball.position.x;
    const slope = -0.3 * Math.sin(x);
    const height = (ball.position.y - 0.3 * Math.cos(x)) * (1 / Math.sqrt(1 + slope * slope));
    expect(Math.abs(height - 0.3)).toBeLessThan(0.01);
    expect(jumper.position.y).toBeCloseTo(3.4, 2);
    expect(marble.position.y).toBeCloseTo(-1.5, 2);
  });

  it('concave: the L weighs its 1.75 m², rests on the ground and sleeps; the cup holds the ball', async () => {
    const { ball, cup, cupPieces, l, pieces, refusal } = await import('../../docs/examples/concave');
    expect(pieces.length).toBe(2);
    expect(l.mass).toBeCloseTo(2 * 1.75, 12);
    // the L as two rectangles: [0, 2] x [0, 0.5] (1 m²) and [0, 0.5] x [0.5, 2] (0.75 m²)
    expect(l.localCenter.x).toBeCloseTo((1 * 1 + 0.75 * 0.25) / 1.75, 12);
    expect(l.localCenter.y).toBeCloseTo((1 * 0.25 + 0.75 * 1.25) / 1.75, 12);
    expect(l.position.y).toBeCloseTo(0, 2); // its bottom edge on the ground's top
    expect(l.isAwake).toBe(false);
    expect(refusal).toContain('Shape.concave');
    expect(cup.shapes.length).toBe(cupPieces.length);
    expect(ball.position.y).toBeCloseTo(0.5 + 0.4, 2); // on the cup's floor, between its walls
    expect(Math.abs(ball.position.x - 2)).toBeLessThan(0.6);
  });

  it('joints: the pendulum keeps its 1 m arm and the speed its fall gives it', async () => {
    const { arm, speed, bob } = await import('../../docs/examples/joints');
    expect(Math.abs(arm - 1)).toBeLessThan(1e-3);
    const fallSpeed = Math.sqrt(2 * G * (10 - bob.position.y)); // energy conservation
    expect(Math.abs(speed - fallSpeed) / fallSpeed).toBeLessThan(0.01);
  });

  it("joints: a Hooke's-law spring of 200 N/m holds 2 kg 0.1 m below its rest length", async () => {
    const { hertz, dampingRatio, weight, springFromHooke } = await import('../../docs/examples/hooke');
    expect(weight.mass).toBeCloseTo(2, 12);
    expect(hertz).toBeCloseTo(Math.sqrt(200 / 2) / (2 * Math.PI), 12);
    expect(dampingRatio).toBeCloseTo(20 / (2 * Math.sqrt(200 * 2)), 12);
    // static extension mg / k below the rest length of 1 m under the hook at y = 5
    expect(weight.position.y).toBeCloseTo(5 - 1 - (2 * G) / 200, 3);
    // two bodies: the reduced mass
    expect(springFromHooke(100, 0, 2, 2).hertz).toBeCloseTo(Math.sqrt(100 / 1) / (2 * Math.PI), 12);
  });

  it('events: one begin with an upward normal, a hit at sqrt(2 g h) = 10 m/s, then sleep', async () => {
    const { ball, hitSpeeds, log, world } = await import('../../docs/examples/events');
    expect(log).toEqual(['begin, normal 0 1', 'sleep true']);
    expect(hitSpeeds.length).toBe(1);
    expect(hitSpeeds[0]).toBeCloseTo(Math.sqrt(2 * G * 5), 6);
    expect(world.events.contactBegin.length).toBe(0);
    expect(ball.isAwake).toBe(false);
  });

  it('queries: ray, ray-all, box, point and shape cast find what the page says', async () => {
    const { all, cast, hit, inBox, underPoint } = await import('../../docs/examples/queries');
    expect(hit).not.toBeNull();
    expect(hit!.point.x).toBeCloseTo(0, 9);
    expect(hit!.point.y).toBeCloseTo(1, 9);
    expect(hit!.normal).toEqual({ x: 0, y: 1 });
    expect(hit!.fraction).toBeCloseTo(9 / 20, 9);
    expect(all.length).toBe(5);
    for (let i = 1; i < all.length; i++) expect(all[i].fraction).toBeGreaterThan(all[i - 1].fraction);
    expect(inBox.length).toBe(3); // crates at x = -2, 0, 2
    expect(underPoint.length).toBe(1);
    expect(cast!.point.x).toBeCloseTo(1, 6);
    expect(cast!.point.y).toBeCloseTo(0, 6);
  });

  it('sensors and filtering: the player visits the sensor, the ghosts pass through each other', async () => {
    const { ghostA, ghostB, player, visitors } = await import('../../docs/examples/sensors-filtering');
    expect([...visitors]).toEqual(['player']);
    expect(player.position.y).toBeCloseTo(0.4, 3); // fell through the sensor onto the ground
    // both ghosts rest on the ground at the same spot, overlapping each other
    expect(ghostA.position.y).toBeCloseTo(0.5, 3);
    expect(ghostB.position.y).toBeCloseTo(0.5, 3);
    expect(ghostA.position.x).toBe(ghostB.position.x);
  });

  it('sleeping: a box at rest sleeps after half a second; an impulse wakes it', async () => {
    const { box, sleptAt } = await import('../../docs/examples/sleeping');
    expect(sleptAt).toBe(30);
    expect(box.isAwake).toBe(true);
  });

  it('continuous collision: the bullet stops at the wall, and passes it without CCD', async () => {
    const { shoot, fireBullet } = await import('../../docs/examples/continuous');
    expect(shoot(true)).toBeCloseTo(5 - 0.05 - 0.1, 3);
    expect(shoot(false)).toBeGreaterThan(5.05);
    const { World } = await import('../../src/index');
    const world = new World();
    expect(fireBullet(world).linearVelocity.x).toBe(300);
  });

  it('determinism: twin worlds and a restored snapshot give the same hash', async () => {
    const { a, b, bytes, c } = await import('../../docs/examples/determinism');
    const { stateHash } = await import('../../src/index');
    expect(bytes.length).toBe(75779);
    expect(stateHash(c)).toBe(stateHash(a));
    expect(b.bodyCount).toBe(a.bodyCount);
  });

  it('Phaser: sprites follow their bodies in pixels, y down, angles negated', async () => {
    const { createPhysics } = await import('../../docs/examples/phaser-scene');
    const made: { x: number; y: number; rotation: number }[] = [];
    const scene = {
      add: {
        rectangle: () => {
          const object = {
            x: 0,
            y: 0,
            rotation: 0,
            setPosition(x: number, y: number) {
              object.x = x;
              object.y = y;
            },
            setRotation(r: number) {
              object.rotation = r;
            },
          };
          made.push(object);
          return object;
        },
      },
    };
    const { sprites, update, world } = createPhysics(scene);
    expect(made.length).toBe(11); // the ground and ten crates
    for (let i = 0; i < 60; i++) update(1000 / 60);
    expect(world.bodyCount).toBe(11);
    for (const [body, object] of sprites) {
      const sprite = object as unknown as { x: number; y: number; rotation: number };
      expect(sprite.x).toBeCloseTo(body.position.x * 50, 9);
      expect(sprite.y).toBeCloseTo(600 - body.position.y * 50, 9);
      expect(sprite.rotation).toBe(-body.angle);
    }
  });

  it('p5.js: the sketch steps once per frame and draws each ball where its body is', async () => {
    const { sketch } = await import('../../docs/examples/p5-sketch');
    const circles: { x: number; y: number }[] = [];
    let offset = { x: 0, y: 0 };
    const stack: { x: number; y: number }[] = [];
    const p = {
      setup: () => {},
      draw: () => {},
      width: 800,
      height: 400,
      createCanvas: () => {},
      background: () => {},
      push: () => stack.push({ ...offset }),
      pop: () => {
        offset = stack.pop()!;
      },
      translate: (x: number, y: number) => {
        offset = { x: offset.x + x, y: offset.y + y };
      },
      rotate: () => {},
      rectMode: () => {},
      rect: () => {},
      circle: () => circles.push({ ...offset }),
    };
    const world = sketch(p);
    p.setup();
    for (let i = 0; i < 30; i++) {
      circles.length = 0;
      p.draw();
    }
    const balls = [...world.bodies].filter((b) => b.type === 'dynamic');
    expect(circles.length).toBe(balls.length);
    balls.forEach((ball, i) => {
      expect(circles[i].x).toBeCloseTo(ball.position.x * 40, 9);
      expect(circles[i].y).toBeCloseTo(400 - ball.position.y * 40, 9);
    });
  });

  it('from matter.js: the ball lands at x 516 px, its centre 20 px above the ground', async () => {
    const { landedAt, toPixels, toWorld } = await import('../../docs/examples/from-matter');
    const at = landedAt as { x: number; y: number } | null;
    expect(at).not.toBeNull();
    const fallTime = Math.sqrt((2 * 4.7) / G); // from y 100 px to 560 px at 100 px/m
    expect(Math.abs(at!.x - (400 + 120 * fallTime))).toBeLessThan(2); // a step's motion is 2 px
    expect(at!.y).toBeCloseTo(560, 0);
    const p = toPixels(toWorld(123, 456));
    expect(p.x).toBeCloseTo(123, 9);
    expect(p.y).toBeCloseTo(456, 9);
  });

  it('from planck / Box2D: the box rests on the edge, the motor turns at its speed', async () => {
    const { box, contacts, wheel } = await import('../../docs/examples/from-box2d');
    expect(box.position.y).toBeCloseTo(1, 3);
    expect(wheel.angularVelocity).toBeCloseTo(1, 6);
    expect(contacts).toBe(1);
  });
});

describe('docs pages', () => {
  const pages = readdirSync(DOCS, { recursive: true, encoding: 'utf8' })
    .filter((f) => f.endsWith('.md') && !f.startsWith('api') && !f.includes('node_modules'))
    .map((f) => ({ file: f, text: readFileSync(join(DOCS, f), 'utf8') }));

  it('show code only from docs/examples, and every included file and region exists', () => {
    expect(pages.length).toBeGreaterThan(15);
    for (const { file, text } of pages) {
      // code in ts, js or html is always an included file, never typed into the page (the API
      // contract's signatures are a notation, not code to run)
      if (!file.endsWith('api-contract.md'))
        expect(text, file).not.toMatch(/^```(ts|js|typescript|javascript|html)\b/m);
      for (const m of text.matchAll(/^<<< @\/examples\/([\w.-]+?)(?:#(\w+))?(?:\{.*\})?$/gm)) {
        const source = readFileSync(join(EXAMPLES, m[1]), 'utf8');
        if (m[2]) expect(source, `${file}: ${m[0]}`).toContain(`// #region ${m[2]}`);
      }
    }
  });

  it('every example is included by a page and run by a test', () => {
    const included = new Set(
      pages.flatMap(({ text }) =>
        [...text.matchAll(/^<<< @\/examples\/([\w.-]+?)(?:#|\{|$)/gm)].map((m) => m[1]),
      ),
    );
    const tested = readFileSync(__filename, 'utf8');
    for (const file of readdirSync(EXAMPLES)) {
      expect(included.has(file), `${file} is on no page`).toBe(true);
      const runHere = tested.includes(`docs/examples/${file.replace(/\.ts$/, '')}'`);
      expect(runHere || BROWSER_EXAMPLES.includes(file), `${file} is run by no test`).toBe(true);
    }
  });
});
