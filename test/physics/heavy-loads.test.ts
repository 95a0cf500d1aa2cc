import { describe, expect, it } from 'vitest';
import { type Body, Shape, stateHash, World, type WorldDef } from '../../src/index';
import { groundWorld, run } from '../helpers/world';

/**
 * Light bodies under a much heavier one, at the default settings (4 substeps). Boxes and balls are
 * 1 m across, so each rests exactly 1 m above the one it stands on: every height below is checked
 * against that rest height, and no body may sink more than 5 cm into another.
 */

const TOLERANCE = 0.05;

/** `n` boxes of 1 kg in a column on the ground, then one box of `heavy` kg (the last body). */
function loadedStack(
  def: WorldDef,
  n: number,
  heavy: number,
): { world: World; ground: Body; bodies: Body[] } {
  const { world, ground } = groundWorld(def);
  const bodies: Body[] = [];
  for (let i = 0; i <= n; i++) {
    const b = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 + i } });
    b.createShape(Shape.box(0.5, 0.5), { density: i === n ? heavy : 1 });
    bodies.push(b);
  }
  return { world, ground, bodies };
}

/** A pyramid of 1 kg boxes with a base of `base`, then one box of `heavy` kg on its top (the last body). */
function loadedPyramid(
  def: WorldDef,
  base: number,
  heavy: number,
): { world: World; ground: Body; bodies: Body[] } {
  const { world, ground } = groundWorld(def);
  const bodies: Body[] = [];
  for (let row = 0; row < base; row++) {
    for (let i = 0; i < base - row; i++) {
      const b = world.createBody({
        type: 'dynamic',
        position: { x: i - (base - row - 1) / 2, y: 0.5 + row },
      });
      b.createShape(Shape.box(0.5, 0.5), { density: 1 });
      bodies.push(b);
    }
  }
  const top = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 + base } });
  top.createShape(Shape.box(0.5, 0.5), { density: heavy });
  bodies.push(top);
  return { world, ground, bodies };
}

/**
 * Steps `seconds` and returns the largest distance of any body from where it started (its rest
 * position) and the deepest overlap of two bodies, one on top of the other, seen at any step.
 */
function watch(world: World, bodies: Body[], seconds: number): { moved: number; overlap: number } {
  const start = bodies.map((b) => b.position);
  let moved = 0;
  let overlap = 0;
  run(world, seconds, () => {
    for (let i = 0; i < bodies.length; i++) {
      const p = bodies[i].position;
      moved = Math.max(moved, Math.hypot(p.x - start[i].x, p.y - start[i].y));
      // on the ground (y = 0.5 at rest), or on any body within half a metre to either side
      overlap = Math.max(overlap, 0.5 - p.y);
      for (let j = 0; j < bodies.length; j++) {
        const q = bodies[j].position;
        if (j !== i && q.y < p.y && Math.abs(q.x - p.x) < 0.5) overlap = Math.max(overlap, 1 - (p.y - q.y));
      }
    }
  });
  return { moved, overlap };
}

/** Sum of the normal impulses the ground's contacts keep, per second: the weight they carry. */
function groundLoad(world: World, ground: Body): number {
  const core = world.core;
  const contacts = core.contacts;
  let sum = 0;
  for (let c = 0; c < contacts.slotCount; c++) {
    if (contacts.alive[c] === 0) continue;
    if (contacts.bodyA[c] !== ground.slot && contacts.bodyB[c] !== ground.slot) continue;
    for (let j = 0; j < contacts.pointCount[c]; j++) sum += contacts.normalImpulse[c * 2 + j];
  }
  return (sum * core.subSteps) / (1 / 60);
}

