import { describe, expect, it } from 'vitest';
import { type ContactBeginEvent, Shape, World } from '../../src/index';
import { groundWorld, run } from '../helpers/world';

describe('events', () => {
  it('contactBegin and contactEnd for a ball that lands and is lifted off', () => {
    const { world, ground } = groundWorld();
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
    ball.createShape(Shape.circle(0.5));
    const begins: ContactBeginEvent[] = [];
    let ends = 0;
    world.on('contactBegin', (e) => begins.push(e));
    world.on('contactEnd', () => ends++);
    run(world, 1.5);
    expect(begins.length).toBe(1);
    const e = begins[0];
    expect(new Set([e.bodyA, e.bodyB])).toEqual(new Set([ball, ground]));
    const sign = e.bodyA === ground ? 1 : -1;
    expect(e.normal.x).toBeCloseTo(0, 9);
    expect(e.normal.y * sign).toBeCloseTo(1, 9);
    expect(e.points.length).toBe(1);
    expect(e.points[0].y).toBeCloseTo(0, 1);
    ball.setPosition({ x: 0, y: 5 });
    run(world, 0.1);
    expect(ends).toBe(1);
  });

  it('contactHit reports the approach speed of a drop, sqrt(2 g h)', () => {
    const { world } = groundWorld();
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 5.5 } });
    ball.createShape(Shape.circle(0.5), { enableHitEvents: true });
    const speeds: number[] = [];
    world.on('contactHit', (e) => speeds.push(e.approachSpeed));
    run(world, 2);
    expect(speeds.length).toBe(1);
    expect(Math.abs(speeds[0] - Math.sqrt(2 * 10 * 5)) / 10).toBeLessThan(0.03);
    // the readable array holds the same events until the next step
    expect(world.events.contactHit.length).toBe(0);
  });

  it('sensor shapes report visitors and do not collide', () => {
    const { world } = groundWorld();
    const hole = world.createBody({ position: { x: 0, y: 0.5 } });
    const sensor = hole.createShape(Shape.box(1, 0.5), { isSensor: true });
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 4 } });
    const visitor = ball.createShape(Shape.circle(0.25));
    const log: string[] = [];
    world.on('sensorBegin', (e) => {
      expect(e.sensorShape).toBe(sensor);
      expect(e.visitorShape).toBe(visitor);
      log.push('begin');
    });
    world.on('sensorEnd', () => log.push('end'));
    run(world, 3);
    expect(log).toEqual(['begin']);
    expect(ball.position.y).toBeCloseTo(0.25, 2);
    ball.setPosition({ x: 5, y: 0.25 });
    run(world, 0.1);
    expect(log).toEqual(['begin', 'end']);
  });

  it('filtering by category/mask and by group', () => {
    const { world } = groundWorld();
    const a = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    a.createShape(Shape.box(0.5, 0.5), { filter: { categoryBits: 2 } });
    const b = world.createBody({ type: 'dynamic', position: { x: 0, y: 3 } });
    b.createShape(Shape.box(0.5, 0.5), { filter: { categoryBits: 4, maskBits: 1 } }); // ignores a, hits ground
    const c = world.createBody({ type: 'dynamic', position: { x: 3, y: 0.5 } });
    c.createShape(Shape.box(0.5, 0.5), { filter: { groupIndex: -1 } });
    const d = world.createBody({ type: 'dynamic', position: { x: 3, y: 3 } });
    const dShape = d.createShape(Shape.box(0.5, 0.5), { filter: { groupIndex: -1 } });
    run(world, 2);
    expect(b.position.y).toBeCloseTo(0.5, 1);
    expect(d.position.y).toBeCloseTo(0.5, 1);
    // changing the filter takes effect: d now lands on c
    d.setPosition({ x: 3, y: 3 });
    dShape.filter = { groupIndex: 0 };
    run(world, 2);
    expect(d.position.y).toBeCloseTo(1.5, 1);
  });

  it('preStep and postStep frame each step; handlers may create and destroy bodies', () => {
    const { world } = groundWorld();
    const order: string[] = [];
    world.on('preStep', (e) => order.push(`pre ${e.dt.toFixed(3)}`));
    world.on('postStep', () => order.push('post'));
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 1 } });
    ball.createShape(Shape.circle(0.5));
    const off = world.on('contactBegin', () => {
      if (!ball.isValid) return;
      world.destroyBody(ball);
      const spawned = world.createBody({ type: 'dynamic', position: { x: 5, y: 1 } });
      spawned.createShape(Shape.circle(0.5));
    });
    run(world, 1);
    expect(order.slice(0, 2)).toEqual(['pre 0.017', 'post']);
    expect(ball.isValid).toBe(false);
    expect(world.bodyCount).toBe(2);
    off();
  });

  it('unsubscribe stops a handler', () => {
    const world = new World();
    let n = 0;
    const off = world.on('postStep', () => n++);
    world.step(1 / 60);
    off();
    world.step(1 / 60);
    expect(n).toBe(1);
  });
});
