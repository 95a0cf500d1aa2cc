import { FulcrumError } from './errors';

/**
 * The most bodies, shapes, joints and contacts a world holds at once, and the mask hot loops put on
 * their counts and slot numbers. V8 types `i * stride + field` as an integer that may overflow 32
 * bits unless it can bound `i`, and then checks every such index for overflow and sign-extends it
 * before the typed array's bounds check (about a tenth of the contact solver's time). A count or a
 * slot masked with MAX is known to be below 2^24, so the index of any record of fewer than 128
 * numbers compiles to plain 32-bit arithmetic. The world never holds more than MAX of anything, so
 * the mask changes no value.
 */
export enum IndexBound {
  MAX = 0xffffff,
}

/** Throws when a world already holds the most `what` (bodies, shapes, joints) it can. */
export function checkRoom(what: string, count: number): void {
  if (count >= IndexBound.MAX) throw new FulcrumError(`${what}: a world holds at most ${IndexBound.MAX}`);
}
