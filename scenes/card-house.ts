/**
 * A house of cards: leaning pairs of thin cards (A-frames) with flat cards laid across their apexes,
 * `levels` storeys high. Cards start touching, never overlapping; friction 0.8 keeps them standing.
 */
import { GRAVITY, groundBody } from './common';
import type { Scene, SceneBody, SceneShape } from './types';

const CARD_HALF_LENGTH = 0.5;
const CARD_HALF_THICKNESS = 0.01;
const LEAN = (20 * Math.PI) / 180; // each card leans 20 degrees from vertical
const FRICTION = 0.8;
const GAP = 0.002; // horizontal gap between the two cards of an A-frame at the apex

function card(x: number, y: number, angle: number, tag: string): SceneBody {
  const shape: SceneShape = {
    kind: 'box',
    halfWidth: CARD_HALF_THICKNESS,
    halfHeight: CARD_HALF_LENGTH,
    friction: FRICTION,
  };
  return { type: 'dynamic', position: { x, y }, angle, shapes: [shape], tag };
}

/** two leaning cards standing on y = floor, their apex on x = cx; returns the apex height */
function aFrame(cx: number, floor: number, out: SceneBody[]): number {
  const h = CARD_HALF_LENGTH;
  const t = CARD_HALF_THICKNESS;
  const s = Math.sin(LEAN);
  const c = Math.cos(LEAN);
  // the left card is turned clockwise by LEAN; its inner face's top corner sits GAP/2 left of cx
  const dx = t * c + h * s + GAP / 2;
  const cy = floor + h * c + t * s;
  out.push(card(cx - dx, cy, -LEAN, 'leaning-card'), card(cx + dx, cy, LEAN, 'leaning-card'));
  return cy + h * c + t * s;
}

export function cardHouse({ levels = 3 }: { levels?: number } = {}): Scene {
  const bodies: SceneBody[] = [groundBody(10)];
  // flat cards lie end to end between apexes, 4 mm apart, each resting on one corner of each apex
  const pitch = 2 * CARD_HALF_LENGTH + 0.004;
  let floor = 0;
  for (let level = 0; level < levels; level++) {
    const frames = levels - level;
    let apex = floor;
    for (let i = 0; i < frames; i++) apex = aFrame((i - (frames - 1) / 2) * pitch, floor, bodies);
    for (let i = 0; i + 1 < frames; i++) {
      const x = (i + 0.5 - (frames - 1) / 2) * pitch;
      bodies.push(card(x, apex + CARD_HALF_THICKNESS, Math.PI / 2, 'flat-card'));
    }
    floor = apex + 2 * CARD_HALF_THICKNESS;
  }
  return {
    name: `card-house-${levels}`,
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: floor / 2 }, halfHeight: floor / 2 + 1 },
  };
}
