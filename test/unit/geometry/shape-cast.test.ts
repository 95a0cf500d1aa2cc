import { describe, expect, it } from 'vitest';
import {
  makeShapeCastInput,
  makeShapeCastOutput,
  type ShapeCastOutput,
  shapeCast,
} from '../../../src/geometry/shape-cast';
import { makeProxy } from '../../../src/geometry/shape-proxy';
import { GjkMemory } from '../../../src/geometry/simplex';
import type { Geometry } from '../../../src/geometry/types';
import type { Transform } from '../../../src/math/vec2';
import {
  box,
  bruteCoreDistance,
  capsule,
  circle,
  radiusOf,
  randomPolygon,
  rng,
  worldCore,
  xf,
} from './distance-fixtures';

const input = makeShapeCastInput();
/** one working memory for every cast: each must write before it reads */
const gjk = new GjkMemory();

function cast(
  ga: Geometry,
  ta: Transform,
  gb: Geometry,
  tb: Transform,
  tx: number,
  ty: number,
  maxFraction = 1,
) {
  makeProxy(ga, input.proxyA);
  makeProxy(gb, input.proxyB);
  input.transformA = ta;
  input.transformB = tb;
  input.translationX = tx;
  input.translationY = ty;
  input.maxFraction = maxFraction;
  return shapeCast(gjk, input, makeShapeCastOutput());
}

function expectHit(o: ShapeCastOutput, fraction: number, px: number, py: number, nx: number, ny: number) {
  expect(o.hit).toBe(true);
  expect(Math.abs(o.fraction - fraction)).toBeLessThan(1e-9);
  expect(Math.abs(o.pointX - px)).toBeLessThan(1e-9);
  expect(Math.abs(o.pointY - py)).toBeLessThan(1e-9);
  expect(Math.abs(o.normalX - nx)).toBeLessThan(1e-9);
  expect(Math.abs(o.normalY - ny)).toBeLessThan(1e-9);
}

describe('shapeCast: analytic fractions', () => {
  it('a circle moving onto a box face', () => {
    const o = cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(-5, 0.3, 0), 10, 0);
    expectHit(o, 0.35, -1, 0.3, -1, 0);
  });

  it('a circle moving onto a box corner', () => {
    // touches the corner (-1, 1) when the centre is at (-1.4, 1.3)
    const o = cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(-5, 1.3, 0), 10, 0);
    expectHit(o, 0.36, -1, 1, -0.8, 0.6);
  });

  it('a circle moving obliquely onto a rotated, translated box', () => {
    const ta = xf(2, 3, 0.5);
    const { c, s } = ta.q;
    // in the box frame: start (-4, 0.2), move (6, 1); contact when x = -1.5, at fraction 2.5 / 6
    const sx = 2 + c * -4 - s * 0.2;
    const sy = 3 + s * -4 + c * 0.2;
    const o = cast(box(1, 1), ta, circle(0, 0, 0.5), xf(sx, sy, 0), c * 6 - s * 1, s * 6 + c * 1);
    const f = 2.5 / 6;
    const ly = 0.2 + f;
    expectHit(o, f, 2 + c * -1 - s * ly, 3 + s * -1 + c * ly, -c, -s);
  });

  it('a capsule falling flat onto a rounded box; a box falling onto a capsule', () => {
    const o = cast(box(2, 1, 0.1), xf(0, 0, 0), capsule(-1, 0, 1, 0, 0.2), xf(0.5, 3, 0), 0, -5);
    expect(o.hit).toBe(true);
    expect(Math.abs(o.fraction - (3 - 0.2 - 1.1) / 5)).toBeLessThan(1e-9);
    expect(Math.abs(o.pointY - 1.1)).toBeLessThan(1e-9);
    expect(Math.abs(o.normalY - 1)).toBeLessThan(1e-9);
    const p = cast(capsule(-1, 0, 1, 0, 0.2), xf(0, 0, 0), box(0.5, 0.5), xf(0.3, 2, 0), 0, -4);
    expect(Math.abs(p.fraction - (2 - 0.5 - 0.2) / 4)).toBeLessThan(1e-9);
  });

  it('misses: moving away, passing by, stopping short of maxFraction', () => {
    expect(cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(-5, 0, 0), -10, 0).hit).toBe(false);
    expect(cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(-5, 1.51, 0), 10, 0).hit).toBe(false);
    const short = cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(-5, 0, 0), 10, 0, 0.3);
    expect(short.hit).toBe(false);
    expect(short.fraction).toBe(0.3);
    // zero translation, apart
    expect(cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(-5, 0, 0), 0, 0).hit).toBe(false);
  });

  it('initial overlap: hit at fraction 0 with a zero normal', () => {
    const o = cast(box(1, 1), xf(0, 0, 0), circle(0, 0, 0.5), xf(1.2, 0, 0), 5, 0);
    expect(o.hit).toBe(true);
    expect(o.fraction).toBe(0);
    expect([o.normalX, o.normalY]).toEqual([0, 0]);
  });
});

