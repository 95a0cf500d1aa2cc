import { describe, expect, it } from 'vitest';
import { PointRows } from '../../../src/solver/point-rows';
import { BodyState } from '../../../src/store/body-store';

/*
 * The point rows' maths against their definition: J written out from the constraint C = (cB + rB) -
 * (cA + rA), then J v, K = J M⁻¹ Jᵀ and the impulse M⁻¹ Jᵀ p worked out as matrix products here.
 */

const rows = new PointRows();

/** A deterministic sequence in [-1, 1) (a linear congruential generator). */
function sequence(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 31 - 1;
  };
}

interface Hinge {
  mA: number;
  iA: number;
  mB: number;
  iB: number;
  rAx: number;
  rAy: number;
  rBx: number;
  rBy: number;
  /** velocities: vAx, vAy, wA, vBx, vBy, wB */
  v: number[];
}

function hinges(count: number): Hinge[] {
  const next = sequence(24);
  const out: Hinge[] = [];
  for (let k = 0; k < count; k++) {
    out.push({
      mA: 0.1 + Math.abs(next()) * 5,
      iA: 0.1 + Math.abs(next()) * 20,
      mB: 0.1 + Math.abs(next()) * 5,
      iB: 0.1 + Math.abs(next()) * 20,
      rAx: next() * 2,
      rAy: next() * 2,
      rBx: next() * 2,
      rBy: next() * 2,
      v: [next() * 10, next() * 10, next() * 5, next() * 10, next() * 10, next() * 5],
    });
    // every fourth body A is static (zero inverse mass and inertia)
    if (k % 4 === 3) {
      out[k].mA = 0;
      out[k].iA = 0;
    }
  }
  return out;
}

/** J from the constraint's derivative: the velocity of B's anchor minus A's, per body (x, y, turn). */
function jacobian(h: Hinge): number[][] {
  return [
    [-1, 0, h.rAy, 1, 0, -h.rBy],
    [0, -1, -h.rAx, 0, 1, h.rBx],
  ];
}

const inverseMass = (h: Hinge): number[] => [h.mA, h.mA, h.iA, h.mB, h.mB, h.iB];

function effectiveMass(h: Hinge): number[][] {
  const j = jacobian(h);
  const m = inverseMass(h);
  return [0, 1].map((r) => [0, 1].map((c) => j[r].reduce((sum, x, k) => sum + x * m[k] * j[c][k], 0)));
}

function close(actual: number, expected: number, scale: number): void {
  expect(Math.abs(actual - expected)).toBeLessThanOrEqual(1e-13 * Math.max(1, scale));
}

