/**
 * Length tolerance of the geometry layer in metres: points closer than this are welded,
 * hull vertices closer than this to the line of their neighbours are dropped, and
 * capsules and segments must be at least this long.
 */
export const LINEAR_SLOP = 0.005;

/**
 * A polygon takes the reference face from shape B only when B's separation beats A's by this much,
 * so that resting contacts do not flip reference faces (and change their ids) from step to step.
 */
export const REFERENCE_FACE_TOLERANCE = 0.1 * LINEAR_SLOP;