describe('heavy loads on light bodies', () => {
  for (const heavy of [100, 1000]) {
    it(`9 boxes of 1 kg under ${heavy} kg keep their heights within 5 cm for 10 s`, () => {
      const { world, bodies } = loadedStack({ enableSleep: false }, 9, heavy);
      const { moved, overlap } = watch(world, bodies, 10);
      expect(moved).toBeLessThan(TOLERANCE);
      expect(overlap).toBeLessThan(TOLERANCE);
      // the heavy box's rest height: 9 boxes of 1 m under its centre
      expect(Math.abs(bodies[9].position.y - 9.5)).toBeLessThan(TOLERANCE);
    });
  }

  it('9 boxes of 1 kg under 10,000 kg sink less than 5 cm into each other for 10 s', () => {
    // each contact gives about a centimetre here, so the nine of them lower the top box by more
    const { world, bodies } = loadedStack({ enableSleep: false }, 9, 10_000);
    const { overlap } = watch(world, bodies, 10);
    expect(overlap).toBeLessThan(TOLERANCE);
    for (const b of bodies) expect(Math.abs(b.position.x)).toBeLessThan(0.001);
  });

  it('a pyramid of 1 kg boxes with a base of 10 under 1,000 kg keeps its shape for 10 s', () => {
    const { world, bodies } = loadedPyramid({ enableSleep: false }, 10, 1000);
    const { moved, overlap } = watch(world, bodies, 10);
    expect(moved).toBeLessThan(TOLERANCE);
    expect(overlap).toBeLessThan(TOLERANCE);
    expect(Math.abs(bodies[bodies.length - 1].position.y - 10.5)).toBeLessThan(TOLERANCE);
  });

  it('the same stack and pyramid hold with sleeping on, and fall asleep', () => {
    for (const { world, bodies } of [loadedStack({}, 9, 1000), loadedPyramid({}, 10, 1000)]) {
      const { moved, overlap } = watch(world, bodies, 3);
      expect(moved).toBeLessThan(TOLERANCE);
      expect(overlap).toBeLessThan(TOLERANCE);
      expect(bodies.every((b) => !b.isAwake)).toBe(true);
    }
  });

  it('a 1,000 kg ball on 9 balls of 1 kg in a well 1 m wide keeps their heights within 5 cm', () => {
    const { world } = groundWorld({ enableSleep: false });
    const walls = world.createBody({ position: { x: 0, y: 0 } });
    walls.createShape(Shape.box(0.5, 10, { x: -1, y: 10 }));
    walls.createShape(Shape.box(0.5, 10, { x: 1, y: 10 }));
    const balls: Body[] = [];
    for (let i = 0; i <= 9; i++) {
      const b = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 + i } });
      b.createShape(Shape.circle(0.5), { density: (i === 9 ? 1000 : 1) / (Math.PI * 0.25) });
      balls.push(b);
    }
    expect(balls[9].mass).toBeCloseTo(1000, 9);
    const { moved, overlap } = watch(world, balls, 10);
    expect(moved).toBeLessThan(TOLERANCE);
    expect(overlap).toBeLessThan(TOLERANCE);
  });

  it('a 1,000 kg box dropped 2 m onto the stack stops on it without passing through or bouncing', () => {
    const { world } = groundWorld({ enableSleep: false });
    const bodies: Body[] = [];
    for (let i = 0; i < 10; i++) {
      const b = world.createBody({ type: 'dynamic', position: { x: 0, y: i < 9 ? 0.5 + i : 11.5 } });
      b.createShape(Shape.box(0.5, 0.5), { density: i < 9 ? 1 : 1000 });
      bodies.push(b);
    }
    const heavy = bodies[9];
    let landed = false;
    let rebound = 0;
    let overlap = 0;
    run(world, 5, () => {
      if (heavy.position.y < 9.6) landed = true;
      if (landed) rebound = Math.max(rebound, heavy.linearVelocity.y);
      for (let i = 1; i < 10; i++)
        overlap = Math.max(overlap, 1 - (bodies[i].position.y - bodies[i - 1].position.y));
    });
    // it hit at sqrt(2 g 2 m) = 6.3 m/s; restitution 0
    expect(overlap).toBeLessThan(TOLERANCE);
    expect(rebound).toBeLessThan(0.1);
    expect(Math.abs(heavy.position.y - 9.5)).toBeLessThan(TOLERANCE);
  });

  it('the contacts carry the whole weight: the ground holds the pile and the heavy box', () => {
    for (const build of [
      () => loadedStack({ enableSleep: false }, 9, 1000),
      () => loadedPyramid({ enableSleep: false }, 10, 1000),
    ]) {
      const { world, ground, bodies } = build();
      run(world, 10);
      const weight = bodies.reduce((sum, b) => sum + b.mass, 0) * -world.gravity.y;
      expect(Math.abs(groundLoad(world, ground) / weight - 1)).toBeLessThan(0.02);
    }
  });

  it('is deterministic and survives a snapshot', () => {
    const a = loadedPyramid({ enableSleep: false }, 10, 1000).world;
    const b = loadedPyramid({ enableSleep: false }, 10, 1000).world;
    run(a, 2);
    run(b, 2);
    expect(stateHash(a)).toBe(stateHash(b));
    const c = World.restore(a.snapshot());
    run(a, 2);
    run(c, 2);
    expect(stateHash(c)).toBe(stateHash(a));
  });
});
