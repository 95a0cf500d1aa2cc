import { describe, expect, it } from 'vitest';
import { createRandom } from '../../scenes/random';
import { FulcrumError, Shape, World } from '../../src/index';

type P = { x: number; y: number };
type Hit = { fraction: number; point: P; normal: P } | null;

const random = createRandom(44);

function staticWorld() {
  return new World({ gravity: { x: 0, y: 0 } });
}

/** smallest t in [0, 1] where o + t d meets the circle, with the outward normal; null on a miss */
function rayCircle(o: P, d: P, c: P, r: number): Hit {
  const mx = o.x - c.x;
  const my = o.y - c.y;
  const a = d.x * d.x + d.y * d.y;
  const b = 2 * (mx * d.x + my * d.y);
  const k = mx * mx + my * my - r * r;
  const disc = b * b - 4 * a * k;
  if (k < 0 || disc < 0) return null;
  const t = (-b - Math.sqrt(disc)) / (2 * a);
  if (t < 0 || t > 1) return null;
  const point = { x: o.x + t * d.x, y: o.y + t * d.y };
  return { fraction: t, point, normal: { x: (point.x - c.x) / r, y: (point.y - c.y) / r } };
}

/** ray against segment a-b (line intersection), with the normal facing the ray's origin */
function raySegment(o: P, d: P, a: P, b: P): Hit {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const den = d.x * ey - d.y * ex;
  if (den === 0) return null;
  const t = ((a.x - o.x) * ey - (a.y - o.y) * ex) / den;
  const u = ((a.x - o.x) * d.y - (a.y - o.y) * d.x) / den;
  if (t < 0 || t > 1 || u < 0 || u > 1) return null;
  const len = Math.hypot(ex, ey);
  let nx = ey / len;
  let ny = -ex / len;
  if (nx * d.x + ny * d.y > 0) {
    nx = -nx;
    ny = -ny;
  }
  return { fraction: t, point: { x: o.x + t * d.x, y: o.y + t * d.y }, normal: { x: nx, y: ny } };
}

function closest(hits: Hit[]): Hit {
  let best: Hit = null;
  for (const h of hits) if (h && (!best || h.fraction < best.fraction)) best = h;
  return best;
}

/** ray against a convex counter-clockwise polygon given by world vertices; origin outside */
function rayPolygon(o: P, d: P, v: P[]): Hit {
  return closest(v.map((a, i) => raySegment(o, d, a, v[(i + 1) % v.length])));
}

/** ray against a capsule: two offset sides and two end discs */
function rayCapsule(o: P, d: P, a: P, b: P, r: number): Hit {
  const len = Math.hypot(b.x - a.x, b.y - a.y);
  const n = { x: (b.y - a.y) / len, y: -(b.x - a.x) / len };
  const side = (s: number) =>
    raySegment(
      o,
      d,
      { x: a.x + s * r * n.x, y: a.y + s * r * n.y },
      { x: b.x + s * r * n.x, y: b.y + s * r * n.y },
    );
  return closest([side(1), side(-1), rayCircle(o, d, a, r), rayCircle(o, d, b, r)]);
}

function worldPoints(local: P[], pos: P, angle: number): P[] {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  return local.map((p) => ({ x: pos.x + c * p.x - s * p.y, y: pos.y + s * p.x + c * p.y }));
}

function expectHit(actual: ReturnType<World['castRay']>, expected: Hit): void {
  expect(actual).not.toBeNull();
  expect(Math.abs(actual!.fraction - expected!.fraction)).toBeLessThan(1e-9);
  expect(Math.abs(actual!.point.x - expected!.point.x)).toBeLessThan(1e-9);
  expect(Math.abs(actual!.point.y - expected!.point.y)).toBeLessThan(1e-9);
  expect(Math.abs(actual!.normal.x - expected!.normal.x)).toBeLessThan(1e-9);
  expect(Math.abs(actual!.normal.y - expected!.normal.y)).toBeLessThan(1e-9);
}

