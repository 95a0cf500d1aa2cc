import { afterEach, describe, expect, it, vi } from 'vitest';
import { FulcrumError, Shape, ShapeHandle, stateHash, type WarningEvent, World } from '../../src/index';
import { groundWorld, pyramid, run } from '../helpers/world';

/**
 * `count` dynamic boxes and circles of 0.5 m (boxes only if `boxesOnly`) created within 1 cm of one
 * point, 2 m above the ground (a golden-angle spiral, so that the crowd has no exact symmetry).
 */
function crowd(count: number, boxesOnly = false): World {
  const { world } = groundWorld();
  for (let i = 0; i < count; i++) {
    const angle = i * 2.399963;
    const r = 0.01 * Math.sqrt(i / count);
    const body = world.createBody({
      type: 'dynamic',
      position: { x: r * Math.cos(angle), y: 2 + r * Math.sin(angle) },
    });
    body.createShape(boxesOnly || i % 2 === 0 ? Shape.box(0.25, 0.25) : Shape.circle(0.25));
  }
  return world;
}

/** The largest count of contacts that count against one shape (see src/world/contact-limit.ts). */
function maxLoad(world: World): number {
  const shapes = world.core.shapes;
  let max = 0;
  for (let s = 0; s < shapes.slotCount; s++)
    if (shapes.alive[s] !== 0) max = Math.max(max, shapes.contactLoad[s]);
  return max;
}

/** The deepest overlap of any contact point, in metres. */
function deepestOverlap(world: World): number {
  const contacts = world.core.contacts;
  let deepest = 0;
  for (let c = 0; c < contacts.slotCount; c++) {
    if (contacts.alive[c] === 0) continue;
    for (let j = 0; j < contacts.pointCount[c]; j++)
      deepest = Math.max(deepest, -contacts.separation[2 * c + j]);
  }
  return deepest;
}

afterEach(() => {
  vi.restoreAllMocks();
});

describe('crowds (bodies created on one spot)', () => {
  it('hold at most maxContactsPerShape contacts a shape: n equal shapes at most 16 n contacts, plus the ground', () => {
    const n = 200;
    // equal shapes: each contact between two of them counts against both
    const world = crowd(n, true);
    world.on('warning', () => {});
    expect(world.maxContactsPerShape).toBe(32);
    let peak = 0;
    run(world, 1, () => {
      // every pair of the crowd overlaps at first: n (n - 1) / 2 = 19,900 pairs without the limit
      expect(world.contactCount).toBeLessThanOrEqual((32 * n) / 2 + n);
      expect(maxLoad(world)).toBeLessThanOrEqual(32);
      peak = Math.max(peak, world.contactCount);
    });
    expect(peak).toBeGreaterThan(n);
  });

  it('come apart: every overlap resolved within a few seconds, no shape left waiting for a contact', () => {
    const world = crowd(200);
    world.on('warning', () => {});
    run(world, 0.1);
    expect(world.crowdedShapeCount).toBeGreaterThan(0);
    expect(deepestOverlap(world)).toBeGreaterThan(0.25);
    run(world, 5.9);
    expect(world.crowdedShapeCount).toBe(0);
    // the contacts' own slop and the speculative distance: 5 mm + 2 cm
    expect(deepestOverlap(world)).toBeLessThan(0.025);
  });

  it("warn once with a 'warning' event naming the limit and a shape, and in world.events", () => {
    const world = crowd(200);
    const warnings: WarningEvent[] = [];
    world.on('warning', (w) => warnings.push(w));
    world.step(1 / 60);
    const limit = warnings.find((w) => w.type === 'contactLimit');
    expect(limit).toBeDefined();
    expect(limit!.limit).toBe(32);
    expect(limit!.count).toBe(world.crowdedShapeCount);
    expect(limit!.shape).toBeInstanceOf(ShapeHandle);
    expect(limit!.shape!.body.type).toBe('dynamic');
    expect(limit!.message).toContain('maxContactsPerShape');
    expect(world.events.warning).toEqual(warnings);
    const first = warnings.length;
    run(world, 1);
    // the crowd is still there: no new contactLimit warning
    expect(warnings.slice(first).filter((w) => w.type === 'contactLimit')).toEqual([]);
  });

  it('warn on the console when no handler listens', () => {
    const spy = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const world = crowd(100);
    world.step(1 / 60);
    expect(spy).toHaveBeenCalled();
    expect(String(spy.mock.calls[0][0])).toMatch(/^Fulcrum: \d+ shapes reached the limit of 32 contacts/);
  });

  it('are deterministic, also across a snapshot taken in the middle of the crowd', () => {
    const a = crowd(150);
    const b = crowd(150);
    a.on('warning', () => {});
    b.on('warning', () => {});
    run(a, 0.1);
    run(b, 0.1);
    expect(stateHash(b)).toBe(stateHash(a));
    expect(a.crowdedShapeCount).toBeGreaterThan(0);
    const restored = World.restore(a.snapshot());
    restored.on('warning', () => {});
    run(a, 1);
    run(b, 1);
    run(restored, 1);
    expect(stateHash(b)).toBe(stateHash(a));
    expect(stateHash(restored)).toBe(stateHash(a));
    expect(restored.contactCount).toBe(a.contactCount);
    expect(restored.crowdedShapeCount).toBe(a.crowdedShapeCount);
  });
});

