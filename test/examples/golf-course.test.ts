/**
 * The gallery's golf course can be played, and each hole's obstacle does its job: the course's own
 * functions (layHole, makeBall, strike) in a world stepped here, a stroke being a pull back from the
 * ball as the demo's drag makes it. The cup is sunk when its sensor sees the ball, as in the demo.
 */
import { describe, expect, it } from 'vitest';
import { holes, layHole, makeBall, strike } from '../../examples/demos/golf';
import { type Vec2, World } from '../../src/index';

interface Outcome {
  sunk: boolean;
  at: Vec2;
}

/** One stroke from the tee of hole `index`: steps until the ball is in, at rest or off the course. */
function stroke(index: number, pull: Vec2): Outcome {
  const world = new World();
  const ball = makeBall(world);
  const course = layHole(world, index, ball);
  let sunk = false;
  world.on('sensorBegin', (e) => {
    if (e.sensorShape === course.cup && e.visitorShape.body === ball) sunk = true;
  });
  const tee = ball.position;
  expect(strike(ball, { x: tee.x - pull.x, y: tee.y - pull.y })).toBe(true);
  let rest = 0;
  for (let step = 0; step < 900 && !sunk; step++) {
    world.step(1 / 60);
    const v = ball.linearVelocity;
    rest = v.x * v.x + v.y * v.y < 0.01 ? rest + 1 : 0;
    const p = ball.position;
    if (p.y < -3 || Math.abs(p.x) > 12) break;
    if (rest >= 15 && step > 30) break;
  }
  return { sunk, at: ball.position };
}

describe('the golf course', () => {
  it('has three holes, each with its cup beyond the tee', () => {
    expect(holes.map((h) => h.name)).toEqual(['Over the hump', 'Chip over the wall', 'The windmill']);
    for (const h of holes) expect(h.cupX).toBeGreaterThan(h.tee.x + 10);
  });

  it('over the hump: a short putt stops before the hump, a 2.5 m pull sinks it', () => {
    const short = stroke(0, { x: 0.6, y: 0 });
    expect(short.sunk).toBe(false);
    // the hump rises from x = -4
    expect(short.at.x).toBeLessThan(-4);
    expect(stroke(0, { x: 2.5, y: 0 }).sunk).toBe(true);
  });

  it('the wall stops every putt along the ground, soft to the hardest; a lob over it goes in', () => {
    const wallLeftFace = -1.3;
    for (let pull = 0.5; pull <= 4; pull += 0.5) {
      const putt = stroke(1, { x: pull, y: 0 });
      expect(putt.sunk, `${pull} m`).toBe(false);
      expect(putt.at.x, `${pull} m`).toBeLessThan(wallLeftFace);
    }
    expect(stroke(1, { x: 2, y: 2.5 }).sunk).toBe(true);
  });

  it('the windmill knocks back putts of the wrong strength and lets a 3 m putt through to the cup', () => {
    for (const pull of [1.5, 2, 2.5, 4]) {
      const putt = stroke(2, { x: pull, y: 0 });
      expect(putt.sunk, `${pull} m`).toBe(false);
      // back on the tee's side of the windmill (its hub at x = -1.5, its sails 1.9 m long)
      expect(putt.at.x, `${pull} m`).toBeLessThan(-3.4);
    }
    expect(stroke(2, { x: 3, y: 0 }).sunk).toBe(true);
  });
});