/**
 * Casts 300 random rays from a ring around the shape toward random points near it; compares every
 * hit (and every clear miss) with the analytic answer. Rays within 1e-6 of grazing are skipped.
 */
function compareRays(
  world: World,
  centre: P,
  size: number,
  analytic: (o: P, d: P) => Hit,
  nearGrazing: (o: P, d: P) => boolean,
): number {
  let hits = 0;
  for (let i = 0; i < 300; i++) {
    const a = random.range(0, 2 * Math.PI);
    const o = { x: centre.x + 3 * size * Math.cos(a), y: centre.y + 3 * size * Math.sin(a) };
    const target = {
      x: centre.x + random.range(-1.5, 1.5) * size,
      y: centre.y + random.range(-1.5, 1.5) * size,
    };
    const scale = random.range(0.6, 2);
    const d = { x: (target.x - o.x) * scale, y: (target.y - o.y) * scale };
    if (nearGrazing(o, d)) continue;
    const expected = analytic(o, d);
    const actual = world.castRay(o, d);
    if (expected === null) {
      expect(actual).toBeNull();
    } else {
      expectHit(actual, expected);
      hits++;
    }
  }
  return hits;
}

describe('castRay matches analytic intersections to 1e-9', () => {
  it('circle (off-centre on a turned, moved body)', () => {
    const world = staticWorld();
    const body = world.createBody({ position: { x: 3, y: -2 }, angle: 0.7 });
    body.createShape(Shape.circle(0.8, { x: 0.3, y: -0.2 }));
    const c = worldPoints([{ x: 0.3, y: -0.2 }], { x: 3, y: -2 }, 0.7)[0];
    const grazing = (o: P, d: P) => {
      const h = Math.abs((c.x - o.x) * d.y - (c.y - o.y) * d.x) / Math.hypot(d.x, d.y);
      return Math.abs(h - 0.8) < 1e-6;
    };
    expect(compareRays(world, c, 0.8, (o, d) => rayCircle(o, d, c, 0.8), grazing)).toBeGreaterThan(80);
  });

  const corners = (v: P[]) => (o: P, d: P) =>
    v.some((p) => Math.abs((p.x - o.x) * d.y - (p.y - o.y) * d.x) / Math.hypot(d.x, d.y) < 1e-6);

  it('box (axis-aligned)', () => {
    const world = staticWorld();
    world.createBody({ position: { x: -1, y: 2 } }).createShape(Shape.box(1.5, 0.5));
    const v = worldPoints(
      [
        { x: -1.5, y: -0.5 },
        { x: 1.5, y: -0.5 },
        { x: 1.5, y: 0.5 },
        { x: -1.5, y: 0.5 },
      ],
      { x: -1, y: 2 },
      0,
    );
    expect(
      compareRays(world, { x: -1, y: 2 }, 1.5, (o, d) => rayPolygon(o, d, v), corners(v)),
    ).toBeGreaterThan(80);
  });

  it('rotated polygon (a pentagon on a turned body)', () => {
    const world = staticWorld();
    const local = [
      { x: 1, y: 0 },
      { x: 0.3, y: 0.9 },
      { x: -0.8, y: 0.6 },
      { x: -0.8, y: -0.6 },
      { x: 0.3, y: -0.9 },
    ];
    world.createBody({ position: { x: 5, y: 1 }, angle: -2.1 }).createShape(Shape.polygon(local));
    const v = worldPoints(local, { x: 5, y: 1 }, -2.1);
    expect(compareRays(world, { x: 5, y: 1 }, 1, (o, d) => rayPolygon(o, d, v), corners(v))).toBeGreaterThan(
      80,
    );
  });

  it('capsule (on a turned body)', () => {
    const world = staticWorld();
    world
      .createBody({ position: { x: -4, y: -3 }, angle: 0.4 })
      .createShape(Shape.capsule({ x: -1, y: 0.2 }, { x: 1, y: -0.1 }, 0.35));
    const [a, b] = worldPoints(
      [
        { x: -1, y: 0.2 },
        { x: 1, y: -0.1 },
      ],
      { x: -4, y: -3 },
      0.4,
    );
    const grazing = (o: P, d: P) => {
      const len = Math.hypot(d.x, d.y);
      const h = (p: P) => Math.abs((p.x - o.x) * d.y - (p.y - o.y) * d.x) / len;
      // tangent to an end disc, or parallel to the sides
      const cross = Math.abs((b.x - a.x) * d.y - (b.y - a.y) * d.x) / len / Math.hypot(b.x - a.x, b.y - a.y);
      return Math.abs(h(a) - 0.35) < 1e-6 || Math.abs(h(b) - 0.35) < 1e-6 || cross < 1e-6;
    };
    expect(
      compareRays(world, { x: -4, y: -3 }, 1.2, (o, d) => rayCapsule(o, d, a, b, 0.35), grazing),
    ).toBeGreaterThan(80);
  });

  it('segment (two-sided, normal against the ray)', () => {
    const world = staticWorld();
    world
      .createBody({ position: { x: 0, y: 4 }, angle: 1.1 })
      .createShape(Shape.segment({ x: -1, y: 0 }, { x: 1.5, y: 0.3 }));
    const [a, b] = worldPoints(
      [
        { x: -1, y: 0 },
        { x: 1.5, y: 0.3 },
      ],
      { x: 0, y: 4 },
      1.1,
    );
    expect(
      compareRays(world, { x: 0, y: 4 }, 1.3, (o, d) => raySegment(o, d, a, b), corners([a, b])),
    ).toBeGreaterThan(60);
  });
});

