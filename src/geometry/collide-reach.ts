/**
 * The speculative distance for collidePacked, set by its caller and read by the pair routines and
 * their helpers: passed as an argument to calls V8 does not inline (the pair table's), a double is
 * boxed on the heap, once for every pair of every step.
 */
export const collideReach = new Float64Array(1);
