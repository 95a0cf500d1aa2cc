import { describe, expect, it } from 'vitest';
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { sceneBuilders } from '../../scenes/index';
import { createRandom } from '../../scenes/random';
import { type Body, Shape, World } from '../../src/index';

const DT = 1 / 60;

/** signed distance of a point from the wall's mid-plane, along the wall's normal (x axis of the wall) */
function alongNormal(wall: Body, p: { x: number; y: number }): number {
  const c = Math.cos(wall.angle);
  const s = Math.sin(wall.angle);
  return c * (p.x - wall.position.x) + s * (p.y - wall.position.y);
}

/**
 * A 0.1 m ball (radius 0.05) at 300 m/s (5 m per step) toward a 0.1 m thick, 10 m long static wall
 * turned by `wallAngle`, approaching at `approach` radians from the normal and aimed `aim` metres
 * along the wall from its centre, starting `distance` metres from the wall's face. Returns the
 * deepest point the ball's centre reached along the wall's normal (the near face is at -0.05) and
 * where it ended.
 */
function ballAtWall(
  continuous: boolean,
  friction: number,
  wallAngle: number,
  approach: number,
  aim: number,
  distance: number,
): { deepest: number; last: number } {
  const world = new World({ gravity: { x: 0, y: 0 }, enableContinuous: continuous });
  const wall = world.createBody({ position: { x: 2, y: -1 }, angle: wallAngle });
  wall.createShape(Shape.box(0.05, 5));
  const c = Math.cos(wallAngle);
  const s = Math.sin(wallAngle);
  // in the wall frame: normal n = (1, 0) -> world (c, s); along t = (0, 1) -> world (-s, c)
  const hitLocalX = -0.05 - 0.05;
  const dirLocalX = Math.cos(approach);
  const dirLocalY = Math.sin(approach);
  const startLocalX = hitLocalX - distance * dirLocalX;
  const startLocalY = aim - distance * dirLocalY;
  const toWorld = (x: number, y: number) => ({ x: 2 + c * x - s * y, y: -1 + s * x + c * y });
  const start = toWorld(startLocalX, startLocalY);
  const dir = { x: c * dirLocalX - s * dirLocalY, y: s * dirLocalX + c * dirLocalY };
  const ball = world.createBody({
    type: 'dynamic',
    position: start,
    linearVelocity: { x: 300 * dir.x, y: 300 * dir.y },
  });
  ball.createShape(Shape.circle(0.05), { friction });
  let deepest = Number.NEGATIVE_INFINITY;
  const steps = Math.ceil(distance / 5) + 4;
  for (let i = 0; i < steps; i++) {
    world.step(DT);
    deepest = Math.max(deepest, alongNormal(wall, ball.position));
  }
  return { deepest, last: alongNormal(wall, ball.position) };
}

describe('continuous collision against static shapes', () => {
  it('a 0.1 m ball at 300 m/s never passes a 0.1 m thick wall, at 1,000 random offsets and angles', () => {
    const random = createRandom(4);
    let worst = Number.NEGATIVE_INFINITY;
    let passedWithoutContinuous = 0;
    for (let i = 0; i < 1000; i++) {
      const wallAngle = random.range(-Math.PI, Math.PI);
      const approach = random.range(-1.2, 1.2); // up to ~69 degrees from the normal
      const aim = random.range(-3, 3);
      const distance = random.range(0.2, 12);
      const { deepest, last } = ballAtWall(true, 0, wallAngle, approach, aim, distance);
      worst = Math.max(worst, deepest);
      // the centre stops a radius before the face (-0.05 - 0.05), less the linear slop, and stays there
      expect(deepest).toBeLessThan(-0.1 + 0.005 + 1e-9);
      expect(last).toBeLessThan(-0.1 + 0.005 + 1e-9);
      if (i < 100 && ballAtWall(false, 0, wallAngle, approach, aim, distance).last > 0.05)
        passedWithoutContinuous++;
    }
    expect(worst).toBeGreaterThan(-0.1 - 1e-9); // the balls do reach the wall
    // the scenario is a real test: without continuous collision most balls pass through
    expect(passedWithoutContinuous).toBeGreaterThan(50);
  });

  it('with the default friction 0.6 the same 1,000 balls never get through either', () => {
    const random = createRandom(4);
    for (let i = 0; i < 1000; i++) {
      const wallAngle = random.range(-Math.PI, Math.PI);
      const approach = random.range(-1.2, 1.2);
      const aim = random.range(-3, 3);
      const distance = random.range(0.2, 12);
      const { deepest, last } = ballAtWall(true, 0.6, wallAngle, approach, aim, distance);
      // an oblique hit spins the ball up fast; it still stops within 1 cm of touching the face
      expect(deepest).toBeLessThan(-0.1 + 0.01);
      expect(last).toBeLessThan(-0.1 + 0.01);
    }
  });

  it('with friction, a fast oblique ball does not sink into the wall (spinning contact anchor)', () => {
    // regression: trial 8 of the random set above, with friction 0.6. The ball spins up to the
    // rotation limit; when the solver turned the contact anchor with the ball (a ball's contact point
    // does not turn with it) the ball sank ~3 cm into the wall. Separation is now tracked on the core.
    const { deepest } = ballAtWall(
      true,
      0.6,
      -2.3806257004903184,
      -0.18954354152083397,
      2.2246450572274625,
      4.419613232510165,
    );
    expect(deepest).toBeLessThan(-0.1 + 0.01);
  });

  it('a thin rod spinning at 50 rad/s next to a wall does not pass through it', () => {
    for (const continuous of [true, false]) {
      const world = new World({ gravity: { x: 0, y: 0 }, enableContinuous: continuous });
      const wall = world.createBody({ position: { x: 0.8, y: 0 } });
      wall.createShape(Shape.box(0.05, 3)); // faces at x = 0.75 and 0.85
      // a 2 m long, 2 cm thick rod: its tip moves 50 m/s, 0.83 m per step, through a 0.1 m wall
      const rod = world.createBody({
        type: 'dynamic',
        position: { x: 0, y: 0 },
        angle: 1.3,
        angularVelocity: 50,
      });
      rod.createShape(Shape.box(1, 0.01));
      let beyond = Number.NEGATIVE_INFINITY;
      let ends = 0;
      for (let i = 0; i < 120; i++) {
        world.step(DT);
        for (const x of [-1, 1]) beyond = Math.max(beyond, rod.getWorldPoint({ x, y: 0 }).x);
        ends = Math.max(rod.getWorldPoint({ x: -1, y: 0 }).x, rod.getWorldPoint({ x: 1, y: 0 }).x);
      }
      if (continuous) {
        // the tip never gets more than a slop into the wall, and the rod ends on its side
        expect(beyond).toBeLessThan(0.75 + 0.02);
        expect(ends).toBeLessThan(0.75 + 0.02);
        expect(rod.position.x).toBeLessThan(0.75);
      } else {
        // without continuous collision the spinning tip goes through the wall
        expect(beyond).toBeGreaterThan(0.85);
      }
    }
  });
});

