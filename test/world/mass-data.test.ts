import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, World } from '../../src/index';

function box(world = new World({ gravity: { x: 0, y: 0 } })) {
  const body = world.createBody({ type: 'dynamic' });
  body.createShape(Shape.box(0.5, 0.5), { density: 1 });
  return { world, body };
}

describe('Body.setMassData', () => {
  it('gives the mass and inertia that impulses then answer to (v = J / m, w = L / I)', () => {
    const { world, body } = box();
    body.setMassData({ mass: 3, inertia: 0.25 });
    expect(body.mass).toBe(3);
    expect(body.inertia).toBe(0.25);
    body.applyLinearImpulse({ x: 6, y: 0 });
    body.applyAngularImpulse(0.5);
    expect(body.linearVelocity.x).toBeCloseTo(2, 12);
    expect(body.angularVelocity).toBeCloseTo(2, 12);
    world.step(1 / 60);
    expect(body.position.x).toBeCloseTo(2 / 60, 12);
  });

  it('keeps the centre of mass of the shapes unless given one, about which the body then turns', () => {
    const { world, body } = box();
    body.setMassData({ mass: 1, inertia: 1 });
    expect(body.localCenter).toEqual({ x: 0, y: 0 });
    body.setMassData({ mass: 1, inertia: 1, center: { x: 0.25, y: 0 } });
    expect(body.worldCenter).toEqual({ x: 0.25, y: 0 });
    body.setAngularVelocity(1);
    for (let i = 0; i < 60; i++) world.step(1 / 60);
    // turning about (0.25, 0), the origin swings round that point at a radius of 0.25
    const p = body.position;
    expect(Math.hypot(p.x - 0.25, p.y)).toBeCloseTo(0.25, 9);
    expect(body.worldCenter.x).toBeCloseTo(0.25, 12);
  });

  it('is kept when shapes change, and resetMassData goes back to density times area', () => {
    const { body } = box();
    body.setMassData({ mass: 5, inertia: 2 });
    body.createShape(Shape.circle(1, { x: 3, y: 0 }));
    expect(body.mass).toBe(5);
    body.setType('static');
    body.setType('dynamic');
    expect(body.mass).toBe(5);
    body.resetMassData();
    expect(body.mass).toBeCloseTo(1 + Math.PI, 12);
  });

  it('leaves fixed rotation to fixedRotation: no inertia is used while it is set', () => {
    const { body } = box();
    body.setFixedRotation(true);
    body.setMassData({ mass: 2, inertia: 3 });
    expect(body.inertia).toBe(0);
    body.setFixedRotation(false);
    expect(body.inertia).toBe(3);
  });

  it('refuses bad data with a FulcrumError naming it, and changes nothing', () => {
    const { body } = box();
    const before = { mass: body.mass, inertia: body.inertia, center: body.localCenter };
    const bad: unknown[] = [
      null,
      { mass: 0, inertia: 1 },
      { mass: Number.NaN, inertia: 1 },
      { mass: 1, inertia: -1 },
      { mass: 1, inertia: Number.POSITIVE_INFINITY },
      { mass: 1, inertia: 1, center: { x: Number.NaN, y: 0 } },
      { mass: 1, inertia: 1, centre: { x: 0, y: 0 } },
    ];
    for (const data of bad) {
      expect(() => body.setMassData(data as never)).toThrow(FulcrumError);
      expect({ mass: body.mass, inertia: body.inertia, center: body.localCenter }).toEqual(before);
    }
    expect(() => body.setMassData({ mass: -2, inertia: 1 })).toThrow(/massData\.mass.*-2/);
  });

  it('survives a snapshot: the restored world steps to the same bits', () => {
    const world = new World();
    const { body } = box(world);
    body.setMassData({ mass: 7, inertia: 0.1, center: { x: 0.1, y: 0.2 } });
    const ground = world.createBody();
    ground.createShape(Shape.box(5, 0.5, { x: 0, y: -2 }));
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    const copy = World.restore(world.snapshot());
    for (let i = 0; i < 90; i++) {
      world.step(1 / 60);
      copy.step(1 / 60);
    }
    expect(copy.snapshot()).toEqual(world.snapshot());
    const restored = [...copy.bodies].find((b) => b.type === 'dynamic');
    expect(restored?.mass).toBe(7);
  });
});
