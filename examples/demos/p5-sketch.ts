import type p5 from 'p5';
import { type Body, Shape, type Transform, World } from '../../src/index';
import type { Demo } from '../demo';

/** p5 fill colours of the dynamic bodies, in turn */
const PALETTE = ['#f2a541', '#e4572e', '#76b041', '#2fb7d4', '#b07bd8', '#f0d35b'];
/** most bodies the clicks may add; past it the oldest goes */
const MAX_ADDED = 200;

/**
 * A p5.js sketch (instance mode) that draws a Fulcrum world. Fulcrum works in metres with y up, p5 in
 * pixels with y down: a world point (x, y) is drawn at pixel (width / 2 + x * scale,
 * height - (y + 1) * scale), and an angle a is drawn as rotate(-a).
 *
 * The world is stepped at a fixed 1/60 s by the gallery's Runner (so Pause, Step and Speed work); the
 * sketch only draws, blending the last two steps with the runner's interpolator. On a page of your own,
 * `new Runner({ world }).start()` from fulcrum/render does the same, or an accumulator in draw():
 * `acc += p.deltaTime / 1000; while (acc >= dt) { world.step(dt); acc -= dt; }`.
 */
export const p5Demo: Demo = {
  id: 'p5',
  title: 'p5.js sketch',
  description:
    'A p5.js sketch in instance mode draws the bodies with circle, line and beginShape/vertex; Fulcrum steps the world at a fixed 1/60 s. Click to drop a ball; drag to pour boxes.',
  view: { center: { x: 0, y: 7 }, halfHeight: 8 },
  drawSwitches: false,
  create: (ctx) => {
    ctx.useExternalRenderer();
    const world = new World();
    const ground = world.createBody({ position: { x: 0, y: -0.5 } });
    ground.createShape(Shape.box(9, 0.5), { friction: 0.6 });
    ground.createShape(Shape.box(0.3, 4, { x: -9.3, y: 4 }), { friction: 0.6 });
    ground.createShape(Shape.box(0.3, 4, { x: 9.3, y: 4 }), { friction: 0.6 });
    const colorOf = new Map<Body, string>();
    const added: Body[] = [];
    const addBox = (x: number, y: number, half: number, angle = 0) => {
      const body = world.createBody({ type: 'dynamic', position: { x, y }, angle });
      body.createShape(Shape.box(half, half), { friction: 0.5 });
      colorOf.set(body, PALETTE[colorOf.size % PALETTE.length]);
      return body;
    };
    const addBall = (x: number, y: number, radius: number) => {
      const body = world.createBody({ type: 'dynamic', position: { x, y } });
      body.createShape(Shape.circle(radius), { friction: 0.5, restitution: 0.3 });
      colorOf.set(body, PALETTE[colorOf.size % PALETTE.length]);
      return body;
    };
    const keep = (body: Body) => {
      added.push(body);
      if (added.length > MAX_ADDED) {
        const oldest = added.shift() as Body;
        colorOf.delete(oldest);
        world.destroyBody(oldest);
      }
    };
    for (let i = 0; i < 6; i++) addBox(-5 + i * 2, 3 + (i % 3) * 1.5, 0.5, i * 0.3);
    for (let i = 0; i < 5; i++) addBall(-4 + i * 2, 8 + (i % 2), 0.4 + 0.1 * (i % 3));

    const state = { frames: 0, drawnStep: -1, scale: 1, width: 0, height: 0 };
    const canvas = document.createElement('canvas');
    canvas.dataset.renderer = 'p5';
    ctx.stage.prepend(canvas);
    let sketch: p5 | null = null;
    let disposed = false;

    const makeSketch = (p: p5) => {
      const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
      /** pixels per metre: the stage shows 16 m of height */
      let scale = 1;
      const toPixelX = (x: number) => p.width / 2 + x * scale;
      const toPixelY = (y: number) => p.height - (y + 1) * scale;
      const toWorld = (px: number, py: number) => ({
        x: (px - p.width / 2) / scale,
        y: (p.height - py) / scale - 1,
      });
      const fitStage = () => {
        p.resizeCanvas(ctx.stage.clientWidth, ctx.stage.clientHeight);
        scale = p.height / 16;
        Object.assign(state, { scale, width: p.width, height: p.height });
      };
      let lastPour: { x: number; y: number } | null = null;
      const onCanvas = (event?: MouseEvent) => event?.target === canvas;

      p.setup = () => {
        p.createCanvas(ctx.stage.clientWidth, ctx.stage.clientHeight, p.P2D, canvas);
        fitStage();
      };
      p.mousePressed = (event) => {
        if (!onCanvas(event)) return;
        const at = toWorld(p.mouseX, p.mouseY);
        keep(addBall(at.x, at.y, 0.45));
        lastPour = at;
      };
      p.mouseDragged = (event) => {
        if (!lastPour || !onCanvas(event)) return;
        const at = toWorld(p.mouseX, p.mouseY);
        // a box for every metre the pointer travels
        if (Math.hypot(at.x - lastPour.x, at.y - lastPour.y) < 1) return;
        keep(addBox(at.x, at.y, 0.3 + 0.1 * (added.length % 3), added.length * 0.7));
        lastPour = at;
      };
      p.mouseReleased = () => {
        lastPour = null;
      };
      p.draw = () => {
        if (p.width !== ctx.stage.clientWidth || p.height !== ctx.stage.clientHeight) fitStage();
        p.background('#15171d');
        p.strokeWeight(1.5);
        for (const body of world.bodies) {
          const t = ctx.runner.interpolator.transformOf(body, xf);
          p.push();
          p.translate(toPixelX(t.p.x), toPixelY(t.p.y));
          // y flips, so a counter-clockwise angle turns clockwise on screen
          p.rotate(-Math.atan2(t.q.s, t.q.c));
          const color = colorOf.get(body) ?? '#5f7a66';
          p.fill(color);
          p.stroke(body.isAwake || body.type === 'static' ? '#0d0f13' : '#80848c');
          for (const shape of body.shapes) {
            const g = shape.geometry;
            if (g.type === 'circle') {
              const cx = g.center.x * scale;
              const cy = -g.center.y * scale;
              p.circle(cx, cy, 2 * g.radius * scale);
              p.line(cx, cy, cx + g.radius * scale, cy);
            } else if (g.type === 'polygon') {
              p.beginShape();
              for (const v of g.vertices) p.vertex(v.x * scale, -v.y * scale);
              p.endShape(p.CLOSE);
            }
          }
          p.pop();
        }
        state.frames++;
        state.drawnStep = ctx.runner.stepCount;
      };
    };

    import('p5')
      .then(({ default: P5 }) => {
        if (disposed) return;
        sketch = new P5(makeSketch, ctx.stage);
      })
      .catch((error: unknown) => console.error(error));

    return {
      world,
      state,
      dispose: () => {
        disposed = true;
        sketch?.remove();
        sketch = null;
        canvas.remove();
      },
    };
  },
};
