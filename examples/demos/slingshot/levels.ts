/**
 * The levels: towers of wood, ice and stone, the targets they guard, rocks, ropes and pivots, and the
 * birds the player gets. Plain data, built into a world by game.ts. The sling stands at x = 0, the
 * ground's top is y = 0.
 */
import type { BirdKind } from './birds';

export type Material = 'wood' | 'stone' | 'ice';

export interface BlockDef {
  material: Material;
  x: number;
  y: number;
  halfWidth: number;
  halfHeight: number;
  angle?: number;
}

export interface TargetDef {
  x: number;
  y: number;
  radius: number;
}

/** a static box of rock: hills, ledges, pillars, beams */
export interface RockDef {
  x: number;
  y: number;
  halfWidth: number;
  halfHeight: number;
  angle?: number;
}

/** a rope from a point of the rock to a point on block `block` (its local coordinates) */
export interface RopeDef {
  kind: 'rope';
  block: number;
  local: { x: number; y: number };
  anchor: { x: number; y: number };
}

/** block `block` turns about `anchor` (a world point) on a pin in the rock, within ±limit radians */
export interface PivotDef {
  kind: 'pivot';
  block: number;
  anchor: { x: number; y: number };
  limit: number;
}

export interface LevelDef {
  name: string;
  /** one line for the player, shown when the level starts */
  hint: string;
  birds: BirdKind[];
  rocks: RockDef[];
  blocks: BlockDef[];
  targets: TargetDef[];
  links: (RopeDef | PivotDef)[];
}

/** Adds two posts and a plank across them, standing on `floor`; returns the plank's top. */
function hut(
  blocks: BlockDef[],
  x: number,
  floor: number,
  span: number,
  posts: Material,
  plank: Material,
  postHeight = 0.8,
): number {
  const half = 0.15;
  blocks.push({
    material: posts,
    x: x - span / 2,
    y: floor + postHeight,
    halfWidth: half,
    halfHeight: postHeight,
  });
  blocks.push({
    material: posts,
    x: x + span / 2,
    y: floor + postHeight,
    halfWidth: half,
    halfHeight: postHeight,
  });
  const top = floor + 2 * postHeight;
  blocks.push({ material: plank, x, y: top + half, halfWidth: span / 2 + 0.4, halfHeight: half });
  return top + 2 * half;
}

function firstFlight(): LevelDef {
  const blocks: BlockDef[] = [];
  const top = hut(blocks, 16, 0, 2, 'wood', 'wood');
  return {
    name: 'First flight',
    hint: 'Pull the bird back and let go. Knock the hut down!',
    birds: ['red', 'red', 'red'],
    rocks: [],
    blocks,
    targets: [
      { x: 16, y: 0.45, radius: 0.45 },
      { x: 16, y: top + 0.45, radius: 0.45 },
    ],
    links: [],
  };
}

function thinIce(): LevelDef {
  const blocks: BlockDef[] = [];
  hut(blocks, 14, 0, 2, 'ice', 'ice');
  const first = hut(blocks, 20, 0, 1.6, 'wood', 'wood', 0.9);
  const second = hut(blocks, 20, first, 1.2, 'ice', 'wood', 0.6);
  return {
    name: 'Thin ice',
    hint: 'Ice shatters easily. The yellow bird dashes ahead when you tap during its flight.',
    birds: ['red', 'fast', 'red'],
    rocks: [],
    blocks,
    targets: [
      { x: 14, y: 0.45, radius: 0.45 },
      { x: 20, y: first + 0.4, radius: 0.4 },
      { x: 20, y: second + 0.4, radius: 0.4 },
    ],
    links: [],
  };
}

function stoneWall(): LevelDef {
  const blocks: BlockDef[] = [];
  // a stone wall in front, a wooden hut on a ledge behind it
  blocks.push({ material: 'stone', x: 13, y: 1.2, halfWidth: 0.3, halfHeight: 1.2 });
  blocks.push({ material: 'stone', x: 13.9, y: 1.2, halfWidth: 0.3, halfHeight: 1.2 });
  blocks.push({ material: 'stone', x: 13.45, y: 2.6, halfWidth: 0.9, halfHeight: 0.2 });
  const ledge = 1.5;
  const top = hut(blocks, 19, ledge, 2.2, 'wood', 'stone', 0.7);
  blocks.push({ material: 'ice', x: 23, y: 0.4, halfWidth: 0.15, halfHeight: 0.4 });
  return {
    name: 'Stone wall',
    hint: 'Stone is tough. The big grey bird is heavy enough to smash it.',
    birds: ['heavy', 'red', 'red'],
    rocks: [{ x: 19.5, y: ledge / 2, halfWidth: 2.5, halfHeight: ledge / 2 }],
    blocks,
    targets: [
      { x: 13.45, y: 3.2, radius: 0.4 },
      { x: 19, y: ledge + 0.45, radius: 0.45 },
      { x: 19, y: top + 0.4, radius: 0.4 },
      { x: 24, y: 0.4, radius: 0.4 },
    ],
    links: [],
  };
}

