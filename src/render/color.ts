import type { Color } from './debug-draw';

/** The alpha in [0, 1] as a byte. */
function alphaByte(alpha: number): number {
  return Math.round(Math.max(0, Math.min(1, alpha)) * 255);
}

function cssText(color: Color, a: number): string {
  const hex = (color & 0xffffff).toString(16).padStart(6, '0');
  return a === 255 ? `#${hex}` : `#${hex}${a.toString(16).padStart(2, '0')}`;
}

/** CSS text of a 0xRRGGBB colour with an alpha in [0, 1]. */
export function cssColor(color: Color, alpha = 1): string {
  return cssText(color, alphaByte(alpha));
}

/** Accepts a 0xRRGGBB number or a CSS colour string and gives CSS text. */
export function toCss(color: Color | string, alpha = 1): string {
  return typeof color === 'string' ? color : cssColor(color, alpha);
}

/**
 * A renderer's memo of cssColor: drawing asks for few colours, each many times a frame, and a
 * renderer that keeps its own shares nothing with another.
 */
export class CssColors {
  private readonly cache = new Map<number, string>();

  get(color: Color, alpha = 1): string {
    const a = alphaByte(alpha);
    const key = color * 256 + a;
    let css = this.cache.get(key);
    if (css === undefined) {
      css = cssText(color, a);
      if (this.cache.size > 4096) this.cache.clear();
      this.cache.set(key, css);
    }
    return css;
  }
}
