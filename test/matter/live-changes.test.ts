import { describe, expect, it } from 'vitest';
import FulcrumMatter from '../../src/matter/index';
import { both, run } from '../helpers/matter-both';

describe("fulcrum/matter keeps matter's masses", () => {
  it('a torque turns a body as much as on matter.js (matter gives every body 4 times its inertia)', () => {
    const spins: number[] = [];
    for (const [, Matter] of both) {
      const engine = Matter.Engine.create();
      engine.gravity.y = 0;
      const box = Matter.Bodies.rectangle(0, 0, 80, 40, { frictionAir: 0 });
      Matter.Composite.add(engine.world, box);
      run(Matter, engine, 1);
      // a force at the box's end, across it: torque = 40 px times 0.01
      Matter.Body.applyForce(box, { x: 40, y: 0 }, { x: 0, y: 0.01 });
      run(Matter, engine, 1);
      spins.push(box.angularVelocity);
    }
    // matter: w = torque / inertia * dt^2 per update (dt = 1000/60 ms), inertia = 4 * m (w^2 + h^2) / 12
    const [matter, layer] = spins;
    const mass = 80 * 40 * 0.001;
    const expected = ((40 * 0.01) / ((4 * mass * (80 * 80 + 40 * 40)) / 12)) * (1000 / 60) ** 2;
    expect(Math.abs(matter - expected) / expected).toBeLessThan(0.01);
    expect(Math.abs(layer - expected) / expected).toBeLessThan(0.01);
  });

  it('Body.setMass and setInertia on a body in the world change how it answers forces', () => {
    const speeds: number[][] = [];
    for (const [, Matter] of both) {
      const engine = Matter.Engine.create();
      engine.gravity.y = 0;
      const box = Matter.Bodies.rectangle(0, 0, 40, 40, { frictionAir: 0 });
      Matter.Composite.add(engine.world, box);
      run(Matter, engine, 2);
      Matter.Body.setMass(box, 10);
      Matter.Body.setInertia(box, 5000);
      Matter.Body.applyForce(box, { x: 20, y: 0 }, { x: 0.01, y: 0.01 });
      run(Matter, engine, 1);
      speeds.push([box.velocity.x, box.angularVelocity]);
    }
    // v = F / m * dt^2 (1000/60 ms), w = torque / I * dt^2
    const dt2 = (1000 / 60) ** 2;
    for (const [vx, w] of speeds) {
      expect(Math.abs(vx - (0.01 / 10) * dt2) / ((0.01 / 10) * dt2)).toBeLessThan(0.01);
      expect(Math.abs(w - ((20 * 0.01) / 5000) * dt2) / (((20 * 0.01) / 5000) * dt2)).toBeLessThan(0.01);
    }
  });

  it("a spinning body's angle keeps counting turns, as matter's does (it does not wrap at pi)", () => {
    const angles: number[] = [];
    for (const [, Matter] of both) {
      const engine = Matter.Engine.create();
      engine.gravity.y = 0;
      const bar = Matter.Bodies.rectangle(0, 0, 80, 10, { frictionAir: 0 });
      Matter.Composite.add(engine.world, bar);
      Matter.Body.setAngularVelocity(bar, 0.3);
      run(Matter, engine, 60);
      angles.push(bar.angle);
    }
    // 60 updates at 0.3 rad each: 18 rad, almost three turns
    for (const angle of angles) expect(angle).toBeCloseTo(18, 6);
  });

  it('a mass far beyond what shapes reach (Body.setMass 1e40, or 0) keeps the update running, as matter does', () => {
    const Matter = FulcrumMatter;
    const engine = Matter.Engine.create();
    const heavy = Matter.Bodies.rectangle(100, 0, 40, 40);
    const weightless = Matter.Bodies.rectangle(300, 0, 40, 40);
    Matter.Composite.add(engine.world, [heavy, weightless]);
    Matter.Body.setMass(heavy, 1e40);
    Matter.Body.setMass(weightless, 0);
    run(Matter, engine, 30);
    // both fall as gravity says, whatever their mass: 125 px in half a second, less frictionAir
    for (const body of [heavy, weightless]) {
      expect(Number.isFinite(body.position.y)).toBe(true);
      expect(body.position.y).toBeGreaterThan(100);
    }
  });

  it('Body.scale on a body in the world: the new size stays and rests on the ground at its new height', () => {
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const ground = Matter.Bodies.rectangle(400, 620, 800, 40, { isStatic: true });
      const box = Matter.Bodies.rectangle(400, 560, 40, 40);
      Matter.Composite.add(engine.world, [ground, box]);
      run(Matter, engine, 60);
      Matter.Body.scale(box, 2, 1.5);
      run(Matter, engine, 120);
      const width = box.bounds.max.x - box.bounds.min.x;
      const height = box.bounds.max.y - box.bounds.min.y;
      expect(Math.abs(width - 80), name).toBeLessThan(1);
      expect(Math.abs(height - 60), name).toBeLessThan(1);
      // resting on the ground's top (y = 600): centre 30 px above it
      expect(Math.abs(box.position.y - 570), name).toBeLessThan(1);
    }
  });
});

