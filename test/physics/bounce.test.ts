import { describe, expect, it } from 'vitest';
import { Shape } from '../../src/index';
import { groundWorld, run } from '../helpers/world';

const RADIUS = 0.25;

/** Drops a ball from `height` (bottom above the ground) and returns the apex heights of its bounces. */
function bounces(restitution: number, height: number, seconds: number): number[] {
  const { world } = groundWorld({}, 0, restitution);
  const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: height + RADIUS } });
  ball.createShape(Shape.circle(RADIUS), { restitution, friction: 0 });
  const apexes: number[] = [];
  let prevVy = 0;
  run(world, seconds, () => {
    const vy = ball.linearVelocity.y;
    if (prevVy > 0 && vy <= 0) apexes.push(ball.position.y - RADIUS);
    prevVy = vy;
  });
  return apexes;
}

describe('bounce', () => {
  it('restitution 0.5 rebounds to 25% of the drop height', () => {
    const apexes = bounces(0.5, 2, 3);
    expect(apexes.length).toBeGreaterThan(0);
    expect(Math.abs(apexes[0] - 0.5) / 0.5).toBeLessThan(0.05);
  });

  it('restitution 1 keeps at least 95% of the height after 5 bounces', () => {
    const apexes = bounces(1, 2, 8);
    expect(apexes.length).toBeGreaterThanOrEqual(5);
    expect(apexes[4]).toBeGreaterThanOrEqual(0.95 * 2);
    expect(apexes[4]).toBeLessThanOrEqual(1.05 * 2);
  });

  it('restitution 0 rebounds less than 1 cm', () => {
    const { world } = groundWorld({}, 0, 0);
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 + RADIUS } });
    ball.createShape(Shape.circle(RADIUS), { friction: 0 });
    let landed = false;
    let maxAfter = 0;
    run(world, 3, () => {
      const bottom = ball.position.y - RADIUS;
      if (!landed && bottom < 0.01) landed = true;
      if (landed) maxAfter = Math.max(maxAfter, bottom);
    });
    expect(landed).toBe(true);
    expect(maxAfter).toBeLessThan(0.01);
  });
});