describe('ray rules (see src/geometry/raycast.ts)', () => {
  function oneOfEach() {
    const world = staticWorld();
    world.createBody({ position: { x: 0, y: 0 } }).createShape(Shape.circle(1));
    world.createBody({ position: { x: 10, y: 0 } }).createShape(Shape.box(1, 1));
    world
      .createBody({ position: { x: 20, y: 0 } })
      .createShape(Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.5));
    world
      .createBody({ position: { x: 30, y: 0 } })
      .createShape(Shape.segment({ x: 0, y: -1 }, { x: 0, y: 1 }));
    return world;
  }

  it('a grazing (tangent) ray hits at the touching point', () => {
    const world = oneOfEach();
    const circle = world.castRay({ x: -5, y: 1 }, { x: 10, y: 0 });
    expect(circle!.fraction).toBeCloseTo(0.5, 12);
    expect(circle!.point).toEqual({ x: 0, y: 1 });
    expect(circle!.normal.y).toBeCloseTo(1, 12);
    // along the top face of the box: hits the corner first
    const box = world.castRay({ x: 5, y: 1 }, { x: 10, y: 0 });
    expect(box!.point.x).toBeCloseTo(9, 12);
    expect(box!.point.y).toBe(1);
    // tangent to the capsule's side
    const capsule = world.castRay({ x: 15, y: 0.5 }, { x: 10, y: 0 });
    expect(capsule!.point.x).toBeCloseTo(20 - 1.5 + 1 - Math.sqrt(0.25 - 0.25) - 0.5, 9);
    expect(capsule!.point.y).toBeCloseTo(0.5, 12);
  });

  it('a ray starting strictly inside a solid shape does not hit it; on the surface going in hits at 0', () => {
    const world = oneOfEach();
    expect(world.castRay({ x: 0.2, y: 0.1 }, { x: 3, y: 0 })).toBeNull(); // out of the circle, nothing beyond
    expect(world.castRay({ x: 10, y: 0 }, { x: 0, y: 5 })).toBeNull();
    expect(world.castRay({ x: 20.5, y: 0.1 }, { x: 0, y: 5 })).toBeNull();
    // from inside the circle toward the box: the box is the first hit
    const hit = world.castRay({ x: 0.5, y: 0 }, { x: 20, y: 0 });
    expect(hit!.point.x).toBe(9);
    expect(hit!.body.position.x).toBe(10);
    const surface = world.castRay({ x: -1, y: 0 }, { x: 1, y: 0 });
    expect(surface!.fraction).toBe(0);
    expect(surface!.normal).toEqual({ x: -1, y: 0 });
  });

  it('a zero-length ray hits nothing, even on or inside a shape', () => {
    const world = oneOfEach();
    expect(world.castRay({ x: -1, y: 0 }, { x: 0, y: 0 })).toBeNull();
    expect(world.castRay({ x: 0, y: 0 }, { x: 0, y: 0 })).toBeNull();
    expect(world.castRayAll({ x: 30, y: 0 }, { x: 0, y: 0 })).toEqual([]);
  });

  it('castRayAll lists every hit by fraction, ties by shape creation order; castRay takes the first', () => {
    const world = staticWorld();
    const bodies = [5, 3, 7, 3].map((x) => world.createBody({ position: { x, y: 0 } }));
    const shapes = bodies.map((b) => b.createShape(Shape.box(0.5, 0.5)));
    const all = world.castRayAll({ x: 0, y: 0 }, { x: 10, y: 0 });
    expect(all.map((h) => h.shape)).toEqual([shapes[1], shapes[3], shapes[0], shapes[2]]);
    expect(all.map((h) => h.fraction)).toEqual([0.25, 0.25, 0.45, 0.65]);
    expect(all[0].body).toBe(bodies[1]);
    expect(world.castRay({ x: 0, y: 0 }, { x: 10, y: 0 })!.shape).toBe(shapes[1]);
    // each hit is a fresh object
    expect(world.castRay({ x: 0, y: 0 }, { x: 10, y: 0 })).not.toBe(
      world.castRay({ x: 0, y: 0 }, { x: 10, y: 0 }),
    );
  });
});