describe('shapeCast: random polygons against a fine-stepped brute-force sweep', () => {
  it('agrees within 1 mm (and within 1e-6 after bisection) on 100 random casts', () => {
    const r = rng(3);
    let hits = 0;
    for (let i = 0; i < 100; i++) {
      const ga = randomPolygon(r, 0.3 + r(), r() < 0.5 ? 0 : 0.1 * r());
      const gb =
        r() < 0.3
          ? circle(0, 0, 0.1 + 0.3 * r())
          : randomPolygon(r, 0.2 + 0.5 * r(), r() < 0.5 ? 0 : 0.1 * r());
      const ta = xf(10 * r(), 10 * r(), 7 * r());
      const ang = 7 * r();
      const start = 2.5 + 2 * r();
      const tb = xf(ta.p.x + start * Math.cos(ang), ta.p.y + start * Math.sin(ang), 7 * r());
      // aim roughly at A, with a random miss distance
      const len = 3 + 3 * r();
      const aim = ang + Math.PI + (r() - 0.5) * 0.8;
      const tx = len * Math.cos(aim);
      const ty = len * Math.sin(aim);
      const o = cast(ga, ta, gb, tb, tx, ty);

      const gap = (f: number) => {
        const moved = { p: { x: tb.p.x + f * tx, y: tb.p.y + f * ty }, q: tb.q };
        return bruteCoreDistance(worldCore(ga, ta), worldCore(gb, moved)) - radiusOf(ga) - radiusOf(gb);
      };
      const steps = Math.ceil(len / 0.0005);
      let first = -1;
      for (let k = 0; k <= steps; k++) {
        if (gap(k / steps) <= 0) {
          first = k;
          break;
        }
      }
      if (first < 0) {
        expect(o.hit).toBe(false);
        continue;
      }
      hits++;
      expect(o.hit).toBe(true);
      expect(Math.abs(o.fraction - first / steps) * len).toBeLessThan(0.001);
      if (first > 0) {
        let lo = (first - 1) / steps;
        let hi = first / steps;
        for (let k = 0; k < 40; k++) {
          const mid = 0.5 * (lo + hi);
          if (gap(mid) <= 0) hi = mid;
          else lo = mid;
        }
        expect(Math.abs(o.fraction - hi) * len).toBeLessThan(1e-6);
        expect(o.normalX * tx + o.normalY * ty).toBeLessThan(0);
        // the point lies on A's surface
        const onA = bruteCoreDistance([{ x: o.pointX, y: o.pointY }], worldCore(ga, ta)) - radiusOf(ga);
        expect(Math.abs(onA)).toBeLessThan(1e-6);
      }
    }
    expect(hits).toBeGreaterThan(40);
  });
});

describe('shapeCast: determinism', () => {
  it('gives the same bits for the same inputs', () => {
    const run = () => {
      const r = rng(8);
      const bits: number[] = [];
      for (let i = 0; i < 200; i++) {
        const o = cast(
          randomPolygon(r, 1, 0.1 * r()),
          xf(r(), r(), 7 * r()),
          circle(0, 0, 0.2),
          xf(4, 4, 0),
          -6 * r(),
          -6 * r(),
        );
        bits.push(o.fraction, o.pointX, o.pointY, o.normalX, o.normalY, o.hit ? 1 : 0);
      }
      return new Float64Array(bits);
    };
    expect(Buffer.from(run().buffer).equals(Buffer.from(run().buffer))).toBe(true);
  });
});
