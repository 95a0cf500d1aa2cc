import type { Body } from '../api/body';
import type { World } from '../api/world';
import { Emitter } from '../core/emitter';
import { Limits } from '../core/limits';
import { testPoint } from '../geometry/raycast';
import type { MouseJoint } from '../joints/mouse-joint';
import type { Transform, Vec2 } from '../math/vec2';
import type { WorkerBody, WorkerJoint } from '../worker/handles';
import type { WorkerWorld } from '../worker/worker-world';
import type { AnyWorld } from './draw-source';
import { clientToCanvas, type Render } from './render';
import { isWorkerWorld } from './source-of';

/**
 * Whether `world` is a worker world that has stopped (its worker failed, or it was terminated): its
 * commands throw, so a drag in it ends quietly rather than throw out of a DOM event handler.
 */
function stopped(world: AnyWorld): boolean {
  return isWorkerWorld(world) && world.failure !== null;
}

/** The body handle of a world type: a World's Body, a WorkerWorld's WorkerBody. */
export type BodyOf<W extends AnyWorld> = W extends WorkerWorld ? WorkerBody : Body;

export interface PointerOptions<W extends AnyWorld = World> {
  render: Render<W>;
  /** the world to drag in; default: the render's world */
  world?: () => W | null;
  /** which bodies may be dragged (default: every dynamic body) */
  filter?: (body: BodyOf<W>) => boolean;
  /**
   * drag force limit per kilogram of the dragged body, N/kg (default 1000), scaled by gravity over
   * 10 m/s^2; a worker world's body reads its mass as of the last step
   */
  forcePerMass?: number;
  /** stiffness of the drag spring, Hz (default 5) */
  hertz?: number;
  dampingRatio?: number;
  /** drag on empty space pans the camera (default true) */
  pan?: boolean;
  /** the wheel and two-finger pinch zoom (default true) */
  zoom?: boolean;
}

export interface DragEvent<W extends AnyWorld = World> {
  body: BodyOf<W>;
  /** world point under the pointer */
  point: Vec2;
}

export interface PointerEventInfo {
  /** world point under the pointer */
  point: Vec2;
  /** CSS pixels in the canvas */
  screen: Vec2;
  /** the original DOM event; call preventDefault() in 'down' to stop the drag and pan */
  event: PointerEvent;
  /** true once a handler asked the pointer to leave this gesture alone */
  handled: boolean;
}

export interface PointerEvents<W extends AnyWorld = World> {
  dragStart: DragEvent<W>;
  dragMove: DragEvent<W>;
  dragEnd: DragEvent<W>;
  down: PointerEventInfo;
  move: PointerEventInfo;
  up: PointerEventInfo;
}

/**
 * Mouse, pen and touch on a Render's canvas: drag dynamic bodies through a mouse joint, pan on empty
 * space, zoom with the wheel or a pinch. Pointer positions go through getBoundingClientRect, so they
 * stay right when the page is scrolled, zoomed or the canvas is scaled by CSS. A worker world's
 * bodies are picked from the shapes and poses known on this thread and dragged by a mouse joint whose
 * target moves by command, applied at the worker's next step.
 */
export class Pointer<W extends AnyWorld = World> {
  readonly render: Render<W>;
  enabled = true;
  filter: (body: BodyOf<W>) => boolean;
  forcePerMass: number;
  hertz: number;
  dampingRatio: number;
  pan: boolean;
  zoom: boolean;
  /** the body being dragged, if any */
  body: BodyOf<W> | null = null;
  /** world point of the primary pointer, last seen */
  point: Vec2 | null = null;
  private joint: MouseJoint | WorkerJoint | null = null;
  private jointWorld: W | null = null;
  private dragPointer: number | null = null;
  private panPointer: number | null = null;
  private lastScreen: Vec2 = { x: 0, y: 0 };
  private readonly touches = new Map<number, Vec2>();
  private pinchDistance = 0;
  private readonly emitter = new Emitter<PointerEvents<W>>();
  private readonly getWorld: () => W | null;
  private readonly listeners: [string, EventListener, AddEventListenerOptions?][] = [];

