import { expect } from 'vitest';
import { FulcrumError, stateHash, type World } from '../../src/index';

/**
 * Asserts that `f` throws a FulcrumError whose message matches `argument` (the argument's name and
 * value), and that the world is exactly as it was: same state hash and body count.
 */
export function expectRejected(world: World, f: () => unknown, argument: string | RegExp): void {
  const hash = stateHash(world);
  const count = world.bodyCount;
  let error: unknown;
  try {
    f();
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(FulcrumError);
  expect((error as Error).message).toMatch(argument);
  expect(stateHash(world)).toBe(hash);
  expect(world.bodyCount).toBe(count);
}

/** The message of the FulcrumError `call` throws (it must throw one): what a World says, to compare. */
export function fulcrumErrorMessage(call: () => unknown): string {
  try {
    call();
  } catch (e) {
    expect(e).toBeInstanceOf(FulcrumError);
    return (e as Error).message;
  }
  throw new Error('the call threw nothing');
}
