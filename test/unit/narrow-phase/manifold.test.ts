import { describe, expect, it } from 'vitest';
import { Pack, packGeometry } from '../../../src/geometry/packed';
import { Shape } from '../../../src/geometry/shapes';
import {
  type Geometry,
  MAX_POLYGON_VERTICES,
  type Manifold,
  makeManifold,
} from '../../../src/geometry/types';
import type { Transform } from '../../../src/math/vec2';
import { CollideContext } from '../../../src/narrow-phase/collide-context';
import { collide, collidePacked } from '../../../src/narrow-phase/manifold';
import { VERTEX_PAIR_MIN_GAP } from '../../../src/narrow-phase/manifold-polygon';
import { pointDistance, random, signedDistance, worldCore, xf } from '../geometry/brute-force';

const SPECULATIVE = 0.02;

function run(a: Geometry, xfA: Transform, b: Geometry, xfB: Transform, speculative = SPECULATIVE): Manifold {
  const m = makeManifold();
  collide(a, xfA, b, xfB, speculative, m, new CollideContext());
  return m;
}

function minSeparation(m: Manifold): number {
  let min = Number.POSITIVE_INFINITY;
  for (let i = 0; i < m.pointCount; i++) min = Math.min(min, m.points[i].separation);
  return min;
}

const catalog: Record<string, Geometry> = {
  circle: Shape.circle(0.5),
  offsetCircle: Shape.circle(0.3, { x: 0.2, y: -0.1 }),
  capsule: Shape.capsule({ x: -0.5, y: 0 }, { x: 0.5, y: 0.1 }, 0.25),
  segment: Shape.segment({ x: -1, y: 0.2 }, { x: 1, y: -0.2 }),
  box: Shape.box(0.5, 0.5),
  longBox: Shape.box(1, 0.2, { x: 0.1, y: 0 }, 0.3),
  triangle: Shape.polygon([
    { x: -0.5, y: -0.4 },
    { x: 0.6, y: -0.3 },
    { x: 0, y: 0.7 },
  ]),
  roundedBox: Shape.polygon(Shape.box(0.4, 0.3).vertices, 0.1),
  roundedHexagon: Shape.polygon(
    Array.from({ length: 6 }, (_, i) => ({
      x: 0.5 * Math.cos((i * Math.PI) / 3),
      y: 0.5 * Math.sin((i * Math.PI) / 3),
    })),
    0.05,
  ),
};
const names = Object.keys(catalog);

/** B placed along a random direction so that the gap along that direction is `target`. */
function placeNear(
  a: Geometry,
  xfA: Transform,
  b: Geometry,
  angleB: number,
  ux: number,
  uy: number,
  target: number,
) {
  const ca = worldCore(a, xfA);
  const cb = worldCore(b, xf(0, 0, angleB));
  const hA = Math.max(...ca.points.map((p) => p.x * ux + p.y * uy)) + ca.radius;
  const hB = Math.max(...cb.points.map((p) => -(p.x * ux + p.y * uy))) + cb.radius;
  const t = hA + hB + target;
  return xf(t * ux, t * uy, angleB);
}

