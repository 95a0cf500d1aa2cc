import type { Transform, Vec2 } from '../math/vec2';
import { requireBrowser } from './browser';
import { CssColors } from './color';
import type { Color, DebugDraw, ShapeStyle } from './debug-draw';
import type { AnyBody } from './draw-source';

/** An image drawn at a body's position and angle instead of (or over) its shapes. */
export interface Sprite {
  image: CanvasImageSource;
  /** size in metres */
  width: number;
  height: number;
  /** centre of the image in the body's frame, metres (default: the body origin) */
  offset?: Vec2;
  /** extra rotation of the image, radians */
  angle?: number;
  opacity?: number;
  /** also draw the body's shapes under the image */
  drawShapes?: boolean;
}

interface ShapeBatch {
  fill: string | null;
  stroke: string;
  outline: Path2D;
  /** rotation indicators and segments: stroked only */
  lines: Path2D;
}

interface QueuedSprite {
  sprite: Sprite;
  px: number;
  py: number;
  c: number;
  s: number;
}

const TWO_PI = 2 * Math.PI;

function imageReady(image: CanvasImageSource): boolean {
  if (typeof HTMLImageElement !== 'undefined' && image instanceof HTMLImageElement) {
    return image.complete && image.naturalWidth > 0;
  }
  return true;
}

/**
 * The DebugDraw of a 2D canvas. The context must already map world metres to the canvas (y up);
 * `pixel` is the size of one CSS pixel in metres. Shapes, lines and points are batched into paths
 * by colour and drawn by `flush()` in that order: shapes, sprites, lines, points.
 * Trigonometry here is output only.
 */
export class CanvasDebugDraw implements DebugDraw {
  pixel = 1;
  /** a body's sprite and visibility, if styled (set by the Render) */
  styleOf: ((body: AnyBody) => { sprite?: Sprite; visible: boolean } | undefined) | null = null;
  private readonly shapeBatches = new Map<string, ShapeBatch>();
  private readonly lineBatches = new Map<string, Path2D>();
  private readonly pointBatches = new Map<string, Path2D>();
  private readonly sprites: QueuedSprite[] = [];
  private readonly css = new CssColors();

  constructor(readonly context: CanvasRenderingContext2D) {
    requireBrowser('new CanvasDebugDraw()', 'Path2D');
  }

  private batch(style: ShapeStyle): ShapeBatch {
    const fill = style.fill === null ? null : this.css.get(style.fill, style.fillAlpha);
    const stroke = this.css.get(style.stroke);
    const key = `${fill}|${stroke}`;
    let batch = this.shapeBatches.get(key);
    if (!batch) {
      batch = { fill, stroke, outline: new Path2D(), lines: new Path2D() };
      this.shapeBatches.set(key, batch);
    }
    return batch;
  }

  drawBody(body: AnyBody, xf: Transform): boolean {
    const style = this.styleOf?.(body);
    if (!style) return false;
    if (!style.visible) return true;
    const sprite = style.sprite;
    if (!sprite || !imageReady(sprite.image)) return false;
    this.sprites.push({ sprite, px: xf.p.x, py: xf.p.y, c: xf.q.c, s: xf.q.s });
    return !sprite.drawShapes;
  }

  drawPolygon(xf: Transform, vertices: readonly Vec2[], radius: number, style: ShapeStyle): void {
    const path = this.batch(style).outline;
    const { c, s } = xf.q;
    const n = vertices.length;
    if (radius <= 0) {
      for (let i = 0; i < n; i++) {
        const v = vertices[i];
        const x = c * v.x - s * v.y + xf.p.x;
        const y = s * v.x + c * v.y + xf.p.y;
        if (i === 0) path.moveTo(x, y);
        else path.lineTo(x, y);
      }
      path.closePath();
      return;
    }
    // rounded polygon: an arc around each vertex from the previous edge's normal to the next one's
    for (let i = 0; i < n; i++) {
      const v = vertices[i];
      const prev = vertices[(i + n - 1) % n];
      const next = vertices[(i + 1) % n];
      const a0 = Math.atan2(-(v.x - prev.x), v.y - prev.y); // outward normal of edge prev -> v
      const a1 = Math.atan2(-(next.x - v.x), next.y - v.y);
      const angle = Math.atan2(s, c);
      const x = c * v.x - s * v.y + xf.p.x;
      const y = s * v.x + c * v.y + xf.p.y;
      // a new subpath, so the outline does not join the previous shape's
      if (i === 0) path.moveTo(x + radius * Math.cos(a0 + angle), y + radius * Math.sin(a0 + angle));
      path.arc(x, y, radius, a0 + angle, a1 + angle);
    }
    path.closePath();
  }

