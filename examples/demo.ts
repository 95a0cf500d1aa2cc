/** What a demo of the gallery is: a function that builds a world, plus a title and a camera. */
import type { AnyWorld, CameraView, DebugDrawFlags, Pointer, Render, Runner } from '../src/render/index';

export interface DemoContext {
  render: Render<AnyWorld>;
  runner: Runner<AnyWorld>;
  pointer: Pointer<AnyWorld>;
  /** the stage element (holds the canvas); a demo may add its own canvas here */
  stage: HTMLElement;
  /** a layer over the stage for the demo's own buttons and text */
  ui: HTMLElement;
  /**
   * true when the demo runs as a thumbnail on the landing view: drawn small, stepped by the landing
   * view, its buttons and panels in detached elements. It takes no keyboard (the page's keys scroll it).
   */
  preview: boolean;
  /** registers a clean-up to run when the demo ends (unsubscribe functions, timers) */
  track(cleanup: () => void): void;
  /** a line of text under the title: scores, counters, hints */
  setStatus(text: string): void;
  /** adds a button to the demo's layer */
  button(label: string, onClick: () => void): HTMLButtonElement;
  /** hides the gallery's canvas renderer: the demo draws the world itself */
  useExternalRenderer(): void;
}

export interface DemoInstance {
  /** a World on the page's thread, or a WorkerWorld (fulcrum/worker) stepped in a worker */
  world: AnyWorld;
  /** extra state the e2e tests and curious people can read from window.gallery.instance */
  [key: string]: unknown;
  dispose?(): void;
}

export interface Demo {
  id: string;
  title: string;
  description: string;
  view: CameraView;
  /**
   * Half the width of the world the view must show: on a canvas too narrow for it at the view's
   * height (a phone held upright), the view zooms out until it fits, keeping its lower edge (the
   * ground stays at the bottom) or, with fitAnchor 'center', its centre.
   */
  fitWidth?: number;
  fitAnchor?: 'bottom' | 'center';
  flags?: Partial<DebugDrawFlags>;
  /** false for a demo whose own renderer ignores the gallery's draw switches: they are hidden */
  drawSwitches?: boolean;
  /** steps one frame may take at most (default 4) */
  maxStepsPerFrame?: number;
  /** builds the demo; a worker world's demo resolves once its worker runs */
  create(ctx: DemoContext): DemoInstance | Promise<DemoInstance>;
}