describe('collide: basic contracts', () => {
  it('a packed record holds the largest polygon (Pack.STRIDE is written as a number)', () => {
    expect(Pack.STRIDE).toBe(Pack.VERTICES + Pack.VERTEX_STRIDE * MAX_POLYGON_VERTICES);
    const ring = Array.from({ length: MAX_POLYGON_VERTICES }, (_, i) => ({
      x: Math.cos((2 * Math.PI * i) / MAX_POLYGON_VERTICES),
      y: Math.sin((2 * Math.PI * i) / MAX_POLYGON_VERTICES),
    }));
    const out = new Float64Array(2 * Pack.STRIDE).fill(7);
    packGeometry(Shape.polygon(ring), out, 0);
    expect(out[Pack.COUNT]).toBe(MAX_POLYGON_VERTICES);
    // the next record is untouched
    expect(Array.from(out.subarray(Pack.STRIDE))).toEqual(new Array(Pack.STRIDE).fill(7));
  });

  it('circle-circle: separation = distance - r1 - r2 exactly, point halfway, unit normal A to B', () => {
    const a = Shape.circle(0.5);
    const b = Shape.circle(0.25, { x: 0.125, y: 0 });
    const xfA = xf(1, 2, 0);
    const xfB = xf(1.25, 2.5, 0);
    const m = run(a, xfA, b, xfB);
    const dx = 0.375;
    const dy = 0.5;
    const d = Math.sqrt(dx * dx + dy * dy);
    expect(m.pointCount).toBe(1);
    expect(m.points[0].separation).toBe(d - 0.5 - 0.25);
    expect(m.normalX).toBeCloseTo(dx / d, 15);
    expect(m.normalY).toBeCloseTo(dy / d, 15);
    const s = m.points[0].separation;
    expect(m.points[0].x).toBeCloseTo(1 + (dx / d) * (0.5 + s / 2), 14);
    expect(m.points[0].y).toBeCloseTo(2 + (dy / d) * (0.5 + s / 2), 14);
  });

  it('emits only points with separation below the speculative distance', () => {
    const a = Shape.circle(0.5);
    expect(run(a, xf(0, 0, 0), a, xf(1.0199, 0, 0)).pointCount).toBe(1);
    expect(run(a, xf(0, 0, 0), a, xf(1.0201, 0, 0)).pointCount).toBe(0);
    const box = Shape.box(0.5, 0.5);
    expect(run(box, xf(0, 0, 0), box, xf(0, 1.0199, 0)).pointCount).toBe(2);
    expect(run(box, xf(0, 0, 0), box, xf(0, 1.0201, 0)).pointCount).toBe(0);
    // tilted: only the lower corner is within the speculative distance
    const tilted = run(box, xf(0, 0, 0), box, xf(0, 1.01 + 0.5 * Math.SQRT2 - 0.5, Math.PI / 4 - 0.05));
    expect(tilted.pointCount).toBe(1);
  });

  it('segment-segment has no contact', () => {
    const s = Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 });
    expect(run(s, xf(0, 0, 0), s, xf(0, 0, 0.5)).pointCount).toBe(0);
  });
});

describe('collide: box stacks', () => {
  const ground = Shape.box(5, 0.5);
  const box = Shape.box(0.5, 0.5);

  it('a resting box gives two points with the right separation and normal', () => {
    const gap = -0.004;
    const m = run(ground, xf(0, 0, 0), box, xf(1, 1 + gap, 0));
    expect(m.pointCount).toBe(2);
    expect(m.normalX).toBeCloseTo(0, 15);
    expect(m.normalY).toBeCloseTo(1, 15);
    const xs = [m.points[0].x, m.points[1].x].sort((p, q) => p - q);
    expect(xs[0]).toBeCloseTo(0.5, 14);
    expect(xs[1]).toBeCloseTo(1.5, 14);
    for (let i = 0; i < 2; i++) {
      expect(m.points[i].separation).toBeCloseTo(gap, 14);
      expect(m.points[i].y).toBeCloseTo(0.5 + gap / 2, 14);
    }
    expect(m.points[0].id).not.toBe(m.points[1].id);
    // reversed order: same points, flipped normal
    const r = run(box, xf(1, 1 + gap, 0), ground, xf(0, 0, 0));
    expect(r.pointCount).toBe(2);
    expect(r.normalY).toBeCloseTo(-1, 15);
    for (let i = 0; i < 2; i++) expect(r.points[i].separation).toBeCloseTo(gap, 14);
  });

  it('keeps the same ids under tiny motions (warm starting)', () => {
    const reference = run(box, xf(0, 0, 0), box, xf(0.1, 0.996, 0));
    const ids = [reference.points[0].id, reference.points[1].id];
    const rnd = random(3);
    for (let k = 0; k < 200; k++) {
      const jitter = () => (rnd() * 2 - 1) * 2e-3;
      const m = run(
        box,
        xf(jitter(), jitter(), jitter() * 0.5),
        box,
        xf(0.1 + jitter(), 0.996 + jitter(), jitter() * 0.5),
      );
      expect(m.pointCount).toBe(2);
      expect([m.points[0].id, m.points[1].id]).toEqual(ids);
      expect(m.normalY).toBeGreaterThan(0.99);
    }
  });

  it('box on a rotated box: separation matches the rotated geometry', () => {
    const angle = 0.2;
    const xfA = xf(0, 0, angle);
    // B sits on A's top face (normal (-sin, cos)) with a gap of 0.003
    const n = { x: -Math.sin(angle), y: Math.cos(angle) };
    const xfB = xf(n.x * 1.003, n.y * 1.003, angle);
    const m = run(box, xfA, box, xfB);
    expect(m.pointCount).toBe(2);
    expect(m.normalX).toBeCloseTo(n.x, 14);
    expect(m.normalY).toBeCloseTo(n.y, 14);
    for (let i = 0; i < 2; i++) expect(m.points[i].separation).toBeCloseTo(0.003, 14);
  });
});

