// #region example
import type { Vec2 } from 'fulcrum';

/** A view of the world: `scale` pixels to the metre, `origin` the world point at the canvas' top left. */
export interface View {
  scale: number;
  origin: Vec2;
}

/** World metres (y up) to canvas pixels (y down). */
export function toScreen(view: View, p: Vec2): Vec2 {
  return { x: (p.x - view.origin.x) * view.scale, y: (view.origin.y - p.y) * view.scale };
}

/** Canvas pixels (y down) back to world metres (y up), e.g. for a mouse click. */
export function toWorld(view: View, s: Vec2): Vec2 {
  return { x: view.origin.x + s.x / view.scale, y: view.origin.y - s.y / view.scale };
}

// A body's angle turns counter-clockwise with y up; on a y-down canvas draw it at -angle.
// #endregion example