describe('the point rows', () => {
  const all = hinges(64);

  it('write J as the constraint defines it', () => {
    const jA = new Float64Array(9);
    const jB = new Float64Array(9);
    for (const h of all) {
      rows.writeJacobian(jA, jB, 3, h.rAx, h.rAy, h.rBx, h.rBy);
      const j = jacobian(h);
      expect([...jA.subarray(3, 6)]).toEqual(j[0].slice(0, 3));
      expect([...jA.subarray(6, 9)]).toEqual(j[1].slice(0, 3));
      expect([...jB.subarray(3, 6)]).toEqual(j[0].slice(3));
      expect([...jB.subarray(6, 9)]).toEqual(j[1].slice(3));
    }
  });

  it('measure J v, and -J v with the bodies swapped', () => {
    for (const h of all) {
      const [vAx, vAy, wA, vBx, vBy, wB] = h.v;
      const jv = jacobian(h).map((row) => row.reduce((sum, x, k) => sum + x * h.v[k], 0));
      close(rows.speedX(vAx, wA, h.rAy, vBx, wB, h.rBy), jv[0], 100);
      close(rows.speedY(vAy, wA, h.rAx, vBy, wB, h.rBx), jv[1], 100);
      close(rows.speedX(vBx, wB, h.rBy, vAx, wA, h.rAy), -jv[0], 100);
      close(rows.speedY(vBy, wB, h.rBx, vAy, wA, h.rAx), -jv[1], 100);
    }
  });

  it('give K = J M⁻¹ Jᵀ, in both summation orders', () => {
    for (const h of all) {
      const k = effectiveMass(h);
      const scale = k[0][0] + k[1][1];
      close(rows.massDiagonal(h.mA + h.mB, h.iA, h.rAy, h.iB, h.rBy), k[0][0], scale);
      close(rows.massDiagonal(h.mA + h.mB, h.iA, h.rAx, h.iB, h.rBx), k[1][1], scale);
      close(rows.massCoupling(h.iA, h.rAx, h.rAy, h.iB, h.rBx, h.rBy), k[0][1], scale);
      close(rows.pathMassDiagonal(h.mA + h.mB, h.iA, h.rAy, h.iB, h.rBy), k[0][0], scale);
      close(rows.pathMassDiagonal(h.mA + h.mB, h.iA, h.rAx, h.iB, h.rBx), k[1][1], scale);
      close(rows.pathMassCoupling(h.iA, h.rAx, h.rAy, h.iB, h.rBx, h.rBy), k[0][1], scale);
    }
  });

  it('solve K x = b, with K⁻¹ or by Cramer, and give zeros for a singular K', () => {
    const next = sequence(7);
    for (const h of all) {
      const [[k11, k12], [, k22]] = effectiveMass(h);
      const b1 = next() * 10;
      const b2 = next() * 10;
      const det = rows.inverseDeterminant(k11, k12, k22);
      const x = rows.solveX(det, k12, k22, b1, b2);
      const y = rows.solveY(det, k11, k12, b1, b2);
      close(k11 * x + k12 * y, b1, 1e3);
      close(k12 * x + k22 * y, b2, 1e3);
      // the inverse the batch and the paths keep
      const m11 = det * k22;
      const m12 = -det * k12;
      const m22 = det * k11;
      close(m11 * b1 + m12 * b2, x, 1e3);
      close(m12 * b1 + m22 * b2, y, 1e3);
    }
    const det = rows.inverseDeterminant(2, 2, 2);
    expect(det).toBe(0);
    expect(Math.abs(rows.solveX(det, 2, 2, 1, 3))).toBe(0);
    expect(Math.abs(rows.solveY(det, 2, 2, 1, 3))).toBe(0);
  });

  it('apply Δv = M⁻¹ Jᵀ p, and an angular impulse on B relative to A', () => {
    const next = sequence(11);
    const state = new Float64Array(2 * BodyState.STRIDE);
    const sa = 0;
    const sb = BodyState.STRIDE;
    const slots = [
      sa + BodyState.VX,
      sa + BodyState.VY,
      sa + BodyState.W,
      sb + BodyState.VX,
      sb + BodyState.VY,
      sb + BodyState.W,
    ];
    const read = (): number[] => slots.map((i) => state[i]);
    for (const h of all) {
      const px = next() * 3;
      const py = next() * 3;
      const turn = next() * 3;
      const j = jacobian(h);
      const m = inverseMass(h);
      const expected = h.v.map((v, k) => v + m[k] * (j[0][k] * px + j[1][k] * py));
      const set = (): void => {
        slots.forEach((i, k) => {
          state[i] = h.v[k];
        });
      };
      set();
      rows.applyImpulse(state, sa, sb, h.mA, h.iA, h.mB, h.iB, h.rAx, h.rAy, h.rBx, h.rBy, px, py);
      for (const [k, v] of read().entries()) close(v, expected[k], 100);
      set();
      rows.applyTurnImpulse(state, sa, sb, h.mA, h.iA, h.mB, h.iB, h.rAx, h.rAy, h.rBx, h.rBy, px, py, turn);
      const turned = [...expected];
      turned[2] -= h.iA * turn;
      turned[5] += h.iB * turn;
      for (const [k, v] of read().entries()) close(v, turned[k], 100);
      // the moment of the impulse at an anchor
      close(rows.anchorMoment(h.rAx, h.rAy, px, py), h.rAx * py - h.rAy * px, 10);
    }
  });

  it('measure the separation of the anchors from the bodies’ moves and turns', () => {
    const next = sequence(5);
    for (let k = 0; k < 32; k++) {
      const angle = next() * Math.PI;
      const c = Math.cos(angle);
      const s = Math.sin(angle);
      const x = next() * 2;
      const y = next() * 2;
      const rx = rows.turnedX(c, s, x, y);
      const ry = rows.turnedY(c, s, x, y);
      // a turn keeps the length and turns by the angle
      close(Math.hypot(rx, ry), Math.hypot(x, y), 10);
      close(x * ry - y * rx, Math.sin(angle) * (x * x + y * y), 10);
      // anchor B minus anchor A: centres dc apart at the step's start, moved by dpA and dpB since
      const dc = next() * 5;
      const dpA = next();
      const dpB = next();
      const rA = next();
      const rB = next();
      close(rows.separation(dpA, dpB, dc, rA, rB), dc + dpB + rB - (dpA + rA), 10);
    }
  });

  it('bound the bias row by row or as a whole, and soften the impulse', () => {
    expect(rows.boundedBias(10, 0.5, 2)).toBe(2);
    expect(rows.boundedBias(10, -0.5, 2)).toBe(-2);
    expect(rows.boundedBias(10, 0.1, 2)).toBe(1);
    expect(rows.pullBound(3, 4, 10)).toBe(1);
    const f = rows.pullBound(30, 40, 10);
    close(Math.hypot(30 * f, 40 * f), 10, 10);
    expect(rows.softImpulse(1, 0, 2.5, 7)).toBe(-2.5);
    expect(rows.softImpulse(0.5, 0.25, 2, 4)).toBe(-2);
  });
});
