import type { MatterBody } from './body';
import { Bounds, type MatterBounds } from './bounds';
import { Composite } from './composite';
import { Constraint } from './constraint';
import type { MatterEngine } from './engine';
import { Events } from './events';
import { type MatterMouse, Mouse } from './mouse';

/** matter's Render options (those this layer draws; the rest are accepted and ignored). */
export interface MatterRenderOptions {
  width: number;
  height: number;
  pixelRatio: number;
  background: string;
  wireframeBackground: string;
  wireframeStrokeStyle: string;
  hasBounds: boolean;
  enabled: boolean;
  wireframes: boolean;
  showSleeping: boolean;
  showVelocity: boolean;
  showCollisions: boolean;
  showAngleIndicator: boolean;
  showBounds: boolean;
  showPositions: boolean;
  [option: string]: unknown;
}

/** A matter.js renderer: a canvas, the engine it draws, the view's bounds. */
export interface MatterRender {
  engine: MatterEngine;
  element: { appendChild(child: unknown): unknown } | null;
  canvas: HTMLCanvasElement;
  context: CanvasRenderingContext2D;
  mouse: MatterMouse | null;
  options: MatterRenderOptions;
  bounds: MatterBounds;
  textures: Record<string, HTMLImageElement>;
  frameRequestId: number | null;
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
}

type Paintable = {
  vertices: { x: number; y: number }[];
  circleRadius: number;
  position: { x: number; y: number };
  angle: number;
};

function texture(render: MatterRender, path: string): HTMLImageElement {
  let image = render.textures[path];
  if (!image) {
    image = new Image();
    image.src = path;
    render.textures[path] = image;
  }
  return image;
}

function outline(context: CanvasRenderingContext2D, part: Paintable): void {
  context.beginPath();
  if (part.circleRadius > 0) {
    context.arc(part.position.x, part.position.y, part.circleRadius, 0, 2 * Math.PI);
  } else {
    const v = part.vertices;
    context.moveTo(v[0].x, v[0].y);
    for (let i = 1; i < v.length; i++) context.lineTo(v[i].x, v[i].y);
    context.closePath();
  }
}

function drawBodies(render: MatterRender, bodies: readonly MatterBody[]): void {
  const { context: c, options } = render;
  for (const body of bodies) {
    if (!body.render.visible) continue;
    const parts = body.parts.length > 1 ? body.parts.slice(1) : [body];
    for (const part of parts) {
      const style = part.render as Record<string, unknown> & { sprite: Record<string, unknown> };
      const alpha = (style.opacity as number) ?? 1;
      c.globalAlpha = options.showSleeping && body.isSleeping ? 0.5 * alpha : alpha;
      const sprite = style.sprite;
      if (!options.wireframes && typeof sprite.texture === 'string') {
        const image = texture(render, sprite.texture);
        c.translate(part.position.x, part.position.y);
        c.rotate(part.angle);
        c.drawImage(
          image,
          image.width * -(sprite.xOffset as number) * (sprite.xScale as number),
          image.height * -(sprite.yOffset as number) * (sprite.yScale as number),
          image.width * (sprite.xScale as number),
          image.height * (sprite.yScale as number),
        );
        c.rotate(-part.angle);
        c.translate(-part.position.x, -part.position.y);
        continue;
      }
      outline(c, part);
      if (options.wireframes) {
        c.lineWidth = 1;
        c.strokeStyle = options.wireframeStrokeStyle;
        c.stroke();
      } else {
        c.fillStyle = style.fillStyle as string;
        c.fill();
        if ((style.lineWidth as number) > 0) {
          c.lineWidth = style.lineWidth as number;
          c.strokeStyle = style.strokeStyle as string;
          c.stroke();
        }
      }
    }
    c.globalAlpha = 1;
    if (options.showAngleIndicator || options.showVelocity || options.showPositions) {
      c.beginPath();
      if (options.showAngleIndicator) {
        const v = body.vertices;
        c.moveTo(body.position.x, body.position.y);
        c.lineTo((v[0].x + v[v.length - 1].x) / 2, (v[0].y + v[v.length - 1].y) / 2);
      }
      if (options.showVelocity) {
        c.moveTo(body.position.x, body.position.y);
        c.lineTo(body.position.x + body.velocity.x * 2, body.position.y + body.velocity.y * 2);
      }
      c.lineWidth = 1;
      c.strokeStyle = options.wireframes ? '#cd5c5c' : 'rgba(255,255,255,0.4)';
      c.stroke();
      if (options.showPositions) {
        c.fillStyle = options.wireframes ? 'indianred' : 'rgba(0,0,0,0.5)';
        c.fillRect(body.position.x - 2, body.position.y - 2, 4, 4);
      }
    }
    if (options.showBounds) {
      c.lineWidth = 1;
      c.strokeStyle = 'rgba(255,255,255,0.08)';
      c.strokeRect(
        body.bounds.min.x,
        body.bounds.min.y,
        body.bounds.max.x - body.bounds.min.x,
        body.bounds.max.y - body.bounds.min.y,
      );
    }
  }
}

