import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';

describe('Body.readState', () => {
  it('writes what the getters give, at an offset, and 0 for a sleeping body', () => {
    const world = new World();
    const ground = world.createBody();
    ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));
    const box = world.createBody({
      type: 'dynamic',
      position: { x: 1, y: 3 },
      angle: 0.3,
      angularVelocity: 2,
    });
    box.createShape(Shape.box(0.5, 0.25, { x: 0.1, y: 0 }));
    world.step(1 / 60);
    const out = new Float64Array(10);
    box.readState(out, 2);
    const { x, y } = box.worldCenter;
    const { c, s } = box.rotation;
    const v = box.linearVelocity;
    expect([...out]).toEqual([0, 0, x, y, c, s, v.x, v.y, box.angularVelocity, 1]);
    for (let i = 0; i < 600; i++) world.step(1 / 60);
    expect(box.isAwake).toBe(false);
    box.readState(out);
    expect(out[7]).toBe(0);
  });
});

describe('Body.getContacts', () => {
  it('a resting box: one contact of two points, normal from A to B, impulses that carry its weight (m g dt)', () => {
    const world = new World({ enableSleep: false });
    const ground = world.createBody();
    ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    box.createShape(Shape.box(0.5, 0.5), { density: 2 });
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    const contacts = box.getContacts();
    expect(contacts.length).toBe(1);
    const [contact] = contacts;
    expect(contact.points.length).toBe(2);
    const a = contact.shapeA.body.position;
    const b = contact.shapeB.body.position;
    // the normal points from A's side to B's
    expect(contact.normal.x * (b.x - a.x) + contact.normal.y * (b.y - a.y)).toBeGreaterThan(0);
    expect(Math.abs(contact.normal.y)).toBeCloseTo(1, 9);
    // the two points under the box's bottom corners, the surfaces within a centimetre
    const xs = contact.points.map((p) => p.point.x).sort((p, q) => p - q);
    expect(xs[0]).toBeCloseTo(-0.5, 2);
    expect(xs[1]).toBeCloseTo(0.5, 2);
    for (const p of contact.points) expect(Math.abs(p.separation)).toBeLessThan(0.01);
    // at rest each substep's normal impulses hold the weight for a substep: 2 kg * 10 m/s^2 / 60 / 4
    const impulse = contact.points.reduce((sum, p) => sum + p.normalImpulse, 0);
    expect(impulse * world.subSteps).toBeCloseTo((2 * 10) / 60, 3);
    // the ground sees the same contact
    expect(ground.getContacts().length).toBe(1);
  });

  it('lists nothing for a body that overlaps only a sensor', () => {
    const world = new World();
    const sensor = world.createBody();
    sensor.createShape(Shape.box(5, 5), { isSensor: true });
    const ball = world.createBody({ type: 'dynamic' });
    ball.createShape(Shape.circle(0.5));
    world.step(1 / 60);
    // the ball overlaps the sensor, which reports it with sensor events, not as a contact
    expect(ball.getContacts().length).toBe(0);
    expect(sensor.getContacts().length).toBe(0);
  });
});
