import { describe, expect, it } from 'vitest';
import { both } from '../helpers/matter-both';

describe('fulcrum/matter constraints as matter programs use them', () => {
  it("a slingshot's elastic (soft, to a world point, length 0) flings the ball past the anchor as far as on matter.js", () => {
    const flights: Record<string, { far: number; top: number }> = {};
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      engine.gravity.y = 0;
      const ball = Matter.Bodies.circle(100, 300, 18, { frictionAir: 0 });
      const elastic = Matter.Constraint.create({
        pointA: { x: 200, y: 300 },
        bodyB: ball,
        length: 0.01,
        stiffness: 0.05,
        damping: 0.01,
      });
      Matter.Composite.add(engine.world, [ball, elastic]);
      let far = 0;
      let top = 0;
      for (let i = 0; i < 60; i++) {
        Matter.Engine.update(engine, 1000 / 60);
        far = Math.max(far, ball.position.x);
        top = Math.max(top, ball.speed);
      }
      flights[name] = { far, top };
    }
    const matter = flights['matter-js'];
    const layer = flights['fulcrum/matter'];
    // released 100 px out: past the anchor (x = 200) by about as much, top speed as much
    expect(Math.abs(layer.far - 200 - (matter.far - 200)) / (matter.far - 200)).toBeLessThan(0.3);
    expect(Math.abs(layer.top - matter.top) / matter.top).toBeLessThan(0.15);
  });

  it('bodies joined by a constraint still collide: a ball on a spring rests on the one below', () => {
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const ground = Matter.Bodies.rectangle(400, 600, 800, 40, { isStatic: true });
      const lower = Matter.Bodies.circle(400, 560, 20);
      const upper = Matter.Bodies.circle(400, 500, 20);
      const spring = Matter.Constraint.create({ bodyA: lower, bodyB: upper, stiffness: 0.0005 });
      Matter.Composite.add(engine.world, [ground, lower, upper, spring]);
      for (let i = 0; i < 240; i++) Matter.Engine.update(engine, 1000 / 60);
      // centres the sum of the radii apart
      expect(Math.abs(lower.position.y - upper.position.y - 40), name).toBeLessThan(1);
    }
  });

  it('stiff pins (stiffness 0.4 and 0.6) in a swinging chain stretch about as little as on matter.js', () => {
    for (const stiffness of [0.4, 0.6]) {
      const stretch: Record<string, number> = {};
      for (const [name, Matter] of both) {
        const engine = Matter.Engine.create();
        const group = Matter.Body.nextGroup(true);
        const chain = Matter.Composites.stack(300, 100, 8, 1, 0, 0, (x: number, y: number) =>
          Matter.Bodies.rectangle(x, y, 40, 16, { collisionFilter: { group } } as never),
        );
        Matter.Composites.chain(chain, 0.45, 0, -0.45, 0, { stiffness, length: 0 } as never);
        const top = Matter.Constraint.create({
          bodyB: chain.bodies[0],
          pointB: { x: -18, y: 0 },
          pointA: { x: 300, y: 100 },
          stiffness: 1,
          length: 0,
        });
        Matter.Composite.add(chain, top);
        Matter.Composite.add(engine.world, chain);
        let sum = 0;
        let count = 0;
        for (let i = 0; i < 240; i++) {
          Matter.Engine.update(engine, 1000 / 60);
          for (const c of Matter.Composite.allConstraints(chain)) {
            if (!c.bodyA || !c.bodyB) continue;
            const dx = c.bodyA.position.x + c.pointA.x - (c.bodyB.position.x + c.pointB.x);
            const dy = c.bodyA.position.y + c.pointA.y - (c.bodyB.position.y + c.pointB.y);
            sum += Math.sqrt(dx * dx + dy * dy);
            count++;
          }
        }
        stretch[name] = sum / count;
      }
      // matter: 0.78 and 0.43 px on average; the layer within a third of a pixel of it
      expect(
        Math.abs(stretch['fulcrum/matter'] - stretch['matter-js']),
        `stiffness ${stiffness}`,
      ).toBeLessThan(0.33);
    }
  });
  it('a program moving the world point of a rigid constraint, or changing its length, is followed, as on matter.js', () => {
    for (const [name, Matter] of both) {
      const engine = Matter.Engine.create();
      const box = Matter.Bodies.rectangle(300, 200, 30, 30, { frictionAir: 0.05 });
      const rope = Matter.Constraint.create({ pointA: { x: 300, y: 100 }, bodyB: box, stiffness: 1 });
      Matter.Composite.add(engine.world, [box, rope]);
      for (let i = 0; i < 60; i++) Matter.Engine.update(engine, 1000 / 60);
      expect(Math.abs(box.position.y - 200), name).toBeLessThan(1);
      rope.pointA = { x: 500, y: 100 };
      rope.length = 150;
      for (let i = 0; i < 600; i++) Matter.Engine.update(engine, 1000 / 60);
      // hanging still under the new point, the new length below it
      expect(Math.abs(box.position.x - 500), name).toBeLessThan(2);
      expect(Math.abs(box.position.y - 250), name).toBeLessThan(2);
    }
  });
});
