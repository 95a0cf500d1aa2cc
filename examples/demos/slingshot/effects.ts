/**
 * Debris, dust and score numbers: a fixed pool of particles in typed arrays, moved once per physics
 * step (they freeze with the game when it is paused) and never fed back into the world.
 */
import type { Block } from './game';
import type { Material } from './levels';

const MAX_PARTICLES = 600;
const MAX_POPUPS = 24;
const GRAVITY = -10;

/** what a particle is: a piece of a block, a puff of dust, a feather */
export const ParticleKind = { Chunk: 0, Dust: 1, Feather: 2 } as const;
type ParticleKind = (typeof ParticleKind)[keyof typeof ParticleKind];

/** the colours a particle may take, by index */
export const particleColors = [
  '#b07a45', // wood
  '#8a5a2e',
  '#9aa1aa', // stone
  '#6d737c',
  '#bfe6f7', // ice
  '#e9f7fd',
  'rgba(214, 196, 160, 0.5)', // dust
  'rgba(140, 200, 90, 0.6)', // target puff
  '#ffffff', // feather
];
const materialColor: Record<Material, number> = { wood: 0, stone: 2, ice: 4 };
const DUST = 6;
const GREEN = 7;
const FEATHER = 8;

export class Effects {
  readonly x = new Float32Array(MAX_PARTICLES);
  readonly y = new Float32Array(MAX_PARTICLES);
  readonly vx = new Float32Array(MAX_PARTICLES);
  readonly vy = new Float32Array(MAX_PARTICLES);
  readonly angle = new Float32Array(MAX_PARTICLES);
  readonly spin = new Float32Array(MAX_PARTICLES);
  readonly size = new Float32Array(MAX_PARTICLES);
  readonly life = new Float32Array(MAX_PARTICLES);
  readonly maxLife = new Float32Array(MAX_PARTICLES);
  readonly kind = new Uint8Array(MAX_PARTICLES);
  readonly color = new Uint8Array(MAX_PARTICLES);
  /** score numbers: where, how long they have left, the text */
  readonly popupX = new Float32Array(MAX_POPUPS);
  readonly popupY = new Float32Array(MAX_POPUPS);
  readonly popupLife = new Float32Array(MAX_POPUPS);
  readonly popupText: string[] = new Array(MAX_POPUPS).fill('');
  private next = 0;
  private nextPopup = 0;
  private seed = 12345;

  /** a number in [0, 1) from a small generator of its own (the pictures need no better) */
  private random(): number {
    this.seed = (this.seed * 16807) % 2147483647;
    return this.seed / 2147483647;
  }

  clear(): void {
    this.life.fill(0);
    this.popupLife.fill(0);
  }

  private spawn(
    kind: ParticleKind,
    color: number,
    x: number,
    y: number,
    vx: number,
    vy: number,
    size: number,
    life: number,
  ): void {
    const i = this.next;
    this.next = (this.next + 1) % MAX_PARTICLES;
    this.kind[i] = kind;
    this.color[i] = color;
    this.x[i] = x;
    this.y[i] = y;
    this.vx[i] = vx;
    this.vy[i] = vy;
    this.size[i] = size;
    this.angle[i] = this.random() * 6.283;
    this.spin[i] = (this.random() - 0.5) * 16;
    this.life[i] = life;
    this.maxLife[i] = life;
  }

  /** A block breaks: pieces of it fly off from where they were, and a cloud of dust. */
  breakBlock(block: Block, x: number, y: number, angle: number, vx: number, vy: number): void {
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const hw = block.halfWidth;
    const hh = block.halfHeight;
    const across = Math.max(1, Math.round(hw / 0.18));
    const up = Math.max(1, Math.round(hh / 0.18));
    const color = materialColor[block.material];
    for (let i = 0; i < across; i++) {
      for (let j = 0; j < up; j++) {
        const lx = -hw + ((i + 0.5) * 2 * hw) / across;
        const ly = -hh + ((j + 0.5) * 2 * hh) / up;
        const px = x + c * lx - s * ly;
        const py = y + s * lx + c * ly;
        const speed = 1.5 + this.random() * 3;
        const dx = px - x;
        const dy = py - y;
        const d = Math.hypot(dx, dy) || 1;
        this.spawn(
          ParticleKind.Chunk,
          color + (this.random() < 0.4 ? 1 : 0),
          px,
          py,
          vx * 0.5 + (dx / d) * speed + (this.random() - 0.5) * 2,
          vy * 0.5 + (dy / d) * speed + this.random() * 2,
          0.07 + this.random() * 0.12,
          0.8 + this.random() * 0.8,
        );
      }
    }
    this.dust(x, y, Math.max(hw, hh), DUST, 8);
  }

