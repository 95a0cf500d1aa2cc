import { beforeAll, describe, expect, it } from 'vitest';
import { createRandom, type Random } from '../../scenes/random';
import { type Geometry, Shape, type ShapeHandle, World } from '../../src/index';
import { type Core, coreAt, coreOf, pointGap, surfaceGap } from './queries-brute-force';

function randomGeometry(random: Random, allowSegment: boolean): Geometry {
  const size = random.range(0.1, 1.2);
  switch (random.int(allowSegment ? 5 : 4)) {
    case 0:
      return Shape.circle(size, { x: random.range(-0.2, 0.2), y: random.range(-0.2, 0.2) });
    case 1:
      return Shape.box(size, random.range(0.05, 1), { x: 0, y: 0 }, random.range(0, 3));
    case 2:
      return Shape.capsule(
        { x: -size, y: 0 },
        { x: size, y: random.range(-0.3, 0.3) },
        random.range(0.05, 0.4),
      );
    case 3: {
      const n = 3 + random.int(6);
      const points = [];
      for (let i = 0; i < n; i++) {
        const a = (2 * Math.PI * i) / n + random.range(0, 0.5);
        points.push({ x: size * Math.cos(a), y: size * Math.sin(a) });
      }
      return Shape.polygon(points, random.int(3) === 0 ? 0.1 : 0);
    }
    default:
      return Shape.segment({ x: -size, y: 0 }, { x: size, y: random.range(-1, 1) });
  }
}

/**
 * 5,000 bodies (static with segments too, kinematic, dynamic awake and asleep, sensors, filters)
 * in a 300 m square, stepped a few times so that moving shapes sit off-centre in their fat boxes.
 */
function bigWorld(): { world: World; shapes: ShapeHandle[] } {
  const random = createRandom(5000);
  const world = new World({ gravity: { x: 0, y: 0 } });
  const shapes: ShapeHandle[] = [];
  for (let i = 0; i < 5000; i++) {
    const kind = random.int(10);
    const type = kind < 3 ? 'static' : kind < 4 ? 'kinematic' : 'dynamic';
    const body = world.createBody({
      type,
      position: { x: random.range(-150, 150), y: random.range(-150, 150) },
      angle: random.range(-3, 3),
      linearVelocity: type === 'static' ? { x: 0, y: 0 } : { x: random.range(-3, 3), y: random.range(-3, 3) },
      angularVelocity: type === 'static' ? 0 : random.range(-2, 2),
    });
    const count = 1 + (random.int(4) === 0 ? 1 : 0);
    for (let k = 0; k < count; k++) {
      shapes.push(
        body.createShape(randomGeometry(random, type !== 'dynamic'), {
          isSensor: random.int(20) === 0,
          filter: { categoryBits: 1 << random.int(3) },
        }),
      );
    }
    if (type === 'dynamic' && random.int(3) === 0) body.setAwake(false);
  }
  for (let i = 0; i < 3; i++) world.step(1 / 60);
  return { world, shapes };
}

