/**
 * A demo run small, on a card of the landing view: its own `create` in a preview context (no keyboard,
 * no pointer, its buttons and panels in detached elements), on the card's canvas, stepped only when
 * the landing view says so.
 */
import { type AnyWorld, defaultDebugDrawFlags, Pointer, Render, Runner } from '../src/render/index';
import type { Demo, DemoContext, DemoInstance } from './demo';

/** Device pixels per CSS pixel at most: a thumbnail is small, a 4K screen's ratio of 3 buys nothing. */
const MAX_RATIO = 2;

export class DemoThumbnail {
  readonly render: Render<AnyWorld>;
  readonly runner: Runner<AnyWorld>;
  private readonly cleanups: (() => void)[] = [];
  private instance: DemoInstance | null = null;
  private disposed = false;

  /** Builds `demo` on `canvas` (laid out already: the camera takes its size) and draws it once. */
  constructor(
    readonly demo: Demo,
    canvas: HTMLCanvasElement,
  ) {
    this.render = new Render<AnyWorld>({
      canvas,
      pixelRatio: Math.min(MAX_RATIO, window.devicePixelRatio || 1),
    });
    this.runner = new Runner<AnyWorld>({ render: this.render });
    // a pointer that hears nothing: a demo may subscribe to it, but the card's clicks, touches (the page
    // scrolls) and context menu (open in a new tab) are the link's
    const pointer = new Pointer<AnyWorld>({ render: this.render });
    pointer.destroy();
    canvas.style.touchAction = '';
    this.render.flags = { ...defaultDebugDrawFlags, ...demo.flags };
    this.render.resize();
    this.render.camera.setView(demo.view);
    const stage = document.createElement('div');
    const ui = document.createElement('div');
    const ctx: DemoContext = {
      render: this.render,
      runner: this.runner,
      pointer,
      stage,
      ui,
      preview: true,
      track: (cleanup) => this.cleanups.push(cleanup),
      setStatus: () => {},
      button: (label) => {
        const b = document.createElement('button');
        b.textContent = label;
        ui.append(b);
        return b;
      },
      useExternalRenderer: () => {
        throw new Error(`${demo.id}: a demo with its own renderer has no live thumbnail`);
      },
    };
    const made = demo.create(ctx);
    if (made instanceof Promise)
      throw new Error(`${demo.id}: a demo made asynchronously has no live thumbnail`);
    this.instance = made;
    this.runner.setWorld(made.world);
    this.render.draw(null);
  }

  /** steps taken since the thumbnail was made */
  get steps(): number {
    return this.runner.stepCount;
  }

  /** One step, drawn. */
  step(): void {
    if (!this.disposed) this.runner.step();
  }

  /** Lets the world go; the canvas keeps the last picture. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    for (const cleanup of this.cleanups.splice(0).reverse()) cleanup();
    this.instance?.dispose?.();
    this.instance = null;
    this.runner.setWorld(null);
    this.render.world = null;
    this.render.destroy();
  }
}
