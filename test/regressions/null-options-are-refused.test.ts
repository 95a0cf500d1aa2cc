import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, stateHash, World } from '../../src/index';

/**
 * Found by the API fuzzer (test/property, tame seeds 1008, 2003, 2004, 4004, 4005): `null` where an
 * option object or an option value is expected is taken as "not given" by the `??` defaults, where every
 * other wrong value is refused: `createBody({ type: null })` makes a static body,
 * `body.createShape(geometry, null)` a shape with the default options, and a filter's
 * `categoryBits: null` or `maskBits: null` the default bits. (`createBody(null)` is refused.) API.md:
 * every public function validates its arguments; null is not a body type, a shape definition or a mask.
 */
function refuses(world: World, f: () => unknown, argument: RegExp): void {
  const hash = stateHash(world);
  const bodies = world.bodyCount;
  expect(f).toThrow(FulcrumError);
  expect(f).toThrow(argument);
  expect(stateHash(world)).toBe(hash);
  expect(world.bodyCount).toBe(bodies);
}

describe('null options', () => {
  it('createBody({ type: null }) is refused', () => {
    const world = new World();
    refuses(world, () => world.createBody({ type: null as never }), /type/);
  });

  it('createShape(geometry, null) is refused', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    refuses(world, () => body.createShape(Shape.circle(1), null as never), /def/);
    expect(body.shapes).toHaveLength(0);
  });

  it('a filter with categoryBits or maskBits null is refused', () => {
    const world = new World();
    const body = world.createBody({ type: 'dynamic' });
    const shape = body.createShape(Shape.circle(1));
    for (const filter of [{ categoryBits: null }, { maskBits: null }]) {
      refuses(world, () => body.createShape(Shape.circle(1), { filter: filter as never }), /filter/);
      refuses(
        world,
        () => {
          shape.filter = filter as never;
        },
        /filter/,
      );
      expect(shape.filter).toEqual({ categoryBits: 1, maskBits: 0xffffffff, groupIndex: 0 });
    }
    expect(body.shapes).toHaveLength(1);
  });
});
