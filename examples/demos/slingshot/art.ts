/**
 * The game's pictures, painted on the gallery's canvas before the (optional) debug view: a sky with
 * clouds and hills in parallax, the ground, textured blocks that crack as they take damage, targets
 * with faces, birds with eyes, the sling and its band, the aiming guide, debris and dust. Gradients,
 * patterns and paths are made once and reused; a frame allocates nothing but the odd score text.
 */
import type { Body, Transform } from '../../../src/index';
import type { AnyWorld, Interpolator, Render } from '../../../src/render/index';
import { type BirdKind, birdTypes } from './birds';
import { type Effects, PARTICLE_COUNT, ParticleKind, POPUP_COUNT, particleColors } from './effects';
import { ANCHOR, type Bird, type Block, type SlingshotGame, type Target } from './game';
import type { Material } from './levels';
import type { TrajectoryPreview } from './preview';
import { makeTextures, TEXTURE_SCALE, type Textures } from './textures';

/** the tips of the sling's fork, where the band is tied; the back one is drawn behind the bird */
const BACK_TIP = { x: ANCHOR.x + 0.5, y: ANCHOR.y + 0.15 };
const FRONT_TIP = { x: ANCHOR.x - 0.5, y: ANCHOR.y + 0.15 };
const FORK = { x: ANCHOR.x, y: ANCHOR.y - 0.75 };
const outlineOf: Record<Material, string> = { wood: '#5c3a1a', stone: '#4a4f57', ice: '#5a9cc0' };

interface HillLayer {
  path: Path2D;
  /** how fast it moves with the camera (1: with the ground) */
  parallax: number;
  color: string;
}
const HILL_PERIOD = 64;
/**
 * where the hills' shapes end below: inside the grass band (-0.1 to 0.18 m), which with the dirt
 * under it covers everything lower, so nothing is painted there only to be painted over
 */
const HILL_FOOT = -0.05;

function hillPath(base: number, a1: number, a2: number, phase: number): Path2D {
  const path = new Path2D();
  path.moveTo(0, HILL_FOOT);
  for (let x = 0; x <= HILL_PERIOD; x += 1) {
    const t = (x / HILL_PERIOD) * 2 * Math.PI;
    path.lineTo(x, base + a1 * Math.sin(t + phase) + a2 * Math.sin(3 * t + phase * 2));
  }
  path.lineTo(HILL_PERIOD, HILL_FOOT);
  path.closePath();
  return path;
}

function cloudPath(): Path2D {
  const path = new Path2D();
  for (const [x, y, r] of [
    [0, 0, 1],
    [1.1, 0.3, 1.2],
    [2.3, 0, 0.9],
    [1.2, -0.3, 1],
  ]) {
    path.moveTo(x + r, y);
    path.arc(x, y, r, 0, 2 * Math.PI);
  }
  return path;
}

export class Painter {
  private textures: Textures | null = null;
  private sky: CanvasGradient | null = null;
  private skyHeight = -1;
  private bevel: CanvasGradient | null = null;
  private targetSkin: CanvasGradient | null = null;
  private readonly birdSkin = new Map<BirdKind, CanvasGradient>();
  private grass: CanvasGradient | null = null;
  private readonly cracks = new WeakMap<Block, Path2D[]>();
  private readonly hills: HillLayer[] = [
    { path: hillPath(4.2, 1.6, 0.7, 0.5), parallax: 0.2, color: '#b5dcc2' },
    { path: hillPath(2.6, 1.2, 0.6, 2.1), parallax: 0.45, color: '#8fca84' },
    { path: hillPath(1.1, 0.7, 0.4, 4), parallax: 0.7, color: '#6bb25a' },
  ];
  private readonly cloud = cloudPath();
  private readonly xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
  private readonly screen = { x: 0, y: 0 };
  private font = '';
  private fontSize = 0;
  /** how far the clouds have drifted, m */
  cloudDrift = 0;

  constructor(
    private readonly render: Render<AnyWorld>,
    private readonly interpolator: Interpolator,
    private readonly game: SlingshotGame,
    private readonly preview: TrajectoryPreview,
    private readonly effects: Effects,
  ) {}

