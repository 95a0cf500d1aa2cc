import { type Body, Shape, World, type WorldDef } from '../../src/index';

/** Steps `world` for `seconds` at 60 Hz, calling `each` after every step. */
export function run(world: World, seconds: number, each?: (t: number) => void): void {
  const steps = Math.round(seconds * 60);
  for (let i = 1; i <= steps; i++) {
    world.step(1 / 60);
    each?.(i / 60);
  }
}

/**
 * Like run(), but yields to the event loop every simulated second so that long tests do not starve
 * the test runner's worker messages.
 */
export async function runYielding(world: World, seconds: number): Promise<void> {
  for (let t = 0; t < seconds; t++) {
    run(world, Math.min(1, seconds - t));
    await new Promise((resolve) => setImmediate(resolve));
  }
}

/** A world with a static ground box whose top surface is y = 0. */
export function groundWorld(
  def: WorldDef = {},
  friction = 0.6,
  restitution = 0,
): { world: World; ground: Body } {
  const world = new World(def);
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  ground.createShape(Shape.box(100, 1), { friction, restitution });
  return { world, ground };
}

/** A pyramid of 1 m boxes, `base` wide, standing on y = 0 around x = 0, bottom row first. */
export function pyramid(world: World, base: number): Body[] {
  const boxes: Body[] = [];
  for (let row = 0; row < base; row++) {
    for (let i = 0; i < base - row; i++) {
      const b = world.createBody({
        type: 'dynamic',
        position: { x: i - (base - row - 1) / 2, y: 0.5 + row },
      });
      b.createShape(Shape.box(0.5, 0.5));
      boxes.push(b);
    }
  }
  return boxes;
}

export function dist(a: { x: number; y: number }, b: { x: number; y: number }): number {
  return Math.sqrt((a.x - b.x) ** 2 + (a.y - b.y) ** 2);
}

/** Linear momentum and angular momentum about (ox, oy) of `bodies`. */
export function momentum(bodies: readonly Body[], ox = 0, oy = 0): { px: number; py: number; l: number } {
  let px = 0;
  let py = 0;
  let l = 0;
  for (const b of bodies) {
    const v = b.linearVelocity;
    const c = b.worldCenter;
    px += b.mass * v.x;
    py += b.mass * v.y;
    l += b.inertia * b.angularVelocity + b.mass * ((c.x - ox) * v.y - (c.y - oy) * v.x);
  }
  return { px, py, l };
}
