import fc from 'fast-check';
import { tame } from './settings';

/**
 * Number arbitraries for the API fuzzer: ordinary values most of the time, and now and then an
 * extreme but finite one (the API accepts every finite number for these arguments, so the step must
 * survive them or the call must refuse them). Every arbitrary shrinks towards an ordinary value.
 */

/** finite values far from everyday physics, of both signs where it makes sense */
const HUGE = [1e6, 1e9, 1e15, 1e18, 1e20, 1e100, 1e200, 1e300, Number.MAX_VALUE];
const TINY = [Number.MIN_VALUE, 1e-300, 1e-100, 1e-12, 1e-6];

function mostly<T>(ordinary: fc.Arbitrary<T>, extreme: fc.Arbitrary<T>): fc.Arbitrary<T> {
  return tame ? ordinary : fc.oneof({ weight: 24, arbitrary: ordinary }, { weight: 1, arbitrary: extreme });
}

/** doubles in [min, max]; tame runs (settings.ts) leave out the subnormal and near-zero ones */
function range(min: number, max: number): fc.Arbitrary<number> {
  const all = fc.double({ min, max, noNaN: true, noDefaultInfinity: true });
  return tame ? all.map((v) => (Math.abs(v) < 1e-6 ? 0 : v)) : all;
}

const signedExtreme = fc.constantFrom(...HUGE, ...HUGE.map((v) => -v), ...TINY, -0);

/** a coordinate, a velocity component, a force or an offset */
export const anyNumber = mostly(range(-20, 20), signedExtreme);

/** an angle in radians (huge ones included: the API takes any finite angle) */
export const angle = mostly(range(-7, 7), signedExtreme);

/** a length that must be > 0: radius, half extent */
export const size = mostly(range(0.05, 3), fc.constantFrom(...TINY, 10, 1e3, 1e6, 1e100, 1e200, 1e300));

/** a value that must be >= 0: damping, friction, density, hertz, max force */
export const nonNegative = mostly(fc.oneof(range(0, 10), fc.constant(0)), fc.constantFrom(...TINY, ...HUGE));

/** a restitution, friction or damping ratio: usually in [0, 1] */
export const unitish = mostly(range(0, 1), fc.constantFrom(2, 100, 1e10, 1e300));

/** a step's dt: mostly 1/60, sometimes another ordinary step, rarely 0 or a huge one */
export const dt = fc.oneof(
  { weight: 30, arbitrary: fc.constant(1 / 60) },
  { weight: 6, arbitrary: range(0.001, 0.1) },
  { weight: 2, arbitrary: fc.constant(0) },
  {
    weight: 1,
    arbitrary: tame ? fc.constant(0.2) : fc.constantFrom(0.5, 1, 10, 1e6, 1e300, Number.MIN_VALUE),
  },
);

export const vec = fc.record({ x: anyNumber, y: anyNumber });

/** a point near the origin, where bodies and shapes mostly are */
export const nearPoint = fc.record({ x: range(-6, 6), y: range(-6, 6) });

/** a 32-bit unsigned mask: all, none, a few categories */
export const bits = fc.oneof(
  fc.constant(0xffffffff),
  fc.constant(1),
  fc.constant(0),
  fc.integer({ min: 0, max: 0xffffffff }),
);
export const groupIndex = fc.oneof(
  { weight: 6, arbitrary: fc.constant(0) },
  { weight: 2, arbitrary: fc.integer({ min: -3, max: 3 }) },
  { weight: 1, arbitrary: fc.constantFrom(-0x80000000, 0x7fffffff) },
);

/** an index into the list of handles made so far (modulo its length, destroyed ones included) */
export const pick = fc.nat({ max: 1000 });
