import { BodyState } from '../store/body-store';
import type { World } from './world';

/**
 * 32-bit FNV-1a hash over the exact bits of every live body's transform and velocity, in slot order.
 * Two worlds with the same hash are, for all practical purposes, bit-identical.
 */
export function stateHash(world: World): number {
  const bodies = world.core.bodies;
  const f64 = new Float64Array(1);
  const u32 = new Uint32Array(f64.buffer);
  let h = 0x811c9dc5;
  const mix = (x: number) => {
    f64[0] = x;
    for (let k = 0; k < 2; k++) {
      let w = u32[k];
      for (let byte = 0; byte < 4; byte++) {
        h ^= w & 0xff;
        h = Math.imul(h, 0x01000193);
        w >>>= 8;
      }
    }
  };
  for (let b = 0; b < bodies.slotCount; b++) {
    if (bodies.alive[b] === 0) continue;
    mix(b);
    mix(bodies.px[b]);
    mix(bodies.py[b]);
    mix(bodies.qc[b]);
    mix(bodies.qs[b]);
    const s = b * BodyState.STRIDE;
    mix(bodies.state[s]);
    mix(bodies.state[s + 1]);
    mix(bodies.state[s + 2]);
  }
  return h >>> 0;
}