describe('filters, sensors, sleeping bodies', () => {
  function scene() {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const plain = world.createBody({ position: { x: 2, y: 0 } }).createShape(Shape.box(0.5, 0.5));
    const enemy = world
      .createBody({ position: { x: 4, y: 0 } })
      .createShape(Shape.box(0.5, 0.5), { filter: { categoryBits: 2, maskBits: 0xffff } });
    const shy = world
      .createBody({ position: { x: 6, y: 0 } })
      .createShape(Shape.box(0.5, 0.5), { filter: { categoryBits: 4, maskBits: 1 } });
    const sensor = world
      .createBody({ position: { x: 1, y: 0 } })
      .createShape(Shape.circle(0.3), { isSensor: true });
    const sleeper = world.createBody({ type: 'dynamic', position: { x: 8, y: 0 }, awake: false });
    const sleeping = sleeper.createShape(Shape.circle(0.5));
    sleeper.setAwake(false); // adding a shape woke it
    return { world, plain, enemy, shy, sensor, sleeping };
  }

  it('category and mask bits on both sides', () => {
    const { world, plain, enemy, shy, sleeping } = scene();
    const along = (filter?: object) =>
      world.castRayAll({ x: 0, y: 0 }, { x: 10, y: 0 }, filter).map((h) => h.shape);
    expect(along()).toEqual([plain, enemy, shy, sleeping]);
    expect(along({ maskBits: 2 })).toEqual([enemy]);
    // the query's category must be in the shape's mask: shy only sees category 1
    expect(along({ categoryBits: 2 })).toEqual([plain, enemy, sleeping]);
    expect(along({ categoryBits: 2, maskBits: 4 })).toEqual([]);
    expect(world.castRay({ x: 0, y: 0 }, { x: 10, y: 0 }, { maskBits: 4 })!.shape).toBe(shy);
    const box = { lowerBound: { x: -1, y: -1 }, upperBound: { x: 10, y: 1 } };
    expect(world.queryAABB(box, { maskBits: 6 })).toEqual([enemy, shy]);
  });

  it('casts skip sensors unless includeSensors; overlap queries include them unless told not to', () => {
    const { world, plain, sensor } = scene();
    expect(world.castRay({ x: 0, y: 0 }, { x: 10, y: 0 })!.shape).toBe(plain);
    expect(world.castRay({ x: 0, y: 0 }, { x: 10, y: 0 }, { includeSensors: true })!.shape).toBe(sensor);
    expect(world.castShape(Shape.circle(0.1), { position: { x: 0, y: 0 } }, { x: 10, y: 0 })!.shape).toBe(
      plain,
    );
    expect(world.queryPoint({ x: 1, y: 0 })).toEqual([sensor]);
    expect(world.queryPoint({ x: 1, y: 0 }, { includeSensors: false })).toEqual([]);
    expect(world.overlapShape(Shape.box(0.1, 0.1), { position: { x: 1.2, y: 0 } })).toEqual([sensor]);
  });

  it('sleeping bodies are found by every query', () => {
    const { world, sleeping } = scene();
    expect(sleeping.body.isAwake).toBe(false);
    expect(world.queryPoint({ x: 8.2, y: 0.1 })).toEqual([sleeping]);
    expect(world.castRay({ x: 8, y: 5 }, { x: 0, y: -10 })!.shape).toBe(sleeping);
    expect(world.queryAABB({ lowerBound: { x: 7.9, y: -0.1 }, upperBound: { x: 8.1, y: 0.1 } })).toEqual([
      sleeping,
    ]);
    expect(world.overlapShape(Shape.circle(0.1), { position: { x: 8.55, y: 0 } })).toEqual([sleeping]);
    expect(world.castShape(Shape.circle(0.1), { position: { x: 8, y: 5 } }, { x: 0, y: -10 })!.shape).toBe(
      sleeping,
    );
    expect(sleeping.body.isAwake).toBe(false);
  });

  it('queries after bodies move see the new positions (also while they are still inside their fat boxes)', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const body = world.createBody({ type: 'dynamic', linearVelocity: { x: 1.5, y: 0 } });
    const shape = body.createShape(Shape.circle(0.25));
    world.step(1 / 60); // moves 0.025 m: within the fat box margin
    const x = body.position.x;
    expect(world.queryPoint({ x: x + 0.249, y: 0 })).toEqual([shape]);
    expect(world.queryPoint({ x: x - 0.251, y: 0 })).toEqual([]);
    expect(
      world.queryAABB({ lowerBound: { x: x - 0.26, y: 0 }, upperBound: { x: x - 0.2505, y: 0 } }),
    ).toEqual([]);
    body.setPosition({ x: 50, y: 0 });
    expect(world.queryPoint({ x: 50, y: 0 })).toEqual([shape]);
  });
});

