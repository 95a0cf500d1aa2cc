/**
 * The landing view: a card per demo, in the registry's order, each with its title, a line in plain
 * words and a thumbnail of the demo's own world, drawn small and moving.
 *
 * The cost stays bounded so the page keeps its frame rate on a small machine: a thumbnail's world is
 * built only once its card has been on screen (at most one built per frame), only the thumbnails on
 * screen are stepped, and a frame takes at most MAX_STEPS_PER_FRAME steps in all, one per thumbnail in
 * turn, and stops early once FRAME_BUDGET_MS has gone. With more thumbnails on screen than steps per
 * frame, each moves in slow motion rather than the page stuttering. Heavy scenes are drawn once
 * (a still), demos that draw with a library of their own show a stored picture (see cards.ts).
 */
import { type Card, cardOf } from './cards';
import type { Demo } from './demo';
import { DemoThumbnail } from './thumbnail';

const MAX_STEPS_PER_FRAME = 6;
/** milliseconds of a frame the thumbnails may take before the rest wait for the next one */
const FRAME_BUDGET_MS = 7;

interface CardView {
  demo: Demo;
  card: Card;
  element: HTMLAnchorElement;
  canvas: HTMLCanvasElement | null;
  visible: boolean;
  /** a live thumbnail, while it runs */
  thumbnail: DemoThumbnail | null;
  /** a still drawn, or a live thumbnail made: nothing more to build */
  made: boolean;
}

/** What the e2e tests read of a card's thumbnail. */
export interface ThumbnailState {
  id: string;
  kind: Card['thumbnail']['kind'];
  visible: boolean;
  made: boolean;
  steps: number;
}

export class Landing {
  /** stops the stepping (thumbnails are still built as their cards come on screen) */
  paused = false;
  private views: CardView[] = [];
  private observer: IntersectionObserver | null = null;
  private frame: number | null = null;
  private cursor = 0;

  constructor(
    private readonly grid: HTMLElement,
    private readonly demos: readonly Demo[],
  ) {}

  get shown(): boolean {
    return this.observer !== null;
  }

  /** Builds the cards and starts the thumbnails of those on screen. */
  show(): void {
    if (this.shown) return;
    this.views = this.demos.map((demo) => this.cardView(demo));
    this.grid.replaceChildren(...this.views.map((v) => v.element));
    const observer = new IntersectionObserver(
      (entries) => {
        for (const entry of entries) {
          const view = this.views.find((v) => v.element === entry.target);
          if (view) view.visible = entry.isIntersecting;
        }
      },
      { rootMargin: '40px' },
    );
    for (const view of this.views) observer.observe(view.element);
    this.observer = observer;
    const loop = (): void => {
      this.frame = requestAnimationFrame(loop);
      this.tick();
    };
    this.frame = requestAnimationFrame(loop);
  }

  /** Lets every thumbnail's world go and removes the cards. */
  hide(): void {
    if (!this.shown) return;
    if (this.frame !== null) cancelAnimationFrame(this.frame);
    this.frame = null;
    this.observer?.disconnect();
    this.observer = null;
    for (const view of this.views) view.thumbnail?.dispose();
    this.views = [];
    this.grid.replaceChildren();
  }

  /** Takes `steps` steps on every live thumbnail there is, each drawn (the tests' step hook). */
  advance(steps: number): void {
    for (const view of this.views) {
      for (let i = 0; i < steps; i++) view.thumbnail?.step();
    }
  }

  /** Builds the thumbnails of the cards on screen again, from their first step. */
  restart(): void {
    for (const view of this.views) {
      view.thumbnail?.dispose();
      view.thumbnail = null;
      view.made = false;
    }
    for (const view of this.views) if (view.visible) this.make(view);
  }

  /** The state of every card's thumbnail. */
  thumbnails(): ThumbnailState[] {
    return this.views.map((v) => ({
      id: v.demo.id,
      kind: v.card.thumbnail.kind,
      visible: v.visible,
      made: v.made,
      steps: v.thumbnail?.steps ?? 0,
    }));
  }

  private tick(): void {
    const start = performance.now();
    const waiting = this.views.find((v) => v.visible && !v.made);
    if (waiting) this.make(waiting);
    if (this.paused) return;
    const running = this.views.filter((v) => v.visible && v.thumbnail !== null);
    const steps = Math.min(MAX_STEPS_PER_FRAME, running.length);
    for (let i = 0; i < steps && performance.now() - start < FRAME_BUDGET_MS; i++) {
      this.cursor %= running.length;
      running[this.cursor].thumbnail?.step();
      this.cursor++;
    }
  }

  private make(view: CardView): void {
    view.made = true;
    const thumbnail = view.card.thumbnail;
    if (!view.canvas || thumbnail.kind === 'picture') return;
    try {
      if (thumbnail.kind === 'live') {
        view.thumbnail = new DemoThumbnail(view.demo, view.canvas);
      } else if (!this.copyStill(view, thumbnail.from)) {
        const source =
          thumbnail.from === undefined ? view.demo : this.demos.find((d) => d.id === thumbnail.from);
        if (!source) throw new Error(`${view.demo.id}: no demo ${thumbnail.from} to draw`);
        new DemoThumbnail(source, view.canvas).dispose();
      }
    } catch (error) {
      // a card without its picture is still a link to its demo
      console.error(error);
    }
  }

  /**
   * Draws the still of demo `from` on the card, copied from that demo's own card if it is drawn already:
   * the 5,000-body scene takes a fifth of a second to build, once is enough. False if it is not.
   */
  private copyStill(view: CardView, from: string | undefined): boolean {
    const drawn = this.views.find((v) => v.demo.id === from && v.made && v.card.thumbnail.kind === 'still');
    const canvas = view.canvas;
    if (!drawn?.canvas || !canvas) return false;
    canvas.width = drawn.canvas.width;
    canvas.height = drawn.canvas.height;
    canvas.getContext('2d')?.drawImage(drawn.canvas, 0, 0);
    return true;
  }

  private cardView(demo: Demo): CardView {
    const card = cardOf(demo);
    const element = document.createElement('a');
    element.className = 'card';
    element.href = `#${demo.id}`;
    element.dataset.card = demo.id;
    const frame = document.createElement('div');
    frame.className = 'thumb';
    let canvas: HTMLCanvasElement | null = null;
    if (card.thumbnail.kind === 'picture') {
      const img = document.createElement('img');
      img.src = card.thumbnail.url;
      img.alt = '';
      img.loading = 'lazy';
      img.className = 'thumb-picture';
      frame.append(img);
    } else {
      canvas = document.createElement('canvas');
      canvas.className = 'thumb-picture';
      frame.append(canvas);
    }
    const title = document.createElement('h3');
    title.textContent = demo.title;
    const summary = document.createElement('p');
    summary.textContent = card.summary;
    element.append(frame, title, summary);
    return { demo, card, element, canvas, visible: false, thumbnail: null, made: false };
  }
}
