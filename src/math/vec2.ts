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

export function vec2(x: number, y: number): Vec2 {
  return { x, y };
}

export function makeTransform(): Transform {
  return { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
}

/** out = q * v */
export function rotateInto(q: Rot, x: number, y: number, out: Vec2): Vec2 {
  out.x = q.c * x - q.s * y;
  out.y = q.s * x + q.c * y;
  return out;
}

/** out = q^T * v */
export function invRotateInto(q: Rot, x: number, y: number, out: Vec2): Vec2 {
  out.x = q.c * x + q.s * y;
  out.y = -q.s * x + q.c * y;
  return out;
}

/** out = xf * v (local point to world point) */
export function transformPointInto(xf: Transform, x: number, y: number, out: Vec2): Vec2 {
  const wx = xf.q.c * x - xf.q.s * y + xf.p.x;
  const wy = xf.q.s * x + xf.q.c * y + xf.p.y;
  out.x = wx;
  out.y = wy;
  return out;
}

/** out = xf^-1 * v (world point to local point) */
export function invTransformPointInto(xf: Transform, x: number, y: number, out: Vec2): Vec2 {
  const dx = x - xf.p.x;
  const dy = y - xf.p.y;
  out.x = xf.q.c * dx + xf.q.s * dy;
  out.y = -xf.q.s * dx + xf.q.c * dy;
  return out;
}

export function length(x: number, y: number): number {
  return Math.sqrt(x * x + y * y);
}

export function cross(ax: number, ay: number, bx: number, by: number): number {
  return ax * by - ay * bx;
}

export function dot(ax: number, ay: number, bx: number, by: number): number {
  return ax * bx + ay * by;
}
