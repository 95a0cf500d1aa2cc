import { describe, expect, it } from 'vitest';
import FulcrumMatter from '../../src/matter/index';
import { both } from '../helpers/matter-both';

describe('fulcrum/matter has the calls matter programs make', () => {
  it('engine.world.gravity is engine.gravity (matter 0.20 keeps the old name)', () => {
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const world = engine.world as unknown as { gravity: unknown };
      expect(world.gravity, name).toBe(engine.gravity);
      const box = Matter.Bodies.rectangle(0, 0, 20, 20, { frictionAir: 0 });
      Matter.Composite.add(engine.world, box);
      (world.gravity as { y: number }).y = -1;
      for (let i = 0; i < 60; i++) Matter.Engine.update(engine);
      // falls up: 500 px in a second
      expect(Math.abs(box.position.y + 500) / 500, name).toBeLessThan(0.02);
    }
  });

  it('Composite.addBody, addConstraint, addComposite, removeBody, move, rebase and bounds', () => {
    for (const [name, Matter] of both) {
      const { Composite, Bodies, Constraint } = Matter;
      const a = Composite.create();
      const b = Composite.create();
      const box = Bodies.rectangle(0, 0, 20, 40);
      const ball = Bodies.circle(100, 50, 10);
      Composite.addBody(a, box);
      Composite.addBody(a, ball);
      Composite.addConstraint(a, Constraint.create({ bodyA: box, bodyB: ball }));
      Composite.addComposite(a, b);
      expect(Composite.allBodies(a).length, name).toBe(2);
      expect(b.parent, name).toBe(a);
      const bounds = Composite.bounds(a);
      expect(bounds.min.x, name).toBeCloseTo(-10, 6);
      expect(bounds.min.y, name).toBeCloseTo(-20, 6);
      expect(bounds.max.y, name).toBeCloseTo(60, 0);
      Composite.move(a, ball, b);
      expect(a.bodies, name).toEqual([box]);
      expect(b.bodies, name).toEqual([ball]);
      Composite.removeBody(a, ball, true);
      expect(Composite.allBodies(a), name).toEqual([box]);
      const before = box.id;
      Composite.rebase(a);
      expect(box.id, name).not.toBe(before);
    }
  });

  it('adding a mouse constraint fires afterAdd once (matter.js: once, the mouse constraint as its object)', () => {
    const Matter = FulcrumMatter;
    const engine = Matter.Engine.create();
    const drag = Matter.MouseConstraint.create(engine, { mouse: Matter.Mouse.create(null) });
    const added: unknown[] = [];
    Matter.Events.on(engine.world, 'afterAdd', (event) => {
      added.push(event.object);
    });
    Matter.Composite.add(engine.world, drag as never);
    expect(added).toEqual([drag]);
    expect(Matter.Composite.allConstraints(engine.world)).toEqual([drag.constraint]);
  });

  it('Common.random gives the same seeded sequence as matter.js, so seeded scenes match', () => {
    const sequences = both.map(([, Matter]) => {
      Matter.Common._seed = 42;
      return Array.from({ length: 5 }, () => Matter.Common.random(10, 20));
    });
    expect(sequences[1]).toEqual(sequences[0]);
  });

  it('Render.startViewTransform and endViewTransform set the view and the canvas transforms', () => {
    const calls: number[][] = [];
    const context = new Proxy(
      {},
      {
        get: (_target, key) =>
          key === 'setTransform' ? (...args: number[]) => calls.push(args) : () => undefined,
        set: () => true,
      },
    );
    const canvas = { width: 800, height: 600, style: {}, getContext: () => context };
    const engine = FulcrumMatter.Engine.create();
    const render = FulcrumMatter.Render.create({
      engine,
      canvas: canvas as never,
      options: { width: 800, height: 600, pixelRatio: 1 } as never,
    });
    render.bounds = { min: { x: 100, y: 50 }, max: { x: 500, y: 350 } };
    FulcrumMatter.Render.startViewTransform(render);
    FulcrumMatter.Render.endViewTransform(render);
    // 400 by 300 of the world on 800 by 600 pixels: scale 2, the view's corner at the origin
    expect(calls).toEqual([
      [2, 0, 0, 2, -200, -100],
      [1, 0, 0, 1, 0, 0],
    ]);
  });
});
