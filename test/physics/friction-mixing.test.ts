import { describe, expect, it } from 'vitest';
import { type FrictionMixing, FulcrumError, Shape, World } from '../../src/index';
import { run } from '../helpers/world';

const THETA = Math.PI / 6;
const G = 10;

/** A box of friction 0.5 on a 30° slope of friction 1.6: their geometric mean 0.894 holds it, the smaller slides. */
function slope(frictionMixing?: FrictionMixing) {
  const world = new World({ enableSleep: false, frictionMixing });
  const c = Math.cos(THETA);
  const s = Math.sin(THETA);
  const ground = world.createBody({ position: { x: 0.5 * s, y: -0.5 * c }, angle: THETA });
  ground.createShape(Shape.box(50, 0.5), { friction: 1.6 });
  const box = world.createBody({ type: 'dynamic', position: { x: -0.5 * s, y: 0.5 * c }, angle: THETA });
  box.createShape(Shape.box(0.5, 0.5), { friction: 0.5 });
  return { world, box, along: (p: { x: number; y: number }) => p.x * c + p.y * s };
}

describe('frictionMixing', () => {
  it("'geometric' (the default) takes sqrt(0.5 * 1.6) = 0.894 > tan 30° = 0.577: the box holds", () => {
    for (const mixing of [undefined, 'geometric'] as const) {
      const { world, box, along } = slope(mixing);
      expect(world.frictionMixing).toBe('geometric');
      const s0 = along(box.position);
      run(world, 2);
      expect(Math.abs(along(box.position) - s0)).toBeLessThan(0.001);
    }
  });

  it("'min' takes 0.5 < tan 30°: the box slides with a = g (sin - 0.5 cos)", () => {
    const { world, box, along } = slope('min');
    const s0 = along(box.position);
    run(world, 2);
    const a = (2 * (s0 - along(box.position))) / (2 * 2);
    const expected = G * (Math.sin(THETA) - 0.5 * Math.cos(THETA));
    expect(Math.abs(a - expected) / expected).toBeLessThan(0.03);
  });

  it('can be changed between steps, and refuses anything else', () => {
    const { world, box, along } = slope();
    run(world, 0.5);
    world.frictionMixing = 'min';
    const s0 = along(box.position);
    run(world, 1);
    // from rest: s = a t^2 / 2 over the second run
    const expected = (G * (Math.sin(THETA) - 0.5 * Math.cos(THETA))) / 2;
    expect(Math.abs(s0 - along(box.position) - expected) / expected).toBeLessThan(0.03);
    expect(() => {
      world.frictionMixing = 'max' as FrictionMixing;
    }).toThrow(FulcrumError);
    expect(world.frictionMixing).toBe('min');
    expect(() => new World({ frictionMixing: 'average' as FrictionMixing })).toThrow(/frictionMixing/);
  });
});
