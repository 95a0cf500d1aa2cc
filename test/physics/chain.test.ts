import { describe, expect, it } from 'vitest';
import {
  type Chain,
  type Concave,
  FulcrumError,
  Shape,
  stateHash,
  svgShapes,
  type Vec2,
  World,
} from '../../src/index';
import { run } from '../helpers/world';

const G = 10;

/** Points of a straight floor at y = 0 from x = `from` down to x = `to` (right to left: it faces up). */
function floorPoints(from: number, to: number, segments: number): Vec2[] {
  const points: Vec2[] = [];
  for (let i = 0; i <= segments; i++) points.push({ x: from + ((to - from) * i) / segments, y: 0 });
  return points;
}

/** A world with a static floor chain of `segments` links of 0.1 m from x = -1 to the right. */
function chainFloor(segments: number, friction: number) {
  const world = new World({ enableSleep: false });
  const ground = world.createBody();
  const shapes = ground.createShape(Shape.chain(floorPoints(-1 + 0.1 * segments, -1, segments)), {
    friction,
  });
  return { world, ground, shapes };
}

describe('Shape.chain: one surface across its seams', () => {
  it('a box pushed at 10 m/s over 200 segments loses speed to friction only, and never lifts at a seam', () => {
    const mu = 0.2;
    const { world, shapes } = chainFloor(200, mu);
    expect(shapes).toHaveLength(200);
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.25 } });
    box.createShape(Shape.box(0.25, 0.25), { friction: mu });
    run(world, 0.5); // settle onto the floor
    box.setLinearVelocity({ x: 10, y: 0 });
    let worstVertical = 0;
    let worstSpin = 0;
    const seconds = 2;
    run(world, seconds, () => {
      worstVertical = Math.max(worstVertical, Math.abs(box.linearVelocity.y));
      worstSpin = Math.max(worstSpin, Math.abs(box.angularVelocity));
    });
    const lost = 10 - box.linearVelocity.x;
    // it crossed about 160 seams
    expect(box.position.x).toBeGreaterThan(15);
    expect(Math.abs(lost - mu * G * seconds) / (mu * G * seconds)).toBeLessThan(0.01);
    expect(worstVertical).toBeLessThan(0.001);
    expect(worstSpin).toBeLessThan(0.01);
  });

  it('a ball rolls across 200 segments with no bump and keeps its speed', () => {
    const { world } = chainFloor(200, 0.6);
    const r = 0.25;
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: r } });
    ball.createShape(Shape.circle(r), { friction: 0.6 });
    run(world, 0.5);
    ball.setLinearVelocity({ x: 5, y: 0 });
    ball.setAngularVelocity(-5 / r); // rolling to the right, clockwise
    let worstVertical = 0;
    run(world, 3, () => {
      worstVertical = Math.max(worstVertical, Math.abs(ball.linearVelocity.y));
    });
    expect(ball.position.x).toBeGreaterThan(14);
    expect(worstVertical).toBeLessThan(0.001);
    expect(Math.abs(ball.linearVelocity.x - 5)).toBeLessThan(0.005);
    expect(Math.abs(ball.angularVelocity * r + ball.linearVelocity.x)).toBeLessThan(0.005);
  });

  it('a box slides down a polyline slope of many bends at a = g (sin - mu cos)', () => {
    // a 30 degree slope drawn as 100 segments, every other point nudged 0.1 mm off the line: a
    // chain of tiny convex and hollow bends that must still act as one plane
    const theta = Math.PI / 6;
    const c = Math.cos(theta);
    const s = Math.sin(theta);
    const points: Vec2[] = [];
    for (let i = 0; i <= 100; i++) {
      const along = 20 - 0.2 * i; // right to left: the front faces up the slope's normal
      const off = i % 2 === 0 ? 0 : 1e-4;
      points.push({ x: along * c - off * s, y: along * s + off * c });
    }
    const world = new World({ enableSleep: false });
    world.createBody().createShape(Shape.chain(points), { friction: 0.3 });
    const box = world.createBody({
      type: 'dynamic',
      position: { x: 15 * c - 0.25 * s, y: 15 * s + 0.25 * c },
      angle: theta,
    });
    box.createShape(Shape.box(0.25, 0.25), { friction: 0.3 });
    const along = () => box.position.x * c + box.position.y * s;
    run(world, 0.25);
    const s0 = along();
    const v0 = box.linearVelocity.x * c + box.linearVelocity.y * s;
    const t = 1.5;
    run(world, t);
    const travelled = along() - s0;
    const a = (2 * (travelled - v0 * t)) / (t * t);
    const expected = -G * (s - 0.3 * c);
    expect(Math.abs(a - expected) / Math.abs(expected)).toBeLessThan(0.02);
  });
});