  constructor(options: PointerOptions<W>) {
    this.render = options.render;
    this.getWorld = options.world ?? (() => this.render.world);
    this.filter = options.filter ?? ((body) => body.type === 'dynamic');
    this.forcePerMass = options.forcePerMass ?? 1000;
    this.hertz = options.hertz ?? 5;
    this.dampingRatio = options.dampingRatio ?? 0.7;
    this.pan = options.pan ?? true;
    this.zoom = options.zoom ?? true;
    const canvas = this.render.canvas;
    canvas.style.touchAction = 'none';
    this.listen('pointerdown', (e) => this.onDown(e as PointerEvent));
    this.listen('pointermove', (e) => this.onMove(e as PointerEvent));
    this.listen('pointerup', (e) => this.onUp(e as PointerEvent));
    this.listen('pointercancel', (e) => this.onUp(e as PointerEvent));
    this.listen('wheel', (e) => this.onWheel(e as WheelEvent), { passive: false });
    this.listen('contextmenu', (e) => e.preventDefault());
  }

  on<K extends keyof PointerEvents<W>>(event: K, handler: (e: PointerEvents<W>[K]) => void): () => void {
    return this.emitter.on(event, handler);
  }

  private listen(type: string, fn: EventListener, options?: AddEventListenerOptions): void {
    this.render.canvas.addEventListener(type, fn, options);
    this.listeners.push([type, fn, options]);
  }

  /** CSS pixels in the canvas of a pointer event */
  toScreen(e: { clientX: number; clientY: number }): Vec2 {
    return clientToCanvas(this.render.canvas, e.clientX, e.clientY);
  }

  /** world point of a pointer event */
  toWorld(e: { clientX: number; clientY: number }): Vec2 {
    const p = this.toScreen(e);
    return this.render.camera.screenToWorld(p.x, p.y);
  }

  /** The draggable body under a world point (the last created wins), or null. */
  pick(point: Vec2): BodyOf<W> | null {
    const world = this.getWorld();
    if (!world) return null;
    if (isWorkerWorld(world)) return this.pickWorker(world, point) as BodyOf<W> | null;
    let found: Body | null = null;
    for (const body of world.bodies) {
      if (!this.filter(body as BodyOf<W>)) continue;
      for (const shape of body.shapes) {
        if (shape.isSensor) continue;
        if (shape.testPoint(point)) {
          found = body;
          break;
        }
      }
    }
    return found as BodyOf<W> | null;
  }

  /** pick in a worker world: its shapes at the poses its worker published last */
  private pickWorker(world: WorkerWorld, point: Vec2): WorkerBody | null {
    const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
    let found: WorkerBody | null = null;
    for (const body of world.bodies) {
      if (!this.filter(body as BodyOf<W>)) continue;
      body.readPose(xf);
      for (const shape of body.shapeList) {
        if (shape.isSensor) continue;
        if (testPoint(shape.geometry, xf, point.x, point.y)) {
          found = body;
          break;
        }
      }
    }
    return found;
  }

  private info(e: PointerEvent): PointerEventInfo {
    const screen = this.toScreen(e);
    return { point: this.render.camera.screenToWorld(screen.x, screen.y), screen, event: e, handled: false };
  }

  private onDown(e: PointerEvent): void {
    if (!this.enabled) return;
    const info = this.info(e);
    if (e.pointerType === 'touch') this.touches.set(e.pointerId, info.screen);
    this.point = info.point;
    this.emitter.emit('down', info);
    if (info.handled || e.defaultPrevented) return;
    e.preventDefault();
    try {
      this.render.canvas.setPointerCapture(e.pointerId);
    } catch {
      // a synthetic event has no active pointer to capture
    }
    if (this.touches.size === 2) {
      // second finger: end any drag and pinch instead
      this.endDrag();
      this.panPointer = null;
      this.pinchDistance = this.touchDistance();
      return;
    }
    if (this.dragPointer !== null || this.panPointer !== null) return;
    if (e.button !== 0 && e.pointerType === 'mouse') {
      if (this.pan) this.startPan(e, info.screen);
      return;
    }
    const body = this.pick(info.point);
    if (body && this.startDrag(body, info.point)) {
      this.dragPointer = e.pointerId;
    } else if (this.pan) {
      this.startPan(e, info.screen);
    }
  }

  private startPan(e: PointerEvent, screen: Vec2): void {
    this.panPointer = e.pointerId;
    this.lastScreen = screen;
  }