describe('collide: specific pairs', () => {
  it('circle against a box corner and face, sharp and rounded', () => {
    const circle = Shape.circle(0.25);
    const box = Shape.box(0.5, 0.5);
    // corner region: distance to corner (0.5, 0.5)
    const corner = run(circle, xf(0.7, 0.6, 0), box, xf(0, 0, 0));
    const d = Math.hypot(0.2, 0.1);
    expect(corner.pointCount).toBe(1);
    expect(corner.points[0].separation).toBeCloseTo(d - 0.25, 15);
    expect(corner.normalX).toBeCloseTo(-0.2 / d, 15);
    expect(corner.normalY).toBeCloseTo(-0.1 / d, 15);
    // face region, centre inside the box
    const inside = run(circle, xf(0.4, 0.1, 0), box, xf(0, 0, 0));
    expect(inside.points[0].separation).toBeCloseTo(-0.1 - 0.25, 15);
    expect([inside.normalX, inside.normalY]).toEqual([-1, -0]);
    // rounded box: the corner is a quarter circle of radius 0.1 around the core corner
    const rounded = Shape.polygon(Shape.box(0.4, 0.4).vertices, 0.1);
    const r = run(circle, xf(0.7, 0.6, 0), rounded, xf(0, 0, 0));
    expect(r.points[0].separation).toBeCloseTo(Math.hypot(0.3, 0.2) - 0.1 - 0.25, 15);
  });

  it('capsule lying on a box: two points at the capsule ends', () => {
    const capsule = Shape.capsule({ x: -0.5, y: 0 }, { x: 0.5, y: 0 }, 0.2);
    const box = Shape.box(2, 0.5);
    const m = run(capsule, xf(0.3, 0.7 - 0.002, 0), box, xf(0, 0, 0));
    expect(m.pointCount).toBe(2);
    expect(m.normalY).toBeCloseTo(-1, 15);
    const xs = [m.points[0].x, m.points[1].x].sort((p, q) => p - q);
    expect(xs[0]).toBeCloseTo(-0.2, 14);
    expect(xs[1]).toBeCloseTo(0.8, 14);
    for (let i = 0; i < 2; i++) expect(m.points[i].separation).toBeCloseTo(-0.002, 14);
  });

  it('capsules: parallel gives two points, crossing gives one', () => {
    const capsule = Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.1);
    const parallel = run(capsule, xf(0, 0, 0), capsule, xf(0.5, 0.195, 0));
    expect(parallel.pointCount).toBe(2);
    for (let i = 0; i < 2; i++) expect(parallel.points[i].separation).toBeCloseTo(-0.005, 14);
    const crossing = run(capsule, xf(0, 0, 0), capsule, xf(0.2, 1.19, Math.PI / 2));
    expect(crossing.pointCount).toBe(1);
    expect(crossing.points[0].separation).toBeCloseTo(-0.01, 14);
    expect(crossing.normalY).toBeCloseTo(1, 14);
    // end to end on one line: the gap between the caps, along the line
    const inline = run(capsule, xf(0, 0, 0), capsule, xf(2.21, 0, 0));
    expect(inline.pointCount).toBe(1);
    expect(inline.points[0].separation).toBeCloseTo(0.01, 14);
    expect(inline.normalX).toBeCloseTo(1, 14);
  });

  it('separated rounded corners give one point along the corner-to-corner line', () => {
    const rounded = Shape.polygon(Shape.box(0.4, 0.4).vertices, 0.1);
    const m = run(rounded, xf(0, 0, 0), rounded, xf(0.81, 0.81, 0), 0.5);
    expect(m.pointCount).toBe(1);
    expect(m.points[0].separation).toBeCloseTo(0.01 * Math.SQRT2 - 0.2, 14);
    expect(m.normalX).toBeCloseTo(Math.SQRT1_2, 14);
    expect(m.points[0].x).toBeCloseTo(0.405, 14);
  });
});