function drawConstraints(render: MatterRender): void {
  const c = render.context;
  for (const constraint of Composite.allConstraints(render.engine.world)) {
    if (!constraint.render.visible || (!constraint.bodyA && !constraint.bodyB)) continue;
    const a = Constraint.pointAWorld(constraint);
    const b = Constraint.pointBWorld(constraint);
    c.beginPath();
    c.moveTo(a.x, a.y);
    if (constraint.render.type === 'spring') {
      // a zigzag of 24 turns between the ends
      const dx = b.x - a.x;
      const dy = b.y - a.y;
      const length = Math.sqrt(dx * dx + dy * dy) || 1;
      for (let i = 1; i < 24; i++) {
        const side = i % 2 === 0 ? 1 : -1;
        c.lineTo(
          a.x + (dx * i) / 24 + (-dy / length) * 5 * side,
          a.y + (dy * i) / 24 + (dx / length) * 5 * side,
        );
      }
    }
    c.lineTo(b.x, b.y);
    c.lineWidth = constraint.render.lineWidth;
    c.strokeStyle = constraint.render.strokeStyle;
    c.stroke();
    if (constraint.render.anchors) {
      c.fillStyle = constraint.render.strokeStyle;
      c.beginPath();
      c.arc(a.x, a.y, 3, 0, 2 * Math.PI);
      c.arc(b.x, b.y, 3, 0, 2 * Math.PI);
      c.closePath();
      c.fill();
    }
  }
}

function drawCollisions(render: MatterRender): void {
  const c = render.context;
  c.beginPath();
  for (const pair of render.engine.pairs.list) {
    for (const s of pair.collision.supports) c.rect(s.x - 1.5, s.y - 1.5, 3.5, 3.5);
  }
  c.fillStyle = render.options.wireframes ? 'rgba(255,255,255,0.7)' : 'orange';
  c.fill();
}

/**
 * matter.js's `Render`: draws an engine's world on a canvas with matter's options (wireframes,
 * background, angle indicators, velocities, collisions, bounds with `lookAt`, sprites). A plain,
 * mutable module object.
 */
