import { describe, expect, it } from 'vitest';
import { makeProxy, makeShapeProxy } from '../../../src/geometry/shape-proxy';
import { getSweepTransform, makeSweep, type Sweep } from '../../../src/geometry/sweep';
import { makeTOIOutput, TOIMemory, type TOIOutput, timeOfImpact } from '../../../src/geometry/toi';
import type { Geometry } from '../../../src/geometry/types';
import { makeRot } from '../../../src/math/rot';
import { makeTransform } from '../../../src/math/vec2';
import { box, bruteCoreDistance, capsule, circle, radiusOf, rng, worldCore } from './distance-fixtures';

const SLOP = 0.005;
const proxyA = makeShapeProxy();
const proxyB = makeShapeProxy();
/** one working memory for every call: each must write before it reads */
const memory = new TOIMemory();

/** Sweep of a body whose centre of mass (localCenter in the body frame) goes c1 -> c2, angle a1 -> a2. */
function sweep(
  lcx: number,
  lcy: number,
  c1: [number, number],
  c2: [number, number],
  a1: number,
  a2: number,
): Sweep {
  const s = makeSweep();
  const q1 = makeRot(a1);
  const q2 = makeRot(a2);
  s.localCenterX = lcx;
  s.localCenterY = lcy;
  [s.c1X, s.c1Y, s.c2X, s.c2Y] = [c1[0], c1[1], c2[0], c2[1]];
  [s.q1C, s.q1S, s.q2C, s.q2S] = [q1.c, q1.s, q2.c, q2.s];
  return s;
}

function toi(ga: Geometry, sa: Sweep, gb: Geometry, sb: Sweep, maxFraction = 1): TOIOutput {
  makeProxy(ga, proxyA);
  makeProxy(gb, proxyB);
  return timeOfImpact(memory, { proxyA, sweepA: sa, proxyB, sweepB: sb, maxFraction }, makeTOIOutput());
}

/** Brute-force surface distance (negative inside) of the two swept shapes at fraction t. */
function gapAt(ga: Geometry, sa: Sweep, gb: Geometry, sb: Sweep, t: number): number {
  const ta = getSweepTransform(sa, t, makeTransform());
  const tb = getSweepTransform(sb, t, makeTransform());
  const core = bruteCoreDistance(worldCore(ga, ta), worldCore(gb, tb));
  return core - radiusOf(ga) - radiusOf(gb);
}

describe('getSweepTransform', () => {
  it('interpolates the centre linearly and the rotation by nlerp, keeping the centre of mass on its path', () => {
    const s = sweep(0.3, -0.2, [1, 2], [3, -1], 0.2, 1.0);
    const xf = makeTransform();
    for (const t of [0, 0.25, 0.5, 1]) {
      getSweepTransform(s, t, xf);
      const cx = xf.q.c * 0.3 - xf.q.s * -0.2 + xf.p.x;
      const cy = xf.q.s * 0.3 + xf.q.c * -0.2 + xf.p.y;
      expect(cx).toBeCloseTo(1 + 2 * t, 14);
      expect(cy).toBeCloseTo(2 - 3 * t, 14);
      expect(Math.hypot(xf.q.c, xf.q.s)).toBeCloseTo(1, 15);
    }
    getSweepTransform(s, 0.5, xf);
    // nlerp at the midpoint is exact: the bisecting angle
    expect(xf.q.c).toBeCloseTo(Math.cos(0.6), 14);
    expect(xf.q.s).toBeCloseTo(Math.sin(0.6), 14);
    getSweepTransform(s, 1, xf);
    expect(xf.q.c).toBeCloseTo(Math.cos(1), 15);
  });
});