  private place(body: Body): Transform {
    return this.interpolator.transformOf(body, this.xf);
  }

  /** Paints a frame (in 'beforeDraw': the context maps CSS pixels). */
  draw(ctx: CanvasRenderingContext2D): void {
    if (!this.textures) this.makeCache(ctx);
    const camera = this.render.camera;
    const pixel = 1 / camera.scale;
    this.drawSky(ctx);
    this.render.setWorldTransform();
    this.drawGround(ctx);
    this.drawRocks(ctx);
    this.drawLinks(ctx, pixel);
    this.drawSlingBack(ctx);
    for (const block of this.game.blocks) this.drawBlock(ctx, block, pixel);
    for (const target of this.game.targets) this.drawTarget(ctx, target, pixel);
    for (const bird of this.game.flying) this.drawBird(ctx, bird, pixel);
    this.drawLoaded(ctx, pixel);
    this.drawPreview(ctx);
    this.drawParticles(ctx);
    this.render.setScreenTransform();
    this.drawPopups(ctx);
  }

  private makeCache(ctx: CanvasRenderingContext2D): void {
    this.textures = makeTextures(ctx);
    const bevel = ctx.createLinearGradient(0, 1, 0, -1);
    bevel.addColorStop(0, 'rgba(255, 255, 255, 0.35)');
    bevel.addColorStop(0.25, 'rgba(255, 255, 255, 0.05)');
    bevel.addColorStop(0.75, 'rgba(0, 0, 0, 0.05)');
    bevel.addColorStop(1, 'rgba(0, 0, 0, 0.35)');
    this.bevel = bevel;
    const skin = ctx.createRadialGradient(-0.3, 0.35, 0.1, 0, 0, 1);
    skin.addColorStop(0, '#b8ec7c');
    skin.addColorStop(0.6, '#6cbf3c');
    skin.addColorStop(1, '#3f8a24');
    this.targetSkin = skin;
    for (const type of Object.values(birdTypes)) {
      const g = ctx.createRadialGradient(-0.25, 0.35, 0.1, 0, 0, 1);
      g.addColorStop(0, type.body);
      g.addColorStop(0.7, type.body);
      g.addColorStop(1, type.shade);
      this.birdSkin.set(type.kind, g);
    }
    const grass = ctx.createLinearGradient(0, 0.18, 0, -0.1);
    grass.addColorStop(0, '#7fd14e');
    grass.addColorStop(1, '#3f8f2a');
    this.grass = grass;
  }