export const Render = {
  create(options: {
    element?: MatterRender['element'];
    canvas?: HTMLCanvasElement;
    engine: MatterEngine;
    mouse?: MatterMouse;
    options?: Partial<MatterRenderOptions>;
    bounds?: MatterBounds;
  }): MatterRender {
    const settings: MatterRenderOptions = {
      width: 800,
      height: 600,
      pixelRatio: 1,
      background: '#14151f',
      wireframeBackground: '#14151f',
      wireframeStrokeStyle: '#bbb',
      hasBounds: !!options.bounds,
      enabled: true,
      wireframes: true,
      showSleeping: true,
      showVelocity: false,
      showCollisions: false,
      showAngleIndicator: false,
      showBounds: false,
      showPositions: false,
      ...options.options,
    };
    const canvas = options.canvas ?? document.createElement('canvas');
    if (!options.canvas) {
      canvas.width = settings.width;
      canvas.height = settings.height;
    }
    const render: MatterRender = {
      engine: options.engine,
      element: options.element ?? null,
      canvas,
      context: canvas.getContext('2d') as CanvasRenderingContext2D,
      mouse: options.mouse ?? null,
      options: settings,
      bounds: options.bounds ?? { min: { x: 0, y: 0 }, max: { x: canvas.width, y: canvas.height } },
      textures: {},
      frameRequestId: null,
      events: null,
    };
    if (settings.pixelRatio !== 1) Render.setPixelRatio(render, settings.pixelRatio);
    render.element?.appendChild(canvas);
    return render;
  },

  /** Draws on every animation frame until `Render.stop`. */
  run(render: MatterRender): void {
    const frame = (time: number) => {
      render.frameRequestId = requestAnimationFrame(frame);
      Render.world(render, time);
    };
    frame(0);
  },

  stop(render: MatterRender): void {
    if (render.frameRequestId !== null) cancelAnimationFrame(render.frameRequestId);
    render.frameRequestId = null;
  },

  setPixelRatio(render: MatterRender, pixelRatio: number | 'auto'): void {
    const ratio =
      pixelRatio === 'auto' ? (typeof window !== 'undefined' ? window.devicePixelRatio || 1 : 1) : pixelRatio;
    render.options.pixelRatio = ratio;
    render.canvas.setAttribute?.('data-pixel-ratio', String(ratio));
    render.canvas.width = render.options.width * ratio;
    render.canvas.height = render.options.height * ratio;
    render.canvas.style.width = `${render.options.width}px`;
    render.canvas.style.height = `${render.options.height}px`;
  },

  setSize(render: MatterRender, width: number, height: number): void {
    render.options.width = width;
    render.options.height = height;
    render.bounds.max.x = render.bounds.min.x + width;
    render.bounds.max.y = render.bounds.min.y + height;
    Render.setPixelRatio(render, render.options.pixelRatio);
  },

  /**
   * Fits the view (`render.bounds`) around `objects` (bodies, or anything with `bounds` or a
   * `position`) with `padding`, keeping the canvas's aspect ratio, centred on them when `center`.
   */
  lookAt(
    render: MatterRender,
    objects: unknown | unknown[],
    padding: { x: number; y: number } = { x: 0, y: 0 },
    center = true,
  ): void {
    const list = Array.isArray(objects) ? objects : [objects];
    const box = { min: { x: Infinity, y: Infinity }, max: { x: -Infinity, y: -Infinity } };
    for (const object of list as {
      bounds?: MatterBounds;
      position?: { x: number; y: number };
      min?: unknown;
    }[]) {
      const b = object.bounds ?? (object.min ? (object as unknown as MatterBounds) : null);
      const min = b ? b.min : object.position;
      const max = b ? b.max : object.position;
      if (!min || !max) continue;
      box.min.x = Math.min(box.min.x, min.x);
      box.min.y = Math.min(box.min.y, min.y);
      box.max.x = Math.max(box.max.x, max.x);
      box.max.y = Math.max(box.max.y, max.y);
    }
    const width = box.max.x - box.min.x + 2 * padding.x;
    const height = box.max.y - box.min.y + 2 * padding.y;
    const viewHeight = render.canvas.height;
    const viewWidth = render.canvas.width;
    const aspect = viewWidth / viewHeight;
    let scaleX = 1;
    let scaleY = 1;
    if (width / height > aspect) scaleY = width / aspect / height;
    else scaleX = (height * aspect) / width;
    render.options.hasBounds = true;
    render.bounds.min.x = box.min.x;
    render.bounds.max.x = box.min.x + width * scaleX;
    render.bounds.min.y = box.min.y;
    render.bounds.max.y = box.min.y + height * scaleY;
    if (center) {
      const shiftX = (width * scaleX - width) * 0.5;
      const shiftY = (height * scaleY - height) * 0.5;
      Bounds.translate(render.bounds, { x: -shiftX, y: -shiftY });
    }
    Bounds.translate(render.bounds, { x: -padding.x, y: -padding.y });
    if (render.mouse) {
      Mouse.setScale(render.mouse, {
        x: (render.bounds.max.x - render.bounds.min.x) / render.canvas.width,
        y: (render.bounds.max.y - render.bounds.min.y) / render.canvas.height,
      });
      Mouse.setOffset(render.mouse, render.bounds.min);
    }
  },

  /** Sets the context to draw in world coordinates within the render's bounds (its view). */
  startViewTransform(render: MatterRender): void {
    const { canvas, bounds } = render;
    const sx = canvas.width / (bounds.max.x - bounds.min.x);
    const sy = canvas.height / (bounds.max.y - bounds.min.y);
    render.context.setTransform(sx, 0, 0, sy, -bounds.min.x * sx, -bounds.min.y * sy);
  },

  /** Sets the context back to the canvas's own pixels (at the pixel ratio). */
  endViewTransform(render: MatterRender): void {
    const ratio = render.options.pixelRatio;
    render.context.setTransform(ratio, 0, 0, ratio, 0, 0);
  },

  /** Draws the world once: background, bodies, constraints, and what the options ask for. */
  world(render: MatterRender, time?: number): void {
    const { context: c, options, canvas } = render;
    const event = { timestamp: render.engine.timing.timestamp, time };
    Events.trigger(render, 'beforeRender', event);
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.fillStyle = options.wireframes ? options.wireframeBackground : options.background;
    c.fillRect(0, 0, canvas.width, canvas.height);
    if (options.hasBounds) Render.startViewTransform(render);
    else Render.endViewTransform(render);
    const bodies = Composite.allBodies(render.engine.world).filter((body) =>
      options.hasBounds ? Bounds.overlaps(body.bounds, render.bounds) : true,
    );
    drawBodies(render, bodies);
    drawConstraints(render);
    if (options.showCollisions) drawCollisions(render);
    c.setTransform(1, 0, 0, 1, 0, 0);
    Events.trigger(render, 'afterRender', event);
  },
};
