/**
 * A small seeded pseudo-random generator (xorshift32) using 32-bit integer maths only, so scenes
 * built from the same seed are identical on every JavaScript engine.
 */
export interface Random {
  /** next unsigned 32-bit integer */
  nextUint32(): number;
  /** uniform in [0, 1), a multiple of 2^-32 */
  nextFloat(): number;
  /** uniform in [min, max) */
  range(min: number, max: number): number;
  /** uniform integer in [0, n) */
  int(n: number): number;
}

export function createRandom(seed: number): Random {
  // xorshift32 must not start at zero; mix the seed so small seeds differ quickly
  let state = Math.imul(seed ^ 0x9e3779b9, 0x85ebca6b) >>> 0 || 0x6d2b79f5;
  const nextUint32 = (): number => {
    state ^= state << 13;
    state >>>= 0;
    state ^= state >>> 17;
    state ^= state << 5;
    state >>>= 0;
    return state;
  };
  const nextFloat = (): number => nextUint32() / 4294967296;
  return {
    nextUint32,
    nextFloat,
    range: (min, max) => min + (max - min) * nextFloat(),
    int: (n) => Math.floor(nextFloat() * n),
  };
}
