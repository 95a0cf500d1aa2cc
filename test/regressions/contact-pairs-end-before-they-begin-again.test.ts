import { describe, expect, it } from 'vitest';
import { Shape, type ShapeHandle, World } from '../../src/index';

/**
 * Found by the API fuzzer (test/property, tame runs, seeds 2000-2005 and 3000-3007): a contact or sensor
 * overlap that began can begin again without a contactEnd/sensorEnd in between, so a user who counts
 * touching pairs from the events counts them twice. It happens when the engine drops a live pair
 * between steps and finds it again in the next step:
 * - `shape.filter = ...` and `shape.isSensor = ...` (even to the value it had) drop the shape's contacts
 *   silently (destroyShapeContacts never reports);
 * - `body.setType(...)` drops the body's contacts silently;
 * - `world.createJoint(...)` without collideConnected records the end of the touching pair between its
 *   bodies, but between steps, and `step()` clears the event buffers before anything delivers it.
 * Every begin of a pair whose shapes still exist must be followed by its end before it begins again.
 */
function touchingPair(sensor = false) {
  const world = new World();
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  const floor = ground.createShape(Shape.box(10, 1));
  const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.49 } });
  const box = body.createShape(Shape.box(0.5, 0.5), { isSensor: sensor });
  const log: string[] = [];
  const name = (a: ShapeHandle, b: ShapeHandle) =>
    [a, b].includes(floor) && [a, b].includes(box) ? 'pair' : 'other';
  world.on('contactBegin', (e) => log.push(`begin ${name(e.shapeA, e.shapeB)}`));
  world.on('contactEnd', (e) => log.push(`end ${name(e.shapeA, e.shapeB)}`));
  world.on('sensorBegin', (e) => log.push(`begin ${name(e.sensorShape, e.visitorShape)}`));
  world.on('sensorEnd', (e) => log.push(`end ${name(e.sensorShape, e.visitorShape)}`));
  world.step(1 / 60);
  expect(log).toEqual(['begin pair']);
  return { world, ground, body, box, log };
}

/** begins and ends alternate, starting with a begin */
function expectAlternating(log: readonly string[]): void {
  for (let i = 0; i < log.length; i++) expect(log[i]).toBe(i % 2 === 0 ? 'begin pair' : 'end pair');
}

describe('a pair that began ends before it begins again', () => {
  it('when the filter is set (to the same filter)', () => {
    const { world, box, log } = touchingPair();
    const same = box.filter;
    box.filter = same;
    world.step(1 / 60);
    world.step(1 / 60);
    expectAlternating(log);
  });

  it('when the filter changes and the pair still collides: it ends and begins again in the next step', () => {
    const { world, box, log } = touchingPair();
    box.filter = { categoryBits: 2 };
    world.step(1 / 60);
    expect(log).toEqual(['begin pair', 'end pair', 'begin pair']);
    // and the record of that step holds both
    expect(world.events.contactEnd).toHaveLength(1);
    expect(world.events.contactBegin).toHaveLength(1);
  });

  it('when the filter changes and a shape is destroyed before the next step: no end is owed', () => {
    const { world, body, box, log } = touchingPair();
    box.filter = { categoryBits: 2 };
    body.destroyShape(box);
    world.step(1 / 60);
    expect(log).toEqual(['begin pair']);
  });

  it('when a sensor becomes solid: its overlap ends as a sensor event, then it touches as a contact', () => {
    const { world, box, log } = touchingPair(true);
    box.isSensor = false;
    world.step(1 / 60);
    // (touchingPair logs sensor and contact events of the pair alike, as begin/end pair)
    expect(log).toEqual(['begin pair', 'end pair', 'begin pair']);
    expect(world.events.sensorEnd.map((e) => e.sensorShape)).toEqual([box]);
    expect(world.events.contactBegin).toHaveLength(1);
  });

  it('when isSensor is set to the value it had', () => {
    const { world, box, log } = touchingPair();
    box.isSensor = false;
    world.step(1 / 60);
    expectAlternating(log);
  });

  it('when the body turns kinematic and back to dynamic', () => {
    const { world, body, log } = touchingPair();
    body.setType('kinematic');
    world.step(1 / 60);
    body.setType('dynamic');
    world.step(1 / 60);
    expectAlternating(log);
  });

  it('when a joint without collideConnected joins the bodies and is destroyed again', () => {
    const { world, ground, body, log } = touchingPair();
    const joint = world.createJoint({ type: 'distance', bodyA: ground, bodyB: body });
    world.step(1 / 60);
    world.destroyJoint(joint);
    world.step(1 / 60);
    world.step(1 / 60);
    expectAlternating(log);
  });

  it('for a sensor, when a joint joins the bodies and is destroyed again', () => {
    const { world, ground, body, log } = touchingPair(true);
    const joint = world.createJoint({ type: 'weld', bodyA: ground, bodyB: body });
    world.step(1 / 60);
    world.destroyJoint(joint);
    world.step(1 / 60);
    world.step(1 / 60);
    expectAlternating(log);
  });
});