describe('collide: degenerate overlaps', () => {
  it('gives finite points and a unit normal for coincident and deeply overlapping shapes', () => {
    const rnd = random(8);
    for (const nameA of names) {
      for (const nameB of names) {
        if (nameA === 'segment' && nameB === 'segment') continue;
        for (let k = 0; k < 8; k++) {
          // k = 0: exactly coincident frames; then deep random overlaps
          const xfA = k === 0 ? xf(0, 0, 0) : xf(rnd() * 0.2, rnd() * 0.2, rnd() * 6.3);
          const xfB = k === 0 ? xf(0, 0, 0) : xf(rnd() * 0.2, rnd() * 0.2, rnd() * 6.3);
          const m = run(catalog[nameA], xfA, catalog[nameB], xfB);
          const label = `${nameA}-${nameB} ${k}`;
          expect(m.pointCount, label).toBeGreaterThan(0);
          expect(Math.hypot(m.normalX, m.normalY), label).toBeCloseTo(1, 12);
          for (let i = 0; i < m.pointCount; i++) {
            const p = m.points[i];
            expect(Number.isFinite(p.x) && Number.isFinite(p.y) && p.separation < SPECULATIVE, label).toBe(
              true,
            );
          }
        }
      }
    }
  });
});

describe('collide: random pairs against brute force', () => {
  it('the deepest point matches the sampled signed distance; points lie halfway between the surfaces', () => {
    const rnd = random(21);
    let worst = 0;
    let checked = 0;
    for (let trial = 0; trial < 320; trial++) {
      const nameA = names[trial % names.length];
      const nameB = names[Math.floor(trial / names.length) % names.length];
      if (nameA === 'segment' && nameB === 'segment') continue;
      const a = catalog[nameA];
      const b = catalog[nameB];
      const xfA = xf(0, 0, rnd() * 6.3);
      const direction = rnd() * 6.3;
      const target = -0.03 + 0.06 * rnd();
      const xfB = placeNear(a, xfA, b, rnd() * 6.3, Math.cos(direction), Math.sin(direction), target);
      const exact = signedDistance(a, xfA, b, xfB);
      const m = run(a, xfA, b, xfB, 0.1);
      // the gap along the placement direction is `target`; the true distance may be larger
      if (exact > 0.1) {
        expect(m.pointCount, `${nameA}-${nameB}`).toBe(0);
        continue;
      }
      checked++;
      expect(m.pointCount, `${nameA}-${nameB}`).toBeGreaterThan(0);
      expect(Math.hypot(m.normalX, m.normalY)).toBeCloseTo(1, 14);
      const error = Math.abs(minSeparation(m) - exact);
      worst = Math.max(worst, error);
      // exact up to the vertex-pair test's tolerance (0.1 x linear slop): near a vertex pair the face
      // separation (a lower bound of the distance) may be kept
      expect(error, `${nameA}-${nameB} trial ${trial}`).toBeLessThan(5e-4);
      for (let i = 0; i < m.pointCount; i++) {
        const p = m.points[i];
        const h = p.separation / 2;
        // surface of A at p - n s/2, surface of B at p + n s/2
        const onA = pointDistance(a, xfA, p.x - h * m.normalX, p.y - h * m.normalY);
        const onB = pointDistance(b, xfB, p.x + h * m.normalX, p.y + h * m.normalY);
        expect(Math.abs(onA), `${nameA}-${nameB} A surface`).toBeLessThan(2e-3);
        expect(Math.abs(onB), `${nameA}-${nameB} B surface`).toBeLessThan(2e-3);
      }
    }
    expect(worst).toBeLessThan(5e-4);
    expect(checked).toBeGreaterThan(150);
  });

  it('every pair is symmetric under swapping: same points, flipped normal', () => {
    const rnd = random(5);
    for (let trial = 0; trial < 160; trial++) {
      const nameA = names[trial % names.length];
      const nameB = names[Math.floor(rnd() * names.length)];
      const a = catalog[nameA];
      const b = catalog[nameB];
      const xfA = xf(rnd(), rnd(), rnd() * 6.3);
      const direction = rnd() * 6.3;
      const xfB = placeNear(
        a,
        xfA,
        b,
        rnd() * 6.3,
        Math.cos(direction),
        Math.sin(direction),
        -0.02 + 0.05 * rnd(),
      );
      const ab = run(a, xfA, b, xfB);
      const ba = run(b, xfB, a, xfA);
      const label = `${nameA}-${nameB}`;
      expect(ba.pointCount, label).toBe(ab.pointCount);
      if (ab.pointCount === 0) continue;
      if (a.kind !== b.kind) {
        // the same pair function runs: bit-identical apart from the normal's sign
        expect(ba.normalX).toBe(-ab.normalX);
        expect(ba.normalY).toBe(-ab.normalY);
        expect(ba.points.slice(0, ba.pointCount)).toEqual(ab.points.slice(0, ab.pointCount));
      } else {
        // same kinds: each call prefers its own A as reference, so allow the reference-face tolerance
        expect(ab.normalX * ba.normalX + ab.normalY * ba.normalY, label).toBeLessThan(-0.999);
        expect(Math.abs(minSeparation(ab) - minSeparation(ba)), label).toBeLessThan(1e-3);
      }
    }
  });
});

