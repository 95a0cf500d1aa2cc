import { describe, expect, it } from 'vitest';
import { type Body, FulcrumError, type JointDef, Shape, World } from '../../src/index';

/**
 * Found by the API fuzzer (test/property, seed 9002: a distance joint from the ground to a body with
 * `enableSpring: true, hertz: 5e-324, dampingRatio: 0`, one step, and the static ground's velocity is
 * NaN): a spring frequency so small that h * 2 pi hertz underflows to 0 with no damping makes the soft
 * constraint's bias rate omega / (2 zeta + h omega) = x / 0 (softness.ts). Such a spring is as good as
 * none; it must be refused at the call or leave the world finite.
 */
function finite(body: Body): boolean {
  const p = body.position;
  const v = body.linearVelocity;
  return [p.x, p.y, v.x, v.y, body.angularVelocity, body.rotation.c, body.rotation.s].every(Number.isFinite);
}

const joints: [string, (ground: Body, body: Body) => JointDef][] = [
  [
    'distance',
    (ground, body) => ({
      type: 'distance',
      bodyA: ground,
      bodyB: body,
      enableSpring: true,
      hertz: 5e-324,
      dampingRatio: 0,
    }),
  ],
  [
    'revolute',
    (ground, body) => ({
      type: 'revolute',
      bodyA: ground,
      bodyB: body,
      anchor: { x: 0, y: 2 },
      enableSpring: true,
      hertz: 5e-324,
      dampingRatio: 0,
    }),
  ],
  [
    'prismatic',
    (ground, body) => ({
      type: 'prismatic',
      bodyA: ground,
      bodyB: body,
      anchor: { x: 0, y: 2 },
      axis: { x: 0, y: 1 },
      enableSpring: true,
      hertz: 5e-324,
      dampingRatio: 0,
    }),
  ],
  [
    'wheel',
    (ground, body) => ({
      type: 'wheel',
      bodyA: ground,
      bodyB: body,
      anchor: { x: 0, y: 2 },
      axis: { x: 0, y: 1 },
      hertz: 5e-324,
      dampingRatio: 0,
    }),
  ],
  ['mouse', (_, body) => ({ type: 'mouse', body, target: { x: 1, y: 3 }, hertz: 5e-324, dampingRatio: 0 })],
  [
    'weld',
    (ground, body) => ({
      type: 'weld',
      bodyA: ground,
      bodyB: body,
      anchor: { x: 0, y: 2 },
      linearHertz: 5e-324,
      angularHertz: 5e-324,
      dampingRatio: 0,
    }),
  ],
];

describe('a spring of 5e-324 Hz without damping', () => {
  for (const [name, def] of joints) {
    it(`on a ${name} joint leaves the world finite (or is refused)`, () => {
      const world = new World();
      const ground = world.createBody({ position: { x: 0, y: 0 } });
      ground.createShape(Shape.box(5, 0.5));
      const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
      body.createShape(Shape.box(0.25, 0.25));
      try {
        world.createJoint(def(ground, body));
      } catch (e) {
        expect(e).toBeInstanceOf(FulcrumError);
        return;
      }
      for (let i = 0; i < 30; i++) world.step(1 / 60);
      expect(finite(ground)).toBe(true);
      expect(ground.linearVelocity).toEqual({ x: 0, y: 0 });
      expect(finite(body)).toBe(true);
    });
  }
});
