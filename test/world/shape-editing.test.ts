import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';
import { expectRejected } from '../helpers/rejects';

const DT = 1 / 60;

/** Mass and inertia about the centre of a w × h rectangle of density `rho`. */
function rectangle(w: number, h: number, rho: number) {
  const mass = rho * w * h;
  return { mass, inertia: (mass * (w * w + h * h)) / 12 };
}

function closeTo(actual: number, expected: number, relative = 1e-12) {
  expect(Math.abs(actual - expected)).toBeLessThanOrEqual(relative * Math.abs(expected));
}

describe('editing shapes at run time', () => {
  it('setGeometry gives the body the mass, centre and inertia of its new outline', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    const shape = body.createShape(Shape.box(0.5, 0.5), { density: 3 });
    closeTo(body.mass, rectangle(1, 1, 3).mass);
    // an off-centre 2 × 1 rectangle given as polygon points
    shape.setGeometry(
      Shape.polygon([
        { x: 1, y: 0 },
        { x: 3, y: 0 },
        { x: 3, y: 1 },
        { x: 1, y: 1 },
      ]),
    );
    const r = rectangle(2, 1, 3);
    closeTo(body.mass, r.mass);
    closeTo(body.localCenter.x, 2);
    closeTo(body.localCenter.y, 0.5);
    closeTo(body.inertia, r.inertia);
    expect(shape.geometry.type).toBe('polygon');
    expect(shape.type).toBe('polygon');
  });

  it('a box grown under a resting body ends its contacts and comes to rest on its new outline', () => {
    const world = new World();
    world.createBody({ position: { x: 0, y: -1 } }).createShape(Shape.box(20, 1));
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    const shape = body.createShape(Shape.box(0.5, 0.5));
    for (let i = 0; i < 120; i++) world.step(DT);
    expect(world.contactCount).toBe(1);
    closeTo(body.position.y, 0.5, 0.02);
    // the new box reaches 0.5 m into the ground: the solver pushes it out, no faster than its bound
    shape.setGeometry(Shape.box(1, 1));
    world.step(DT);
    expect(world.events.contactEnd.length).toBe(1);
    expect(world.events.contactBegin.length).toBe(1);
    for (let i = 0; i < 240; i++) world.step(DT);
    // at rest on its new half height, within the contact slop
    expect(Math.abs(body.position.y - 1)).toBeLessThan(0.01);
    expect(Math.abs(body.linearVelocity.y)).toBeLessThan(1e-3);
  });

  it('scale by one factor: a circle grows about its centre of mass, mass with area', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.createBody({
      type: 'dynamic',
      position: { x: 1, y: 2 },
      linearVelocity: { x: 3, y: 0 },
    });
    body.createShape(Shape.circle(0.5, { x: 1, y: 0 }), { density: 2 });
    const center = body.worldCenter;
    body.scale(3);
    closeTo(body.mass, 2 * Math.PI * 1.5 * 1.5);
    closeTo(body.inertia, (body.mass * 1.5 * 1.5) / 2);
    expect(body.worldCenter.x).toBeCloseTo(center.x, 12);
    expect(body.worldCenter.y).toBeCloseTo(center.y, 12);
    // the origin moved away from the fixed centre by the factor
    expect(body.position.x).toBeCloseTo(center.x - 3 * 1, 12);
    expect(body.linearVelocity.x).toBe(3);
  });

  it('scale about a world point moves the body with the scale', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic', position: { x: 1, y: 0 } });
    body.createShape(Shape.circle(0.25));
    body.scale(2, { x: 0, y: 0 });
    expect(body.position.x).toBe(2);
    expect(body.position.y).toBe(0);
    expect((body.shapes[0].geometry as { radius: number }).radius).toBe(0.5);
  });

  it('scale along the world axes of a turned box stretches it along the world axes', () => {
    const world = new World();
    // a 2 × 1 box turned a quarter turn spans 1 along x and 2 along y
    const body = world.createBody({ type: 'kinematic', angle: Math.PI / 2 });
    const shape = body.createShape(Shape.box(1, 0.5));
    body.scale({ x: 3, y: 0.5 });
    const box = shape.getAABB();
    expect(box.upperBound.x - box.lowerBound.x).toBeCloseTo(3, 9);
    expect(box.upperBound.y - box.lowerBound.y).toBeCloseTo(1, 9);
    closeTo(body.mass, 0); // kinematic: no mass
  });

  it('a mirror (negative factor) keeps a valid polygon of the same area', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    body.createShape(
      Shape.polygon([
        { x: 0, y: 0 },
        { x: 2, y: 0 },
        { x: 0, y: 1 },
      ]),
    );
    body.scale({ x: -1, y: 1 });
    closeTo(body.mass, 1);
    closeTo(body.localCenter.x, -2 / 3);
  });

  it('bad scales and geometries are refused and leave the world as it was', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    const shape = body.createShape(Shape.circle(0.5));
    body.createShape(Shape.box(0.5, 0.5, { x: 2, y: 0 }));
    world.step(DT);
    const bytes = world.snapshot();
    expectRejected(world, () => body.scale({ x: 2, y: 1 }), /factor.*circle.*same factor/);
    expectRejected(world, () => body.scale(0), /factor.*0/);
    expectRejected(world, () => body.scale(Number.NaN), /factor.*NaN/);
    expectRejected(world, () => body.scale({ x: 1 } as never), /factor/);
    expectRejected(world, () => body.scale(1e-9), /factor.*valid shape/);
    expectRejected(world, () => body.scale(2, { x: Number.NaN, y: 0 }), /point.*NaN/);
    expectRejected(world, () => shape.setGeometry(Shape.segment({ x: 0, y: 0 }, { x: 1, y: 0 })), /segment/);
    expectRejected(world, () => shape.setGeometry({ type: 'circle' } as never), /geometry/);
    expect(world.snapshot()).toEqual(bytes);
  });

  it('an edited world snapshots and restores to the same bits', () => {
    const world = new World();
    world.createBody({ position: { x: 0, y: -1 } }).createShape(Shape.box(20, 1));
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 1 } });
    const shape = body.createShape(Shape.box(0.5, 0.5));
    for (let i = 0; i < 30; i++) world.step(DT);
    shape.setGeometry(Shape.box(0.5, 0.25));
    body.scale(1.5);
    const restored = World.restore(world.snapshot());
    for (let i = 0; i < 60; i++) {
      world.step(DT);
      restored.step(DT);
    }
    expect(restored.snapshot()).toEqual(world.snapshot());
    const [, restoredBody] = [...restored.bodies];
    expect(restoredBody.shapes[0].geometry).toEqual(shape.geometry);
  });
});
