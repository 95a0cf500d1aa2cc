import { createRequire } from 'node:module';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { Bounds } from '../../src/matter/bounds';
import { Vector } from '../../src/matter/vector';
import { Vertices } from '../../src/matter/vertices';

// the real matter.js, to hold the layer's modules to: same inputs, same answers
const Matter = createRequire(import.meta.url)('matter-js');

const coordinate = fc.double({ min: -1000, max: 1000, noNaN: true });
const point = fc.record({ x: coordinate, y: coordinate });

/** A convex polygon: points on an ellipse at increasing angles (counter-clockwise in its numbers). */
const convexPolygon = fc
  .record({
    cx: coordinate,
    cy: coordinate,
    rx: fc.double({ min: 1, max: 300, noNaN: true }),
    ry: fc.double({ min: 1, max: 300, noNaN: true }),
    angles: fc.uniqueArray(fc.integer({ min: 0, max: 359 }), { minLength: 3, maxLength: 12 }),
  })
  .map(({ cx, cy, rx, ry, angles }) =>
    [...angles]
      .sort((a, b) => a - b)
      .map((deg) => ({
        x: cx + rx * Math.cos((deg * Math.PI) / 180),
        y: cy + ry * Math.sin((deg * Math.PI) / 180),
      })),
  )
  .filter((points) => Math.abs(Matter.Vertices.area(points, true)) > 1);

const close = (a: number, b: number, scale: number) => Math.abs(a - b) <= 1e-9 * Math.max(1, scale);

describe('fulcrum/matter Vector and Vertices agree with matter.js', () => {
  it('Vector: every function', () => {
    fc.assert(
      fc.property(point, point, point, fc.double({ min: -10, max: 10, noNaN: true }), (a, b, c, k) => {
        expect(Vector.add(a, b)).toEqual(Matter.Vector.add(a, b));
        expect(Vector.sub(a, b)).toEqual(Matter.Vector.sub(a, b));
        expect(Vector.mult(a, k)).toEqual(Matter.Vector.mult(a, k));
        expect(Vector.dot(a, b)).toBe(Matter.Vector.dot(a, b));
        expect(Vector.cross(a, b)).toBe(Matter.Vector.cross(a, b));
        expect(Vector.cross3(a, b, c)).toBe(Matter.Vector.cross3(a, b, c));
        expect(Vector.perp(a)).toEqual(Matter.Vector.perp(a));
        expect(Vector.perp(a, true)).toEqual(Matter.Vector.perp(a, true));
        expect(Vector.neg(a)).toEqual(Matter.Vector.neg(a));
        expect(Vector.angle(a, b)).toBe(Matter.Vector.angle(a, b));
        expect(Vector.magnitude(a)).toBe(Matter.Vector.magnitude(a));
        const n = Vector.normalise(a);
        const m = Matter.Vector.normalise(a);
        expect(close(n.x, m.x, 1) && close(n.y, m.y, 1)).toBe(true);
        const r = Vector.rotateAbout(a, k, b);
        const s = Matter.Vector.rotateAbout(a, k, b);
        expect(close(r.x, s.x, 2000) && close(r.y, s.y, 2000)).toBe(true);
      }),
    );
  });

  it('Vertices: area, centre, inertia, mean, contains, isConvex, translate, rotate, scale, hull', () => {
    fc.assert(
      fc.property(convexPolygon, point, fc.double({ min: -7, max: 7, noNaN: true }), (points, p, angle) => {
        const ours = Vertices.create(points);
        const theirs = Matter.Vertices.create(points);
        const size = Math.abs(Matter.Vertices.area(theirs));
        expect(close(Vertices.area(ours, true), Matter.Vertices.area(theirs, true), size)).toBe(true);
        const c1 = Vertices.centre(ours);
        const c2 = Matter.Vertices.centre(theirs);
        expect(close(c1.x, c2.x, 1000) && close(c1.y, c2.y, 1000)).toBe(true);
        // inertia about the centroid, as matter calls it
        const centred = points.map((v) => ({ x: v.x - c2.x, y: v.y - c2.y }));
        const i1 = Vertices.inertia(centred, 2);
        const i2 = Matter.Vertices.inertia(centred, 2);
        expect(close(i1, i2, i2)).toBe(true);
        expect(Vertices.mean(ours)).toEqual(Matter.Vertices.mean(theirs));
        expect(Vertices.contains(ours, p)).toBe(Matter.Vertices.contains(theirs, p));
        expect(Vertices.contains(ours, c1)).toBe(true);
        expect(Vertices.isConvex(ours)).toBe(Matter.Vertices.isConvex(theirs));
        expect(Vertices.isConvex([...ours].reverse())).toBe(Matter.Vertices.isConvex([...theirs].reverse()));
        Vertices.rotate(ours, angle, p);
        Matter.Vertices.rotate(theirs, angle, p);
        Vertices.translate(ours, p, 0.5);
        Matter.Vertices.translate(theirs, p, 0.5);
        Vertices.scale(ours, 1.5, 0.5);
        Matter.Vertices.scale(theirs, 1.5, 0.5);
        ours.forEach((v, i) => {
          expect(close(v.x, theirs[i].x, 3000) && close(v.y, theirs[i].y, 3000)).toBe(true);
        });
        const key = (q: { x: number; y: number }) => `${q.x},${q.y}`;
        expect(new Set(Vertices.hull(points).map(key))).toEqual(
          new Set(Matter.Vertices.hull(points).map(key)),
        );
      }),
    );
  });

  it('Vertices.fromPath and Bounds', () => {
    const path = 'L 0 0 L 10.5 0 L 10.5 -2e1 L .5,-20';
    expect(Vertices.fromPath(path).map(({ x, y }) => ({ x, y }))).toEqual(
      Matter.Vertices.fromPath(path).map(({ x, y }: { x: number; y: number }) => ({ x, y })),
    );
    fc.assert(
      fc.property(convexPolygon, point, point, (points, velocity, p) => {
        const ours = Bounds.create(points);
        const theirs = Matter.Bounds.create(points);
        expect(ours).toEqual(theirs);
        Bounds.update(ours, points, velocity);
        Matter.Bounds.update(theirs, points, velocity);
        expect(ours).toEqual(theirs);
        expect(Bounds.contains(ours, p)).toBe(Matter.Bounds.contains(theirs, p));
        const other = Bounds.create([p, { x: p.x + 50, y: p.y + 50 }]);
        expect(Bounds.overlaps(ours, other)).toBe(Matter.Bounds.overlaps(theirs, other));
        Bounds.shift(ours, p);
        Matter.Bounds.shift(theirs, p);
        expect(ours).toEqual(theirs);
      }),
    );
  });

  it('Vertices.chamfer rounds each corner within the original outline and keeps the outline elsewhere', () => {
    const square = [
      { x: 0, y: 0 },
      { x: 100, y: 0 },
      { x: 100, y: 100 },
      { x: 0, y: 100 },
    ];
    const rounded = Vertices.chamfer(square, 10);
    // a square of side 100 with corners of radius 10 has area 100^2 - (4 - pi) 10^2; the arcs' chords
    // (4 per corner at this radius, as matter cuts them) take 0.1 % more
    const exact = 100 * 100 - (4 - Math.PI) * 100;
    expect(Math.abs(Vertices.area(rounded) - exact) / exact).toBeLessThan(0.002);
    for (const v of rounded) expect(Vertices.contains(square, v)).toBe(true);
  });
});
