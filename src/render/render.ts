import type { World } from '../api/world';
import { Emitter } from '../core/emitter';
import { FulcrumError } from '../core/errors';
import type { Vec2 } from '../math/vec2';
import { requireBrowser } from './browser';
import { Camera, type CameraView } from './camera';
import { CanvasDebugDraw, type Sprite } from './canvas-draw';
import {
  type Color,
  type DebugDrawFlags,
  type DrawWorldOptions,
  defaultDebugDrawFlags,
  drawWorld,
} from './debug-draw';
import type { AnyBody, AnyWorld } from './draw-source';
import type { Interpolator } from './interpolation';

/** How one body looks; anything left out keeps the default. */
export interface BodyStyle {
  /** 0xRRGGBB or '#rrggbb' */
  color?: Color | string;
  sprite?: Sprite;
  /** false hides the body */
  visible?: boolean;
}

export interface RenderOptions<W extends AnyWorld = World> {
  /** the canvas to draw on; without one a canvas is created inside `element` */
  canvas?: HTMLCanvasElement;
  element?: HTMLElement;
  /** a World, or a WorkerWorld (drawn from the state its worker publishes) */
  world?: W | null;
  /** CSS background colour */
  background?: string;
  flags?: Partial<DebugDrawFlags>;
  view?: Partial<CameraView>;
  /** device pixels per CSS pixel; default window.devicePixelRatio */
  pixelRatio?: number;
}

export interface DrawEvent {
  render: Render<AnyWorld>;
  context: CanvasRenderingContext2D;
  /**
   * 'afterDraw': the context maps world metres (y up) and `pixel` is one CSS pixel in metres;
   * 'beforeDraw' and 'overlay': the context maps CSS pixels (y down) and `pixel` is 1.
   */
  pixel: number;
}

export interface RenderEvents {
  beforeDraw: DrawEvent;
  afterDraw: DrawEvent;
  overlay: DrawEvent;
}

function parseColor(color: Color | string): Color | undefined {
  if (typeof color === 'number') return color;
  const m = /^#?([0-9a-f]{6})$/i.exec(color.trim());
  return m ? Number.parseInt(m[1], 16) : undefined;
}

/**
 * Draws a world on a 2D canvas through the DebugDraw interface: shapes (filled or wireframe), AABBs,
 * contacts, joints, velocities, centres of mass, sleeping bodies tinted, per-body colours and sprites.
 * The canvas follows its CSS size at the device pixel ratio (HiDPI); the camera pans and zooms.
 * It draws a World on this thread or a WorkerWorld alike, through their drawing sources.
 */
export class Render<W extends AnyWorld = World> {
  readonly canvas: HTMLCanvasElement;
  readonly context: CanvasRenderingContext2D;
  readonly camera: Camera;
  flags: DebugDrawFlags;
  world: W | null;
  background: string;
  /** device pixels per CSS pixel; null follows window.devicePixelRatio */
  pixelRatio: number | null;
  private readonly emitter = new Emitter<RenderEvents>();
  private readonly debugDraw: CanvasDebugDraw;
  private readonly styles = new WeakMap<AnyBody, { color?: Color; sprite?: Sprite; visible: boolean }>();
  private readonly ownsCanvas: boolean;

  constructor(options: RenderOptions<W> = {}) {
    requireBrowser('new Render()', 'Path2D');
    if (options.canvas) {
      if (typeof options.canvas.getContext !== 'function') {
        throw new FulcrumError(
          'options.canvas must be an HTML canvas element, got an object without getContext',
        );
      }
      this.canvas = options.canvas;
      this.ownsCanvas = false;
    } else {
      requireBrowser('new Render()', 'document');
      this.canvas = document.createElement('canvas');
      this.canvas.style.width = '100%';
      this.canvas.style.height = '100%';
      this.canvas.style.display = 'block';
      (options.element ?? document.body).appendChild(this.canvas);
      this.ownsCanvas = true;
    }
    const context = this.canvas.getContext('2d');
    if (!context) throw new FulcrumError('options.canvas has no 2D context (getContext("2d") gave null)');
    this.context = context;
    this.debugDraw = new CanvasDebugDraw(context);
    this.debugDraw.styleOf = (body) => this.styles.get(body);
    this.camera = new Camera(options.view);
    this.flags = { ...defaultDebugDrawFlags, ...options.flags };
    this.world = options.world ?? null;
    this.background = options.background ?? '#15171d';
    this.pixelRatio = options.pixelRatio ?? null;
    this.resize();
  }

  on<K extends keyof RenderEvents>(event: K, handler: (e: RenderEvents[K]) => void): () => void {
    return this.emitter.on(event, handler);
  }

