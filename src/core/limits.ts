import { fail } from './errors';

/**
 * The ranges the public API accepts, in world units (metres unless `lengthUnitsPerMeter` says
 * otherwise), kilograms, seconds and radians. They are far wider than anything a simulation needs,
 * and narrow enough that no accepted value can bring NaN or Infinity into a step: the products the
 * solver forms (masses times speeds, inertias, squared distances, spring coefficients) stay below
 * about 1e100, far from the 1.8e308 where doubles overflow, and no accepted mass or inertia is so
 * small that its inverse overflows. The README's API section lists them; the bad-input tests pin them.
 */
export const Limits = {
  /** positions, anchors, targets, offsets, shape coordinates, lengths, query points and translations */
  COORDINATE: 1e9,
  /**
   * the smallest circle or capsule radius and box half extent: with the smallest density, the mass
   * and rotational inertia of the smallest shape stay far above the ~1e-308 whose inverse overflows
   */
  MIN_SIZE: 1e-6,
  /**
   * angles (bodies, shapes, joints' reference angles, limits and offsets, queries): up to here the
   * deterministic sine and cosine reduce the angle exactly (below 2^20 quarter turns)
   */
  ANGLE: 1e6,
  /**
   * speeds given (linear and angular velocity, motor speeds), gravity, gravity scale, damping, spring
   * frequencies and damping ratios, friction and restitution; bodies are then held to the speed
   * limits by the step (see Settings.maxLinearSpeed and MAX_ROTATION_PER_SUBSTEP)
   */
  RATE: 1e9,
  /**
   * spring frequencies other than 0 (a period of 11.6 days): a lower one makes the spring's terms
   * (2 pi hertz times the substep) underflow to 0, and an undamped spring divide by them
   */
  MIN_HERTZ: 1e-6,
  /** densities other than 0 (kg per square world unit) */
  MIN_DENSITY: 1e-12,
  MAX_DENSITY: 1e12,
  /**
   * masses and rotational inertias given by Body.setMassData: the range shapes can reach (the smallest
   * density on the smallest shape to the largest density on the largest)
   */
  MIN_MASS: 1e-24,
  MAX_MASS: 1e30,
  MIN_INERTIA: 1e-36,
  MAX_INERTIA: 1e48,
  /** forces, torques, impulses, and the joints' force and torque caps */
  FORCE: 1e40,
  /** the time step, other than 0 */
  MIN_DT: 1e-6,
  MAX_DT: 1,
  /** world units per metre */
  MIN_UNITS: 1e-3,
  MAX_UNITS: 1e4,
} as const;

/** A finite number in [min, max]. */
export function checkRange(argument: string, value: unknown, min: number, max: number): number {
  if (typeof value !== 'number' || !(value >= min && value <= max)) {
    fail(argument, value, `a number in [${min}, ${max}]`);
  }
  return value;
}

/** A finite number whose magnitude is at most `bound`. */
function checkMagnitude(argument: string, value: unknown, bound: number): number {
  if (typeof value !== 'number' || !(Math.abs(value) <= bound)) {
    fail(argument, value, `a number in [-${bound}, ${bound}]`);
  }
  return value;
}

/** 0, or a number in [min, max]. */
export function checkZeroOrRange(argument: string, value: unknown, min: number, max: number): number {
  if (typeof value !== 'number' || !(value === 0 || (value >= min && value <= max))) {
    fail(argument, value, `0 or a number in [${min}, ${max}]`);
  }
  return value;
}

/** A vector { x, y } whose components' magnitudes are at most `bound`; returns a copy. */
export function checkVector(argument: string, value: unknown, bound: number): { x: number; y: number } {
  if (typeof value !== 'object' || value === null) fail(argument, value, 'a vector { x, y }');
  const v = value as { x: unknown; y: unknown };
  const x = v.x;
  const y = v.y;
  if (typeof x !== 'number' || typeof y !== 'number' || !(Math.abs(x) <= bound && Math.abs(y) <= bound)) {
    fail(argument, value, `a vector { x, y } of numbers in [-${bound}, ${bound}]`);
  }
  return { x, y };
}

/** A point or translation: components within Limits.COORDINATE. */
export function checkCoordinates(argument: string, value: unknown): { x: number; y: number } {
  return checkVector(argument, value, Limits.COORDINATE);
}

/** A length or coordinate: magnitude within Limits.COORDINATE. */
export function checkCoordinate(argument: string, value: unknown): number {
  return checkMagnitude(argument, value, Limits.COORDINATE);
}

/** A length: in [0, Limits.COORDINATE]. */
export function checkLength(argument: string, value: unknown): number {
  return checkRange(argument, value, 0, Limits.COORDINATE);
}

/** A circle or capsule radius or a box half extent: in [Limits.MIN_SIZE, Limits.COORDINATE]. */
export function checkSize(argument: string, value: unknown): number {
  return checkRange(argument, value, Limits.MIN_SIZE, Limits.COORDINATE);
}

export function checkAngle(argument: string, value: unknown): number {
  return checkMagnitude(argument, value, Limits.ANGLE);
}

/** A speed, frequency, ratio or coefficient that may be negative: magnitude within Limits.RATE. */
export function checkRate(argument: string, value: unknown): number {
  return checkMagnitude(argument, value, Limits.RATE);
}

/** As checkRate, not negative. */
export function checkNonNegativeRate(argument: string, value: unknown): number {
  return checkRange(argument, value, 0, Limits.RATE);
}

/** A spring frequency in hertz: 0 (no spring) or in [Limits.MIN_HERTZ, Limits.RATE]. */
export function checkHertz(argument: string, value: unknown): number {
  return checkZeroOrRange(argument, value, Limits.MIN_HERTZ, Limits.RATE);
}

/** A force, torque or impulse (or a cap on one) that may be negative. */
export function checkForce(argument: string, value: unknown): number {
  return checkMagnitude(argument, value, Limits.FORCE);
}

/** As checkForce, not negative. */
export function checkNonNegativeForce(argument: string, value: unknown): number {
  return checkRange(argument, value, 0, Limits.FORCE);
}

export function checkDensity(argument: string, value: unknown): number {
  return checkZeroOrRange(argument, value, Limits.MIN_DENSITY, Limits.MAX_DENSITY);
}