describe('bullets', () => {
  function gun(bullet: boolean, continuous = true) {
    const world = new World({ gravity: { x: 0, y: 0 }, enableContinuous: continuous });
    const plank = world.createBody({ type: 'dynamic', position: { x: 6, y: 0 } });
    plank.createShape(Shape.box(0.05, 1), { density: 1 }); // 0.1 m thick, 2 m tall, 0.2 kg
    const shot = world.createBody({
      type: 'dynamic',
      position: { x: 0, y: 0 },
      linearVelocity: { x: 300, y: 0 },
      bullet,
    });
    shot.createShape(Shape.circle(0.05), { density: 20 }); // 0.157 kg
    return { world, plank, shot };
  }

  it('a bullet at 300 m/s hits a 0.1 m thick dynamic plank and moves it', () => {
    const { world, plank, shot } = gun(true);
    const p0 = shot.mass * 300;
    let maxShotX = Number.NEGATIVE_INFINITY;
    for (let i = 0; i < 30; i++) {
      world.step(DT);
      maxShotX = Math.max(maxShotX, shot.position.x - plank.position.x);
    }
    // the bullet stays in front of the plank's face (x - 0.05) by its radius, less a slop
    expect(maxShotX).toBeLessThan(-0.1 + 0.01);
    // momentum is conserved: plank and bullet share it (perfectly inelastic, restitution 0)
    const p1 = shot.mass * shot.linearVelocity.x + plank.mass * plank.linearVelocity.x;
    expect(Math.abs(p1 - p0) / p0).toBeLessThan(1e-6);
    const shared = p0 / (shot.mass + plank.mass);
    expect(plank.linearVelocity.x).toBeGreaterThan(0.9 * shared);
    expect(plank.position.x).toBeGreaterThan(6 + 0.2);
  });

  it('without bullet (or with continuous off) the same shot passes through the plank', () => {
    for (const [bullet, continuous] of [
      [false, true],
      [true, false],
    ]) {
      const { world, plank, shot } = gun(bullet, continuous);
      for (let i = 0; i < 5; i++) world.step(DT);
      expect(shot.position.x).toBeGreaterThan(plank.position.x + 1);
      expect(plank.linearVelocity.x).toBe(0);
    }
  });

  it('a bullet tied to the plank by a joint without collideConnected flies through it', () => {
    const { world, plank, shot } = gun(true);
    // a slack rope (a spring of 0 Hz, at most 40 m): it never pulls in these 5 steps (the ends get
    // at most 19 m apart), it only forbids contact between them
    world.createJoint({
      type: 'distance',
      bodyA: plank,
      bodyB: shot,
      enableSpring: true,
      hertz: 0,
      minLength: 0,
      maxLength: 40,
    });
    for (let i = 0; i < 5; i++) world.step(DT);
    // unhindered flight: 5 steps of 5 m each
    expect(shot.position.x).toBeCloseTo(25, 9);
    expect(plank.linearVelocity.x).toBe(0);
  });

  it('a bullet stops at a kinematic plank moving across its path', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const plank = world.createBody({
      type: 'kinematic',
      position: { x: 6, y: 0 },
      linearVelocity: { x: 0, y: 1 },
    });
    plank.createShape(Shape.box(0.05, 1));
    const shot = world.createBody({ type: 'dynamic', linearVelocity: { x: 300, y: 0 }, bullet: true });
    shot.createShape(Shape.circle(0.05));
    let maxShotX = Number.NEGATIVE_INFINITY;
    for (let i = 0; i < 10; i++) {
      world.step(DT);
      maxShotX = Math.max(maxShotX, shot.position.x - plank.position.x);
    }
    expect(maxShotX).toBeLessThan(-0.1 + 0.01);
  });
});

