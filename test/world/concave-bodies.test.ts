import { describe, expect, it } from 'vitest';
import { type Body, type Concave, Shape, ShapeHandle, stateHash, World } from '../../src/index';
import { expectRejected } from '../helpers/rejects';
import { groundWorld, run } from '../helpers/world';

type V = { x: number; y: number };

/**
 * Mass properties of a simple polygon of uniform density from its outline alone (shoelace area, first
 * and second moments of the triangles from the first point), inertia about the centre of mass.
 */
function outlineMass(points: readonly V[], density: number): { mass: number; center: V; inertia: number } {
  const o = points[0];
  let area = 0;
  let mx = 0;
  let my = 0;
  let polar = 0;
  for (let i = 0; i < points.length; i++) {
    const ax = points[i].x - o.x;
    const ay = points[i].y - o.y;
    const bx = points[(i + 1) % points.length].x - o.x;
    const by = points[(i + 1) % points.length].y - o.y;
    const cross = ax * by - bx * ay;
    area += cross / 2;
    mx += (cross * (ax + bx)) / 6;
    my += (cross * (ay + by)) / 6;
    polar += (cross * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by)) / 12;
  }
  const sign = Math.sign(area);
  const cx = mx / area;
  const cy = my / area;
  return {
    mass: density * sign * area,
    center: { x: o.x + cx, y: o.y + cy },
    inertia: density * sign * (polar - area * (cx * cx + cy * cy)),
  };
}

function expectRelative(actual: number, expected: number, tolerance: number): void {
  expect(Math.abs(actual - expected)).toBeLessThanOrEqual(tolerance * Math.abs(expected));
}

function expectMassOf(body: Body, expected: { mass: number; center: V; inertia: number }): void {
  const size = Math.sqrt(expected.inertia / expected.mass); // radius of gyration: the scale of the centre
  expectRelative(body.mass, expected.mass, 1e-9);
  expectRelative(body.inertia, expected.inertia, 1e-9);
  expect(Math.abs(body.localCenter.x - expected.center.x)).toBeLessThanOrEqual(1e-9 * size);
  expect(Math.abs(body.localCenter.y - expected.center.y)).toBeLessThanOrEqual(1e-9 * size);
}

// the L: its hull would have area 2.875
const L: V[] = [
  { x: 0, y: 0 },
  { x: 2, y: 0 },
  { x: 2, y: 0.5 },
  { x: 0.5, y: 0.5 },
  { x: 0.5, y: 2 },
  { x: 0, y: 2 },
];

function star(points: number, outer: number, inner: number): V[] {
  return Array.from({ length: 2 * points }, (_, i) => {
    const r = i % 2 === 0 ? outer : inner;
    const a = Math.PI / 2 + (Math.PI * i) / points;
    return { x: r * Math.cos(a), y: r * Math.sin(a) };
  });
}

/** A ring sector from angle 0 to `sweep`, each arc as `segments` edges, clockwise (the other winding). */
function ringSector(inner: number, outer: number, sweep: number, segments: number): V[] {
  const points: V[] = [];
  for (let i = segments; i >= 0; i--) {
    const a = (sweep * i) / segments;
    points.push({ x: outer * Math.cos(a), y: outer * Math.sin(a) });
  }
  for (let i = 0; i <= segments; i++) {
    const a = (sweep * i) / segments;
    points.push({ x: inner * Math.cos(a), y: inner * Math.sin(a) });
  }
  return points;
}

