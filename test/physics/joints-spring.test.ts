import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';

const DT = 1 / 60;

/** A 1 kg disc on a distance spring from a static anchor at the origin; rest length 1 m along +x. */
function springWorld(hertz: number, dampingRatio: number, gravity: number) {
  const world = new World({ gravity: { x: 0, y: -gravity } });
  const anchor = world.createBody();
  const body = world.createBody({ type: 'dynamic', position: { x: 1.2, y: 0 }, fixedRotation: true });
  body.createShape(Shape.circle(0.1), { density: 1 / (Math.PI * 0.01) });
  const joint = world.createJoint({
    type: 'distance',
    bodyA: anchor,
    bodyB: body,
    length: 1,
    enableSpring: true,
    hertz,
    dampingRatio,
  });
  return { world, body, joint };
}

describe('distance spring (Hooke)', () => {
  it('a 1 kg body on a 2 Hz spring oscillates at 2 Hz', () => {
    const { world, body } = springWorld(2, 0, 0);
    expect(body.mass).toBeCloseTo(1, 12);
    const crossings: number[] = [];
    let prev = body.position.x - 1;
    for (let i = 1; i <= 600; i++) {
      world.step(DT);
      const x = body.position.x - 1;
      if (prev < 0 && x >= 0) crossings.push((i - 1 + -prev / (x - prev)) * DT);
      prev = x;
    }
    const period = (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
    expect(Math.abs(1 / period - 2) / 2).toBeLessThan(0.02);
  });

  it('damping ratio 1 returns without overshoot', () => {
    const { world, body } = springWorld(2, 1, 0);
    let minX = Number.POSITIVE_INFINITY;
    for (let i = 0; i < 300; i++) {
      world.step(DT);
      minX = Math.min(minX, body.position.x);
    }
    expect(minX).toBeGreaterThan(1 - 1e-3);
    expect(body.position.x - 1).toBeLessThan(0.005);
  });

  it('under gravity the static extension is m g / k, with k = m (2 pi f)^2', () => {
    const world = new World({ gravity: { x: 0, y: -10 } });
    const anchor = world.createBody({ position: { x: 0, y: 0 } });
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: -1 }, fixedRotation: true });
    body.createShape(Shape.circle(0.1), { density: 1 / (Math.PI * 0.01) });
    world.createJoint({
      type: 'distance',
      bodyA: anchor,
      bodyB: body,
      length: 1,
      enableSpring: true,
      hertz: 2,
      dampingRatio: 1,
    });
    for (let i = 0; i < 600; i++) world.step(DT);
    const k = body.mass * (2 * Math.PI * 2) ** 2;
    const expected = (body.mass * 10) / k;
    const extension = -body.position.y - 1;
    expect(Math.abs(extension - expected) / expected).toBeLessThan(0.02);
  });

  it('a rope (maxLength) goes slack and holds at its length', () => {
    const world = new World();
    const anchor = world.createBody({ position: { x: 0, y: 0 } });
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: -0.5 } });
    body.createShape(Shape.circle(0.1));
    world.createJoint({
      type: 'distance',
      bodyA: anchor,
      bodyB: body,
      enableSpring: true,
      hertz: 0,
      maxLength: 2,
    });
    let maxLength = 0;
    for (let i = 0; i < 300; i++) {
      world.step(DT);
      maxLength = Math.max(maxLength, -body.position.y);
    }
    expect(maxLength).toBeLessThan(2 + 0.01);
    expect(-body.position.y).toBeGreaterThan(2 - 0.01);
  });
});