  private drawSky(ctx: CanvasRenderingContext2D): void {
    const camera = this.render.camera;
    const w = camera.width;
    const h = camera.height;
    if (!this.sky || this.skyHeight !== h) {
      const sky = ctx.createLinearGradient(0, 0, 0, h);
      sky.addColorStop(0, '#4aa8e8');
      sky.addColorStop(0.6, '#a9dcf6');
      sky.addColorStop(1, '#e6f6fc');
      this.sky = sky;
      this.skyHeight = h;
    }
    ctx.fillStyle = this.sky;
    ctx.fillRect(0, 0, w, h);
    const s = camera.scale;
    const r = this.render.ratio;
    // the sun, far away: it does not move with the camera
    ctx.fillStyle = 'rgba(255, 250, 215, 0.35)';
    ctx.beginPath();
    ctx.arc(w * 0.82, h * 0.16, Math.min(w, h) * 0.09, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillStyle = '#fff7cf';
    ctx.beginPath();
    ctx.arc(w * 0.82, h * 0.16, Math.min(w, h) * 0.055, 0, 2 * Math.PI);
    ctx.fill();
    // clouds, drifting, at a tenth of the camera's movement
    ctx.fillStyle = 'rgba(255, 255, 255, 0.85)';
    const cloudScale = s * 0.9;
    const groundY = h / 2 + camera.center.y * s;
    const span = 26;
    const shift = camera.center.x * 0.1 - this.cloudDrift;
    for (let k = 0; k < 4; k++) {
      const wx = (((k * span * 0.37 - shift) % span) + span) % span;
      for (let copy = -1; copy < Math.ceil(w / (span * cloudScale)) + 1; copy++) {
        const x = (wx + copy * span) * cloudScale;
        const y = groundY - (9 + (k % 3) * 1.6) * s;
        const size = cloudScale * (0.8 + (k % 2) * 0.4);
        ctx.setTransform(r * size, 0, 0, -r * size, r * x, r * y);
        ctx.fill(this.cloud);
      }
    }
    // hills, nearer ones moving faster
    for (const layer of this.hills) {
      ctx.fillStyle = layer.color;
      const offset = w / 2 - camera.center.x * layer.parallax * s;
      const first = Math.floor(-offset / (HILL_PERIOD * s)) - 1;
      const last = Math.ceil((w - offset) / (HILL_PERIOD * s));
      for (let k = first; k <= last; k++) {
        ctx.setTransform(r * s, 0, 0, -r * s, r * (offset + k * HILL_PERIOD * s), r * groundY);
        ctx.fill(layer.path);
      }
    }
  }

  private drawGround(ctx: CanvasRenderingContext2D): void {
    const camera = this.render.camera;
    const halfWidth = (camera.halfHeight * camera.width) / camera.height;
    const left = camera.center.x - halfWidth - 1;
    const right = camera.center.x + halfWidth + 1;
    const bottom = camera.center.y - camera.halfHeight - 1;
    if (bottom < 0) {
      ctx.save();
      ctx.scale(1 / TEXTURE_SCALE, 1 / TEXTURE_SCALE);
      ctx.fillStyle = this.textures?.dirt as CanvasPattern;
      ctx.fillRect(
        left * TEXTURE_SCALE,
        bottom * TEXTURE_SCALE,
        (right - left) * TEXTURE_SCALE,
        -bottom * TEXTURE_SCALE,
      );
      ctx.restore();
    }
    ctx.fillStyle = this.grass as CanvasGradient;
    ctx.fillRect(left, -0.1, right - left, 0.28);
  }

  private drawRocks(ctx: CanvasRenderingContext2D): void {
    for (const rock of this.game.levelDef.rocks) {
      ctx.save();
      ctx.translate(rock.x, rock.y);
      if (rock.angle) ctx.rotate(rock.angle);
      const hw = rock.halfWidth;
      const hh = rock.halfHeight;
      ctx.save();
      ctx.scale(1 / TEXTURE_SCALE, 1 / TEXTURE_SCALE);
      ctx.fillStyle = this.textures?.rock as CanvasPattern;
      ctx.fillRect(-hw * TEXTURE_SCALE, -hh * TEXTURE_SCALE, 2 * hw * TEXTURE_SCALE, 2 * hh * TEXTURE_SCALE);
      ctx.restore();
      ctx.save();
      ctx.scale(hw, hh);
      ctx.fillStyle = this.bevel as CanvasGradient;
      ctx.fillRect(-1, -1, 2, 2);
      ctx.restore();
      // a tuft of grass on top
      ctx.fillStyle = this.grass as CanvasGradient;
      ctx.translate(0, hh - 0.08);
      ctx.fillRect(-hw - 0.04, -0.1, 2 * hw + 0.08, 0.28);
      ctx.restore();
    }
  }

  private drawLinks(ctx: CanvasRenderingContext2D, pixel: number): void {
    for (const link of this.game.links) {
      const t = this.place(link.body);
      const x = t.p.x + t.q.c * link.local.x - t.q.s * link.local.y;
      const y = t.p.y + t.q.s * link.local.x + t.q.c * link.local.y;
      if (link.kind === 'rope') {
        ctx.strokeStyle = '#6b4a2b';
        ctx.lineWidth = Math.max(0.06, 2 * pixel);
        ctx.beginPath();
        ctx.moveTo(link.anchor.x, link.anchor.y);
        ctx.lineTo(x, y);
        ctx.stroke();
        ctx.fillStyle = '#3a3d44';
        ctx.beginPath();
        ctx.arc(link.anchor.x, link.anchor.y, 0.09, 0, 2 * Math.PI);
        ctx.fill();
      }
    }
  }

  /** the pins of see-saws, drawn over their planks */
  private drawPins(ctx: CanvasRenderingContext2D): void {
    for (const link of this.game.links) {
      if (link.kind !== 'pivot') continue;
      ctx.fillStyle = '#c9ced6';
      ctx.strokeStyle = '#3a3d44';
      ctx.lineWidth = 0.04;
      ctx.beginPath();
      ctx.arc(link.anchor.x, link.anchor.y, 0.12, 0, 2 * Math.PI);
      ctx.fill();
      ctx.stroke();
    }
  }

  private drawBlock(ctx: CanvasRenderingContext2D, block: Block, pixel: number): void {
    const t = this.place(block.body);
    const hw = block.halfWidth;
    const hh = block.halfHeight;
    ctx.save();
    ctx.transform(t.q.c, t.q.s, -t.q.s, t.q.c, t.p.x, t.p.y);
    // the texture, its grain along the block's long side, shifted by the block's own number
    ctx.save();
    if (hh > hw) ctx.transform(0, 1, -1, 0, 0, 0);
    const long = Math.max(hw, hh) * TEXTURE_SCALE;
    const short = Math.min(hw, hh) * TEXTURE_SCALE;
    const shift = block.seed % 97;
    ctx.scale(1 / TEXTURE_SCALE, 1 / TEXTURE_SCALE);
    ctx.translate(-shift, -shift * 0.7);
    ctx.fillStyle = (this.textures as Textures).material[block.material];
    ctx.fillRect(-long + shift, -short + shift * 0.7, 2 * long, 2 * short);
    ctx.restore();
    // light from above
    ctx.save();
    ctx.scale(hw, hh);
    ctx.fillStyle = this.bevel as CanvasGradient;
    ctx.fillRect(-1, -1, 2, 2);
    ctx.restore();
    ctx.strokeStyle = outlineOf[block.material];
    ctx.lineWidth = 1.5 * pixel;
    ctx.strokeRect(-hw, -hh, 2 * hw, 2 * hh);
    // damage: one crack, then two
    const health = block.hp / block.maxHp;
    if (health < 0.75) {
      const cracks = this.cracksOf(block);
      ctx.strokeStyle = block.material === 'ice' ? 'rgba(255, 255, 255, 0.9)' : 'rgba(30, 20, 10, 0.75)';
      ctx.lineWidth = 1.6 * pixel;
      ctx.stroke(cracks[0]);
      if (health < 0.4) ctx.stroke(cracks[1]);
    }
    ctx.restore();
  }

  private cracksOf(block: Block): Path2D[] {
    let cracks = this.cracks.get(block);
    if (cracks) return cracks;
    let seed = block.seed;
    const random = () => {
      seed = (seed * 16807) % 2147483647;
      return seed / 2147483647;
    };
    const hw = block.halfWidth;
    const hh = block.halfHeight;
    cracks = [];
    for (let k = 0; k < 2; k++) {
      const path = new Path2D();
      // from a point on an edge, zigzag across
      const alongX = hw > hh;
      let x = alongX ? (random() - 0.5) * 1.6 * hw : k === 0 ? -hw : hw;
      let y = alongX ? (k === 0 ? hh : -hh) : (random() - 0.5) * 1.6 * hh;
      path.moveTo(x, y);
      const steps = 4;
      for (let i = 0; i < steps; i++) {
        if (alongX) {
          y += ((k === 0 ? -1 : 1) * 1.3 * hh) / steps;
          x += (random() - 0.5) * hh;
        } else {
          x += ((k === 0 ? 1 : -1) * 1.3 * hw) / steps;
          y += (random() - 0.5) * hw * 1.5;
        }
        path.lineTo(x, y);
      }
      cracks.push(path);
    }
    this.cracks.set(block, cracks);
    return cracks;
  }

  private drawTarget(ctx: CanvasRenderingContext2D, target: Target, pixel: number): void {
    const t = this.place(target.body);
    const r = target.radius;
    ctx.save();
    ctx.transform(t.q.c * r, t.q.s * r, -t.q.s * r, t.q.c * r, t.p.x, t.p.y);
    const line = (1.5 * pixel) / r;
    ctx.lineWidth = line;
    ctx.strokeStyle = '#2d5e18';
    // ears
    ctx.fillStyle = '#5fae35';
    for (const side of [-1, 1]) {
      ctx.beginPath();
      ctx.arc(side * 0.55, 0.78, 0.26, 0, 2 * Math.PI);
      ctx.fill();
      ctx.stroke();
    }
    ctx.fillStyle = this.targetSkin as CanvasGradient;
    ctx.beginPath();
    ctx.arc(0, 0, 1, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
    // snout
    ctx.fillStyle = '#a6de7a';
    ctx.beginPath();
    ctx.ellipse(0, -0.12, 0.4, 0.29, 0, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
    ctx.fillStyle = '#2d5e18';
    for (const side of [-1, 1]) {
      ctx.beginPath();
      ctx.ellipse(side * 0.15, -0.12, 0.07, 0.11, 0, 0, 2 * Math.PI);
      ctx.fill();
    }
    const hurt = target.hp < target.maxHp * 0.6;
    // eyes (one shut when hurt), and a bruise
    for (const side of [-1, 1]) {
      const x = side * 0.4;
      if (hurt && side < 0) {
        ctx.beginPath();
        ctx.moveTo(x - 0.18, 0.36);
        ctx.lineTo(x + 0.18, 0.3);
        ctx.lineWidth = 0.08;
        ctx.stroke();
        ctx.lineWidth = line;
        continue;
      }
      ctx.fillStyle = '#ffffff';
      ctx.beginPath();
      ctx.arc(x, 0.34, 0.2, 0, 2 * Math.PI);
      ctx.fill();
      ctx.stroke();
      ctx.fillStyle = '#111';
      ctx.beginPath();
      ctx.arc(x + 0.04, 0.32, 0.09, 0, 2 * Math.PI);
      ctx.fill();
    }
    if (hurt) {
      ctx.fillStyle = 'rgba(90, 60, 140, 0.45)';
      ctx.beginPath();
      ctx.arc(0.55, 0.5, 0.2, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
  }

  private drawBird(ctx: CanvasRenderingContext2D, bird: Bird, pixel: number): void {
    const t = this.place(bird.body);
    this.drawBirdAt(ctx, bird.type.kind, t.p.x, t.p.y, t.q.c, t.q.s, pixel);
  }

  private drawBirdAt(
    ctx: CanvasRenderingContext2D,
    kind: BirdKind,
    x: number,
    y: number,
    c: number,
    s: number,
    pixel: number,
  ): void {
    const type = birdTypes[kind];
    const r = type.radius;
    ctx.save();
    ctx.transform(c * r, s * r, -s * r, c * r, x, y);
    const line = (1.5 * pixel) / r;
    ctx.lineWidth = line;
    ctx.strokeStyle = '#1b1b1f';
    // tail feathers
    ctx.fillStyle = '#1b1b1f';
    ctx.beginPath();
    ctx.moveTo(-0.85, 0.1);
    ctx.lineTo(-1.35, 0.35);
    ctx.lineTo(-1.25, 0.05);
    ctx.lineTo(-1.4, -0.2);
    ctx.lineTo(-0.85, -0.15);
    ctx.fill();
    // a tuft on the head
    if (kind !== 'heavy') {
      ctx.fillStyle = type.shade;
      ctx.beginPath();
      ctx.moveTo(-0.1, 0.9);
      ctx.lineTo(-0.05, 1.35);
      ctx.lineTo(0.15, 0.95);
      ctx.lineTo(0.35, 1.25);
      ctx.lineTo(0.35, 0.85);
      ctx.fill();
    }
    ctx.fillStyle = this.birdSkin.get(kind) as CanvasGradient;
    ctx.beginPath();
    ctx.arc(0, 0, 1, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
    // belly
    ctx.fillStyle = type.belly;
    ctx.beginPath();
    ctx.ellipse(0.1, -0.5, 0.62, 0.38, 0, 0, 2 * Math.PI);
    ctx.fill();
    // eyes, looking ahead
    for (const ex of [0.18, 0.55]) {
      ctx.fillStyle = '#ffffff';
      ctx.beginPath();
      ctx.arc(ex, 0.25, 0.21, 0, 2 * Math.PI);
      ctx.fill();
      ctx.stroke();
      ctx.fillStyle = '#111';
      ctx.beginPath();
      ctx.arc(ex + 0.08, 0.23, 0.1, 0, 2 * Math.PI);
      ctx.fill();
    }
    // brows
    ctx.lineWidth = 0.16;
    ctx.lineCap = 'round';
    ctx.beginPath();
    ctx.moveTo(-0.05, 0.55);
    ctx.lineTo(0.36, 0.42);
    ctx.lineTo(0.78, 0.55);
    ctx.stroke();
    ctx.lineCap = 'butt';
    ctx.lineWidth = line;
    // beak
    ctx.fillStyle = '#f39c1e';
    ctx.beginPath();
    ctx.moveTo(0.62, 0.02);
    ctx.lineTo(1.25, -0.14);
    ctx.lineTo(0.62, -0.34);
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
    ctx.restore();
  }

  private drawSlingBack(ctx: CanvasRenderingContext2D): void {
    ctx.lineCap = 'round';
    ctx.strokeStyle = '#6b4322';
    ctx.lineWidth = 0.26;
    ctx.beginPath();
    ctx.moveTo(ANCHOR.x, 0);
    ctx.lineTo(FORK.x, FORK.y);
    ctx.lineTo(BACK_TIP.x, BACK_TIP.y);
    ctx.stroke();
    ctx.strokeStyle = '#9a6a3a';
    ctx.lineWidth = 0.08;
    ctx.beginPath();
    ctx.moveTo(ANCHOR.x - 0.05, 0.1);
    ctx.lineTo(FORK.x - 0.05, FORK.y);
    ctx.lineTo(BACK_TIP.x - 0.05, BACK_TIP.y);
    ctx.stroke();
    ctx.lineCap = 'butt';
  }

  /** the loaded bird between the band's two halves and the fork's two arms */
  private drawLoaded(ctx: CanvasRenderingContext2D, pixel: number): void {
    const bird = this.game.loaded;
    let px = ANCHOR.x;
    let py = ANCHOR.y;
    let dx = -1;
    let dy = 0;
    const held = bird !== null;
    if (bird) {
      const t = this.place(bird.body);
      px = t.p.x;
      py = t.p.y;
      const ex = px - ANCHOR.x;
      const ey = py - ANCHOR.y;
      const d = Math.hypot(ex, ey);
      if (d > 0.05) {
        dx = ex / d;
        dy = ey / d;
      }
      const r = bird.type.radius;
      // the pouch behind the bird
      const bx = px + dx * r * 0.85;
      const by = py + dy * r * 0.85;
      ctx.strokeStyle = '#3b2414';
      ctx.lineCap = 'round';
      ctx.lineWidth = d > 0.3 ? 0.09 : 0.12;
      ctx.beginPath();
      ctx.moveTo(BACK_TIP.x, BACK_TIP.y);
      ctx.lineTo(bx, by);
      ctx.stroke();
      this.drawBirdAt(ctx, bird.type.kind, t.p.x, t.p.y, t.q.c, t.q.s, pixel);
      ctx.fillStyle = '#4a2c17';
      ctx.beginPath();
      ctx.ellipse(bx, by, r * 0.35, r * 0.75, Math.atan2(dy, dx), 0, 2 * Math.PI);
      ctx.fill();
      ctx.strokeStyle = '#3b2414';
      ctx.beginPath();
      ctx.moveTo(bx, by);
      ctx.lineTo(FRONT_TIP.x, FRONT_TIP.y);
      ctx.stroke();
    }
    // the front arm of the fork
    ctx.lineCap = 'round';
    ctx.strokeStyle = '#6b4322';
    ctx.lineWidth = 0.26;
    ctx.beginPath();
    ctx.moveTo(FORK.x, FORK.y);
    ctx.lineTo(FRONT_TIP.x, FRONT_TIP.y);
    ctx.stroke();
    ctx.strokeStyle = '#9a6a3a';
    ctx.lineWidth = 0.08;
    ctx.beginPath();
    ctx.moveTo(FORK.x - 0.05, FORK.y);
    ctx.lineTo(FRONT_TIP.x - 0.05, FRONT_TIP.y);
    ctx.stroke();
    if (!held) {
      // an empty sling: the band hangs between the tips
      ctx.strokeStyle = '#3b2414';
      ctx.lineWidth = 0.09;
      ctx.beginPath();
      ctx.moveTo(FRONT_TIP.x, FRONT_TIP.y);
      ctx.quadraticCurveTo(ANCHOR.x, ANCHOR.y - 0.35, BACK_TIP.x, BACK_TIP.y);
      ctx.stroke();
    }
    ctx.lineCap = 'butt';
    this.drawPins(ctx);
  }

  private drawPreview(ctx: CanvasRenderingContext2D): void {
    const preview = this.preview;
    if (this.game.state !== 'aiming' || preview.count === 0) return;
    const n = preview.count;
    ctx.fillStyle = '#ffffff';
    for (let i = 2; i < n; i += 4) {
      const f = 1 - i / (n + 8);
      ctx.globalAlpha = 0.35 + 0.6 * f;
      ctx.beginPath();
      ctx.arc(preview.points[2 * i], preview.points[2 * i + 1], 0.05 + 0.06 * f, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.globalAlpha = 1;
  }

  private drawParticles(ctx: CanvasRenderingContext2D): void {
    const e = this.effects;
    for (let i = 0; i < PARTICLE_COUNT; i++) {
      const life = e.life[i];
      if (life <= 0) continue;
      const fade = Math.min(1, life / (0.5 * e.maxLife[i]));
      ctx.globalAlpha = fade;
      ctx.fillStyle = particleColors[e.color[i]];
      const size = e.size[i];
      if (e.kind[i] === ParticleKind.Dust) {
        ctx.beginPath();
        ctx.arc(e.x[i], e.y[i], size, 0, 2 * Math.PI);
        ctx.fill();
      } else {
        const c = Math.cos(e.angle[i]);
        const s = Math.sin(e.angle[i]);
        ctx.save();
        ctx.transform(c, s, -s, c, e.x[i], e.y[i]);
        if (e.kind[i] === ParticleKind.Chunk) ctx.fillRect(-size / 2, -size / 3, size, (2 * size) / 3);
        else {
          ctx.beginPath();
          ctx.ellipse(0, 0, size, size * 0.3, 0, 0, 2 * Math.PI);
          ctx.fill();
        }
        ctx.restore();
      }
    }
    ctx.globalAlpha = 1;
  }

  private drawPopups(ctx: CanvasRenderingContext2D): void {
    const e = this.effects;
    const camera = this.render.camera;
    const size = Math.round(Math.max(14, Math.min(30, camera.scale * 0.55)));
    if (size !== this.fontSize) {
      this.fontSize = size;
      this.font = `800 ${size}px system-ui, sans-serif`;
    }
    ctx.font = this.font;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.lineWidth = 3;
    ctx.strokeStyle = 'rgba(40, 30, 20, 0.8)';
    for (let i = 0; i < POPUP_COUNT; i++) {
      const life = e.popupLife[i];
      if (life <= 0) continue;
      this.screen.x = e.popupX[i];
      this.screen.y = e.popupY[i];
      const p = camera.worldToScreen(this.screen, this.screen);
      ctx.globalAlpha = Math.min(1, life * 2);
      ctx.fillStyle = '#fff3b0';
      ctx.strokeText(e.popupText[i], p.x, p.y);
      ctx.fillText(e.popupText[i], p.x, p.y);
    }
    ctx.globalAlpha = 1;
  }
}