describe('collide: rectangles', () => {
  const data = new Float64Array(2 * Pack.STRIDE);

  /** collidePacked on packed `a` and `b`; with `generic` the rectangle flags are cleared first. */
  function runPacked(a: Geometry, xfA: Transform, b: Geometry, xfB: Transform, generic: boolean): Manifold {
    packGeometry(a, data, 0);
    packGeometry(b, data, Pack.STRIDE);
    if (generic) {
      data[Pack.RECTANGLE] = 0;
      data[Pack.STRIDE + Pack.RECTANGLE] = 0;
    }
    const m = makeManifold();
    const context = new CollideContext();
    context.reach = SPECULATIVE;
    collidePacked(a.kind, b.kind, data, 0, xfA, Pack.STRIDE, xfB, m, context);
    return m;
  }

  it('boxes are packed as rectangles; parallelograms and other quads are not', () => {
    const flag = (g: Geometry) => {
      packGeometry(g, data, 0);
      return data[Pack.RECTANGLE];
    };
    expect(flag(Shape.box(0.5, 0.2))).toBe(1);
    expect(flag(Shape.box(0.3, 0.7, { x: 0.4, y: -1 }, 0.7))).toBe(1);
    expect(flag(Shape.polygon(Shape.box(0.4, 0.3).vertices, 0.1))).toBe(1);
    const parallelogram = [
      { x: 0, y: 0 },
      { x: 1, y: 0 },
      { x: 1.3, y: 1 },
      { x: 0.3, y: 1 },
    ];
    expect(flag(Shape.polygon(parallelogram))).toBe(0);
    const kite = [
      { x: 0, y: -1 },
      { x: 0.5, y: 0 },
      { x: 0, y: 1 },
      { x: -0.5, y: 0 },
    ];
    expect(flag(Shape.polygon(kite))).toBe(0);
    expect(flag(catalog.triangle)).toBe(0);
  });

  const xfAngle = (t: Transform) => Math.atan2(t.q.s, t.q.c);

  it('the two-axis test gives the manifold of the every-vertex test', () => {
    // the generic polygon routine tries every vertex against every edge: an independent oracle
    const rnd = random(77);
    const counts = [0, 0, 0];
    for (let trial = 0; trial < 600; trial++) {
      const turnA = rnd() * 6.3;
      const a = Shape.polygon(
        Shape.box(0.1 + rnd(), 0.1 + rnd(), { x: rnd() - 0.5, y: rnd() - 0.5 }, turnA).vertices,
        trial % 3 === 0 ? 0.1 * rnd() : 0,
      );
      const turnB = rnd() * 6.3;
      const b = Shape.box(0.05 + 2 * rnd(), 0.05 + 0.5 * rnd(), { x: rnd() - 0.5, y: 0 }, turnB);
      const xfA = xf(rnd() * 4 - 2, rnd() * 4 - 2, rnd() * 6.3);
      // B along a random direction at a signed distance `target` (bisection on the brute-force distance)
      const direction = rnd() * 6.3;
      // a third with faces parallel to A's, as in stacks (ties between the two reference faces)
      const angleB =
        trial % 3 === 1 ? xfAngle(xfA) + turnA - turnB + Math.floor(4 * rnd()) * (Math.PI / 2) : rnd() * 6.3;
      const target = trial % 10 === 0 ? -0.3 * rnd() : -0.04 + 0.07 * rnd();
      const at = (t: number) =>
        xf(xfA.p.x + t * Math.cos(direction), xfA.p.y + t * Math.sin(direction), angleB);
      let lo = 0;
      let hi = 10;
      for (let k = 0; k < 50; k++) {
        const mid = 0.5 * (lo + hi);
        if (signedDistance(a, xfA, b, at(mid)) < target) lo = mid;
        else hi = mid;
      }
      const xfB = at(hi);
      const fast = runPacked(a, xfA, b, xfB, false);
      const slow = runPacked(a, xfA, b, xfB, true);
      const label = `trial ${trial}`;
      expect(fast.pointCount, label).toBe(slow.pointCount);
      counts[fast.pointCount]++;
      if (fast.pointCount === 0) continue;
      expect(fast.normalX, label).toBeCloseTo(slow.normalX, 12);
      expect(fast.normalY, label).toBeCloseTo(slow.normalY, 12);
      for (let i = 0; i < fast.pointCount; i++) {
        const p = fast.points[i];
        const q = slow.points[i];
        expect(p.id, label).toBe(q.id);
        expect(p.x, label).toBeCloseTo(q.x, 12);
        expect(p.y, label).toBeCloseTo(q.y, 12);
        expect(p.separation, label).toBeCloseTo(q.separation, 12);
      }
    }
    // every outcome was exercised
    expect(Math.min(...counts)).toBeGreaterThan(50);
  });
});

