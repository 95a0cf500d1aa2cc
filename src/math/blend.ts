import type { Transform } from './vec2';

/**
 * The pose a share `t` of the way from the pose (px0, py0, c0, s0) to (px1, py1, c1, s1), into `out`:
 * positions blended linearly, rotations by a normalised linear blend (the end pose where the two
 * rotations are opposite). For drawing between steps: output only, it never feeds the step.
 */
export function blendTransform(
  px0: number,
  py0: number,
  c0: number,
  s0: number,
  px1: number,
  py1: number,
  c1: number,
  s1: number,
  t: number,
  out: Transform,
): Transform {
  out.p.x = px0 + (px1 - px0) * t;
  out.p.y = py0 + (py1 - py0) * t;
  let c = c0 + (c1 - c0) * t;
  let s = s0 + (s1 - s0) * t;
  const length = Math.sqrt(c * c + s * s);
  if (length > 1e-9) {
    c /= length;
    s /= length;
  } else {
    c = c1;
    s = s1;
  }
  out.q.c = c;
  out.q.s = s;
  return out;
}
