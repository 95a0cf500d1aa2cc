import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../src/index';
import { run } from '../helpers/world';

function headOn(densityA: number, densityB: number) {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const a = world.createBody({ type: 'dynamic', position: { x: -2, y: 0 }, linearVelocity: { x: 5, y: 0 } });
  a.createShape(Shape.circle(0.5), { density: densityA, restitution: 1, friction: 0 });
  const b = world.createBody({ type: 'dynamic', position: { x: 2, y: 0 } });
  b.createShape(Shape.circle(0.5), { density: densityB, restitution: 1, friction: 0 });
  return { world, a, b };
}

describe('momentum', () => {
  it('equal circles exchange their velocities in a head-on elastic hit', () => {
    const { world, a, b } = headOn(1, 1);
    run(world, 2);
    expect(Math.abs(a.linearVelocity.x)).toBeLessThan(0.02 * 5);
    expect(Math.abs(b.linearVelocity.x - 5) / 5).toBeLessThan(0.02);
  });

  it('unequal masses match the textbook elastic result and conserve momentum', () => {
    const { world, a, b } = headOn(1, 3);
    const mA = a.mass;
    const mB = b.mass;
    expect(mB / mA).toBeCloseTo(3, 12);
    const p0 = mA * 5;
    let worst = 0;
    run(world, 2, () => {
      const p = mA * a.linearVelocity.x + mB * b.linearVelocity.x;
      worst = Math.max(worst, Math.abs(p - p0));
      expect(a.linearVelocity.y).toBe(0);
    });
    const vA = ((mA - mB) / (mA + mB)) * 5;
    const vB = ((2 * mA) / (mA + mB)) * 5;
    expect(Math.abs(a.linearVelocity.x - vA) / Math.abs(vA)).toBeLessThan(0.03);
    expect(Math.abs(b.linearVelocity.x - vB) / vB).toBeLessThan(0.03);
    expect(worst).toBeLessThan(1e-9);
  });

  it('an off-centre hit turns a free box the right way', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0 } });
    box.createShape(Shape.box(0.5, 0.5));
    // a ball moving +x strikes the box above its centre: the box must turn clockwise (negative spin)
    const above = world.createBody({
      type: 'dynamic',
      position: { x: -2, y: 0.35 },
      linearVelocity: { x: 6, y: 0 },
    });
    above.createShape(Shape.circle(0.1), { density: 5 });
    run(world, 1);
    expect(box.angularVelocity).toBeLessThan(-0.1);
    expect(box.linearVelocity.x).toBeGreaterThan(0);

    const world2 = new World({ gravity: { x: 0, y: 0 } });
    const box2 = world2.createBody({ type: 'dynamic' });
    box2.createShape(Shape.box(0.5, 0.5));
    const below = world2.createBody({
      type: 'dynamic',
      position: { x: -2, y: -0.35 },
      linearVelocity: { x: 6, y: 0 },
    });
    below.createShape(Shape.circle(0.1), { density: 5 });
    run(world2, 1);
    expect(box2.angularVelocity).toBeGreaterThan(0.1);
  });

  it('angular momentum about the hit is conserved in an off-centre hit without friction', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const box = world.createBody({ type: 'dynamic' });
    box.createShape(Shape.box(0.5, 0.5), { friction: 0 });
    const ball = world.createBody({
      type: 'dynamic',
      position: { x: -2, y: 0.3 },
      linearVelocity: { x: 4, y: 0 },
    });
    ball.createShape(Shape.circle(0.1), { density: 5, friction: 0, restitution: 0.5 });
    // angular momentum about the origin: L = sum(m (r x v)) + I w
    const L = () => {
      let total = 0;
      for (const body of [box, ball]) {
        const c = body.worldCenter;
        const v = body.linearVelocity;
        total += body.mass * (c.x * v.y - c.y * v.x) + body.inertia * body.angularVelocity;
      }
      return total;
    };
    const L0 = L();
    run(world, 1);
    expect(Math.abs(L() - L0)).toBeLessThan(1e-9 * Math.max(1, Math.abs(L0)));
  });
});
