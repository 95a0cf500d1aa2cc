import { describe, expect, it } from 'vitest';
import { type Body, Shape, type World } from '../../src/index';
import { dist, groundWorld, pyramid, run, runYielding } from '../helpers/world';

function verticalStack(world: World, n: number): Body[] {
  const boxes: Body[] = [];
  for (let i = 0; i < n; i++) {
    const b = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 + i } });
    b.createShape(Shape.box(0.5, 0.5));
    boxes.push(b);
  }
  return boxes;
}

/** Largest displacement of any body from where it was after `settle` seconds, over `seconds` more. */
function drift(world: World, boxes: Body[], settle: number, seconds: number): number {
  run(world, settle);
  const start = boxes.map((b) => b.position);
  run(world, seconds);
  return Math.max(...boxes.map((b, i) => dist(b.position, start[i])));
}

function allAsleepWithin(world: World, boxes: Body[], seconds: number): boolean {
  world.enableSleep = true;
  let asleep = false;
  run(world, seconds, () => {
    if (!asleep && boxes.every((b) => !b.isAwake)) asleep = true;
  });
  return asleep;
}

describe('stacking', () => {
  it('a vertical stack of 20 boxes stands for 30 s, then sleeps within 5 s', () => {
    const { world } = groundWorld({ enableSleep: false });
    const boxes = verticalStack(world, 20);
    expect(drift(world, boxes, 1, 29)).toBeLessThan(0.01);
    expect(allAsleepWithin(world, boxes, 5)).toBe(true);
  });

  it('a pyramid with a base of 20 stands for 30 s, then sleeps within 5 s', () => {
    const { world } = groundWorld({ enableSleep: false });
    const boxes = pyramid(world, 20);
    expect(drift(world, boxes, 1, 29)).toBeLessThan(0.01);
    expect(allAsleepWithin(world, boxes, 5)).toBe(true);
  });

  it('a pyramid with a base of 20 comes to rest at 2 substeps and at 1', () => {
    // Fewer substeps make each contact spring relatively faster; with the contact stiffness capped at
    // a quarter of the substep rate this pile breathed +-6 cm at 3 Hz for good at 2 substeps (Box2D v3
    // caps at an eighth and settles it). At rest no box moves: under 1 mm in 4 s, after 4 s of
    // settling at 2 substeps and 8 s at 1, at every step.
    for (const [subSteps, settle] of [
      [2, 4],
      [1, 8],
    ]) {
      const { world } = groundWorld({ enableSleep: false, subSteps });
      const boxes = pyramid(world, 20);
      run(world, settle);
      const start = boxes.map((b) => b.position);
      let moved = 0;
      run(world, 4, () => {
        for (let i = 0; i < boxes.length; i++) moved = Math.max(moved, dist(boxes[i].position, start[i]));
      });
      expect(moved).toBeLessThan(0.001);
    }
  });

  it('a pyramid with a base of 40 stays centred: the solve order does not push it sideways', () => {
    // The pile is symmetric, so nothing should move its centre of mass sideways or its top off the
    // axis. With the constraints coloured in a fixed order every box of a row was favoured the same
    // way: the ground's friction pushed the pile 6.5 mm aside within 0.3 s, the top swung 26 mm and
    // the pile crept 4 mm between 1 s and 4 s.
    const { world } = groundWorld({ enableSleep: false });
    const boxes = pyramid(world, 40);
    const top = boxes[boxes.length - 1];
    const centreX = () => boxes.reduce((sum, b) => sum + b.position.x, 0) / boxes.length;
    let worstCentre = 0;
    let worstTop = 0;
    run(world, 1, () => {
      worstCentre = Math.max(worstCentre, Math.abs(centreX()));
      worstTop = Math.max(worstTop, Math.abs(top.position.x));
    });
    const start = boxes.map((b) => b.position);
    let moved = 0;
    run(world, 3, () => {
      worstCentre = Math.max(worstCentre, Math.abs(centreX()));
      for (let i = 0; i < boxes.length; i++) moved = Math.max(moved, dist(boxes[i].position, start[i]));
    });
    expect(worstCentre).toBeLessThan(0.001);
    expect(worstTop).toBeLessThan(0.005);
    expect(moved).toBeLessThan(0.002);
  });

  it('a pyramid with a base of 100 (5,050 boxes) stands for 10 s', async () => {
    const { world } = groundWorld({ enableSleep: false });
    const boxes = pyramid(world, 100);
    expect(boxes.length).toBe(5050);
    const initial = boxes.map((b) => b.position);
    await runYielding(world, 10);
    // standing: no box has fallen or slid off (a fallen box moves metres); the soft contacts compress
    // the 100 rows by 0.73 m in all, as Box2D v3 does with the same contact stiffness
    const moved = Math.max(...boxes.map((b, i) => dist(b.position, initial[i])));
    expect(moved).toBeLessThan(1);
    const top = boxes[boxes.length - 1].position;
    expect(Math.abs(top.x)).toBeLessThan(0.1);
    expect(Math.abs(boxes[boxes.length - 1].angle)).toBeLessThan(0.01);
  }, 180_000); // about 20 s alone; room for a loaded 2-core machine

  it('a 100 kg box on a 1 kg box sinks less than 2 cm into it', () => {
    const { world } = groundWorld({ enableSleep: false });
    const light = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    light.createShape(Shape.box(0.5, 0.5), { density: 1 });
    const heavy = world.createBody({ type: 'dynamic', position: { x: 0, y: 1.5 } });
    heavy.createShape(Shape.box(0.5, 0.5), { density: 100 });
    expect(heavy.mass / light.mass).toBeCloseTo(100, 10);
    let worst = 0;
    run(world, 5, () => {
      worst = Math.max(worst, 1 - (heavy.position.y - light.position.y), 0.5 - light.position.y);
    });
    expect(worst).toBeLessThan(0.02);
  });
});