describe('continuous-collision scenes', () => {
  function escaped(
    name: 'bullets' | 'spinning-bar' | 'high-drop',
    seconds: number,
    continuous = true,
  ): number {
    const scene = sceneBuilders[name]();
    const { bodies } = buildFulcrumWorld(scene, { enableContinuous: continuous });
    const world = bodies[0].world;
    const box = scene.containment!;
    let out = 0;
    const gone = new Set<number>();
    for (let i = 0; i < Math.round(seconds * 60); i++) {
      world.step(DT);
      bodies.forEach((b, k) => {
        const p = b.position;
        if (
          b.type === 'dynamic' &&
          (p.x < box.lower.x || p.x > box.upper.x || p.y < box.lower.y || p.y > box.upper.y)
        )
          gone.add(k);
      });
    }
    out = gone.size;
    return out;
  }

  it('bullets: every bullet stays in front of the backstop and nothing falls through the ground', () => {
    expect(escaped('bullets', 2)).toBe(0);
    expect(escaped('bullets', 2, false)).toBeGreaterThan(0);
  });

  it('bullets scene varied: planks knocked spinning into the 0.1 m backstop never pass through it', () => {
    // 24 variants (bullet speed, plank places): planks hit at 30-60 m/s reach the backstop spinning
    // at up to 45 rad/s. Before the disc's sinking check, 7 of these 24 variants lost a plank through
    // the wall: the swept core pinned in front of it one step, the plank through it the next.
    let through = 0;
    for (let v = 0; v < 24; v++) {
      const scene = sceneBuilders.bullets();
      let plank = 0;
      for (const b of scene.bodies) {
        if (b.tag === 'bullet') b.linearVelocity = { x: 280 + v, y: 0 };
        if (b.tag === 'plank') b.position = { x: b.position.x + ((v * 7 + plank++ * 3) % 10) * 0.03, y: 1 };
      }
      const { bodies } = buildFulcrumWorld(scene, { enableContinuous: true });
      const world = bodies[0].world;
      const crossed = new Set<number>();
      for (let i = 0; i < 120; i++) {
        world.step(DT);
        // beyond the backstop's far face (x 30.05) below its top (y 20): through it, not over it
        bodies.forEach((b, k) => {
          if (b.type === 'dynamic' && b.position.x > 30.05 && b.position.y < 20) crossed.add(k);
        });
      }
      through += crossed.size;
    }
    expect(through).toBe(0);
  });

  it('a thin plank sliding fast over a floor of tiles goes as far as without continuous collision', () => {
    // a plank 1 cm thick: its core disc touches the floor at rest, and at a seam the next tile's
    // nearest feature is its corner (a check on the normal to it froze the plank where it was)
    const tiles = (world: World) => {
      const ground = world.createBody();
      for (let i = -4; i < 12; i++)
        ground.createShape(Shape.box(0.25, 0.25, { x: 0.5 * i, y: -0.25 }), { friction: 0 });
    };
    const slide = (continuous: boolean) => {
      const world = new World({ enableContinuous: continuous });
      tiles(world);
      const plank = world.createBody({ type: 'dynamic', position: { x: -1.003, y: 0.005 } });
      plank.createShape(Shape.box(0.3, 0.005), { friction: 0 });
      plank.setLinearVelocity({ x: 2, y: 0 });
      for (let i = 0; i < 30; i++) world.step(DT);
      return plank.position.x;
    };
    // frictionless at 2 m/s: it went 0.45 m to the seam at -0.25, where its square end catches on the
    // next tile's side (continuous or not: the internal-edge problem of separate tiles); a check on
    // the normal to the nearest feature froze it at a seam before, 0.2 m short
    const free = slide(false);
    expect(free).toBeGreaterThan(-0.6);
    expect(Math.abs(slide(true) - free)).toBeLessThan(0.01);
  });

  it('spinning bar: the bar stays inside its walls', () => {
    expect(escaped('spinning-bar', 3)).toBe(0);
  });

  it('high drop: balls hitting a 0.1 m plate at ~170 m/s stay above it', () => {
    expect(escaped('high-drop', 8.5)).toBe(0);
    expect(escaped('high-drop', 8.5, false)).toBeGreaterThan(0);
  });
});
