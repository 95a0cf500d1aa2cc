import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';
import { run } from '../helpers/world';

// Semi-implicit Euler with step h for n steps from rest: y = g h^2 n (n + 1) / 2.
function semiImplicitDrop(g: number, h: number, n: number): number {
  return (g * h * h * n * (n + 1)) / 2;
}

describe('free fall', () => {
  it('falls 5.083 m in 1 s with one substep, as semi-implicit Euler at dt = 1/60', () => {
    const world = new World({ subSteps: 1 });
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 100 } });
    body.createShape(Shape.circle(0.5));
    run(world, 1);
    const drop = 100 - body.position.y;
    expect(Math.abs(drop - 5.083) / 5.083).toBeLessThan(0.005);
    expect(drop).toBeCloseTo(semiImplicitDrop(10, 1 / 60, 60), 10);
  });

  it('falls 5 m in 1 s (1/2 g t^2) with the default 4 substeps, as Euler at the substep size', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 100 } });
    body.createShape(Shape.box(0.5, 0.5));
    run(world, 1);
    const drop = 100 - body.position.y;
    expect(Math.abs(drop - 5) / 5).toBeLessThan(0.005);
    expect(drop).toBeCloseTo(semiImplicitDrop(10, 1 / 240, 240), 10);
    expect(body.linearVelocity.y).toBeCloseTo(-10, 10);
  });

  it('honours gravity scale and custom gravity', () => {
    const world = new World({ gravity: { x: 3, y: 0 } });
    const body = world.createBody({ type: 'dynamic', gravityScale: 0.5 });
    body.createShape(Shape.circle(0.5));
    run(world, 1);
    expect(body.linearVelocity.x).toBeCloseTo(1.5, 10);
    expect(body.linearVelocity.y).toBe(0);
  });
});
