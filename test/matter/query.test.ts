import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import FulcrumMatter from '../../src/matter/index';
import { type M, RealMatter } from '../helpers/matter-both';

/** The same bodies in both libraries: a row of boxes, circles, polygons and a turned box. */
function scene(Matter: M) {
  return [
    Matter.Bodies.rectangle(100, 100, 80, 40),
    Matter.Bodies.circle(250, 100, 30),
    Matter.Bodies.polygon(400, 100, 5, 40),
    Matter.Bodies.rectangle(550, 100, 100, 20, { angle: 0.6 }),
    Matter.Bodies.trapezoid(700, 100, 80, 50, 0.4),
  ];
}

const ours = scene(FulcrumMatter);
const theirs = scene(RealMatter as M);
const indices = (found: unknown[], list: unknown[]) => found.map((b) => list.indexOf(b)).sort();
const parents = (records: { parentA: unknown }[], list: unknown[]) =>
  indices(
    records.map((r) => r.parentA),
    list,
  );

const point = fc.record({
  x: fc.double({ min: 0, max: 800, noNaN: true }),
  y: fc.double({ min: 40, max: 160, noNaN: true }),
});

describe('fulcrum/matter Query agrees with matter.js', () => {
  it('Query.point and Query.region', () => {
    fc.assert(
      fc.property(point, point, (p, q) => {
        expect(indices(FulcrumMatter.Query.point(ours, p), ours)).toEqual(
          indices(RealMatter.Query.point(theirs, p), theirs),
        );
        const bounds = {
          min: { x: Math.min(p.x, q.x), y: Math.min(p.y, q.y) },
          max: { x: Math.max(p.x, q.x), y: Math.max(p.y, q.y) },
        };
        expect(indices(FulcrumMatter.Query.region(ours, bounds), ours)).toEqual(
          indices(RealMatter.Query.region(theirs, bounds), theirs),
        );
        expect(indices(FulcrumMatter.Query.region(ours, bounds, true), ours)).toEqual(
          indices(RealMatter.Query.region(theirs, bounds, true), theirs),
        );
      }),
    );
  });

  it('Query.ray, thin and wide', () => {
    fc.assert(
      fc.property(point, point, fc.constantFrom(1e-100, 10), (p, q, width) => {
        expect(parents(FulcrumMatter.Query.ray(ours, p, q, width), ours)).toEqual(
          parents(RealMatter.Query.ray(theirs, p, q, width), theirs),
        );
      }),
    );
  });

  it('Query.collides', () => {
    fc.assert(
      fc.property(point, (p) => {
        const probeOurs = FulcrumMatter.Bodies.rectangle(p.x, p.y, 60, 60);
        const probeTheirs = RealMatter.Bodies.rectangle(p.x, p.y, 60, 60);
        expect(parents(FulcrumMatter.Query.collides(probeOurs, ours), ours)).toEqual(
          parents(RealMatter.Query.collides(probeTheirs, theirs), theirs),
        );
      }),
    );
  });
});
