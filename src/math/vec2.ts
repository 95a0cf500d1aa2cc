/** A 2D vector. Any `{ x, y }` object is accepted by the public API; getters return fresh objects. */
export interface Vec2 {
  x: number;
  y: number;
}

/** Rotation stored as a cosine/sine pair (never as an angle inside the step). */
export interface Rot {
  c: number;
  s: number;
}

/** Rigid transform: rotate by `q`, then translate by `p`. */
export interface Transform {
  p: Vec2;
  q: Rot;
}

export function makeTransform(): Transform {
  return { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
}
