/**
 * The game's camera: it shows the level at the start, glides back to the sling, follows a bird in
 * flight and comes back when the flight is over. It moves once per physics step (so it holds still
 * while the game is paused, and a pointer that aims is never under a moving picture), and never
 * while the bird is held.
 */
import type { Camera } from '../../../src/render/index';
import { ANCHOR, type SlingshotGame } from './game';

/**
 * The least of the world the view shows around the sling, m: wide on a wide screen, narrower on a
 * phone held upright (else everything would be tiny under a tall sky).
 */
const MIN_WIDTH = 8;
const MAX_WIDTH = 20;
const WIDTH_PER_ASPECT = 12;
const MIN_HEIGHT = 8;
/** how much of the ground shows below its top, m */
const BELOW_GROUND = 1.2;
/** the sling sits this far from the view's left edge, m, at most this share of the view's width */
const SLING_MARGIN = 4.5;
const SLING_SHARE = 0.35;
/** the whole level stays in view when it fits at this many CSS pixels per metre or more (a bird 20 px wide) */
const WHOLE_LEVEL_SCALE = 28;
/** the level's far end: right of its last block, m */
const FAR_MARGIN = 3;
/** steps the opening view of the level is held before the glide to the sling */
const INTRO_HOLD = 50;
/** share of the distance to its goal the camera covers each step */
const EASE = 0.07;

export class GameCamera {
  /** the camera is at its goal (within a millimetre) */
  settled = false;
  private x = 0;
  private halfHeight = 6;
  private goalX = 0;
  private goalHalfHeight = 6;
  private levelRight = 20;
  private introSteps = 0;

  constructor(
    private readonly camera: Camera,
    private readonly game: SlingshotGame,
  ) {}

  /** A new level: starts on a view of all of it. */
  reset(): void {
    let right = 12;
    for (const b of this.game.blocks) right = Math.max(right, b.body.position.x + b.halfWidth);
    for (const t of this.game.targets) right = Math.max(right, t.body.position.x + t.radius);
    this.levelRight = right + FAR_MARGIN;
    this.introSteps = 0;
    this.goals('level');
    this.x = this.goalX;
    this.halfHeight = this.goalHalfHeight;
    this.settled = false;
    this.apply();
  }

  /** The half-height that fits `width` × `height` metres in the viewport. */
  private fit(width: number, height: number): number {
    const aspect = this.camera.width / this.camera.height;
    return Math.max(height / 2, width / 2 / aspect);
  }

  /** Sets the goal: the whole level, the sling, or the bird. */
  private goals(what: 'level' | 'sling' | 'bird'): void {
    const aspect = this.camera.width / this.camera.height;
    const width = Math.min(MAX_WIDTH, Math.max(MIN_WIDTH, aspect * WIDTH_PER_ASPECT));
    const left = ANCHOR.x - Math.min(SLING_MARGIN, SLING_SHARE * width);
    const slingHalf = this.fit(width, MIN_HEIGHT);
    const levelHalf = this.fit(this.levelRight - left, MIN_HEIGHT);
    // on a wide screen the whole level fits at a good size: it stays in view all the time
    const wholeFits = this.camera.height / (2 * levelHalf) >= WHOLE_LEVEL_SCALE;
    const half = wholeFits ? levelHalf : what === 'level' ? levelHalf : slingHalf;
    const halfWidth = half * aspect;
    let x = left + halfWidth;
    if (!wholeFits && what === 'bird') {
      const bird = this.game.bird;
      const bx = bird ? bird.position.x : ANCHOR.x;
      x = Math.min(Math.max(x, bx + halfWidth * 0.2), Math.max(x, this.levelRight - halfWidth));
    }
    this.goalX = x;
    this.goalHalfHeight = half;
  }

  /** Moves a step towards the goal of the game's state. */
  step(): void {
    const state = this.game.state;
    if (state === 'aiming') return;
    const intro = this.introSteps < INTRO_HOLD;
    if (intro) {
      this.introSteps++;
      this.goals('level');
    } else {
      this.goals(state === 'flying' ? 'bird' : 'sling');
    }
    this.x += (this.goalX - this.x) * EASE;
    this.halfHeight += (this.goalHalfHeight - this.halfHeight) * EASE;
    this.settled =
      !intro &&
      Math.abs(this.goalX - this.x) < 1e-3 &&
      Math.abs(this.goalHalfHeight - this.halfHeight) < 1e-3;
    this.apply();
  }

  /** The viewport changed size: jump to the goal at once. */
  resized(): void {
    const state = this.game.state;
    this.goals(this.introSteps < INTRO_HOLD ? 'level' : state === 'flying' ? 'bird' : 'sling');
    this.x = this.goalX;
    this.halfHeight = this.goalHalfHeight;
    this.apply();
  }

  private apply(): void {
    const camera = this.camera;
    camera.center.x = this.x;
    camera.center.y = this.halfHeight - BELOW_GROUND;
    camera.halfHeight = this.halfHeight;
  }
}
