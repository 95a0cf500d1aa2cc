/**
 * The materials' textures, painted once on small canvases and used as repeating patterns: wood with
 * its grain, stone with speckles, ice with streaks, and the rock of the ground.
 */
import type { Material } from './levels';

/** texture pixels per metre of the world */
export const TEXTURE_SCALE = 160;
const SIZE = 128;

function canvas(): [HTMLCanvasElement, CanvasRenderingContext2D] {
  const c = document.createElement('canvas');
  c.width = SIZE;
  c.height = SIZE;
  const ctx = c.getContext('2d');
  if (!ctx) throw new Error('slingshot: no 2D context for a texture');
  return [c, ctx];
}

/** a small generator of its own, so that the textures look the same on every visit */
function generator(seed: number): () => number {
  let s = seed;
  return () => {
    s = (s * 16807) % 2147483647;
    return s / 2147483647;
  };
}

function wood(): HTMLCanvasElement {
  const [c, ctx] = canvas();
  const random = generator(7);
  ctx.fillStyle = '#c08a50';
  ctx.fillRect(0, 0, SIZE, SIZE);
  // the grain: wavy lines along x, lighter and darker
  for (let i = 0; i < 22; i++) {
    const y0 = random() * SIZE;
    const amp = 1 + random() * 3;
    const phase = random() * 6.28;
    ctx.strokeStyle = random() < 0.6 ? 'rgba(110, 66, 30, 0.35)' : 'rgba(240, 200, 140, 0.3)';
    ctx.lineWidth = 0.8 + random() * 1.8;
    for (const shift of [-SIZE, 0, SIZE]) {
      ctx.beginPath();
      for (let x = 0; x <= SIZE; x += 4) {
        const y = y0 + shift + amp * Math.sin((x / SIZE) * 2 * Math.PI * 2 + phase);
        if (x === 0) ctx.moveTo(x, y);
        else ctx.lineTo(x, y);
      }
      ctx.stroke();
    }
  }
  // a knot
  ctx.strokeStyle = 'rgba(100, 58, 26, 0.5)';
  ctx.lineWidth = 1.5;
  for (let r = 2; r < 9; r += 3) {
    ctx.beginPath();
    ctx.ellipse(84, 40, r * 1.8, r, 0, 0, 2 * Math.PI);
    ctx.stroke();
  }
  return c;
}

function stone(base: string, light: string, dark: string, seed: number): HTMLCanvasElement {
  const [c, ctx] = canvas();
  const random = generator(seed);
  ctx.fillStyle = base;
  ctx.fillRect(0, 0, SIZE, SIZE);
  for (let i = 0; i < 70; i++) {
    ctx.fillStyle = random() < 0.5 ? light : dark;
    const x = random() * SIZE;
    const y = random() * SIZE;
    const r = 1 + random() * 6;
    for (const dx of [-SIZE, 0, SIZE]) {
      for (const dy of [-SIZE, 0, SIZE]) {
        ctx.beginPath();
        ctx.arc(x + dx, y + dy, r, 0, 2 * Math.PI);
        ctx.fill();
      }
    }
  }
  return c;
}

function ice(): HTMLCanvasElement {
  const [c, ctx] = canvas();
  const random = generator(3);
  ctx.fillStyle = 'rgba(168, 222, 246, 0.82)';
  ctx.fillRect(0, 0, SIZE, SIZE);
  ctx.strokeStyle = 'rgba(255, 255, 255, 0.55)';
  for (let i = 0; i < 9; i++) {
    ctx.lineWidth = 1 + random() * 3;
    const x = random() * SIZE;
    for (const dx of [-SIZE, 0, SIZE]) {
      ctx.beginPath();
      ctx.moveTo(x + dx, 0);
      ctx.lineTo(x + dx + SIZE * 0.5, SIZE);
      ctx.stroke();
    }
  }
  return c;
}

export interface Textures {
  material: Record<Material, CanvasPattern>;
  rock: CanvasPattern;
  dirt: CanvasPattern;
}

export function makeTextures(ctx: CanvasRenderingContext2D): Textures {
  const pattern = (c: HTMLCanvasElement) => {
    const p = ctx.createPattern(c, 'repeat');
    if (!p) throw new Error('slingshot: no pattern');
    return p;
  };
  return {
    material: {
      wood: pattern(wood()),
      stone: pattern(stone('#9aa0a8', 'rgba(220, 224, 230, 0.35)', 'rgba(60, 64, 72, 0.3)', 11)),
      ice: pattern(ice()),
    },
    rock: pattern(stone('#7b6a58', 'rgba(170, 150, 125, 0.4)', 'rgba(50, 40, 30, 0.35)', 5)),
    dirt: pattern(stone('#7a5232', 'rgba(150, 110, 70, 0.4)', 'rgba(60, 35, 20, 0.4)', 9)),
  };
}
