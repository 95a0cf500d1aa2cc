import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';
import { run } from '../helpers/world';

const THETA = Math.PI / 6;
const G = 10;

/** A static slope of angle THETA through the origin and a 1 m box resting on it, both with friction mu. */
function slope(mu: number) {
  const world = new World({ enableSleep: false });
  const c = Math.cos(THETA);
  const s = Math.sin(THETA);
  // the slope's top surface passes through the origin; its normal is (-sin, cos)
  const ground = world.createBody({ position: { x: 0.5 * s, y: -0.5 * c }, angle: THETA });
  ground.createShape(Shape.box(50, 0.5), { friction: mu });
  const box = world.createBody({ type: 'dynamic', position: { x: -0.5 * s, y: 0.5 * c }, angle: THETA });
  box.createShape(Shape.box(0.5, 0.5), { friction: mu });
  return { world, box, along: (p: { x: number; y: number }) => p.x * c + p.y * s };
}

describe('friction on a 30 degree slope', () => {
  it('mu = 0.7 holds the box: it moves less than 1 mm in 3 s', () => {
    const { world, box } = slope(0.7);
    const start = box.position;
    run(world, 3);
    const end = box.position;
    expect(Math.hypot(end.x - start.x, end.y - start.y)).toBeLessThan(0.001);
  });

  it('mu = 0.4 slides with a = g (sin - mu cos)', () => {
    const { world, box, along } = slope(0.4);
    const s0 = along(box.position);
    run(world, 2);
    const travelled = s0 - along(box.position);
    const a = (2 * travelled) / (2 * 2);
    const expected = G * (Math.sin(THETA) - 0.4 * Math.cos(THETA));
    expect(Math.abs(a - expected) / expected).toBeLessThan(0.03);
  });
});