describe('castShape and overlapShape', () => {
  it('a circle cast at a box stops where the surfaces touch, with the box normal', () => {
    const world = staticWorld();
    const box = world.createBody({ position: { x: 5, y: 0 } }).createShape(Shape.box(1, 1));
    const hit = world.castShape(Shape.circle(0.5), { position: { x: 0, y: 0.3 } }, { x: 10, y: 0 });
    expect(hit!.shape).toBe(box);
    expect(hit!.fraction).toBeCloseTo(0.35, 9); // centre reaches x = 3.5
    expect(hit!.point.x).toBeCloseTo(4, 9);
    expect(hit!.point.y).toBeCloseTo(0.3, 9);
    expect(hit!.normal.x).toBeCloseTo(-1, 9);
    expect(hit!.normal.y).toBeCloseTo(0, 9);
    // the { p, q } form gives the same answer: a box turned by 90 degrees
    const a = world.castShape(
      Shape.box(0.5, 0.2),
      { position: { x: 0, y: 0 }, angle: Math.PI / 2 },
      { x: 10, y: 0 },
    );
    const b = world.castShape(Shape.box(0.5, 0.2), { p: { x: 0, y: 0 }, q: { c: 0, s: 1 } }, { x: 10, y: 0 });
    expect(a!.fraction).toBeCloseTo(0.38, 9);
    expect(b!.fraction).toBeCloseTo(0.38, 9);
    // starting in contact: fraction 0, normal (0, 0); missing: null
    const start = world.castShape(Shape.circle(0.5), { position: { x: 4, y: 0 } }, { x: 1, y: 0 });
    expect(start!.fraction).toBe(0);
    expect(start!.normal).toEqual({ x: 0, y: 0 });
    expect(world.castShape(Shape.circle(0.5), { position: { x: 0, y: 3 } }, { x: 10, y: 0 })).toBeNull();
  });

  it('overlapShape reports overlapping and touching shapes by creation order', () => {
    const world = staticWorld();
    const a = world.createBody({ position: { x: 0, y: 0 } }).createShape(Shape.box(1, 1));
    const b = world.createBody({ position: { x: 3, y: 0 } }).createShape(Shape.circle(1));
    world.createBody({ position: { x: 9, y: 0 } }).createShape(Shape.circle(1));
    expect(world.overlapShape(Shape.box(0.5, 0.5), { position: { x: 1.5, y: 0 } })).toEqual([a, b]);
    expect(world.overlapShape(Shape.circle(0.49), { position: { x: 1.5, y: 0 } })).toEqual([]);
    expect(
      world.overlapShape(Shape.segment({ x: -5, y: 0 }, { x: 5, y: 0 }), { position: { x: 0, y: 0 } }),
    ).toEqual([a, b]);
  });
});

