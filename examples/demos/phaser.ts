import type Phaser from 'phaser';
import { type Body, Shape, type Transform, World } from '../../src/index';
import type { Demo } from '../demo';

/** Phaser world pixels per Fulcrum metre; the camera's zoom fits the scene to the stage */
const PPM = 48;
/** metres of height the camera shows */
const VIEW_HEIGHT = 16;
const COLORS = [0xf2a541, 0xe4572e, 0x76b041, 0x2fb7d4, 0xb07bd8, 0xf0d35b];
/** most crates the clicks may add; past it the oldest goes */
const MAX_ADDED = 150;

/**
 * A Phaser 4 scene whose sprites follow Fulcrum bodies. Phaser's own physics is not configured (no
 * `physics` in the game config, so no Arcade or Matter world exists): Fulcrum does all the physics,
 * stepped at a fixed 1/60 s by the gallery's Runner, and Phaser only draws. The textures are drawn
 * on 2D canvases as bodies appear, one per size and colour (no assets to load).
 *
 * Fulcrum works in metres with y up, Phaser in pixels with y down: each frame a sprite is placed at
 * (x * PPM, -y * PPM) with rotation -angle, blended between the last two steps by the runner's
 * interpolator. A click turns the pointer's world pixels back into metres and drops a crate there.
 */
const cssHex = (color: number) => `#${color.toString(16).padStart(6, '0')}`;

