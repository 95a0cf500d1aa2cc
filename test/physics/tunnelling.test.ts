import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';
import { run } from '../helpers/world';

describe('no tunnelling at everyday speeds', () => {
  it('a 0.2 m ball at 30 m/s stops at a 0.2 m thick static wall', () => {
    for (const y of [0, 0.37, -0.81]) {
      const world = new World({ gravity: { x: 0, y: 0 } });
      const wall = world.createBody({ position: { x: 5, y: 0 } });
      wall.createShape(Shape.box(0.1, 3));
      const ball = world.createBody({
        type: 'dynamic',
        position: { x: 0, y },
        linearVelocity: { x: 30, y: 0 },
      });
      ball.createShape(Shape.circle(0.1));
      let maxX = Number.NEGATIVE_INFINITY;
      run(world, 1, () => {
        maxX = Math.max(maxX, ball.position.x);
      });
      // the ball's centre never gets closer than its radius (less the linear slop) to the wall's face
      expect(maxX).toBeLessThan(4.9 - 0.1 + 0.005);
    }
  });
});
