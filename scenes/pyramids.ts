/**
 * Pyramids of 1 m boxes (half extents 0.5, density 1, so 1 kg each) on a static ground whose top is
 * y = 0. Boxes start exactly touching their neighbours, with no overlap.
 */
import { dynamicBody, GRAVITY, groundBody } from './common';
import type { Scene, SceneBody } from './types';

const HALF = 0.5;

/** boxes of one pyramid with base `base`, centred on x = centerX */
function pyramidBoxes(base: number, centerX: number): SceneBody[] {
  const boxes: SceneBody[] = [];
  for (let row = 0; row < base; row++) {
    const count = base - row;
    for (let i = 0; i < count; i++) {
      const x = centerX + (i - (count - 1) / 2) * 2 * HALF;
      const y = HALF + row * 2 * HALF;
      boxes.push(dynamicBody({ x, y }, { kind: 'box', halfWidth: HALF, halfHeight: HALF }, 'box'));
    }
  }
  return boxes;
}

/** one pyramid, `base` boxes wide: base * (base + 1) / 2 boxes */
export function pyramid({ base = 20 }: { base?: number } = {}): Scene {
  return {
    name: `pyramid-${base}`,
    gravity: GRAVITY,
    bodies: [groundBody(base + 10), ...pyramidBoxes(base, 0)],
    joints: [],
    view: { center: { x: 0, y: base / 2 }, halfHeight: base / 2 + 2 },
  };
}

/** `count` pyramids of base `base` side by side on one ground, 2 m apart at their bases */
export function manyPyramids({ count = 20, base = 10 }: { count?: number; base?: number } = {}): Scene {
  const pitch = base + 2;
  const width = count * pitch;
  const bodies: SceneBody[] = [groundBody(width / 2 + 5)];
  for (let p = 0; p < count; p++) {
    bodies.push(...pyramidBoxes(base, (p - (count - 1) / 2) * pitch));
  }
  return {
    name: `many-pyramids-${count}x${base}`,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: base / 2 }, halfHeight: width / 4 },
  };
}
