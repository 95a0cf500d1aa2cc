import { describe, expect, it } from 'vitest';
import { type Body, Shape, World } from '../../src/index';

const G = 10;
const L = 1;
const DT = 1 / 60;

/** Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean. */
function ellipticK(k: number): number {
  let a = 1;
  let b = Math.sqrt(1 - k * k);
  for (let i = 0; i < 30; i++) {
    const an = (a + b) / 2;
    b = Math.sqrt(a * b);
    a = an;
  }
  return Math.PI / (2 * a);
}

/** A bob on a 1 m pendulum from a static pivot at the origin, released at `theta0` from straight down. */
function pendulum(kind: 'revolute' | 'distance', theta0: number): { world: World; bob: Body } {
  const world = new World({ gravity: { x: 0, y: -G } });
  const pivot = world.createBody({ position: { x: 0, y: 0 } });
  const bob = world.createBody({
    type: 'dynamic',
    position: { x: L * Math.sin(theta0), y: -L * Math.cos(theta0) },
  });
  bob.createShape(Shape.circle(0.05), { density: 100 });
  if (kind === 'revolute')
    world.createJoint({ type: 'revolute', bodyA: pivot, bodyB: bob, anchor: { x: 0, y: 0 } });
  else world.createJoint({ type: 'distance', bodyA: pivot, bodyB: bob, length: L });
  return { world, bob };
}

/** Times of upward zero crossings of x (linear interpolation), and the peaks of |angle| in between. */
function swing(world: World, bob: Body, seconds: number): { crossings: number[]; peaks: number[] } {
  const crossings: number[] = [];
  const peaks: number[] = [];
  let prevX = bob.position.x;
  let peak = 0;
  for (let i = 1; i <= Math.round(seconds / DT); i++) {
    world.step(DT);
    const p = bob.position;
    const angle = Math.abs(Math.atan2(p.x, -p.y));
    peak = Math.max(peak, angle);
    if (prevX < 0 && p.x >= 0) {
      crossings.push((i - 1 + -prevX / (p.x - prevX)) * DT);
      peaks.push(peak);
      peak = 0;
    }
    prevX = p.x;
  }
  return { crossings, peaks };
}

function meanPeriod(crossings: number[]): number {
  return (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
}

describe('pendulum', () => {
  for (const kind of ['revolute', 'distance'] as const) {
    it(`${kind}: small-amplitude period is 2 pi sqrt(L/g)`, () => {
      const { world, bob } = pendulum(kind, 0.05);
      const { crossings } = swing(world, bob, 12);
      // the bob is a small disc: a physical pendulum, I = m L^2 + m r^2 / 2 about the pivot
      const pointPeriod = 2 * Math.PI * Math.sqrt(L / G);
      const expected =
        kind === 'revolute' ? pointPeriod * Math.sqrt(1 + (0.05 * 0.05) / 2 / (L * L)) : pointPeriod;
      expect(Math.abs(meanPeriod(crossings) - expected) / expected).toBeLessThan(0.01);
    });
  }

  it('90 degree amplitude: period equals the exact elliptic-integral value', () => {
    const { world, bob } = pendulum('distance', Math.PI / 2);
    const { crossings } = swing(world, bob, 12);
    const expected = 4 * Math.sqrt(L / G) * ellipticK(Math.sin(Math.PI / 4));
    expect(Math.abs(meanPeriod(crossings) - expected) / expected).toBeLessThan(0.01);
  });

  it('amplitude decays less than 1% per period without damping', () => {
    const { world, bob } = pendulum('revolute', 0.5);
    const { peaks } = swing(world, bob, 20);
    for (let i = 2; i < peaks.length; i++) expect(peaks[i] / peaks[i - 1]).toBeGreaterThan(0.99);
    expect(peaks[peaks.length - 1] / peaks[1]).toBeGreaterThan(0.9);
  });
});