  drawCircle(xf: Transform, center: Vec2, radius: number, style: ShapeStyle): void {
    const batch = this.batch(style);
    const { c, s } = xf.q;
    const x = c * center.x - s * center.y + xf.p.x;
    const y = s * center.x + c * center.y + xf.p.y;
    batch.outline.moveTo(x + radius, y);
    batch.outline.arc(x, y, radius, 0, TWO_PI);
    batch.lines.moveTo(x, y);
    batch.lines.lineTo(x + c * radius, y + s * radius);
  }

  drawCapsule(xf: Transform, p1: Vec2, p2: Vec2, radius: number, style: ShapeStyle): void {
    const batch = this.batch(style);
    const { c, s } = xf.q;
    const x1 = c * p1.x - s * p1.y + xf.p.x;
    const y1 = s * p1.x + c * p1.y + xf.p.y;
    const x2 = c * p2.x - s * p2.y + xf.p.x;
    const y2 = s * p2.x + c * p2.y + xf.p.y;
    const a = Math.atan2(y2 - y1, x2 - x1);
    const path = batch.outline;
    path.moveTo(x2 + radius * Math.cos(a - Math.PI / 2), y2 + radius * Math.sin(a - Math.PI / 2));
    path.arc(x2, y2, radius, a - Math.PI / 2, a + Math.PI / 2);
    path.arc(x1, y1, radius, a + Math.PI / 2, a + (3 * Math.PI) / 2);
    path.closePath();
    batch.lines.moveTo(x1, y1);
    batch.lines.lineTo(x2, y2);
  }

  private lines(color: Color): Path2D {
    const key = this.css.get(color);
    let path = this.lineBatches.get(key);
    if (!path) {
      path = new Path2D();
      this.lineBatches.set(key, path);
    }
    return path;
  }

  drawLine(p1: Vec2, p2: Vec2, color: Color): void {
    const path = this.lines(color);
    path.moveTo(p1.x, p1.y);
    path.lineTo(p2.x, p2.y);
  }

  drawPoint(p: Vec2, size: number, color: Color): void {
    const key = this.css.get(color);
    let path = this.pointBatches.get(key);
    if (!path) {
      path = new Path2D();
      this.pointBatches.set(key, path);
    }
    const r = (size / 2) * this.pixel;
    path.moveTo(p.x + r, p.y);
    path.arc(p.x, p.y, r, 0, TWO_PI);
  }

  drawAABB(minX: number, minY: number, maxX: number, maxY: number, color: Color): void {
    this.lines(color).rect(minX, minY, maxX - minX, maxY - minY);
  }

  drawTransform(xf: Transform): void {
    const length = 0.3;
    const { c, s } = xf.q;
    this.drawLine(xf.p, { x: xf.p.x + c * length, y: xf.p.y + s * length }, 0xff4040);
    this.drawLine(xf.p, { x: xf.p.x - s * length, y: xf.p.y + c * length }, 0x40ff40);
  }

  /** Draws everything queued since the last flush and empties the queues. */
  flush(): void {
    const ctx = this.context;
    ctx.lineWidth = this.pixel;
    ctx.lineJoin = 'round';
    ctx.globalAlpha = 1;
    for (const batch of this.shapeBatches.values()) {
      if (batch.fill !== null) {
        ctx.fillStyle = batch.fill;
        ctx.fill(batch.outline);
      }
      ctx.strokeStyle = batch.stroke;
      ctx.stroke(batch.outline);
      ctx.stroke(batch.lines);
    }
    this.shapeBatches.clear();
    for (const q of this.sprites) this.drawSprite(q);
    this.sprites.length = 0;
    ctx.lineWidth = 1.5 * this.pixel;
    for (const [color, path] of this.lineBatches) {
      ctx.strokeStyle = color;
      ctx.stroke(path);
    }
    this.lineBatches.clear();
    for (const [color, path] of this.pointBatches) {
      ctx.fillStyle = color;
      ctx.fill(path);
    }
    this.pointBatches.clear();
  }

  private drawSprite(q: QueuedSprite): void {
    const ctx = this.context;
    const { sprite } = q;
    ctx.save();
    ctx.transform(q.c, q.s, -q.s, q.c, q.px, q.py);
    if (sprite.offset) ctx.translate(sprite.offset.x, sprite.offset.y);
    if (sprite.angle) ctx.rotate(sprite.angle);
    // the world is y up; flip back so the image is upright
    ctx.scale(1, -1);
    ctx.globalAlpha = sprite.opacity ?? 1;
    ctx.drawImage(sprite.image, -sprite.width / 2, -sprite.height / 2, sprite.width, sprite.height);
    ctx.restore();
  }
}
