import type { Application, Container, Graphics } from 'pixi.js';
import { createRandom } from '../../scenes/index';
import { type Body, Shape, type Transform, World } from '../../src/index';
import {
  colors,
  type DebugDrawFlags,
  defaultBodyColor,
  defaultDebugDrawFlags,
  drawWorld,
  mixColor,
} from '../../src/render/index';
import type { Demo } from '../demo';
import { regularPolygon } from '../lib';
import { PixiDebugDraw } from '../pixi-draw';

/**
 * PixiJS draws this world: the engine is only the model. Each body gets one Pixi Graphics built
 * from its shapes once; every frame the demo copies positions and angles (interpolated by the runner)
 * into the Graphics. The gallery's draw switches work through Fulcrum's `drawWorld`, which describes
 * outlines, AABBs, contacts and the rest to a Pixi Graphics (examples/pixi-draw.ts). Fulcrum's canvas
 * renderer is not used.
 */
export const pixiDemo: Demo = {
  id: 'pixi',
  title: 'PixiJS renderer',
  description:
    "The same engine drawn by PixiJS (WebGL, or its canvas renderer without a GPU): one Graphics per body, built once from its shapes; each frame copies body positions and angles into it. Fulcrum is the model, Pixi the view; the draw switches go through Fulcrum's drawWorld onto a Pixi Graphics.",
  view: { center: { x: 0, y: 8 }, halfHeight: 10 },
  create: (ctx) => {
    ctx.useExternalRenderer();
    const world = new World();
    const random = createRandom(17);
    const bin = world.createBody({ position: { x: 0, y: 0 } });
    bin.createShape(Shape.box(12, 0.5, { x: 0, y: -0.5 }));
    bin.createShape(Shape.box(0.5, 9, { x: -12.5, y: 8 }));
    bin.createShape(Shape.box(0.5, 9, { x: 12.5, y: 8 }));
    const paddle = world.createBody({ type: 'kinematic', position: { x: 0, y: 5 }, angularVelocity: 0.8 });
    paddle.createShape(Shape.box(4, 0.2));
    paddle.createShape(Shape.box(0.2, 4));
    for (let i = 0; i < 260; i++) {
      const body = world.createBody({
        type: 'dynamic',
        position: { x: random.range(-10.5, 10.5), y: 10 + i * 0.12 },
        angle: random.range(0, 3),
      });
      const kind = random.int(3);
      body.createShape(
        kind === 0
          ? Shape.circle(random.range(0.2, 0.4))
          : kind === 1
            ? Shape.box(random.range(0.2, 0.4), random.range(0.15, 0.3))
            : Shape.polygon(regularPolygon(3 + random.int(4), random.range(0.25, 0.45))),
        { friction: 0.5, restitution: 0.1 },
      );
    }

    let disposed = false;
    let app: Application | null = null;
    const state = { renderer: 'loading', frames: 0, drawnStep: -1 };
    const views = new Map<Body, Graphics>();

    void (async () => {
      const pixi = await import('pixi.js');
      const application = new pixi.Application();
      await application.init({
        resizeTo: ctx.stage,
        background: '#15171d',
        antialias: true,
        autoDensity: true,
        resolution: window.devicePixelRatio || 1,
        preference: ['webgl', 'canvas'],
        // the e2e test reads the pixels back
        preserveDrawingBuffer: true,
      });
      if (disposed) {
        application.destroy(true);
        return;
      }
      app = application;
      state.renderer = application.renderer.name;
      application.canvas.style.position = 'absolute';
      application.canvas.style.inset = '0';
      application.canvas.dataset.renderer = 'pixi';
      ctx.stage.prepend(application.canvas);
      // bodies (one Graphics each, built once) under an overlay redrawn each frame by drawWorld
      const scene: Container = new pixi.Container();
      const bodyLayer: Container = new pixi.Container();
      const overlay: Graphics = new pixi.Graphics();
      scene.addChild(bodyLayer, overlay);
      application.stage.addChild(scene);
      const overlayDraw = new PixiDebugDraw(overlay);
      const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
      const transformOf = (body: Body, out: Transform) => ctx.runner.interpolator.transformOf(body, out);
      const overlayFlags: DebugDrawFlags = { ...defaultDebugDrawFlags };

      const viewOf = (body: Body): Graphics => {
        let g = views.get(body);
        if (g) return g;
        // drawn white and coloured by its tint, so the sleep tint can come and go
        g = new pixi.Graphics();
        for (const shape of body.shapes) {
          const geometry = shape.geometry;
          if (geometry.type === 'circle') {
            g.circle(geometry.center.x, geometry.center.y, geometry.radius).fill(0xffffff);
            g.moveTo(geometry.center.x, geometry.center.y)
              .lineTo(geometry.center.x + geometry.radius, geometry.center.y)
              .stroke({ color: 0x15171d, width: 0.05 });
          } else if (geometry.type === 'polygon') {
            g.poly(geometry.vertices.flatMap((v) => [v.x, v.y])).fill(0xffffff);
          }
        }
        bodyLayer.addChild(g);
        views.set(body, g);
        return g;
      };

      ctx.track(
        ctx.runner.on('afterFrame', () => {
          const camera = ctx.render.camera;
          camera.setViewport(application.screen.width, application.screen.height);
          const s = camera.scale;
          scene.scale.set(s, -s);
          scene.position.set(camera.width / 2 - camera.center.x * s, camera.height / 2 + camera.center.y * s);
          // the gallery's draw switches: filled shapes here, everything else through drawWorld
          const flags = ctx.render.flags;
          bodyLayer.visible = flags.shapes && !flags.wireframe;
          for (const body of world.bodies) {
            const g = viewOf(body);
            transformOf(body, xf);
            g.position.set(xf.p.x, xf.p.y);
            g.rotation = Math.atan2(xf.q.s, xf.q.c);
            const color = defaultBodyColor(world, body);
            const asleep = body.type === 'dynamic' && !body.isAwake;
            g.tint = asleep && flags.sleeping ? mixColor(color, colors.sleepingTint, 0.6) : color;
          }
          Object.assign(overlayFlags, flags);
          overlayFlags.shapes = flags.shapes && flags.wireframe;
          overlay.clear();
          overlayDraw.pixel = 1 / s;
          drawWorld(world, overlayDraw, overlayFlags, { transformOf });
          state.frames++;
          state.drawnStep = ctx.runner.stepCount;
        }),
      );
    })().catch((error: unknown) => {
      state.renderer = `failed: ${String(error)}`;
      console.error(error);
    });

    return {
      world,
      state,
      dispose: () => {
        disposed = true;
        app?.destroy(true, { children: true });
        app = null;
      },
    };
  },
};