describe('the contact limit', () => {
  it('leaves scenes of shapes that do not overlap alone: no warning, no shape at the limit', () => {
    const { world } = groundWorld();
    pyramid(world, 20);
    const warn = vi.spyOn(console, 'warn');
    run(world, 3, () => expect(world.crowdedShapeCount).toBe(0));
    expect(maxLoad(world)).toBeLessThan(32);
    expect(warn).not.toHaveBeenCalled();
  });

  it('does not limit a large shape: a plank carries 24 boxes with the limit at 4', () => {
    const { world } = groundWorld();
    world.maxContactsPerShape = 4;
    const plank = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.1 } });
    plank.createShape(Shape.box(6.5, 0.1));
    const boxes = [];
    for (let i = 0; i < 24; i++) {
      const box = world.createBody({ type: 'dynamic', position: { x: -5.75 + 0.5 * i, y: 0.4 } });
      box.createShape(Shape.box(0.2, 0.2));
      boxes.push(box);
    }
    const warnings: WarningEvent[] = [];
    world.on('warning', (w) => warnings.push(w));
    run(world, 2);
    expect(warnings).toEqual([]);
    // resting on the plank's top (y = 0.2): centres at 0.4, less the contacts' slop
    for (const box of boxes) expect(Math.abs(box.position.y - 0.4)).toBeLessThan(0.01);
  });

  it('keeps the nearest pairs: a pile of 3 cm grains at a limit of 8 settles as high as without limit', () => {
    const pile = (limit: number) => {
      const world = new World({ enableSleep: false });
      world.maxContactsPerShape = limit;
      const warnings: WarningEvent[] = [];
      world.on('warning', (w) => warnings.push(w));
      const container = world.createBody({});
      container.createShape(Shape.box(0.7, 0.05, { x: 0, y: -0.05 }));
      container.createShape(Shape.box(0.05, 1, { x: -0.65, y: 1 }));
      container.createShape(Shape.box(0.05, 1, { x: 0.65, y: 1 }));
      for (let row = 0; row < 12; row++) {
        for (let col = 0; col < 18; col++) {
          const grain = world.createBody({
            type: 'dynamic',
            position: { x: -0.55 + col * 0.065 + (row % 2) * 0.01, y: 0.05 + row * 0.07 },
          });
          grain.createShape((row + col) % 2 === 1 ? Shape.circle(0.03) : Shape.box(0.03, 0.024));
        }
      }
      let peakLoad = 0;
      run(world, 3, () => {
        peakLoad = Math.max(peakLoad, maxLoad(world));
      });
      let top = Number.NEGATIVE_INFINITY;
      for (const body of world.bodies) if (body.type === 'dynamic') top = Math.max(top, body.position.y);
      return { top, peakLoad, contacts: world.contactCount, warnings };
    };
    const free = pile(16777215);
    const limited = pile(8);
    // the 10 cm margin of the broad phase gives each grain up to ~100 pairs, a few of them touching
    expect(free.peakLoad).toBeGreaterThan(40);
    expect(limited.peakLoad).toBe(8);
    expect(limited.contacts).toBeLessThan(free.contacts / 3);
    expect(limited.warnings).toEqual([]);
    // a grain that passed through another would lower the pile by a grain: under half a radius
    expect(Math.abs(limited.top - free.top)).toBeLessThan(0.015);
  });

  it('never refuses a dynamic shape its contact with the ground', () => {
    const world = crowd(60);
    world.maxContactsPerShape = 2;
    world.on('warning', () => {});
    run(world, 4, () => {
      for (const body of world.bodies) {
        if (body.type === 'dynamic') expect(body.position.y).toBeGreaterThan(-0.25);
      }
    });
  });

  it('maxContactsPerShape takes an integer from 1 to 16,777,215 and refuses anything else unchanged', () => {
    const world = new World();
    world.maxContactsPerShape = 1;
    world.maxContactsPerShape = 16777215;
    for (const bad of [0, -3, 2.5, Number.NaN, Number.POSITIVE_INFINITY, 16777216, '8', null]) {
      expect(() => {
        (world as { maxContactsPerShape: unknown }).maxContactsPerShape = bad;
      }).toThrow(FulcrumError);
      expect(world.maxContactsPerShape).toBe(16777215);
    }
    expect(() => {
      (world as { maxContactsPerShape: unknown }).maxContactsPerShape = 0;
    }).toThrow(/maxContactsPerShape must be an integer in \[1, 16777215\], got 0/);
  });
});
