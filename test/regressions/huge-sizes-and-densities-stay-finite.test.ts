import { describe, expect, it } from 'vitest';
import { type Body, FulcrumError, Shape, World } from '../../src/index';

/**
 * Issue 27 (known), found again by the API fuzzer (test/property, seeds 5005 and 5006: a dynamic body with
 * a box of half extents 0.05 x 1e200 and a small triangle gets a contactBegin whose normal is (0, 0)):
 * sizes and densities of 1e200 and more are accepted and then break the step.
 * Each must be refused with a FulcrumError at the call, or the world must stay finite.
 */
function finite(body: Body): boolean {
  const p = body.position;
  const v = body.linearVelocity;
  const q = body.rotation;
  return [p.x, p.y, v.x, v.y, q.c, q.s, body.angularVelocity].every(Number.isFinite);
}

/** Runs `build` (which may refuse), steps 30 times, and checks every body and contact normal. */
function stepsFinite(build: (world: World) => void): void {
  const world = new World();
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  ground.createShape(Shape.box(20, 1));
  const normals: { x: number; y: number }[] = [];
  world.on('contactBegin', (e) => normals.push(e.normal));
  try {
    build(world);
  } catch (e) {
    expect(e).toBeInstanceOf(FulcrumError);
    return;
  }
  for (let i = 0; i < 30; i++) world.step(1 / 60);
  for (const body of world.bodies) expect(finite(body)).toBe(true);
  for (const n of normals) expect(Math.hypot(n.x, n.y)).toBeCloseTo(1, 9);
}

describe('huge but finite values', () => {
  it('a box of half height 1e200 beside a small triangle on one body', () => {
    stepsFinite((world) => {
      const body = world.createBody({ type: 'dynamic' });
      body.createShape(Shape.box(0.05, 1e200));
      body.createShape(
        Shape.polygon([
          { x: 0, y: 0 },
          { x: 0.5, y: 0 },
          { x: 0, y: 0.5 },
        ]),
      );
    });
  });

  for (const radius of [1e200, 1e300]) {
    it(`a circle of radius ${radius}`, () => {
      stepsFinite((world) => {
        world.createBody({ type: 'dynamic', position: { x: 0, y: 3 } }).createShape(Shape.circle(radius));
      });
    });
  }

  it('a density of 1e308', () => {
    stepsFinite((world) => {
      world.createBody({ type: 'dynamic', position: { x: 0, y: 1 } }).createShape(Shape.box(0.5, 0.5), {
        density: 1e308,
      });
    });
  });
});
