import type { World } from '../api/world';
import { blendTransform } from '../math/blend';
import type { Transform } from '../math/vec2';
import type { WorkerBody } from '../worker/handles';
import type { AnyBody } from './draw-source';

function grow(a: Float64Array<ArrayBuffer>, n: number): Float64Array<ArrayBuffer> {
  if (a.length >= n) return a;
  return new Float64Array(Math.max(n, a.length * 2, 64));
}

/**
 * Keeps the body transforms of the state before the last step, so that drawing can blend the last
 * two states: `alpha` = 0 shows the previous state, 1 the current one. Output only: nothing here
 * feeds the step. A worker world's bodies need no capture: its worker publishes both states.
 */
export class Interpolator {
  /** blend factor in [0, 1] between the previous state and the current one */
  alpha = 1;
  private world: World | null = null;
  private count = 0;
  private px: Float64Array<ArrayBuffer> = new Float64Array(0);
  private py: Float64Array<ArrayBuffer> = new Float64Array(0);
  private qc: Float64Array<ArrayBuffer> = new Float64Array(0);
  private qs: Float64Array<ArrayBuffer> = new Float64Array(0);
  private generation = new Uint32Array(0);

  /** Remembers the current transforms of every body; call it just before `world.step`. */
  capture(world: World): void {
    const bodies = world.core.bodies;
    const n = bodies.slotCount;
    this.px = grow(this.px, n);
    this.py = grow(this.py, n);
    this.qc = grow(this.qc, n);
    this.qs = grow(this.qs, n);
    if (this.generation.length < n) this.generation = new Uint32Array(this.px.length);
    this.px.set(bodies.px.subarray(0, n));
    this.py.set(bodies.py.subarray(0, n));
    this.qc.set(bodies.qc.subarray(0, n));
    this.qs.set(bodies.qs.subarray(0, n));
    this.generation.set(bodies.generation.subarray(0, n));
    this.world = world;
    this.count = n;
  }

  /** Forgets the previous state: bodies are drawn where they are until the next capture. */
  reset(): void {
    this.world = null;
    this.count = 0;
    this.alpha = 1;
  }

  /** The transform to draw `body` at: blended when the previous state knows it, current otherwise. */
  transformOf(body: AnyBody, out: Transform): Transform {
    if (!('slot' in body)) return this.workerTransformOf(body, out);
    const bodies = body.world.core.bodies;
    const b = body.slot;
    const cx = bodies.px[b];
    const cy = bodies.py[b];
    const cc = bodies.qc[b];
    const cs = bodies.qs[b];
    const t = this.alpha;
    if (t >= 1 || body.world !== this.world || b >= this.count || this.generation[b] !== body.generation) {
      out.p.x = cx;
      out.p.y = cy;
      out.q.c = cc;
      out.q.s = cs;
      return out;
    }
    return blendTransform(this.px[b], this.py[b], this.qc[b], this.qs[b], cx, cy, cc, cs, t, out);
  }

  /** A worker body's pose `alpha` of the way through the last step its worker finished. */
  private workerTransformOf(body: WorkerBody, out: Transform): Transform {
    return this.alpha >= 1 ? body.readPose(out) : body.getInterpolatedTransform(Math.max(0, this.alpha), out);
  }
}