function hangingGarden(): LevelDef {
  const blocks: BlockDef[] = [];
  // a gallows of rock: a pillar at the back and a beam; a wooden platform hangs from it on two ropes
  const beamY = 8;
  const platformY = 4.6;
  blocks.push({ material: 'wood', x: 20, y: platformY, halfWidth: 1.8, halfHeight: 0.15 });
  const platform = blocks.length - 1;
  blocks.push({ material: 'ice', x: 19, y: platformY + 0.65, halfWidth: 0.15, halfHeight: 0.5 });
  blocks.push({ material: 'ice', x: 21, y: platformY + 0.65, halfWidth: 0.15, halfHeight: 0.5 });
  hut(blocks, 20, 0, 2.4, 'wood', 'ice', 0.8);
  return {
    name: 'Hanging garden',
    hint: 'A tap splits the blue bird in three. Break the platform and its guests fall.',
    birds: ['split', 'red', 'fast'],
    rocks: [
      { x: 23.6, y: beamY / 2, halfWidth: 0.3, halfHeight: beamY / 2 },
      { x: 20.6, y: beamY + 0.25, halfWidth: 3.3, halfHeight: 0.25 },
    ],
    blocks,
    targets: [
      { x: 20, y: platformY + 0.5, radius: 0.35 },
      { x: 20, y: 0.4, radius: 0.4 },
    ],
    links: [
      { kind: 'rope', block: platform, local: { x: -1.6, y: 0 }, anchor: { x: 18.4, y: beamY } },
      { kind: 'rope', block: platform, local: { x: 1.6, y: 0 }, anchor: { x: 21.6, y: beamY } },
    ],
  };
}

function seeSaw(): LevelDef {
  const blocks: BlockDef[] = [];
  // a long plank on a pin; a target at each end behind a little ice fence
  const pivotY = 1.2;
  blocks.push({ material: 'wood', x: 21, y: pivotY, halfWidth: 4, halfHeight: 0.15 });
  const plank = 0;
  blocks.push({ material: 'ice', x: 17.6, y: pivotY + 0.55, halfWidth: 0.12, halfHeight: 0.4 });
  blocks.push({ material: 'ice', x: 24.4, y: pivotY + 0.55, halfWidth: 0.12, halfHeight: 0.4 });
  // a stone shelter in front
  blocks.push({ material: 'stone', x: 13.5, y: 1, halfWidth: 0.25, halfHeight: 1 });
  blocks.push({ material: 'stone', x: 13.5, y: 2.25, halfWidth: 0.8, halfHeight: 0.25 });
  blocks.push({ material: 'wood', x: 28, y: 1.2, halfWidth: 0.2, halfHeight: 1.2 });
  return {
    name: 'See-saw',
    hint: 'Push one end down and the other flies up.',
    birds: ['red', 'heavy', 'split'],
    rocks: [{ x: 21, y: (pivotY - 0.2) / 2, halfWidth: 0.35, halfHeight: (pivotY - 0.2) / 2 }],
    blocks,
    targets: [
      { x: 18.2, y: pivotY + 0.5, radius: 0.35 },
      { x: 23.8, y: pivotY + 0.5, radius: 0.35 },
      { x: 13.5, y: 0.4, radius: 0.4 },
    ],
    links: [{ kind: 'pivot', block: plank, anchor: { x: 21, y: pivotY }, limit: 0.25 }],
  };
}

function fortress(): LevelDef {
  const blocks: BlockDef[] = [];
  // an ice hall on a stone plinth, a lookout on a pillar of rock, a keep of stone at the back
  blocks.push({ material: 'stone', x: 15, y: 0.4, halfWidth: 2.2, halfHeight: 0.4 });
  const hall = hut(blocks, 15, 0.8, 2.6, 'ice', 'stone', 0.8);
  const attic = hut(blocks, 15, hall, 1.2, 'wood', 'wood', 0.45);
  const pillarTop = 5;
  const lookout = hut(blocks, 21, pillarTop, 1, 'wood', 'ice', 0.5);
  const keep = hut(blocks, 27, 0, 1.6, 'stone', 'stone', 0.9);
  const tower = hut(blocks, 27, keep, 1, 'wood', 'wood', 0.5);
  return {
    name: 'The fortress',
    hint: 'Every bird has its job. Choose your targets.',
    birds: ['heavy', 'split', 'fast', 'red'],
    rocks: [{ x: 21, y: pillarTop / 2, halfWidth: 0.9, halfHeight: pillarTop / 2 }],
    blocks,
    targets: [
      { x: 15, y: 0.8 + 0.4, radius: 0.4 },
      { x: 15, y: hall + 0.35, radius: 0.35 },
      { x: 15, y: attic + 0.35, radius: 0.35 },
      { x: 21, y: lookout + 0.35, radius: 0.35 },
      { x: 27, y: 0.45, radius: 0.45 },
      { x: 27, y: tower + 0.35, radius: 0.35 },
    ],
    links: [],
  };
}

export const levels: readonly (() => LevelDef)[] = [
  firstFlight,
  thinIce,
  stoneWall,
  hangingGarden,
  seeSaw,
  fortress,
];
