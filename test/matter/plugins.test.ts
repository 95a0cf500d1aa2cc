import { describe, expect, it } from 'vitest';
import Matter from '../../src/matter/index';
import { RealMatter } from '../helpers/matter-both';

describe('fulcrum/matter Plugin, Matter.use, Matter.after, Svg and Detector', () => {
  it('a wrap-around plugin (as matter-wrap is written) installs once and hooks Engine.update by path', () => {
    let installs = 0;
    const wrap = {
      name: 'wrap-test',
      version: '0.1.0',
      install(base: typeof Matter) {
        installs++;
        // matter-wrap's way: run after every Engine.update (with the engine it returned as this),
        // moving bodies that left the bounds
        base.after('Engine.update', function (this: unknown) {
          const engine = this as ReturnType<typeof Matter.Engine.create>;
          for (const body of Matter.Composite.allBodies(engine.world)) {
            if (body.position.y > 600)
              Matter.Body.setPosition(body, { x: body.position.x, y: body.position.y - 600 });
          }
        });
      },
    };
    Matter.use(wrap);
    Matter.use(wrap);
    expect(installs).toBe(1);
    const engine = Matter.Engine.create();
    const ball = Matter.Bodies.circle(100, 550, 10);
    Matter.Composite.add(engine.world, ball);
    let lowest = 0;
    for (let i = 0; i < 120; i++) {
      Matter.Engine.update(engine);
      lowest = Math.max(lowest, ball.position.y);
    }
    expect(lowest).toBeLessThanOrEqual(600);
    expect(ball.position.y).toBeLessThan(600);
  });

  it('Svg.pathToVertices gives the outline of a path, as Bodies.fromVertices takes it', () => {
    const points = Matter.Svg.pathToVertices('M0 0 L100 0 L100 50 L0 50 Z');
    expect(points).toEqual([
      { x: 0, y: 0 },
      { x: 100, y: 0 },
      { x: 100, y: 50 },
      { x: 0, y: 50 },
    ]);
    const body = Matter.Bodies.fromVertices(300, 200, [points]);
    expect(body.area).toBeCloseTo(5000, 9);
    expect(body.position).toEqual({ x: 300, y: 200 });
  });

  it('Detector.collisions and canCollide agree with matter.js', () => {
    for (const M of [RealMatter, Matter]) {
      const a = M.Bodies.rectangle(0, 0, 40, 40);
      const b = M.Bodies.rectangle(30, 0, 40, 40);
      const c = M.Bodies.rectangle(200, 0, 40, 40);
      const d = M.Bodies.rectangle(10, 10, 40, 40, { collisionFilter: { group: -1 } });
      const e = M.Bodies.rectangle(10, 10, 40, 40, { collisionFilter: { group: -1 } });
      const detector = M.Detector.create();
      M.Detector.setBodies(detector, [a, b, c]);
      expect(M.Detector.collisions(detector).length).toBe(1);
      expect(M.Detector.canCollide(d.collisionFilter, e.collisionFilter)).toBe(false);
      expect(M.Detector.canCollide(a.collisionFilter, e.collisionFilter)).toBe(true);
    }
  });
});