describe('bad input throws FulcrumError naming the argument and value', () => {
  const world = staticWorld();
  world.createBody().createShape(Shape.circle(1));
  const o = { x: 0, y: 0 };
  const cases: [string, () => unknown, RegExp][] = [
    ['origin NaN', () => world.castRay({ x: Number.NaN, y: 0 }, o), /origin.*NaN/],
    ['translation missing', () => world.castRay(o, undefined as never), /translation.*undefined/],
    [
      'translation infinite',
      () => world.castRayAll(o, { x: 1, y: Number.POSITIVE_INFINITY }),
      /translation.*Infinity/,
    ],
    ['filter not an object', () => world.castRay(o, o, 3 as never), /filter.*3/],
    ['filter bits', () => world.castRay(o, o, { maskBits: -1 }), /filter\.maskBits.*-1/],
    ['filter fraction bits', () => world.queryPoint(o, { categoryBits: 1.5 }), /filter\.categoryBits.*1\.5/],
    ['filter unknown key', () => world.queryPoint(o, { groupIndex: 1 } as never), /filter.*groupIndex/],
    [
      'filter includeSensors',
      () => world.queryPoint(o, { includeSensors: 1 } as never),
      /filter\.includeSensors.*1/,
    ],
    ['aabb null', () => world.queryAABB(null as never), /aabb.*null/],
    [
      'aabb bound',
      () => world.queryAABB({ lowerBound: o, upperBound: { x: 1, y: 'a' } } as never),
      /aabb\.upperBound/,
    ],
    [
      'aabb inverted',
      () => world.queryAABB({ lowerBound: { x: 1, y: 0 }, upperBound: { x: 0, y: 1 } }),
      /aabb.*1/,
    ],
    ['point', () => world.queryPoint('here' as never), /point.*"here"/],
    [
      'geometry',
      () => world.overlapShape({ type: 'circle', radius: 1 } as never, { position: o }),
      /geometry/,
    ],
    ['transform', () => world.overlapShape(Shape.circle(1), 5 as never), /transform.*5/],
    [
      'transform angle',
      () => world.overlapShape(Shape.circle(1), { position: o, angle: Number.NaN }),
      /transform\.angle.*NaN/,
    ],
    [
      'transform q',
      () => world.castShape(Shape.circle(1), { p: o, q: { c: 2, s: 0 } }, o),
      /transform\.q.*2/,
    ],
    [
      'transform key',
      () => world.castShape(Shape.circle(1), { position: o, spin: 1 } as never, o),
      /transform.*spin/,
    ],
    [
      'castShape translation',
      () => world.castShape(Shape.circle(1), { position: o }, null as never),
      /translation.*null/,
    ],
  ];
  it.each(cases)('%s', (_name, call, message) => {
    let error: unknown;
    try {
      call();
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(FulcrumError);
    expect((error as Error).message).toMatch(message);
  });
});
