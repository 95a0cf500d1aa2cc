/** The kinds of bird: how big and heavy each is, what a tap in flight does, how it looks. */

export type BirdKind = 'red' | 'heavy' | 'split' | 'fast';

export interface BirdType {
  kind: BirdKind;
  /** shown in the HUD and the level's hint */
  name: string;
  radius: number;
  density: number;
  restitution: number;
  /** what a tap does while it flies: nothing, split in three, or dash ahead */
  ability: 'none' | 'split' | 'dash';
  /** the body's colour and the darker shade of its lower half */
  body: string;
  shade: string;
  belly: string;
}

export const birdTypes: Record<BirdKind, BirdType> = {
  red: {
    kind: 'red',
    name: 'Red',
    radius: 0.35,
    density: 4,
    restitution: 0.3,
    ability: 'none',
    body: '#e0443a',
    shade: '#9c1f1a',
    belly: '#f4d6b8',
  },
  heavy: {
    kind: 'heavy',
    name: 'Boulder',
    radius: 0.46,
    density: 9,
    restitution: 0.1,
    ability: 'none',
    body: '#4a4d57',
    shade: '#23252c',
    belly: '#8a8d96',
  },
  split: {
    kind: 'split',
    name: 'Triplet',
    radius: 0.26,
    density: 4,
    restitution: 0.3,
    ability: 'split',
    body: '#4fa3e3',
    shade: '#215f99',
    belly: '#d8ecf8',
  },
  fast: {
    kind: 'fast',
    name: 'Dart',
    radius: 0.32,
    density: 4,
    restitution: 0.2,
    ability: 'dash',
    body: '#f2c230',
    shade: '#b58411',
    belly: '#fbecb5',
  },
};

/** the speed a dash adds in the direction of flight, as a factor of the speed */
export const DASH_FACTOR = 2.2;
/** the angle between the three birds of a split, radians */
export const SPLIT_ANGLE = 0.17;