describe('fulcrum/matter follows fields a program sets directly', () => {
  it('collisionFilter.mask set to 0 lets a resting box fall through the ground, as on matter.js', () => {
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const ground = Matter.Bodies.rectangle(400, 620, 800, 40, { isStatic: true });
      const box = Matter.Bodies.rectangle(400, 560, 40, 40);
      Matter.Composite.add(engine.world, [ground, box]);
      run(Matter, engine, 60);
      expect(Math.abs(box.position.y - 580), name).toBeLessThan(1);
      box.collisionFilter.mask = 0;
      run(Matter, engine, 60);
      expect(box.position.y, name).toBeGreaterThan(700);
    }
  });

  it('frictionAir changed on a moving body slows it from then on', () => {
    const speeds: number[] = [];
    for (const [, Matter] of both) {
      const engine = Matter.Engine.create();
      engine.gravity.y = 0;
      const ball = Matter.Bodies.circle(0, 0, 10, { frictionAir: 0 });
      Matter.Composite.add(engine.world, ball);
      Matter.Body.setVelocity(ball, { x: 10, y: 0 });
      run(Matter, engine, 10);
      ball.frictionAir = 0.1;
      run(Matter, engine, 10);
      speeds.push(ball.velocity.x);
    }
    // 10 * 0.9^10 = 3.49
    for (const v of speeds) expect(Math.abs(v - 10 * 0.9 ** 10)).toBeLessThan(0.05);
  });

  it('friction mixes by the smaller: a box of friction 0.01 slides down a slope of friction 1 at g (sin - 0.09 cos)', () => {
    // matter's friction acts as a coefficient of about 9 times its value (see the next test)
    const Matter = FulcrumMatter;
    const engine = Matter.Engine.create();
    const slope = Matter.Bodies.rectangle(400, 400, 800, 40, { isStatic: true, angle: 0.35, friction: 1 });
    const box = Matter.Bodies.rectangle(400, 357.4, 40, 40, { angle: 0.35, friction: 0.01, frictionAir: 0 });
    Matter.Composite.add(engine.world, [slope, box]);
    run(Matter, engine, 10);
    const along = (p: { x: number; y: number }) => p.x * Math.cos(0.35) + p.y * Math.sin(0.35);
    const s0 = along(box.position);
    const v0 = along(box.velocity) * 60;
    run(Matter, engine, 60);
    // 1000 px/s^2 gravity; the slope's own friction (9) would hold the box
    const a = 1000 * (Math.sin(0.35) - 0.09 * Math.cos(0.35));
    const expected = v0 + a / 2;
    expect(Math.abs(along(box.position) - s0 - expected) / expected).toBeLessThan(0.03);
  });

  it("a box slid along the ground stops about where matter's does (matter's friction: a fixed loss of speed per update)", () => {
    for (const friction of [0.05, 0.1]) {
      const distances: number[] = [];
      for (const [, Matter] of both) {
        const engine = Matter.Engine.create();
        const ground = Matter.Bodies.rectangle(2000, 620, 8000, 40, { isStatic: true });
        const box = Matter.Bodies.rectangle(100, 580, 40, 40, { friction, frictionAir: 0 });
        Matter.Composite.add(engine.world, [ground, box]);
        run(Matter, engine, 10);
        Matter.Body.setVelocity(box, { x: 10, y: 0 });
        const x0 = box.position.x;
        run(Matter, engine, 300);
        distances.push(box.position.x - x0);
      }
      // matter: 338 and 196 px; Coulomb's law with the layer's coefficient (9 x friction): 399 and 199
      const [matter, layer] = distances;
      expect(Math.abs(layer - matter) / matter, `friction ${friction}`).toBeLessThan(0.25);
    }
  });
});