  /** Sets (or with null clears) how a body looks. */
  setBodyStyle(body: AnyBody, style: BodyStyle | null): void {
    if (style === null) {
      this.styles.delete(body);
      return;
    }
    const color = style.color === undefined ? undefined : parseColor(style.color);
    this.styles.set(body, { color, sprite: style.sprite, visible: style.visible ?? true });
  }

  getBodyStyle(body: AnyBody): BodyStyle | undefined {
    return this.styles.get(body);
  }

  /** The device pixel ratio in use. */
  get ratio(): number {
    return this.pixelRatio ?? (typeof window === 'undefined' ? 1 : window.devicePixelRatio || 1);
  }

  /**
   * Matches the canvas' backing store to its CSS size times the pixel ratio, and the camera's
   * viewport to its CSS size. Returns true when something changed. `draw` calls it every frame.
   */
  resize(): boolean {
    const canvas = this.canvas;
    const cssWidth = canvas.clientWidth || canvas.width || 300;
    const cssHeight = canvas.clientHeight || canvas.height || 150;
    const ratio = this.ratio;
    const width = Math.max(1, Math.round(cssWidth * ratio));
    const height = Math.max(1, Math.round(cssHeight * ratio));
    let changed = false;
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
      changed = true;
    }
    if (this.camera.width !== cssWidth || this.camera.height !== cssHeight) {
      this.camera.setViewport(cssWidth, cssHeight);
      changed = true;
    }
    return changed;
  }

  /** Maps CSS pixels (y down) on the context. */
  setScreenTransform(): void {
    const r = this.ratio;
    this.context.setTransform(r, 0, 0, r, 0, 0);
  }

  /** Maps world metres (y up) on the context, through the camera. */
  setWorldTransform(): void {
    const r = this.ratio;
    const cam = this.camera;
    const s = cam.scale;
    this.context.setTransform(
      r * s,
      0,
      0,
      -r * s,
      r * (cam.width / 2 - cam.center.x * s),
      r * (cam.height / 2 + cam.center.y * s),
    );
  }

  worldToScreen(p: Vec2): Vec2 {
    return this.camera.worldToScreen(p);
  }

  /** From a mouse or touch event's clientX/clientY to world metres (see `clientToCanvas`). */
  clientToWorld(clientX: number, clientY: number): Vec2 {
    const p = clientToCanvas(this.canvas, clientX, clientY);
    return this.camera.screenToWorld(p.x, p.y);
  }

  /**
   * Draws the world. With an interpolator, bodies are drawn between their last two states (a worker
   * world's: the two its worker published last).
   */
  draw(interpolator?: Interpolator | null): void {
    this.resize();
    const ctx = this.context;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.globalAlpha = 1;
    ctx.fillStyle = this.background;
    ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
    this.setScreenTransform();
    this.emitter.emit('beforeDraw', { render: this, context: ctx, pixel: 1 });
    this.setWorldTransform();
    const pixel = 1 / this.camera.scale;
    const world = this.world;
    if (world) {
      this.debugDraw.pixel = pixel;
      drawWorld(world, this.debugDraw, this.flags, {
        transformOf: interpolator ? (body, out) => interpolator.transformOf(body, out) : undefined,
        colorOf: (body) => this.styles.get(body)?.color,
      } satisfies DrawWorldOptions);
      this.debugDraw.flush();
    }
    ctx.lineWidth = pixel;
    this.emitter.emit('afterDraw', { render: this, context: ctx, pixel });
    this.setScreenTransform();
    this.emitter.emit('overlay', { render: this, context: ctx, pixel: 1 });
  }

  /** Removes the canvas if the Render created it, and every handler. */
  destroy(): void {
    this.emitter.clear();
    if (this.ownsCanvas) this.canvas.remove();
  }
}

/**
 * CSS pixel coordinates inside a canvas' layout box from a pointer's clientX/clientY. Correct when
 * the page is scrolled (both are viewport coordinates), zoomed, or the canvas is scaled by CSS
 * transforms (the bounding rectangle is the scaled box, clientWidth the layout width).
 */
export function clientToCanvas(canvas: HTMLElement, clientX: number, clientY: number): Vec2 {
  const rect = canvas.getBoundingClientRect();
  // offsetWidth: the unscaled layout width, border included, like the bounding rectangle's
  const sx = rect.width > 0 ? (canvas.offsetWidth || rect.width) / rect.width : 1;
  const sy = rect.height > 0 ? (canvas.offsetHeight || rect.height) / rect.height : 1;
  // clientLeft/Top: the border width, outside the drawing area
  return {
    x: (clientX - rect.left) * sx - canvas.clientLeft,
    y: (clientY - rect.top) * sy - canvas.clientTop,
  };
}
