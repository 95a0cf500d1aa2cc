import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';
import { run } from '../helpers/world';

describe('kinematic bodies', () => {
  it('move by their velocity alone, whatever gravity and contacts do', () => {
    const world = new World();
    const k = world.createBody({ type: 'kinematic', linearVelocity: { x: 2, y: 0 }, angularVelocity: 0.5 });
    k.createShape(Shape.box(1, 0.1));
    run(world, 1);
    expect(k.position.x).toBeCloseTo(2, 10);
    expect(k.position.y).toBe(0);
    expect(k.angle).toBeCloseTo(0.5, 9);
  });

  it('keep moving however slowly they are told to, with or without a shape (they never fall asleep)', () => {
    const world = new World();
    // 1 cm/s and 0.01 rad/s: both below the 5 cm/s at which a dynamic body would sleep
    const lift = world.createBody({ type: 'kinematic', linearVelocity: { x: 0, y: 0.01 } });
    lift.createShape(Shape.box(1, 0.1));
    const spinner = world.createBody({ type: 'kinematic', angularVelocity: 0.01 });
    run(world, 10);
    expect(lift.isAwake).toBe(true);
    expect(lift.position.y).toBeCloseTo(0.1, 9);
    expect(spinner.isAwake).toBe(true);
    expect(spinner.angle).toBeCloseTo(0.1, 9);
  });

  it('a paddle turning at 1 rad/s carries a box resting on it', () => {
    const world = new World();
    const paddle = world.createBody({ type: 'kinematic' });
    paddle.createShape(Shape.box(3, 0.1));
    const box = world.createBody({ type: 'dynamic', position: { x: 1, y: 0.35 } });
    box.createShape(Shape.box(0.25, 0.25), { friction: 0.8 });
    run(world, 0.5);
    const local0 = paddle.getLocalPoint(box.position);
    paddle.setAngularVelocity(1);
    run(world, 0.5);
    expect(paddle.angle).toBeCloseTo(0.5, 9);
    const local1 = paddle.getLocalPoint(box.position);
    // the box rides with the paddle: it stays where it was in the paddle's frame and turns with it
    expect(Math.hypot(local1.x - local0.x, local1.y - local0.y)).toBeLessThan(0.02);
    expect(Math.abs(box.angle - 0.5)).toBeLessThan(0.02);
  });

  it('a moving kinematic body pushes a dynamic one', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const pusher = world.createBody({
      type: 'kinematic',
      position: { x: -2, y: 0 },
      linearVelocity: { x: 1, y: 0 },
    });
    pusher.createShape(Shape.box(0.5, 0.5));
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0 } });
    box.createShape(Shape.box(0.5, 0.5), { friction: 0 });
    run(world, 3);
    expect(box.position.x).toBeGreaterThan(0.9);
    expect(box.position.x - pusher.position.x).toBeGreaterThan(0.99);
  });
});
