/** Small helpers the demos share. */
import { type Body, Shape, type ShapeDef, type Transform, type Vec2, type World } from '../src/index';
import type { AnyWorld, Runner } from '../src/render/index';
import type { DemoContext } from './demo';

/** A static ground box whose top face is at y = top. */
export function ground(world: World, halfWidth: number, top = 0, centerX = 0): Body {
  const body = world.createBody({ position: { x: centerX, y: top - 0.5 } });
  body.createShape(Shape.box(halfWidth, 0.5), { friction: 0.6 });
  return body;
}

/** A dynamic box. */
export function box(
  world: World,
  position: Vec2,
  halfWidth: number,
  halfHeight: number,
  def?: ShapeDef,
  angle = 0,
): Body {
  const body = world.createBody({ type: 'dynamic', position, angle });
  body.createShape(Shape.box(halfWidth, halfHeight), def);
  return body;
}

/** A dynamic ball. */
export function ball(world: World, position: Vec2, radius: number, def?: ShapeDef): Body {
  const body = world.createBody({ type: 'dynamic', position });
  body.createShape(Shape.circle(radius), def);
  return body;
}

/** Vertices of a regular polygon around the origin. */
export function regularPolygon(sides: number, radius: number, phase = Math.PI / 2): Vec2[] {
  const points: Vec2[] = [];
  for (let i = 0; i < sides; i++) {
    const a = phase + (2 * Math.PI * i) / sides;
    points.push({ x: radius * Math.cos(a), y: radius * Math.sin(a) });
  }
  return points;
}

/** Draws text at a world point, upright, in CSS pixels (inside an 'afterDraw' handler). */
export function worldText(
  context: CanvasRenderingContext2D,
  pixel: number,
  p: Vec2,
  text: string,
  color = '#d8dce4',
  size = 13,
): void {
  context.save();
  context.translate(p.x, p.y);
  context.scale(pixel, -pixel);
  context.fillStyle = color;
  context.font = `${size}px system-ui, sans-serif`;
  context.textAlign = 'center';
  context.textBaseline = 'middle';
  context.fillText(text, 0, 0);
  context.restore();
}

const scratch: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };

/** Where the runner draws a body's origin this frame (between its last two states). */
export function drawnPosition(runner: Runner<AnyWorld>, body: Body): Vec2 {
  if (!runner.interpolate || !body.isValid) return body.position;
  const t = runner.interpolator.transformOf(body, scratch);
  return { x: t.p.x, y: t.p.y };
}

/**
 * A camera that eases towards `target()` (a world point, read after each step) by `rate` of the way
 * each step, drawn between its last two places as the bodies are: it moves with the simulation, not
 * with the frame rate, so the picture at a given step is the same on every display. `active()` false
 * leaves the camera to the user. Returns the clean-up.
 */
export function followWithCamera(
  ctx: DemoContext,
  world: World,
  target: () => Vec2,
  rate: number,
  active: () => boolean = () => true,
): () => void {
  const camera = ctx.render.camera;
  let previous = { ...camera.center };
  let current = { ...camera.center };
  const stop = world.on('postStep', () => {
    if (!active()) return;
    const to = target();
    previous = current;
    current = { x: current.x + (to.x - current.x) * rate, y: current.y + (to.y - current.y) * rate };
  });
  const stopDraw = ctx.render.on('beforeDraw', () => {
    if (!active()) {
      previous = { ...camera.center };
      current = previous;
      return;
    }
    const t = ctx.runner.interpolate ? ctx.runner.alpha : 1;
    camera.center = {
      x: previous.x + (current.x - previous.x) * t,
      y: previous.y + (current.y - previous.y) * t,
    };
  });
  return () => {
    stop();
    stopDraw();
  };
}

/** Calls `handler(down)` while any of `keys` is held; returns the clean-up. */
export function onKeys(keys: string[], handler: (key: string, down: boolean) => void): () => void {
  const listener = (down: boolean) => (e: KeyboardEvent) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    if (!keys.includes(e.key) || e.repeat) return;
    e.preventDefault();
    handler(e.key, down);
  };
  const onDown = listener(true);
  const onUp = listener(false);
  window.addEventListener('keydown', onDown);
  window.addEventListener('keyup', onUp);
  return () => {
    window.removeEventListener('keydown', onDown);
    window.removeEventListener('keyup', onUp);
  };
}

/**
 * The step hook the e2e tests drive a paused demo with: takes steps by hand, as the Step button does
 * (each one drawn), until `until()` is true or `limit` steps were taken; returns the steps taken.
 */
export function stepHook(runner: Runner<AnyWorld>): (limit: number, until?: () => boolean) => number {
  return (limit, until) => {
    let n = 0;
    while (n < limit && !(until?.() ?? false)) {
      runner.step();
      n++;
    }
    return n;
  };
}

/**
 * Keeps a pointer's events on the canvas until it comes up, wherever it goes: for a 'down' the demo
 * handles itself (the Pointer captures only the pointers it drags or pans with).
 */
export function capturePointer(ctx: DemoContext, event: PointerEvent): void {
  try {
    ctx.render.canvas.setPointerCapture(event.pointerId);
  } catch {
    // a synthetic event has no active pointer to capture
  }
}

/**
 * Fills a disc of `radius` at (x, y) with `skin`, a gradient laid out for the unit disc at the
 * origin, so that one gradient serves balls of every size.
 */
export function fillSkinnedDisc(
  c: CanvasRenderingContext2D,
  x: number,
  y: number,
  radius: number,
  skin: CanvasGradient,
): void {
  c.save();
  c.translate(x, y);
  c.scale(radius, radius);
  c.fillStyle = skin;
  c.beginPath();
  c.arc(0, 0, 1, 0, 2 * Math.PI);
  c.fill();
  c.restore();
}