describe('Shape.chain: one-sided', () => {
  it('a box jumps up through a one-way platform and lands on top of it', () => {
    const world = new World();
    world.createBody().createShape(
      Shape.chain([
        { x: 2, y: 3 },
        { x: -2, y: 3 },
      ]),
    );
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 1 } });
    box.createShape(Shape.box(0.4, 0.4));
    box.setLinearVelocity({ x: 0, y: 10 });
    let highest = box.position.y;
    run(world, 4, () => {
      highest = Math.max(highest, box.position.y);
    });
    // free flight from y = 1 at 10 m/s reaches 1 + v^2 / 2g = 6
    expect(highest).toBeGreaterThan(5.5);
    expect(Math.abs(box.position.y - 3.4)).toBeLessThan(0.01);
    expect(Math.hypot(box.linearVelocity.x, box.linearVelocity.y)).toBeLessThan(0.01);
  });

  it('a fast small ball passes a chain from behind and is stopped from the front (continuous)', () => {
    const world = new World({ enableSleep: false, gravity: { x: 0, y: 0 } });
    world.createBody().createShape(
      Shape.chain([
        { x: 5, y: 0 },
        { x: -5, y: 0 },
      ]),
    );
    const up = world.createBody({ type: 'dynamic', position: { x: -1, y: -2 }, bullet: true });
    up.createShape(Shape.circle(0.05));
    up.setLinearVelocity({ x: 0, y: 300 });
    const down = world.createBody({ type: 'dynamic', position: { x: 1, y: 2 }, bullet: true });
    down.createShape(Shape.circle(0.05));
    down.setLinearVelocity({ x: 0, y: -300 });
    run(world, 0.1);
    expect(up.position.y).toBeGreaterThan(20);
    expect(down.position.y).toBeGreaterThan(0);
    expect(down.position.y).toBeLessThan(0.2);
  });

  it('a counter-clockwise loop is solid; a clockwise one holds what is inside it', () => {
    const square = [
      { x: -2, y: -2 },
      { x: 2, y: -2 },
      { x: 2, y: 2 },
      { x: -2, y: 2 },
    ];
    const world = new World();
    world.createBody({ position: { x: -10, y: 0 } }).createShape(Shape.chain(square, { loop: true }));
    world
      .createBody({ position: { x: 10, y: 0 } })
      .createShape(Shape.chain([...square].reverse(), { loop: true }));
    const onIsland = world.createBody({ type: 'dynamic', position: { x: -10, y: 4 } });
    onIsland.createShape(Shape.box(0.5, 0.5));
    const inBox = world.createBody({ type: 'dynamic', position: { x: 10, y: 0 } });
    inBox.createShape(Shape.circle(0.5));
    run(world, 3);
    expect(Math.abs(onIsland.position.y - 2.5)).toBeLessThan(0.01);
    expect(Math.abs(inBox.position.y - -1.5)).toBeLessThan(0.01);
  });

  it('ray and shape casts see a chain from its front only', () => {
    const world = new World();
    const [shape] = world.createBody().createShape(
      Shape.chain([
        { x: 2, y: 0 },
        { x: -2, y: 0 },
      ]),
    );
    const hit = world.castRay({ x: 0.5, y: 1 }, { x: 0, y: -2 });
    expect(hit?.shape).toBe(shape);
    expect(hit?.fraction).toBeCloseTo(0.5, 12);
    expect(hit?.normal.y).toBeCloseTo(1, 12);
    expect(world.castRay({ x: 0.5, y: -1 }, { x: 0, y: 2 })).toBeNull();
    // a cast shape likewise: stopped from the front 0.2 m down (its radius above the line), passing
    // from behind
    const disc = Shape.circle(0.2);
    const cast = world.castShape(disc, { position: { x: 0, y: 1 } }, { x: 0, y: -2 });
    expect(cast?.shape).toBe(shape);
    expect(cast?.fraction).toBeCloseTo(0.4, 2);
    expect(world.castShape(disc, { position: { x: 0, y: -1 } }, { x: 0, y: 2 })).toBeNull();
    expect(world.queryAABB({ lowerBound: { x: -0.1, y: -0.1 }, upperBound: { x: 0.1, y: 0.1 } })).toEqual([
      shape,
    ]);
  });
});

