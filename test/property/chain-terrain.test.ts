import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { Shape, type Vec2, World } from '../../src/index';

/** Height of the polyline `points` (x increasing) at x. */
function heightAt(points: readonly Vec2[], x: number): number {
  for (let i = 0; i + 1 < points.length; i++) {
    const a = points[i];
    const b = points[i + 1];
    if (x >= a.x && x <= b.x) return a.y + ((b.y - a.y) * (x - a.x)) / (b.x - a.x);
  }
  return Number.NaN;
}

const shapeKind = fc.constantFrom('circle', 'box', 'capsule', 'polygon', 'rounded');

describe('bodies dropped on random chain terrain', () => {
  it('stay in front of it: finite, above the ground line, never through it', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: -1.5, max: 1.5, noNaN: true }), { minLength: 20, maxLength: 60 }),
        fc.array(
          fc.record({
            kind: shapeKind,
            x: fc.double({ min: 0.05, max: 0.95, noNaN: true }),
            size: fc.double({ min: 0.1, max: 0.6, noNaN: true }),
            vx: fc.double({ min: -20, max: 20, noNaN: true }),
            vy: fc.double({ min: -30, max: 5, noNaN: true }),
            angle: fc.double({ min: -3, max: 3, noNaN: true }),
          }),
          { minLength: 1, maxLength: 12 },
        ),
        (heights, drops) => {
          // ground from x = 0 to 0.5 m per segment, listed right to left so that it faces up, with walls
          const profile = heights.map((h, i) => ({ x: 0.5 * i, y: h }));
          const width = profile[profile.length - 1].x;
          const world = new World();
          const ground = world.createBody();
          ground.createShape(Shape.chain([{ x: width, y: 20 }, ...[...profile].reverse(), { x: 0, y: 20 }]), {
            friction: 0.6,
          });
          const bodies = drops.map((d) => {
            const x = 1 + d.x * (width - 2);
            const body = world.createBody({
              type: 'dynamic',
              position: { x, y: heightAt(profile, x) + 3 },
              angle: d.angle,
              linearVelocity: { x: d.vx, y: d.vy },
            });
            const s = d.size;
            const geometry =
              d.kind === 'circle'
                ? Shape.circle(s)
                : d.kind === 'box'
                  ? Shape.box(s, 0.5 * s)
                  : d.kind === 'capsule'
                    ? Shape.capsule({ x: -s, y: 0 }, { x: s, y: 0 }, 0.4 * s)
                    : Shape.polygon(
                        [0, 1, 2, 3, 4].map((k) => ({
                          x: s * Math.cos((2 * Math.PI * k) / 5),
                          y: s * Math.sin((2 * Math.PI * k) / 5),
                        })),
                        d.kind === 'rounded' ? 0.1 * s : 0,
                      );
            body.createShape(geometry);
            return body;
          });
          for (let step = 0; step < 180; step++) {
            world.step(1 / 60);
            for (const body of bodies) {
              const p = body.worldCenter;
              expect(Number.isFinite(p.x) && Number.isFinite(p.y)).toBe(true);
              // inside the walls, and its centre never behind the ground line (the chain's back)
              expect(p.x).toBeGreaterThan(-0.01);
              expect(p.x).toBeLessThan(width + 0.01);
              expect(p.y).toBeGreaterThan(heightAt(profile, Math.min(Math.max(p.x, 0), width)) - 0.01);
            }
          }
        },
      ),
      { numRuns: 25 },
    );
  });
});