describe('timeOfImpact: fast ball against a thin wall', () => {
  const ball = circle(0, 0, 0.05);
  const wall = box(0.05, 1);
  const still = (x: number, y: number, a: number) => sweep(0, 0, [x, y], [x, y], a, a);

  it('a 0.1 m ball moving 5 m stops within slop of touching the 0.1 m wall', () => {
    const o = toi(wall, still(3, 0, 0), ball, sweep(0, 0, [0, 0.2], [5, 0.2], 0, 0));
    expect(o.state).toBe('hit');
    // touching when the centre reaches x = 2.9, at fraction 0.58
    const gap = (0.58 - o.fraction) * 5;
    expect(gap).toBeGreaterThanOrEqual(SLOP - 1e-12);
    expect(gap).toBeLessThanOrEqual(1.25 * SLOP + 1e-12);
  });

  it('at 1,000 random offsets and angles the stop is between slop and 1.25 slop from the wall', () => {
    const r = rng(11);
    let maxIterations = 0;
    for (let i = 0; i < 1000; i++) {
      // scene in the wall frame, then rotated by a and moved by (ox, oy)
      const a = 7 * r();
      const ox = 100 * r() - 50;
      const oy = 100 * r() - 50;
      const q = makeRot(a);
      const place = (x: number, y: number): [number, number] => [
        ox + q.c * x - q.s * y,
        oy + q.s * x + q.c * y,
      ];
      const x0 = -0.2 - 4 * r();
      const y0 = 1.8 * r() - 0.9;
      // aim so the centre crosses x = -0.1 (touching line) at |y| < 0.9, then travels on for 5 m in total
      const yAim = 1.8 * r() - 0.9;
      const dx = -0.1 - x0;
      const dy = yAim - y0;
      const len = Math.hypot(dx, dy);
      const ex = (5 * dx) / len;
      const ey = (5 * dy) / len;
      const o = toi(
        wall,
        sweep(0, 0, place(0, 0), place(0, 0), a, a),
        ball,
        sweep(0, 0, place(x0, y0), place(x0 + ex, y0 + ey), 0, 0),
      );
      expect(o.state).toBe('hit');
      const touch = dx / ex; // fraction at which the centre reaches x = -0.1
      const gap = (touch - o.fraction) * ex; // distance to the wall, along its normal, at the stop
      expect(gap).toBeGreaterThanOrEqual(SLOP - 1e-9);
      expect(gap).toBeLessThanOrEqual(1.25 * SLOP + 1e-9);
      maxIterations = Math.max(maxIterations, o.iterations);
    }
    expect(maxIterations).toBeLessThan(10);
  });

  it('reports separated, overlapped and maxFraction', () => {
    const pass = toi(wall, still(3, 0, 0), ball, sweep(0, 0, [0, 2], [5, 2], 0, 0));
    expect(pass).toMatchObject({ state: 'separated', fraction: 1 });
    const away = toi(wall, still(3, 0, 0), ball, sweep(0, 0, [0, 0], [-5, 0], 0, 0));
    expect(away).toMatchObject({ state: 'separated', fraction: 1 });
    const short = toi(wall, still(3, 0, 0), ball, sweep(0, 0, [0, 0], [5, 0], 0, 0), 0.5);
    expect(short).toMatchObject({ state: 'separated', fraction: 0.5 });
    const inside = toi(wall, still(3, 0, 0), ball, sweep(0, 0, [2.96, 0], [5, 0], 0, 0));
    expect(inside).toMatchObject({ state: 'overlapped', fraction: 0 });
    const touching = toi(wall, still(3, 0, 0), ball, sweep(0, 0, [2.9 - SLOP, 0], [5, 0], 0, 0));
    expect(touching).toMatchObject({ state: 'hit', fraction: 0 });
  });
});

