import { describe, expect, it } from 'vitest';
import { type Body, Shape } from '../../src/index';
import { dist, groundWorld, pyramid, run } from '../helpers/world';

describe('sleeping', () => {
  it('a resting pyramid sleeps; a ball thrown at it wakes the island and the pyramid reacts', () => {
    const { world } = groundWorld();
    const boxes = pyramid(world, 10);
    const slept: Body[] = [];
    world.on('sleep', (e) => slept.push(e.body));
    run(world, 5);
    expect(boxes.every((b) => !b.isAwake)).toBe(true);
    expect(world.awakeBodyCount).toBe(0);
    expect(slept.length).toBe(boxes.length);
    const before = boxes.map((b) => b.position);

    const ball = world.createBody({
      type: 'dynamic',
      position: { x: -12, y: 1 },
      linearVelocity: { x: 25, y: 2 },
    });
    ball.createShape(Shape.circle(0.5), { density: 5 });
    const woken = new Set<Body>();
    world.on('wake', (e) => woken.add(e.body));
    run(world, 1);
    expect(woken.size).toBe(boxes.length);
    const moved = Math.max(...boxes.map((b, i) => dist(b.position, before[i])));
    expect(moved).toBeGreaterThan(0.1);
  });

  it('setters, forces and impulses wake a sleeping body', () => {
    const { world } = groundWorld();
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    box.createShape(Shape.box(0.5, 0.5));
    run(world, 2);
    expect(box.isAwake).toBe(false);
    box.applyForce({ x: 1, y: 0 });
    expect(box.isAwake).toBe(true);
    run(world, 2);
    expect(box.isAwake).toBe(false);
    box.applyLinearImpulse({ x: 0, y: 1 });
    expect(box.isAwake).toBe(true);
    run(world, 3);
    expect(box.isAwake).toBe(false);
    box.setLinearVelocity({ x: 0, y: 0 });
    expect(box.isAwake).toBe(true);
  });

  it('destroying a body wakes the bodies resting on it', () => {
    const { world } = groundWorld();
    const lower = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    lower.createShape(Shape.box(0.5, 0.5));
    const upper = world.createBody({ type: 'dynamic', position: { x: 0, y: 1.5 } });
    upper.createShape(Shape.box(0.5, 0.5));
    run(world, 3);
    expect(upper.isAwake).toBe(false);
    world.destroyBody(lower);
    expect(upper.isAwake).toBe(true);
    run(world, 1);
    expect(upper.position.y).toBeLessThan(0.6);
  });

  it('setAwake(false) puts a body and what it touches to sleep; allowSleep false keeps it awake', () => {
    const { world } = groundWorld();
    const a = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    a.createShape(Shape.box(0.5, 0.5));
    const b = world.createBody({ type: 'dynamic', position: { x: 0, y: 1.5 }, allowSleep: false });
    b.createShape(Shape.box(0.5, 0.5));
    run(world, 3);
    expect(a.isAwake).toBe(true);
    expect(b.isAwake).toBe(true);
    b.setAllowSleep(true);
    run(world, 1);
    expect(a.isAwake).toBe(false);
    const c = world.createBody({ type: 'dynamic', position: { x: 5, y: 0.5 } });
    c.createShape(Shape.box(0.5, 0.5));
    run(world, 0.1);
    c.setAwake(false);
    expect(c.isAwake).toBe(false);
  });
});
