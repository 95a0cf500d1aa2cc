import type { Color } from './debug-draw';

const cache = new Map<number, string>();

/** CSS text of a 0xRRGGBB colour with an alpha in [0, 1] (cached: drawing asks for few colours). */
export function cssColor(color: Color, alpha = 1): string {
  const a = Math.round(Math.max(0, Math.min(1, alpha)) * 255);
  const key = color * 256 + a;
  let css = cache.get(key);
  if (css === undefined) {
    const hex = (color & 0xffffff).toString(16).padStart(6, '0');
    css = a === 255 ? `#${hex}` : `#${hex}${a.toString(16).padStart(2, '0')}`;
    if (cache.size > 4096) cache.clear();
    cache.set(key, css);
  }
  return css;
}

/** Accepts a 0xRRGGBB number or a CSS colour string and gives CSS text. */
export function toCss(color: Color | string, alpha = 1): string {
  return typeof color === 'string' ? color : cssColor(color, alpha);
}
