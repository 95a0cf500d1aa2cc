import { describe, expect, it } from 'vitest';
import { type Body, Shape, ShapeHandle, World } from '../../src/index';

/**
 * Issue 27 (known), which the API fuzzer checks in its 'arrays' sessions (test/property: world.events
 * read late, after the ops that follow a step): with no handler registered, reading `world.events` after
 * a destroy throws a TypeError, or, once a new body has taken the destroyed one's slot, names the new
 * body. The arrays may name the handles of the step (destroyed since or not), never a handle made after
 * it, and reading them never throws. The fuzzer (tame seed 7003) also found it through a restore: a
 * sensorBegin handler destroys the visitor's body, the world is snapshotted and restored, and the
 * restored world's `world.events.sensorBegin` names `undefined` (the restored world reads the step's
 * event buffers, whose shape slots are dead).
 */
function touchingPair() {
  const world = new World();
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  const floor = ground.createShape(Shape.box(10, 1));
  const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.49 } });
  const box = body.createShape(Shape.box(0.5, 0.5), { enableHitEvents: true });
  world.step(1 / 60);
  return { world, ground, floor, body, box };
}

function namedHandles(world: World): { shapes: ShapeHandle[]; bodies: Body[] } {
  const events = world.events;
  const shapes: ShapeHandle[] = [];
  const bodies: Body[] = [];
  for (const e of [...events.contactBegin, ...events.contactEnd, ...events.contactHit]) {
    shapes.push(e.shapeA, e.shapeB);
    bodies.push(e.bodyA, e.bodyB);
  }
  for (const e of [...events.sensorBegin, ...events.sensorEnd]) shapes.push(e.sensorShape, e.visitorShape);
  for (const e of [...events.sleep, ...events.wake]) bodies.push(e.body);
  return { shapes, bodies };
}

describe('world.events read after a destroy, with no handler', () => {
  it('does not throw, and names only the handles of the step', () => {
    const { world, ground, floor, body, box } = touchingPair();
    world.destroyBody(body);
    const named = namedHandles(world);
    for (const s of named.shapes) expect([floor, box]).toContain(s);
    for (const b of named.bodies) expect([ground, body]).toContain(b);
  });

  it('never names a body made after the step in a reused slot', () => {
    const { world, ground, floor, body, box } = touchingPair();
    world.destroyBody(body);
    const newcomer = world.createBody({ type: 'dynamic', position: { x: 3, y: 3 } });
    const newShape = newcomer.createShape(Shape.circle(0.5));
    const named = namedHandles(world);
    expect(named.shapes).not.toContain(newShape);
    expect(named.bodies).not.toContain(newcomer);
    for (const s of named.shapes) expect([floor, box]).toContain(s);
    for (const b of named.bodies) expect([ground, body]).toContain(b);
  });

  it('after a shape is destroyed', () => {
    const { world, floor, box, body } = touchingPair();
    body.destroyShape(box);
    const named = namedHandles(world);
    for (const s of named.shapes) expect([floor, box]).toContain(s);
  });

  it('in a world restored after a handler destroyed a body the event named', () => {
    const world = new World();
    const visitor = world.createBody({ type: 'dynamic' });
    visitor.createShape(Shape.box(0.05, 0.05));
    const holder = world.createBody({ type: 'dynamic' });
    holder.createShape(Shape.circle(0.05), { isSensor: true });
    let destroyed = false;
    world.on('sensorBegin', () => {
      if (!destroyed) world.destroyBody(visitor);
      destroyed = true;
    });
    world.step(1 / 60);
    expect(destroyed).toBe(true);
    const restored = World.restore(world.snapshot());
    const events = restored.events;
    // the restored world may leave the event out or name the (destroyed) shape, never nothing
    for (const e of [...events.sensorBegin, ...events.sensorEnd]) {
      expect(e.sensorShape).toBeInstanceOf(ShapeHandle);
      expect(e.visitorShape).toBeInstanceOf(ShapeHandle);
    }
  });
});
