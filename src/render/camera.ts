import type { Vec2 } from '../math/vec2';

export interface CameraView {
  /** world point at the middle of the view */
  center: Vec2;
  /** world distance from the middle of the view to its top edge, metres */
  halfHeight: number;
}

/**
 * A 2D camera: world (metres, y up) to screen (CSS pixels of the canvas, y down, origin top left).
 * The zoom is kept as the visible half-height, so the same part of the world stays in view when
 * the canvas is resized.
 */
export class Camera {
  center: Vec2 = { x: 0, y: 0 };
  halfHeight = 10;
  /** viewport size in CSS pixels */
  width = 1;
  height = 1;
  minHalfHeight = 0.05;
  maxHalfHeight = 100_000;

  constructor(view?: Partial<CameraView>) {
    if (view) this.setView(view);
  }

  setView(view: Partial<CameraView>): void {
    if (view.center) this.center = { x: view.center.x, y: view.center.y };
    if (view.halfHeight !== undefined) this.halfHeight = this.clampHalfHeight(view.halfHeight);
  }

  get view(): CameraView {
    return { center: { x: this.center.x, y: this.center.y }, halfHeight: this.halfHeight };
  }

  setViewport(width: number, height: number): void {
    this.width = Math.max(1, width);
    this.height = Math.max(1, height);
  }

  /** CSS pixels per metre */
  get scale(): number {
    return this.height / (2 * this.halfHeight);
  }

  worldToScreen(p: Vec2, out: Vec2 = { x: 0, y: 0 }): Vec2 {
    const s = this.scale;
    const x = (p.x - this.center.x) * s + this.width / 2;
    const y = this.height / 2 - (p.y - this.center.y) * s;
    out.x = x;
    out.y = y;
    return out;
  }

  /** `x`, `y` in CSS pixels from the canvas' top-left corner */
  screenToWorld(x: number, y: number, out: Vec2 = { x: 0, y: 0 }): Vec2 {
    const s = this.scale;
    out.x = this.center.x + (x - this.width / 2) / s;
    out.y = this.center.y - (y - this.height / 2) / s;
    return out;
  }

  /** Moves the view by a drag of (dx, dy) CSS pixels: the world follows the pointer. */
  pan(dx: number, dy: number): void {
    const s = this.scale;
    this.center = { x: this.center.x - dx / s, y: this.center.y + dy / s };
  }

  /** Zooms by `factor` (> 1 zooms in) keeping the world point under screen point (x, y) fixed. */
  zoomAt(x: number, y: number, factor: number): void {
    if (!(factor > 0) || !Number.isFinite(factor)) return;
    const before = this.screenToWorld(x, y);
    this.halfHeight = this.clampHalfHeight(this.halfHeight / factor);
    const after = this.screenToWorld(x, y);
    this.center = {
      x: this.center.x + before.x - after.x,
      y: this.center.y + before.y - after.y,
    };
  }

  /** The visible world rectangle. */
  visibleBounds(): { lowerBound: Vec2; upperBound: Vec2 } {
    const halfWidth = (this.halfHeight * this.width) / this.height;
    return {
      lowerBound: { x: this.center.x - halfWidth, y: this.center.y - this.halfHeight },
      upperBound: { x: this.center.x + halfWidth, y: this.center.y + this.halfHeight },
    };
  }

  /** Shows the rectangle [lower, upper] with a margin (fraction of its size). */
  fit(lower: Vec2, upper: Vec2, margin = 0.05): void {
    const w = Math.max(1e-6, upper.x - lower.x);
    const h = Math.max(1e-6, upper.y - lower.y);
    const aspect = this.width / this.height;
    const halfHeight = Math.max(h / 2, w / 2 / aspect) * (1 + margin);
    this.setView({ center: { x: (lower.x + upper.x) / 2, y: (lower.y + upper.y) / 2 }, halfHeight });
  }

  private clampHalfHeight(h: number): number {
    if (!(h > 0) || !Number.isFinite(h)) return this.halfHeight;
    return Math.min(this.maxHalfHeight, Math.max(this.minHalfHeight, h));
  }
}