describe('collide: boxes apart', () => {
  it('gives no point when the bounding boxes are further apart than the speculative distance and the vertex-pair tolerance', () => {
    // the narrow phase skips such pairs without calling collide: it must agree. Points may be up to the
    // tolerance closer than the shapes (face separation near a vertex pair), so the boxes are placed
    // about that far apart
    const rnd = random(33);
    const limit = SPECULATIVE + VERTEX_PAIR_MIN_GAP;
    const box = (g: Geometry, t: Transform) => {
      const core = worldCore(g, t);
      const xs = core.points.map((p) => p.x);
      const ys = core.points.map((p) => p.y);
      const r = core.radius;
      return {
        minX: Math.min(...xs) - r,
        maxX: Math.max(...xs) + r,
        minY: Math.min(...ys) - r,
        maxY: Math.max(...ys) + r,
      };
    };
    let checked = 0;
    for (let trial = 0; trial < 20000; trial++) {
      const nameA = names[trial % names.length];
      const nameB = names[Math.floor(rnd() * names.length)];
      if (nameA === 'segment' && nameB === 'segment') continue;
      const a = catalog[nameA];
      const b = catalog[nameB];
      // nearly square to the axes, B above A with a random sideways offset: corners meet corners
      const quarter = Math.PI / 2;
      const xfA = xf(0, 0, Math.floor(4 * rnd()) * quarter + 0.2 * (rnd() - 0.5));
      const angleB = Math.floor(4 * rnd()) * quarter + 0.2 * (rnd() - 0.5);
      const p = box(a, xfA);
      const q = box(b, xf(0, 0, angleB));
      const gap = limit - 0.0005 + 0.0015 * rnd();
      const x = p.minX - q.maxX + (p.maxX - p.minX + q.maxX - q.minX) * rnd();
      const xfB = xf(x, p.maxY - q.minY + gap, angleB);
      const r = box(b, xfB);
      const actual = Math.max(p.minX - r.maxX, r.minX - p.maxX, p.minY - r.maxY, r.minY - p.maxY);
      if (!(actual > limit)) continue;
      checked++;
      expect(run(a, xfA, b, xfB).pointCount, `${nameA}-${nameB} trial ${trial}`).toBe(0);
    }
    expect(checked).toBeGreaterThan(10000);
  });
});
