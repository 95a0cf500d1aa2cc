import { describe, expect, it } from 'vitest';
import { type Body, Shape, type ShapeHandle, World } from '../../src/index';
import { groundWorld } from '../helpers/world';

/**
 * A ground and three balls resting on it, one of them with hit events and all with contact events:
 * the first step reports a begin for each ball (they start within the speculative margin). The
 * balls are dropped from 1 cm so that the hit event is not reported (approach speed < 1 m/s).
 */
function landing(): { world: World; ground: Body; balls: Body[]; shapes: ShapeHandle[] } {
  const { world, ground } = groundWorld();
  const balls: Body[] = [];
  const shapes: ShapeHandle[] = [];
  for (let i = 0; i < 3; i++) {
    const ball = world.createBody({ type: 'dynamic', position: { x: 3 * i, y: 0.5 } });
    shapes.push(ball.createShape(Shape.circle(0.5)));
    balls.push(ball);
  }
  return { world, ground, balls, shapes };
}

/** The body that is not `ground` in a contact event. */
function ballOf(e: { bodyA: Body; bodyB: Body }, ground: Body): Body {
  return e.bodyA === ground ? e.bodyB : e.bodyA;
}

describe('events name the handles of the step, whatever happens before they are read', () => {
  it('destroying a body between the step and reading world.events keeps its events, with the dead handle', () => {
    const { world, ground, balls } = landing();
    world.step(1 / 60);
    world.destroyBody(balls[1]);
    const begins = world.events.contactBegin;
    expect(begins.length).toBe(3);
    const named = begins.map((e) => ballOf(e, ground));
    expect(named).toEqual(expect.arrayContaining(balls));
    const dead = begins.find((e) => ballOf(e, ground) === balls[1])!;
    expect(dead.bodyA.isValid && dead.bodyB.isValid).toBe(false);
    expect(dead.shapeA.isValid && dead.shapeB.isValid).toBe(false);
    // the begin keeps the point where the ball touched (its bottom, on the ground's top at x = 3)
    expect(dead.points.length).toBe(1);
    expect(dead.points[0].x).toBeCloseTo(3, 9);
    expect(Math.abs(dead.points[0].y)).toBeLessThan(0.03);
    expect(Math.abs(dead.normal.y)).toBeCloseTo(1, 9);
  });

  it('a new body that takes over a destroyed body slot before world.events is read is never named', () => {
    const { world, ground, balls } = landing();
    world.step(1 / 60);
    world.destroyBody(balls[0]);
    // last freed, first reused: the newcomer and its shape get the freed slots
    const newcomer = world.createBody({ type: 'dynamic', position: { x: 20, y: 5 } });
    newcomer.createShape(Shape.circle(0.5));
    expect((newcomer as unknown as { slot: number }).slot).toBe(
      (balls[0] as unknown as { slot: number }).slot,
    );
    const events = world.events;
    const named = events.contactBegin.map((e) => ballOf(e, ground));
    expect(named).toContain(balls[0]);
    expect(named).not.toContain(newcomer);
    for (const e of events.contactBegin) {
      expect(e.shapeA.body).toBe(e.bodyA);
      expect(e.shapeB.body).toBe(e.bodyB);
    }
  });

  it('world.events returns the same objects before and after destroys until the next step', () => {
    const { world, balls } = landing();
    world.step(1 / 60);
    const before = world.events;
    world.destroyBody(balls[0]);
    balls[1].destroyShape(balls[1].shapes[0]);
    expect(world.events).toBe(before);
    world.step(1 / 60);
    expect(world.events).not.toBe(before);
  });

  it('a handler that destroys bodies: the later events of the delivery still name them, as world.events does', () => {
    const { world, ground, balls } = landing();
    const seen: Body[] = [];
    world.on('contactBegin', (e) => {
      seen.push(ballOf(e, ground));
      // the first handler call destroys every ball: the two events still to come name dead handles
      for (const b of balls) if (b.isValid) world.destroyBody(b);
    });
    expect(() => world.step(1 / 60)).not.toThrow();
    expect(seen.length).toBe(3);
    expect(new Set(seen)).toEqual(new Set(balls));
    expect(world.events.contactBegin.map((e) => ballOf(e, ground))).toEqual(seen);
    expect(world.bodyCount).toBe(1);
  });

  it('contactEnd and sensor events of a destroyed body are read without a TypeError', () => {
    const { world, ground } = groundWorld();
    const sensorBody = world.createBody({ position: { x: 0, y: 3 } });
    sensorBody.createShape(Shape.box(2, 0.5), { isSensor: true });
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    ball.createShape(Shape.circle(0.5));
    const visitor = world.createBody({ type: 'dynamic', position: { x: 0, y: 3 }, gravityScale: 0 });
    const visitorShape = visitor.createShape(Shape.circle(0.25));
    world.step(1 / 60);
    expect(world.events.sensorBegin.length).toBe(1);
    // lift the ball off: the next step ends its contact; then destroy both bodies before reading
    ball.setPosition({ x: 0, y: 10 });
    visitor.setPosition({ x: 10, y: 3 });
    world.step(1 / 60);
    world.destroyBody(ball);
    world.destroyBody(visitor);
    world.createBody({ type: 'dynamic' }).createShape(Shape.circle(1));
    const events = world.events;
    expect(events.contactEnd.length).toBe(1);
    expect(new Set([events.contactEnd[0].bodyA, events.contactEnd[0].bodyB])).toEqual(
      new Set([ball, ground]),
    );
    expect(events.sensorEnd.length).toBe(1);
    expect(events.sensorEnd[0].visitorShape).toBe(visitorShape);
  });

  it('a body put to sleep between steps, destroyed and its slot reused: the next step reports no sleep of the newcomer', () => {
    const { world } = groundWorld();
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 5 } });
    box.createShape(Shape.box(0.5, 0.5));
    world.step(1 / 60);
    box.setAwake(false);
    world.destroyBody(box);
    const newcomer = world.createBody({ type: 'dynamic', position: { x: 0, y: 5 } });
    newcomer.createShape(Shape.box(0.5, 0.5));
    const slept: Body[] = [];
    world.on('sleep', (e) => slept.push(e.body));
    world.step(1 / 60);
    expect(slept).toEqual([]);
    expect(world.events.sleep).toEqual([]);
    expect(newcomer.isAwake).toBe(true);
  });

  it('a world restored from a snapshot taken after a destroy leaves the destroyed shapes events out', () => {
    const { world, ground, balls } = landing();
    world.step(1 / 60);
    world.destroyBody(balls[2]);
    const newcomer = world.createBody({ type: 'dynamic', position: { x: 20, y: 5 } });
    newcomer.createShape(Shape.circle(0.5));
    const restored = World.restore(world.snapshot());
    const begins = restored.events.contactBegin;
    expect(begins.length).toBe(2);
    const restoredBodies = [...restored.bodies];
    // slot order: ground, ball 0, ball 1, newcomer (in ball 2's slot)
    const restoredGround = restoredBodies[0];
    const named = begins.map((e) => ballOf(e, restoredGround));
    expect(named).toEqual([restoredBodies[1], restoredBodies[2]]);
    expect(ground.isValid).toBe(true);
  });
});
