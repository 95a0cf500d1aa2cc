/**
 * What the landing view says and shows of each demo: a line in plain words, and how its thumbnail is
 * made. A demo's own description (shown under it) may name the API it uses; these lines are for a
 * visitor who has not met the engine yet.
 */

/**
 * How a card's thumbnail is made:
 * - 'live': the demo's own world, built in a preview context, stepped and drawn small while visible;
 * - 'still': a world built and drawn once, then let go (too heavy to step beside the others);
 * - 'picture': the stored picture of the visual test (the demo draws with a library of its own, which
 *   the landing view does not load).
 */
export type Thumbnail =
  | { kind: 'live' }
  | { kind: 'still' /** the demo whose world is drawn, when not the card's own */; from?: string }
  | { kind: 'picture'; url: string };

export interface Card {
  summary: string;
  thumbnail: Thumbnail;
  /** the demo's source under examples/demos/: a file `<name>.ts` or a folder `<name>/` (default: its id) */
  source?: string;
}

const live: Thumbnail = { kind: 'live' };

/** The visual test's picture of a demo at step 60 (test/e2e/baselines), bundled as an asset. */
const pictures: Record<string, string> = {
  pixi: new URL('../test/e2e/baselines/pixi.png', import.meta.url).href,
  p5: new URL('../test/e2e/baselines/p5.png', import.meta.url).href,
  phaser: new URL('../test/e2e/baselines/phaser.png', import.meta.url).href,
};

export const cards: Readonly<Record<string, Card>> = {
  pyramid: {
    summary: 'Twenty rows of boxes settle into a pyramid. Pull one out and watch.',
    thumbnail: live,
  },
  'card-house': {
    summary: 'A house of cards that stands on friction alone, and a ball rolling in to test it.',
    thumbnail: live,
  },
  slingshot: {
    summary: 'Fling birds at towers of wood, ice and stone and knock out every target.',
    thumbnail: live,
  },
  'newtons-cradle': {
    summary: 'Five steel balls pass a knock down the row, like the desk toy.',
    thumbnail: live,
  },
  'chain-bridge': {
    summary: 'A rope bridge of planks carries boxes while a swinging ball crashes into them.',
    thumbnail: live,
  },
  'heavy-loads': {
    summary: 'A wrecking ball and a crane lift loads far heavier than their chains, which never stretch.',
    thumbnail: live,
  },
  ragdolls: {
    summary: 'Floppy figures are pushed off a landing and tumble down a flight of stairs, again and again.',
    thumbnail: live,
  },
  car: { summary: 'Drive a little car on springy wheels over bumps and up a hill.', thumbnail: live },
  'svg-terrain': {
    summary: 'A buggy rolls over smooth hills drawn in an SVG file. Drive it with the arrow keys.',
    thumbnail: live,
  },
  'concave-rain': { summary: 'Stars, letters and beams rain into a bowl and pile up.', thumbnail: live },
  'one-way': {
    summary: 'Jump up through platforms, land on top of them, and ride the moving lift.',
    thumbnail: live,
  },
  cloth: {
    summary: 'A curtain sways in a breeze and tears where you pull it hard or throw a heavy ball through it.',
    thumbnail: live,
  },
  'soft-body': {
    summary: 'Squishy blobs squash when they land and wobble back into shape.',
    thumbnail: live,
  },
  planets: {
    summary: 'Drag to throw rocks around a sun: fast enough, they fall into orbit and trace their paths.',
    thumbnail: live,
  },
  golf: {
    summary:
      'Mini golf in three holes: pull back from the ball and let go to putt, over a hump, a wall and past a windmill.',
    thumbnail: live,
  },
  filtering: {
    summary: 'Coloured shapes choose what they bump into: some fall straight through each other.',
    thumbnail: live,
  },
  bullets: {
    summary: 'Very fast balls fly at very thin walls, and not one slips through.',
    thumbnail: live,
  },
  'ray-cast': {
    summary: 'A turning lamp lights up whatever its rays hit first; a laser marks everything in its path.',
    thumbnail: live,
  },
  tumbler: { summary: 'Four hundred boxes tumble in a turning drum.', thumbnail: live },
  stress: {
    summary: 'Five thousand shapes pour into a bin: see how fast it all runs.',
    thumbnail: { kind: 'still' },
  },
  'stress-worker': {
    summary: 'The same five thousand shapes, computed in a background thread while the page only draws.',
    thumbnail: { kind: 'still', from: 'stress' },
  },
  pixi: {
    summary: 'The same engine drawn by PixiJS, a popular graphics library.',
    thumbnail: { kind: 'picture', url: pictures.pixi },
  },
  p5: {
    summary: 'A p5.js sketch: click to drop balls, drag to pour boxes.',
    thumbnail: { kind: 'picture', url: pictures.p5 },
    source: 'p5-sketch',
  },
  phaser: {
    summary: 'A Phaser game scene whose sprites are moved by Fulcrum. Click to drop a crate.',
    thumbnail: { kind: 'picture', url: pictures.phaser },
  },
};

/** A demo's card; a demo not listed yet gets its own description and a live thumbnail. */
export function cardOf(demo: { id: string; description: string }): Card {
  return cards[demo.id] ?? { summary: demo.description, thumbnail: live };
}
