import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape } from '../../src/index';

/**
 * Issue 27 (known), found again by the API fuzzer (test/property, tame seeds 1002 and 3000: an invalid
 * call `Shape.polygon(new Array(3))`): a points array with holes throws a TypeError (reading 'x' of
 * undefined) instead of a FulcrumError naming the argument.
 */
describe('Shape.polygon with holes in its points array', () => {
  const holes: [string, unknown[]][] = [
    ['new Array(3)', new Array(3)],
    [
      'a hole at index 1',
      Object.assign(new Array(4), { 0: { x: 0, y: 0 }, 2: { x: 1, y: 1 }, 3: { x: 0, y: 1 } }),
    ],
    ['an undefined point', [{ x: 0, y: 0 }, undefined, { x: 1, y: 1 }, { x: 0, y: 1 }]],
  ];
  for (const [name, points] of holes) {
    it(`${name} throws a FulcrumError naming the points`, () => {
      expect(() => Shape.polygon(points as never)).toThrow(FulcrumError);
      expect(() => Shape.polygon(points as never)).toThrow(/points/);
    });
  }
});