describe('fulcrum/matter collision pairs', () => {
  it('a sensor reports its pair (isSensor) on collisionStart and collisionEnd, as on matter.js', () => {
    const seen: Record<string, string[]> = {};
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const sensor = Matter.Bodies.rectangle(400, 300, 400, 60, { isStatic: true, isSensor: true });
      const ball = Matter.Bodies.circle(400, 100, 10, { frictionAir: 0 });
      Matter.Composite.add(engine.world, [sensor, ball]);
      const log: string[] = [];
      let update = 0;
      Matter.Events.on(engine, 'collisionStart', (event) => {
        for (const pair of event.pairs as { isSensor: boolean; bodyA: unknown; bodyB: unknown }[]) {
          expect(pair.isSensor).toBe(true);
          expect([pair.bodyA, pair.bodyB]).toContain(ball);
          log.push(`start ${update}`);
        }
      });
      Matter.Events.on(engine, 'collisionEnd', () => {
        log.push(`end ${update}`);
      });
      for (update = 1; update <= 60; update++) Matter.Engine.update(engine, 1000 / 60);
      // the ball passes through untouched
      expect(ball.position.y, name).toBeGreaterThan(500);
      seen[name] = log;
    }
    expect(seen['fulcrum/matter'].length).toBe(2);
    expect(seen['matter-js'].length).toBe(2);
    // the same update each, give or take one (matter tests overlaps after moving the bodies)
    for (let i = 0; i < 2; i++) {
      const at = (log: string[]) => Number(log[i].split(' ')[1]);
      expect(Math.abs(at(seen['fulcrum/matter']) - at(seen['matter-js']))).toBeLessThanOrEqual(1);
    }
  });

  it("a pair's collision: matter's normal (from bodyB to bodyA), a depth and supports under the box, kept current while active", () => {
    const seen: Record<string, { normal: { x: number; y: number }; depth: number; supportsY: number[] }> = {};
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const ground = Matter.Bodies.rectangle(400, 620, 800, 40, { isStatic: true });
      const box = Matter.Bodies.rectangle(400, 500, 40, 40);
      Matter.Composite.add(engine.world, [ground, box]);
      let updates = 0;
      Matter.Events.on(engine, 'collisionActive', (event) => {
        if (++updates !== 30) return;
        const [pair] = event.pairs as {
          bodyA: unknown;
          bodyB: unknown;
          collision: { normal: { x: number; y: number }; depth: number; supports: { y: number }[] };
        }[];
        // the same sense whichever body is A: from B's side towards A's
        const sign = pair.bodyA === ground ? 1 : -1;
        seen[name] = {
          normal: { x: sign * pair.collision.normal.x, y: sign * pair.collision.normal.y },
          depth: pair.collision.depth,
          supportsY: pair.collision.supports.map((p) => p.y),
        };
      });
      for (let i = 0; i < 90; i++) Matter.Engine.update(engine, 1000 / 60);
    }
    for (const name of ['matter-js', 'fulcrum/matter']) {
      const { normal, depth, supportsY } = seen[name];
      // ground is A: the normal points from the box down to the ground (y down)
      expect(normal.x, name).toBeCloseTo(0, 9);
      expect(normal.y, name).toBeCloseTo(1, 9);
      expect(depth, name).toBeGreaterThanOrEqual(0);
      expect(depth, name).toBeLessThan(1);
      for (const y of supportsY) expect(Math.abs(y - 600), name).toBeLessThan(1);
    }
  });

  it('a part of many corners (several shapes underneath) is one pair: begun with its first shape, ended with its last', () => {
    const Matter = FulcrumMatter;
    const engine = Matter.Engine.create();
    const sensor = Matter.Bodies.rectangle(400, 300, 600, 200, { isStatic: true, isSensor: true });
    // 20 corners: more than a Fulcrum polygon holds, so split into several pieces, which enter and
    // leave the sensor one after the other
    const ball = Matter.Bodies.polygon(400, 100, 20, 40, { frictionAir: 0 });
    Matter.Composite.add(engine.world, [sensor, ball]);
    const log: string[] = [];
    Matter.Events.on(engine, 'collisionStart', () => log.push('start'));
    Matter.Events.on(engine, 'collisionEnd', () => log.push('end'));
    let pieces = 0;
    engine._fulcrum.world.on('sensorBegin', () => {
      pieces++;
    });
    for (let i = 0; i < 60 && log.length < 2; i++) Matter.Engine.update(engine, 1000 / 60);
    expect(ball.parts.length).toBe(1);
    expect(pieces).toBeGreaterThan(1);
    expect(log).toEqual(['start', 'end']);
    // ended only once the whole ball is out: its top below the sensor's bottom (y = 400)
    expect(ball.bounds.min.y).toBeGreaterThan(400 - 1);
    expect(engine.pairs.list.length).toBe(0);
  });

  it("takes its scale from the program's gravity: 100 px a metre for matter's default, 50 for half of it", () => {
    const a = FulcrumMatter.Engine.create();
    const b = FulcrumMatter.Engine.create();
    b.gravity.y = 0.5;
    const c = FulcrumMatter.Engine.create({ gravity: { x: 0, y: 0, scale: 0.001 } });
    expect(a._fulcrum.world.lengthUnitsPerMeter).toBeCloseTo(100, 9);
    expect(b._fulcrum.world.lengthUnitsPerMeter).toBeCloseTo(50, 9);
    expect(c._fulcrum.world.lengthUnitsPerMeter).toBe(100);
  });
});