export const phaserDemo: Demo = {
  id: 'phaser',
  title: 'Phaser 4 scene',
  description:
    'A Phaser 4 scene with a sprite per body: Fulcrum steps the world (Phaser physics off) and each frame copies body positions and angles into the sprites, metres to pixels with y flipped. Click to drop a crate.',
  view: { center: { x: 0, y: 7 }, halfHeight: VIEW_HEIGHT / 2 },
  drawSwitches: false,
  create: (ctx) => {
    ctx.useExternalRenderer();
    const world = new World();
    const ground = world.createBody({ position: { x: 0, y: -0.5 } });
    ground.createShape(Shape.box(10, 0.5), { friction: 0.6 });
    for (const x of [-10.3, 10.3]) {
      const wall = world.createBody({ position: { x, y: 3 } });
      wall.createShape(Shape.box(0.3, 3), { friction: 0.6 });
    }
    const ramp = world.createBody({ position: { x: -4, y: 5 }, angle: -0.35 });
    ramp.createShape(Shape.box(3.5, 0.15), { friction: 0.3 });
    const added: Body[] = [];
    const addCrate = (x: number, y: number, half: number) => {
      const body = world.createBody({ type: 'dynamic', position: { x, y }, angle: 0.3 });
      body.createShape(Shape.box(half, half), { friction: 0.5 });
      return body;
    };
    for (let row = 0; row < 4; row++) {
      for (let i = 0; i < 5 - row; i++) addCrate(3 + i * 1.05 + row * 0.52, 0.5 + row * 1.02, 0.5);
    }
    for (let i = 0; i < 6; i++) {
      const ball = world.createBody({ type: 'dynamic', position: { x: -6 + i * 0.9, y: 8 + i * 0.7 } });
      ball.createShape(Shape.circle(0.35 + 0.05 * (i % 3)), { friction: 0.4, restitution: 0.4 });
    }

    /** the sprite of each body (read by the e2e test) */
    const sprites = new Map<Body, Phaser.GameObjects.Image>();
    const state = {
      renderer: 'loading',
      frames: 0,
      drawnStep: -1,
      sprites: 0,
      scene: null as Phaser.Scene | null,
    };
    let game: Phaser.Game | null = null;
    let disposed = false;

    /** A texture key for a body's first shape, drawn once on a 2D canvas at PPM pixels per metre. */
    const textureFor = (scene: Phaser.Scene, body: Body, tint: number): string => {
      const g = body.shapes[0].geometry;
      const paper = document.createElement('canvas');
      let key: string;
      if (g.type === 'circle') {
        const r = g.radius * PPM;
        key = `ball-${r.toFixed(1)}-${tint}`;
        paper.width = paper.height = Math.ceil(2 * r);
        const pen = paper.getContext('2d') as CanvasRenderingContext2D;
        pen.fillStyle = cssHex(tint);
        pen.beginPath();
        pen.arc(r, r, r, 0, 2 * Math.PI);
        pen.fill();
        // a radius, so the spin shows
        pen.strokeStyle = '#15171d';
        pen.lineWidth = 2;
        pen.beginPath();
        pen.moveTo(r, r);
        pen.lineTo(2 * r, r);
        pen.stroke();
      } else if (g.type === 'polygon') {
        // a box: its vertices span the texture
        const xs = g.vertices.map((v) => v.x * PPM);
        const ys = g.vertices.map((v) => v.y * PPM);
        const width = Math.ceil(Math.max(...xs) - Math.min(...xs));
        const height = Math.ceil(Math.max(...ys) - Math.min(...ys));
        key = `box-${width}x${height}-${tint}`;
        paper.width = width;
        paper.height = height;
        const pen = paper.getContext('2d') as CanvasRenderingContext2D;
        pen.fillStyle = cssHex(tint);
        pen.fillRect(0, 0, width, height);
        pen.strokeStyle = '#0d0f13';
        pen.lineWidth = 2;
        pen.strokeRect(1, 1, width - 2, height - 2);
      } else {
        throw new Error(`phaser demo: no texture for a ${g.type}`);
      }
      if (!scene.textures.exists(key)) scene.textures.addCanvas(key, paper);
      return key;
    };

    const sceneConfig: Phaser.Types.Scenes.SettingsConfig & Phaser.Types.Scenes.CreateSceneFromObjectConfig =
      {
        key: 'fulcrum',
        create(this: Phaser.Scene) {
          state.scene = this;
          const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
          const fitCamera = () => {
            const camera = this.cameras.main;
            camera.setZoom(this.scale.height / (VIEW_HEIGHT * PPM));
            camera.centerOn(0, -7 * PPM);
          };
          fitCamera();
          this.scale.on('resize', fitCamera);
          this.input.on('pointerdown', (pointer: Phaser.Input.Pointer) => {
            // Phaser world pixels, y down, back to metres, y up
            const body = addCrate(
              pointer.worldX / PPM,
              -pointer.worldY / PPM,
              0.35 + 0.1 * (added.length % 3),
            );
            added.push(body);
            if (added.length > MAX_ADDED) {
              const oldest = added.shift() as Body;
              sprites.get(oldest)?.destroy();
              sprites.delete(oldest);
              world.destroyBody(oldest);
            }
          });
          this.events.on('update', () => {
            let index = 0;
            for (const body of world.bodies) {
              let sprite = sprites.get(body);
              if (!sprite) {
                const tint = body.type === 'static' ? 0x5f7a66 : COLORS[sprites.size % COLORS.length];
                sprite = this.add.image(0, 0, textureFor(this, body, tint));
                sprites.set(body, sprite);
              }
              const t = ctx.runner.interpolator.transformOf(body, xf);
              sprite.setPosition(t.p.x * PPM, -t.p.y * PPM);
              sprite.setRotation(-Math.atan2(t.q.s, t.q.c));
              index++;
            }
            state.sprites = index;
            state.frames++;
            state.drawnStep = ctx.runner.stepCount;
          });
        },
      };

    import('phaser')
      .then((module) => {
        if (disposed) return;
        const P =
          (module as unknown as { default?: typeof Phaser }).default ?? (module as unknown as typeof Phaser);
        game = new P.Game({
          type: P.AUTO,
          parent: ctx.stage,
          backgroundColor: '#15171d',
          banner: false,
          audio: { noAudio: true },
          scale: { mode: P.Scale.RESIZE },
          // preserveDrawingBuffer: the e2e test reads the pixels back. maxTextures 1: in headless Chromium's
          // software WebGL (SwiftShader) the multi-texture batch drew some quads with a triangle missing;
          // one texture per batch draws them whole, and a dozen small textures cost next to nothing
          render: { preserveDrawingBuffer: true, antialias: true, maxTextures: 1 },
          scene: sceneConfig,
          callbacks: {
            postBoot: (booted) => {
              state.renderer = booted.config.renderType === P.WEBGL ? 'webgl' : 'canvas';
              booted.canvas.dataset.renderer = 'phaser';
            },
          },
        });
      })
      .catch((error: unknown) => {
        state.renderer = `failed: ${String(error)}`;
        console.error(error);
      });

    return {
      world,
      state,
      sprites,
      dispose: () => {
        disposed = true;
        game?.destroy(true);
        game = null;
      },
    };
  },
};
