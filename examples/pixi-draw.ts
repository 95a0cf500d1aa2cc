/**
 * Fulcrum's DebugDraw callbacks on a PixiJS Graphics, so `drawWorld` can draw the gallery's overlays
 * (outlines, AABBs, joints, contacts, velocities, centres of mass) over a Pixi scene. The Graphics is
 * expected to sit in a container that maps metres, y up; `pixel` is one CSS pixel in metres.
 */
import type { Graphics } from 'pixi.js';
import type { Transform, Vec2 } from '../src/index';
import type { Color, DebugDraw, ShapeStyle } from '../src/render/index';

export class PixiDebugDraw implements DebugDraw {
  /** one CSS pixel in metres: line widths and point sizes are in screen pixels */
  pixel = 1;

  constructor(readonly g: Graphics) {}

  private finish(style: ShapeStyle): void {
    if (style.fill !== null) this.g.fill({ color: style.fill, alpha: style.fillAlpha });
    this.g.stroke({ color: style.stroke, width: this.pixel });
  }

  drawPolygon(xf: Transform, vertices: readonly Vec2[], _radius: number, style: ShapeStyle): void {
    // a rounded polygon is drawn by its core polygon: the Pixi scene has none
    const { c, s } = xf.q;
    const points: number[] = [];
    for (const v of vertices) points.push(c * v.x - s * v.y + xf.p.x, s * v.x + c * v.y + xf.p.y);
    this.g.poly(points);
    this.finish(style);
  }

  drawCircle(xf: Transform, center: Vec2, radius: number, style: ShapeStyle): void {
    const { c, s } = xf.q;
    const x = c * center.x - s * center.y + xf.p.x;
    const y = s * center.x + c * center.y + xf.p.y;
    this.g.circle(x, y, radius);
    this.finish(style);
    this.g.moveTo(x, y).lineTo(x + c * radius, y + s * radius);
    this.g.stroke({ color: style.stroke, width: this.pixel });
  }

  drawCapsule(xf: Transform, p1: Vec2, p2: Vec2, radius: number, style: ShapeStyle): void {
    const { c, s } = xf.q;
    const x1 = c * p1.x - s * p1.y + xf.p.x;
    const y1 = s * p1.x + c * p1.y + xf.p.y;
    const x2 = c * p2.x - s * p2.y + xf.p.x;
    const y2 = s * p2.x + c * p2.y + xf.p.y;
    const a = Math.atan2(y2 - y1, x2 - x1);
    this.g.moveTo(x2 + radius * Math.cos(a - Math.PI / 2), y2 + radius * Math.sin(a - Math.PI / 2));
    this.g.arc(x2, y2, radius, a - Math.PI / 2, a + Math.PI / 2);
    this.g.arc(x1, y1, radius, a + Math.PI / 2, a + (3 * Math.PI) / 2);
    this.g.closePath();
    this.finish(style);
  }

  drawLine(p1: Vec2, p2: Vec2, color: Color): void {
    this.g.moveTo(p1.x, p1.y).lineTo(p2.x, p2.y).stroke({ color, width: this.pixel });
  }

  drawPoint(p: Vec2, size: number, color: Color): void {
    this.g.circle(p.x, p.y, (size / 2) * this.pixel).fill(color);
  }

  drawAABB(minX: number, minY: number, maxX: number, maxY: number, color: Color): void {
    this.g.rect(minX, minY, maxX - minX, maxY - minY).stroke({ color, width: this.pixel });
  }

  drawTransform(xf: Transform): void {
    const length = 0.3;
    const { c, s } = xf.q;
    this.drawLine(xf.p, { x: xf.p.x + c * length, y: xf.p.y + s * length }, 0xff4040);
    this.drawLine(xf.p, { x: xf.p.x - s * length, y: xf.p.y + c * length }, 0x40ff40);
  }
}
