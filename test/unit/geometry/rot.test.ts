import { describe, expect, it } from 'vitest';
import { arcTangent2 } from '../../../src/math/arc-tangent';
import { makeRot } from '../../../src/math/rot';
import { random } from './brute-force';

describe('deterministic trigonometry', () => {
  it('makeRot matches Math.cos / Math.sin to 1e-15', () => {
    const rnd = random(11);
    const angles = [0, Math.PI / 4, Math.PI / 2, Math.PI, -Math.PI, 2 * Math.PI, 1e-9, -3.3];
    for (let i = 0; i < 5000; i++) angles.push((rnd() * 2 - 1) * 40);
    for (const angle of angles) {
      const q = makeRot(angle);
      expect(Math.abs(q.c - Math.cos(angle))).toBeLessThanOrEqual(1e-15);
      expect(Math.abs(q.s - Math.sin(angle))).toBeLessThanOrEqual(1e-15);
    }
  });

  it('arcTangent2 matches Math.atan2 to 1e-15', () => {
    const rnd = random(12);
    const cases: [number, number][] = [
      [0, 1],
      [1, 0],
      [0, -1],
      [-1, 0],
      [1, 1],
      [1e-300, 1],
      [3, -1e-12],
    ];
    for (let i = 0; i < 5000; i++) cases.push([(rnd() * 2 - 1) * 10, (rnd() * 2 - 1) * 10]);
    for (const [y, x] of cases)
      expect(Math.abs(arcTangent2(y, x) - Math.atan2(y, x))).toBeLessThanOrEqual(1e-15);
    expect(arcTangent2(0, 0)).toBe(0);
  });
});