describe('queries in a 5,000-body world agree with brute force over all shapes', () => {
  let world: World;
  let shapes: ShapeHandle[];
  let boxes: { minX: number; minY: number; maxX: number; maxY: number }[];
  let cores: Core[];
  let index: Map<ShapeHandle, number>;
  beforeAll(() => {
    ({ world, shapes } = bigWorld());
    boxes = shapes.map((s) => {
      const b = s.getAABB();
      return { minX: b.lowerBound.x, minY: b.lowerBound.y, maxX: b.upperBound.x, maxY: b.upperBound.y };
    });
    cores = shapes.map(coreOf);
    index = new Map(shapes.map((s, i) => [s, i]));
  });

  it('has sleeping, static, kinematic and dynamic bodies', () => {
    const bodies = [...world.bodies];
    expect(bodies.length).toBe(5000);
    expect(bodies.filter((b) => b.type === 'dynamic' && !b.isAwake).length).toBeGreaterThan(500);
    expect(bodies.filter((b) => b.type === 'kinematic').length).toBeGreaterThan(300);
  });

  it('queryAABB: 1,000 random boxes, with and without filters', () => {
    const random = createRandom(1);
    let total = 0;
    for (let q = 0; q < 1000; q++) {
      const x = random.range(-155, 150);
      const y = random.range(-155, 150);
      const box = {
        lowerBound: { x, y },
        upperBound: { x: x + random.range(0, 8), y: y + random.range(0, 8) },
      };
      const maskBits = q % 3 === 0 ? 0b101 : 0xffffffff;
      const includeSensors = q % 4 !== 0;
      const expected = shapes.filter(
        (s, i) =>
          (includeSensors || !s.isSensor) &&
          (s.filter.categoryBits & maskBits) !== 0 &&
          !(
            boxes[i].minX > box.upperBound.x ||
            boxes[i].minY > box.upperBound.y ||
            boxes[i].maxX < box.lowerBound.x ||
            boxes[i].maxY < box.lowerBound.y
          ),
      );
      expect(world.queryAABB(box, { maskBits, includeSensors })).toEqual(expected);
      total += expected.length;
    }
    expect(total).toBeGreaterThan(1500);
  });

  it('queryPoint: 1,000 random points (half of them inside some shape)', () => {
    const random = createRandom(2);
    let total = 0;
    for (let q = 0; q < 1000; q++) {
      let p: { x: number; y: number };
      if (q % 2 === 0) {
        p = { x: random.range(-155, 155), y: random.range(-155, 155) };
      } else {
        const b = boxes[random.int(boxes.length)];
        p = { x: random.range(b.minX, b.maxX), y: random.range(b.minY, b.maxY) };
      }
      const expected: ShapeHandle[] = [];
      for (let i = 0; i < shapes.length; i++) {
        const b = boxes[i];
        if (p.x < b.minX || p.x > b.maxX || p.y < b.minY || p.y > b.maxY) continue;
        if (shapes[i].geometry.type === 'segment') continue; // segments contain no point
        const gap = pointGap(cores[i], p);
        if (Math.abs(gap) < 1e-9) continue; // on the surface: either answer is fine
        if (gap < 0) expected.push(shapes[i]);
      }
      const actual = world.queryPoint(p).filter((s) => Math.abs(pointGap(cores[index.get(s)!], p)) >= 1e-9);
      expect(actual).toEqual(expected);
      total += expected.length;
    }
    expect(total).toBeGreaterThan(200);
  });

  it('overlapShape: 300 random shapes at random places', () => {
    const random = createRandom(3);
    let total = 0;
    for (let q = 0; q < 300; q++) {
      const g = randomGeometry(random, true);
      const x = random.range(-150, 150);
      const y = random.range(-150, 150);
      const angle = random.range(-3, 3);
      const query = coreAt(g, x, y, angle);
      const expected: ShapeHandle[] = [];
      const unclear = new Set<ShapeHandle>();
      const xs = query.points.map((v) => v.x);
      const ys = query.points.map((v) => v.y);
      const r = query.radius + 1e-6;
      const [minX, maxX, minY, maxY] = [
        Math.min(...xs) - r,
        Math.max(...xs) + r,
        Math.min(...ys) - r,
        Math.max(...ys) + r,
      ];
      for (let i = 0; i < shapes.length; i++) {
        const b = boxes[i];
        if (b.minX > maxX || b.maxX < minX || b.minY > maxY || b.maxY < minY) continue; // cannot touch
        const gap = surfaceGap(cores[i], query);
        if (Math.abs(gap) < 1e-9) unclear.add(shapes[i]);
        else if (gap < 0) expected.push(shapes[i]);
      }
      const actual = world.overlapShape(g, { position: { x, y }, angle }).filter((s) => !unclear.has(s));
      expect(actual).toEqual(expected);
      total += expected.length;
    }
    expect(total).toBeGreaterThan(50);
  });
});

describe('castShape agrees with a fine-stepped brute-force sweep', () => {
  it('within 1 mm, 40 random casts of every kind of shape through a field of shapes', () => {
    const random = createRandom(7);
    const world = new World({ gravity: { x: 0, y: 0 } });
    const field: ShapeHandle[] = [];
    for (let i = 0; i < 30; i++) {
      const body = world.createBody({
        position: { x: random.range(-6, 6), y: random.range(-6, 6) },
        angle: random.range(-3, 3),
      });
      field.push(body.createShape(randomGeometry(random, true)));
    }
    const cores = field.map(coreOf);
    let hits = 0;
    for (let q = 0; q < 40; q++) {
      const g = randomGeometry(random, false);
      const angle = random.range(-3, 3);
      let start: { x: number; y: number };
      // a start that touches nothing
      do {
        start = { x: random.range(-9, 9), y: random.range(-9, 9) };
      } while (cores.some((c) => surfaceGap(c, coreAt(g, start.x, start.y, angle)) <= 0));
      const a = random.range(0, 2 * Math.PI);
      const length = random.range(2, 8);
      const t = { x: length * Math.cos(a), y: length * Math.sin(a) };
      const hit = world.castShape(g, { position: start, angle }, t);
      // brute force: steps of at most 0.25 mm along the translation
      const steps = Math.ceil(length / 0.00025);
      let first = -1;
      for (let k = 1; k <= steps && first < 0; k++) {
        const f = k / steps;
        const moved = coreAt(g, start.x + f * t.x, start.y + f * t.y, angle);
        for (const c of cores) {
          const b = moved.points;
          // cheap reject by centre distance before the exact test
          const dx = b[0].x - c.points[0].x;
          const dy = b[0].y - c.points[0].y;
          if (Math.sqrt(dx * dx + dy * dy) > 5) continue;
          if (surfaceGap(c, moved) <= 0) {
            first = f;
            break;
          }
        }
      }
      if (first < 0) {
        expect(hit).toBeNull();
        continue;
      }
      hits++;
      expect(hit).not.toBeNull();
      // the cast fraction lies within one brute-force step before the first overlapping step
      expect(Math.abs(hit!.fraction - first) * length).toBeLessThan(0.001);
      // and the hit shape is really touched there
      const touching = coreAt(g, start.x + hit!.fraction * t.x, start.y + hit!.fraction * t.y, angle);
      expect(Math.abs(surfaceGap(coreOf(hit!.shape), touching))).toBeLessThan(1e-6);
      // the normal points out of the hit shape, against the motion
      expect(hit!.normal.x * t.x + hit!.normal.y * t.y).toBeLessThanOrEqual(1e-12);
      expect(Math.hypot(hit!.normal.x, hit!.normal.y)).toBeCloseTo(1, 9);
    }
    expect(hits).toBeGreaterThan(12);
  });
});