describe('concave bodies', () => {
  it('an L: mass, centre of mass and inertia of the outline (two rectangles and the parallel axis theorem)', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic', position: { x: 3, y: -2 }, angle: 0.7 });
    body.createShape(Shape.concave(L), { density: 2 });
    // [0, 2] x [0, 0.5] and [0, 0.5] x [0.5, 2] at 2 kg/m²
    const m1 = 2 * 1;
    const m2 = 2 * 0.75;
    const c1 = { x: 1, y: 0.25 };
    const c2 = { x: 0.25, y: 1.25 };
    const mass = m1 + m2;
    const center = { x: (m1 * c1.x + m2 * c2.x) / mass, y: (m1 * c1.y + m2 * c2.y) / mass };
    const inertia =
      (m1 * (2 * 2 + 0.5 * 0.5)) / 12 +
      m1 * ((c1.x - center.x) ** 2 + (c1.y - center.y) ** 2) +
      (m2 * (0.5 * 0.5 + 1.5 * 1.5)) / 12 +
      m2 * ((c2.x - center.x) ** 2 + (c2.y - center.y) ** 2);
    expect(mass).toBe(3.5); // not the hull's 5.75
    expectMassOf(body, { mass, center, inertia });
    expectMassOf(body, outlineMass(L, 2));
  });

  it('a star and a ring sector: mass, centre of mass and inertia of the outline to 1e-9', () => {
    const world = new World();
    for (const outline of [star(5, 1, 0.4), star(7, 2, 1.5), ringSector(0.5, 1, 1.5 * Math.PI, 24)]) {
      const body = world.createBody({ type: 'dynamic', position: { x: -1, y: 4 }, angle: -2 });
      const concave = Shape.concave(outline);
      expect(concave.outline.length).toBe(outline.length); // nothing to clean
      body.createShape(concave, { density: 0.75 });
      expectMassOf(body, outlineMass(outline, 0.75));
    }
  });

  it('several shapes at offsets and angles: the masses add by the parallel axis theorem', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    body.createShape(Shape.box(0.5, 0.1, { x: 1, y: 2 }, 0.3), { density: 3 });
    body.createShape(Shape.circle(0.25, { x: -1, y: 0.5 }), { density: 2 });
    body.createShape(Shape.concave(L), { density: 1 });
    const parts = [
      // 1 m by 0.2 m at 3 kg/m²: m (w² + h²) / 12 about its centre, whatever its angle
      { mass: 3 * 0.2, center: { x: 1, y: 2 }, inertia: (3 * 0.2 * (1 + 0.04)) / 12 },
      {
        mass: 2 * Math.PI * 0.0625,
        center: { x: -1, y: 0.5 },
        inertia: 0.5 * 2 * Math.PI * 0.0625 * 0.0625,
      },
      outlineMass(L, 1),
    ];
    const mass = parts.reduce((s, p) => s + p.mass, 0);
    const center = {
      x: parts.reduce((s, p) => s + p.mass * p.center.x, 0) / mass,
      y: parts.reduce((s, p) => s + p.mass * p.center.y, 0) / mass,
    };
    const inertia = parts.reduce(
      (s, p) => s + p.inertia + p.mass * ((p.center.x - center.x) ** 2 + (p.center.y - center.y) ** 2),
      0,
    );
    expectMassOf(body, { mass, center, inertia });
  });

  it('createShape returns one handle per piece, in order, each with the definition', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    const concave = Shape.concave(star(5, 1, 0.4));
    const handles = body.createShape(concave, { friction: 0.3, restitution: 0.1, userData: 'star' });
    expect(handles.length).toBe(concave.pieces.length);
    expect(body.shapes).toEqual(handles);
    handles.forEach((handle, i) => {
      expect(handle).toBeInstanceOf(ShapeHandle);
      expect(handle.geometry).toBe(concave.pieces[i]);
      expect(handle.body).toBe(body);
      expect(handle.type).toBe('polygon');
      expect(handle.friction).toBe(0.3);
      expect(handle.restitution).toBe(0.1);
      expect(handle.userData).toBe('star');
    });
    // a convex geometry still gives one handle
    expect(body.createShape(Shape.circle(0.1))).toBeInstanceOf(ShapeHandle);
  });

  it('bad input: a FulcrumError and the world exactly as it was', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    body.createShape(Shape.box(0.5, 0.5));
    const concave = Shape.concave(L);
    expectRejected(world, () => body.createShape(concave, { density: -1 }), /density.*-1/);
    expectRejected(world, () => body.createShape(concave, { frction: 1 } as never), /frction/);
    // a hand-made concave shape: not frozen, or with pieces that are not polygons
    const loose = { type: 'concave', outline: concave.outline, pieces: concave.pieces };
    expectRejected(world, () => body.createShape(loose as Concave), /geometry must be/);
    const circles = Object.freeze({
      type: 'concave',
      outline: concave.outline,
      pieces: Object.freeze([Shape.circle(1)]),
    });
    expectRejected(world, () => body.createShape(circles as unknown as Concave), /geometry must be/);
    expect(body.shapes.length).toBe(1);
    expect(body.mass).toBe(1);
    world.destroyBody(body);
    expect(() => body.createShape(concave)).toThrow(/destroyed/);
  });

  it('the pieces of one body never make contacts with one another', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic', angularVelocity: 3 });
    const pieces = body.createShape(Shape.concave(ringSector(0.5, 1, 1.5 * Math.PI, 24)));
    expect(pieces.length).toBeGreaterThan(3); // their boxes overlap: the broad phase pairs them
    let begins = 0;
    world.on('contactBegin', () => begins++);
    run(world, 1, () => expect(world.contactCount).toBe(0));
    expect(begins).toBe(0);
  });

  it('L bodies dropped on the floor stack, come to rest and sleep, as their pieces would as shapes', () => {
    const build = (piecewise: boolean) => {
      const { world } = groundWorld();
      const bodies: Body[] = [];
      const concave = Shape.concave(L);
      for (let i = 0; i < 5; i++) {
        const body = world.createBody({
          type: 'dynamic',
          position: { x: -3 + 1.2 * i, y: 1 + 1.6 * i },
          angle: 0.9 * i,
        });
        if (piecewise) for (const piece of concave.pieces) body.createShape(piece);
        else body.createShape(concave);
        bodies.push(body);
      }
      return { world, bodies };
    };
    const { world, bodies } = build(false);
    const twin = build(true);
    let selfContacts = 0;
    let contacts = 0;
    world.on('contactBegin', (e) => {
      contacts++;
      if (e.bodyA === e.bodyB) selfContacts++;
    });
    let steps = 0;
    while (bodies.some((b) => b.isAwake) && steps < 1200) {
      world.step(1 / 60);
      twin.world.step(1 / 60);
      steps++;
    }
    expect(bodies.every((b) => !b.isAwake)).toBe(true);
    expect(contacts).toBeGreaterThan(5);
    expect(selfContacts).toBe(0);
    // the same shapes on the same bodies: the same bits
    expect(stateHash(world)).toBe(stateHash(twin.world));
    for (const body of bodies) {
      expect(body.shapes.length).toBe(2);
      // at rest above the floor (y = 0), not in it
      const lowest = Math.min(...L.map((p) => body.getWorldPoint(p).y));
      expect(lowest).toBeGreaterThan(-0.02);
      expect(body.position.y).toBeLessThan(8);
    }
  });

  it('a snapshot holds the pieces: the restored world steps to the same bits', () => {
    const { world } = groundWorld();
    const body = world.createBody({ type: 'dynamic', position: { x: 0, y: 2 }, angle: 0.4 });
    body.createShape(Shape.concave(star(5, 1, 0.4)), { density: 2 });
    run(world, 0.5);
    const restored = World.restore(world.snapshot());
    expect([...restored.bodies][1].shapes.length).toBe(body.shapes.length);
    run(world, 1);
    run(restored, 1);
    expect(stateHash(restored)).toBe(stateHash(world));
  });

  it('a static U holds a ball at its bottom, between its arms', () => {
    const { world } = groundWorld();
    const u = world.createBody({ position: { x: 0, y: 0 } });
    u.createShape(
      Shape.concave([
        { x: -1.5, y: 0 },
        { x: 1.5, y: 0 },
        { x: 1.5, y: 2 },
        { x: 1, y: 2 },
        { x: 1, y: 0.5 },
        { x: -1, y: 0.5 },
        { x: -1, y: 2 },
        { x: -1.5, y: 2 },
      ]),
    );
    const ball = world.createBody({ type: 'dynamic', position: { x: 0.3, y: 3 } });
    ball.createShape(Shape.circle(0.4), { restitution: 0.3 });
    run(world, 4);
    expect(ball.position.y).toBeCloseTo(0.9, 2); // on the U's floor (0.5) plus the radius
    expect(Math.abs(ball.position.x)).toBeLessThan(0.6 + 1e-9);
  });
});