describe('timeOfImpact: thin spinning rod against a box', () => {
  /** Checks one case against fine time stepping; returns the state. */
  function check(ga: Geometry, sa: Sweep, gb: Geometry, sb: Sweep, steps: number): TOIOutput {
    const o = toi(ga, sa, gb, sb);
    const end = o.state === 'separated' ? 1 : o.fraction;
    // nothing comes within the target before the reported fraction (so no overlap is missed)
    for (let k = 0; k <= steps; k++) {
      const t = (k / steps) * end;
      expect(gapAt(ga, sa, gb, sb, t)).toBeGreaterThan(SLOP - 1e-9);
    }
    if (o.state === 'hit') {
      expect(gapAt(ga, sa, gb, sb, o.fraction)).toBeLessThan(1.25 * SLOP + 1e-9);
    }
    return o;
  }

  it('a 1 m rod spinning at 50 rad/s next to a wall: the TOI precedes the first overlap', () => {
    const rod = box(0.5, 0.01);
    const wall = box(2, 0.05);
    const dt = 1 / 60;
    // rod centred 0.3 m above the wall surface, lying flat, turning 50 rad/s * dt = 0.83 rad this step:
    // its tip sweeps through the wall
    const sa = sweep(0, 0, [0, 0], [0, 0], 0, 0);
    const sb = sweep(0, 0, [0.2, 0.35], [0.2, 0.35], 0, 50 * dt);
    const o = check(wall, sa, rod, sb, 2000);
    expect(o.state).toBe('hit');
    // first overlap by fine time stepping
    let first = -1;
    for (let k = 0; k <= 20000; k++) {
      if (gapAt(wall, sa, rod, sb, k / 20000) <= 0) {
        first = k / 20000;
        break;
      }
    }
    expect(first).toBeGreaterThan(0);
    expect(o.fraction).toBeLessThan(first);
  });

  it('200 random spinning rods and capsules (also moving, off-centre mass) never pass a box', () => {
    const r = rng(5);
    const counts = { hit: 0, separated: 0, overlapped: 0, failed: 0 };
    let maxIterations = 0;
    for (let i = 0; i < 200; i++) {
      const rod = r() < 0.5 ? box(0.5, 0.01) : capsule(-0.5, 0, 0.5, 0, 0.01);
      const wall = box(0.5 + r(), 0.05);
      const wa = 4 * r();
      const sa = sweep(0, 0, [0, 0], [0, 0], wa, wa);
      const spin = (r() < 0.5 ? -50 : 50) / 60;
      const a1 = 7 * r();
      const d = 0.15 + 0.5 * r();
      const rc = makeRot(wa + 1.5707963267948966);
      const cx = (r() - 0.5) * 1.5;
      const c1: [number, number] = [cx * Math.cos(wa) + d * rc.c, cx * Math.sin(wa) + d * rc.s];
      const v = 0.3 * r();
      const c2: [number, number] = [c1[0] - v * rc.c, c1[1] - v * rc.s];
      const sb = sweep(0.2 * r() - 0.1, 0, c1, c2, a1, a1 + spin);
      if (gapAt(wall, sa, rod, sb, 0) < 2 * SLOP) continue; // start clear of the wall
      const o = check(wall, sa, rod, sb, 400);
      counts[o.state]++;
      maxIterations = Math.max(maxIterations, o.iterations);
    }
    expect(counts.hit).toBeGreaterThan(40);
    expect(counts.overlapped).toBe(0);
    expect(counts.failed).toBeLessThan(10);
    expect(maxIterations).toBeLessThanOrEqual(50);
  });
});

describe('timeOfImpact: determinism', () => {
  it('gives the same bits for the same inputs', () => {
    const run = () => {
      const r = rng(21);
      const out: number[] = [];
      for (let i = 0; i < 100; i++) {
        const sb = sweep(0, 0, [0.3 * r(), 0.4 + r()], [0.3 * r(), 0.2 * r()], 7 * r(), 7 * r() - 0.8);
        const o = toi(box(1, 0.05), sweep(0, 0, [0, 0], [0, 0], 0, 0), box(0.5, 0.02), sb);
        out.push(o.fraction, o.iterations);
      }
      return new Float64Array(out);
    };
    expect(Buffer.from(run().buffer).equals(Buffer.from(run().buffer))).toBe(true);
  });
});