describe('Shape.chain: arguments', () => {
  it('refuses bad points with a FulcrumError that names them', () => {
    expect(() => Shape.chain([{ x: 0, y: 0 }])).toThrow(FulcrumError);
    expect(() =>
      Shape.chain(
        [
          { x: 0, y: 0 },
          { x: 1, y: 0 },
        ],
        { loop: true },
      ),
    ).toThrow(/points/);
    expect(() =>
      Shape.chain([
        { x: 0, y: 0 },
        { x: 1, y: 0 },
        { x: 1, y: 0 },
      ]),
    ).toThrow(/points\[2\]/);
    expect(() =>
      Shape.chain([
        { x: 0, y: 0 },
        { x: Number.NaN, y: 0 },
      ]),
    ).toThrow(/points\[1\]/);
    expect(() => Shape.chain(floorPoints(1, 0, 2), { loop: 'yes' as unknown as boolean })).toThrow(/loop/);
  });

  it('refuses a hand-made segment whose ends coincide or whose neighbour sits on its end', () => {
    const world = new World();
    const ground = world.createBody();
    const p = Object.freeze({ x: 1, y: 1 });
    const segment = (q: object) =>
      Object.freeze({
        type: 'segment',
        kind: 2,
        point1: p,
        point2: Object.freeze({ x: 2, y: 1 }),
        oneSided: true,
        ghost1: null,
        ghost2: null,
        ...q,
      });
    expect(() => ground.createShape(segment({ point2: p }) as never)).toThrow(FulcrumError);
    expect(() => ground.createShape(segment({ ghost1: p }) as never)).toThrow(FulcrumError);
    expect(() =>
      ground.createShape(segment({ oneSided: false, ghost1: Object.freeze({ x: 0, y: 0 }) }) as never),
    ).toThrow(FulcrumError);
    expect(ground.shapes).toHaveLength(0);
    expect(ground.createShape(segment({}) as never)).toBeDefined();
  });

  it('a dynamic body refuses a chain and is left as it was', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    body.createShape(Shape.circle(0.5));
    const mass = body.mass;
    expect(() => body.createShape(Shape.chain(floorPoints(1, -1, 4)))).toThrow(/static or kinematic/);
    expect([...body.shapes]).toHaveLength(1);
    expect(body.mass).toBe(mass);
  });

  it('a mirrored chain keeps facing the way the mirror carries its front', () => {
    // ground drawn right to left faces up; mirrored in x it runs left to right and still faces up,
    // mirrored in y it is upside down and faces down
    for (const [factor, landsAt] of [
      [{ x: -1, y: 1 }, 0.5],
      [{ x: 1, y: -1 }, null],
    ] as const) {
      const world = new World();
      const ground = world.createBody();
      ground.createShape(Shape.chain(floorPoints(3, -3, 6)));
      ground.scale(factor, { x: 0, y: 0 });
      const box = world.createBody({ type: 'dynamic', position: { x: 0.3, y: 2 } });
      box.createShape(Shape.box(0.5, 0.5));
      run(world, 2);
      if (landsAt === null) expect(box.position.y).toBeLessThan(-5);
      else expect(box.position.y).toBeCloseTo(landsAt, 2);
    }
  });

  it('a chain world restores from a snapshot and steps to the same bits', () => {
    const make = () => {
      const { world } = chainFloor(50, 0.4);
      for (let i = 0; i < 5; i++) {
        const b = world.createBody({ type: 'dynamic', position: { x: i, y: 1 + i }, angle: 0.3 * i });
        b.createShape(
          i % 2 === 0 ? Shape.box(0.2, 0.1) : Shape.capsule({ x: -0.2, y: 0 }, { x: 0.2, y: 0 }, 0.1),
        );
      }
      return world;
    };
    const world = make();
    run(world, 0.5);
    const copy = World.restore(world.snapshot());
    run(world, 1);
    run(copy, 1);
    expect(stateHash(copy)).toBe(stateHash(world));
  });
});

describe('svgShapes', () => {
  it('makes a concave shape of each closed subpath and ground facing up of each open one', () => {
    // y down as drawn, flipped upright: an L and a terrain drawn left to right, then one drawn right to left
    const shapes = svgShapes('M0 0 h2 v-1 h-1 v-1 h-1 z M-10 5 L10 5 M10 8 L-10 8', { flipY: true });
    expect(shapes.map((s) => s.type)).toEqual(['concave', 'chain', 'chain']);
    const [l, drawnRight, drawnLeft] = shapes as [Concave, Chain, Chain];
    expect(l.pieces).toHaveLength(2);
    // both chains run right to left: they face up
    expect(drawnRight.points[0]).toEqual({ x: 10, y: -5 });
    expect(drawnLeft.points[0]).toEqual({ x: 10, y: -8 });
    const world = new World();
    world.createBody().createShape(drawnRight);
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: -3 } });
    box.createShape(l);
    run(world, 2);
    // the L's lowest edge, 0 in the drawing (y = 0 flipped), rests on the line y = -5
    expect(box.getWorldPoint({ x: 0, y: 0 }).y).toBeCloseTo(-5, 2);
  });
});