  /**
   * Starts dragging `body` from world point `point`; false when it is not in the current world (or
   * that world's worker has stopped).
   */
  startDrag(body: BodyOf<W>, point: Vec2): boolean {
    const world = this.getWorld();
    if (!world || body.world !== world || !body.isValid || stopped(world)) return false;
    this.endDrag();
    const gravity = world.gravity;
    const g = Math.max(1, Math.sqrt(gravity.x * gravity.x + gravity.y * gravity.y));
    // held to the accepted range: a heavy body under strong gravity would ask for more
    const maxForce = Math.min(Limits.FORCE, this.forcePerMass * body.mass * (g / 10));
    const def = {
      type: 'mouse',
      target: point,
      maxForce,
      hertz: this.hertz,
      dampingRatio: this.dampingRatio,
    } as const;
    if (isWorkerWorld(world)) this.joint = world.createJoint({ ...def, body: body as WorkerBody });
    else this.joint = world.createJoint({ ...def, body: body as Body });
    this.jointWorld = world;
    body.setAwake(true);
    this.body = body;
    this.emitter.emit('dragStart', { body, point });
    return true;
  }

  /** Ends the drag, if any. */
  endDrag(): void {
    const body = this.body;
    const joint = this.joint;
    const world = this.jointWorld;
    this.body = null;
    this.joint = null;
    this.jointWorld = null;
    this.dragPointer = null;
    if (!body || !joint || !world) return;
    // the body (and with it the joint) may have been destroyed, or the world swapped, meanwhile
    if (joint.isValid && world === this.getWorld() && !stopped(world)) {
      if (isWorkerWorld(world)) world.destroyJoint(joint as WorkerJoint);
      else (world as World).destroyJoint(joint as MouseJoint);
    }
    this.emitter.emit('dragEnd', { body, point: this.point ?? body.position });
  }

  private onMove(e: PointerEvent): void {
    const info = this.info(e);
    if (e.pointerType === 'touch' && this.touches.has(e.pointerId)) {
      this.touches.set(e.pointerId, info.screen);
      if (this.touches.size === 2 && this.zoom) {
        const d = this.touchDistance();
        if (this.pinchDistance > 0 && d > 0) {
          const c = this.touchCenter();
          this.render.camera.zoomAt(c.x, c.y, d / this.pinchDistance);
        }
        this.pinchDistance = d;
        return;
      }
    }
    this.point = info.point;
    this.emitter.emit('move', info);
    if (e.pointerId === this.dragPointer) {
      this.updateDrag(info.point);
    } else if (e.pointerId === this.panPointer) {
      this.render.camera.pan(info.screen.x - this.lastScreen.x, info.screen.y - this.lastScreen.y);
      this.lastScreen = info.screen;
    }
  }

  private updateDrag(point: Vec2): void {
    const body = this.body;
    if (!body) return;
    if (!body.isValid || this.jointWorld !== this.getWorld() || stopped(this.jointWorld!)) {
      this.endDrag();
      return;
    }
    this.joint?.setTarget(point);
    body.setAwake(true);
    this.emitter.emit('dragMove', { body, point });
  }

  private onUp(e: PointerEvent): void {
    this.touches.delete(e.pointerId);
    if (this.touches.size < 2) this.pinchDistance = 0;
    const info = this.info(e);
    this.point = info.point;
    this.emitter.emit('up', info);
    if (e.pointerId === this.dragPointer) this.endDrag();
    if (e.pointerId === this.panPointer) this.panPointer = null;
  }

  private onWheel(e: WheelEvent): void {
    if (!this.enabled || !this.zoom) return;
    e.preventDefault();
    const p = this.toScreen(e);
    // output only: a smooth zoom curve
    this.render.camera.zoomAt(p.x, p.y, Math.exp(-e.deltaY * 0.0015));
  }

  private touchDistance(): number {
    const [a, b] = [...this.touches.values()];
    return a && b ? Math.hypot(a.x - b.x, a.y - b.y) : 0;
  }

  private touchCenter(): Vec2 {
    const [a, b] = [...this.touches.values()];
    return { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 };
  }

  /** Removes the listeners and ends any drag. */
  destroy(): void {
    this.endDrag();
    for (const [type, fn, options] of this.listeners)
      this.render.canvas.removeEventListener(type, fn, options);
    this.listeners.length = 0;
    this.emitter.clear();
  }
}