  /** A puff of dust (or the target's green cloud) of about `radius` around (x, y). */
  dust(x: number, y: number, radius: number, color = DUST, count = 6): void {
    for (let i = 0; i < count; i++) {
      const a = this.random() * 6.283;
      const r = this.random() * radius;
      this.spawn(
        ParticleKind.Dust,
        color,
        x + Math.cos(a) * r,
        y + Math.sin(a) * r,
        Math.cos(a) * (0.3 + this.random()),
        Math.sin(a) * (0.3 + this.random()) + 0.4,
        0.25 + this.random() * 0.3,
        0.6 + this.random() * 0.6,
      );
    }
  }

  /** A target is gone: a green puff. */
  pop(x: number, y: number, radius: number): void {
    this.dust(x, y, radius, GREEN, 12);
  }

  /** A bird is taken away: a few feathers. */
  feathers(x: number, y: number): void {
    for (let i = 0; i < 7; i++) {
      const a = this.random() * 6.283;
      this.spawn(ParticleKind.Feather, FEATHER, x, y, Math.cos(a) * 1.5, Math.sin(a) * 1.5 + 1, 0.12, 1.2);
    }
    this.dust(x, y, 0.3, DUST, 4);
  }

  /** A score number rising from (x, y). */
  popup(x: number, y: number, points: number): void {
    const i = this.nextPopup;
    this.nextPopup = (this.nextPopup + 1) % MAX_POPUPS;
    this.popupX[i] = x;
    this.popupY[i] = y;
    this.popupLife[i] = 1.2;
    this.popupText[i] = String(points);
  }

  /** Moves everything by `dt` seconds. */
  step(dt: number): void {
    for (let i = 0; i < MAX_PARTICLES; i++) {
      if (this.life[i] <= 0) continue;
      this.life[i] -= dt;
      const kind = this.kind[i];
      if (kind === ParticleKind.Chunk) {
        this.vy[i] += GRAVITY * dt;
        this.x[i] += this.vx[i] * dt;
        this.y[i] += this.vy[i] * dt;
        this.angle[i] += this.spin[i] * dt;
        // the pieces bounce once or twice on the ground and stop
        if (this.y[i] < this.size[i] * 0.5 && this.vy[i] < 0) {
          this.y[i] = this.size[i] * 0.5;
          this.vy[i] *= -0.3;
          this.vx[i] *= 0.6;
          this.spin[i] *= 0.5;
        }
      } else if (kind === ParticleKind.Dust) {
        this.x[i] += this.vx[i] * dt;
        this.y[i] += this.vy[i] * dt;
        this.vx[i] *= 0.96;
        this.vy[i] *= 0.96;
        this.size[i] += 0.5 * dt;
      } else {
        // feathers drift down, swaying
        this.vy[i] += (GRAVITY * 0.1 - this.vy[i] * 2) * dt;
        this.vx[i] *= 0.97;
        this.x[i] += this.vx[i] * dt + Math.sin(this.life[i] * 8) * 0.01;
        this.y[i] += this.vy[i] * dt;
        this.angle[i] = Math.sin(this.life[i] * 6) * 0.8;
      }
    }
    for (let i = 0; i < MAX_POPUPS; i++) {
      if (this.popupLife[i] <= 0) continue;
      this.popupLife[i] -= dt;
      this.popupY[i] += 0.8 * dt;
    }
  }
}

export const PARTICLE_COUNT = MAX_PARTICLES;
export const POPUP_COUNT = MAX_POPUPS;
