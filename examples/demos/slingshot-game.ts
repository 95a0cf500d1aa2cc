/**
 * The slingshot game, without any drawing or DOM: levels, the bird on its spring, the shots, targets
 * destroyed by hard hits (contactHit events), the score. The demo (slingshot.ts) adds the pointer and
 * the pictures; tests can play it through `grab`, `pull` and `release`.
 */
import {
  type Body,
  type DistanceJoint,
  type MouseJoint,
  Shape,
  type ShapeHandle,
  type Vec2,
  World,
} from '../../src/index';

export type Material = 'wood' | 'stone' | 'ice';
export type GameState = 'ready' | 'aiming' | 'flying' | 'won' | 'lost';

export const materials: Record<
  Material,
  { density: number; friction: number; restitution: number; color: number }
> = {
  wood: { density: 0.7, friction: 0.7, restitution: 0.05, color: 0xb07a45 },
  stone: { density: 2.4, friction: 0.9, restitution: 0, color: 0x8d949e },
  ice: { density: 0.9, friction: 0.08, restitution: 0.1, color: 0x9fdcf0 },
};

/** where the bird sits in the sling */
export const ANCHOR: Vec2 = { x: -12, y: 2.6 };
export const BIRD_RADIUS = 0.35;
/** the farthest the bird can be pulled from the anchor, m */
export const MAX_PULL = 2.6;
/** pulls shorter than this let the bird go back into the sling without a shot */
const MIN_PULL = 0.6;
/** a target is destroyed by a hit faster than this, m/s */
export const TARGET_HIT_SPEED = 2.5;
/** ice breaks above this approach speed, m/s */
const ICE_BREAK_SPEED = 6;
const BIRDS_PER_LEVEL = 4;
const TARGET_POINTS = 500;
const ICE_POINTS = 50;
const BIRD_BONUS = 1000;
/** category bits: the sling's frame touches nothing */
const SLING = 2;

interface BlockDef {
  material: Material;
  x: number;
  y: number;
  halfWidth: number;
  halfHeight: number;
  angle?: number;
}

interface TargetDef {
  x: number;
  y: number;
  radius: number;
}

/** a static box of rock: hills, ledges and walls */
export interface TerrainDef {
  x: number;
  y: number;
  halfWidth: number;
  halfHeight: number;
  angle?: number;
}

export interface Level {
  name: string;
  terrain?: TerrainDef[];
  blocks: BlockDef[];
  targets: TargetDef[];
}

/** `count` storeys of two posts and a plank across them, starting on `floor`; returns the top */
function frame(
  blocks: BlockDef[],
  x: number,
  floor: number,
  span: number,
  postMaterial: Material,
  plankMaterial: Material,
  postHeight = 0.8,
): number {
  const post = 0.15;
  const plank = 0.15;
  blocks.push({
    material: postMaterial,
    x: x - span / 2,
    y: floor + postHeight,
    halfWidth: post,
    halfHeight: postHeight,
  });
  blocks.push({
    material: postMaterial,
    x: x + span / 2,
    y: floor + postHeight,
    halfWidth: post,
    halfHeight: postHeight,
  });
  const top = floor + 2 * postHeight;
  blocks.push({ material: plankMaterial, x, y: top + plank, halfWidth: span / 2 + 0.4, halfHeight: plank });
  return top + 2 * plank;
}

function level1(): Level {
  const blocks: BlockDef[] = [];
  const top = frame(blocks, 9, 0, 2, 'wood', 'wood');
  return {
    name: 'A wooden hut',
    blocks,
    targets: [
      { x: 9, y: 0.45, radius: 0.45 },
      { x: 9, y: top + 0.45, radius: 0.45 },
    ],
  };
}

function level2(): Level {
  const blocks: BlockDef[] = [];
  // a stone hut in the open, a tower on a rock, and a pit hidden behind the rock
  frame(blocks, 3, 0, 2, 'stone', 'wood');
  const rockTop = 3;
  const tower = frame(blocks, 9.5, rockTop, 1.4, 'wood', 'stone', 0.6);
  blocks.push({ material: 'stone', x: 13.5, y: 0.5, halfWidth: 0.2, halfHeight: 0.5 });
  blocks.push({ material: 'stone', x: 15.5, y: 0.5, halfWidth: 0.2, halfHeight: 0.5 });
  return {
    name: 'Stone and wood',
    terrain: [{ x: 9.5, y: rockTop / 2, halfWidth: 1.5, halfHeight: rockTop / 2 }],
    blocks,
    targets: [
      { x: 3, y: 0.4, radius: 0.4 },
      { x: 9.5, y: tower + 0.4, radius: 0.4 },
      { x: 14.5, y: 0.4, radius: 0.4 },
    ],
  };
}

function level3(): Level {
  const blocks: BlockDef[] = [];
  // an ice hall on a stone plinth; a lookout on a pillar of rock; a watchtower behind a wall
  blocks.push({ material: 'stone', x: 2, y: 0.4, halfWidth: 2.2, halfHeight: 0.4 });
  const hall = frame(blocks, 2, 0.8, 2.6, 'ice', 'stone', 0.8);
  frame(blocks, 2, hall, 1.2, 'ice', 'wood', 0.45);
  const pillarTop = 5;
  const lookout = frame(blocks, 8.5, pillarTop, 1, 'wood', 'wood', 0.5);
  const watch = frame(blocks, 15.5, frame(blocks, 15.5, 0, 1.4, 'stone', 'ice', 0.9), 1, 'wood', 'wood', 0.5);
  return {
    name: 'The ice fortress',
    terrain: [
      { x: 8.5, y: pillarTop / 2, halfWidth: 0.9, halfHeight: pillarTop / 2 },
      { x: 12.8, y: 1, halfWidth: 0.35, halfHeight: 1 },
    ],
    blocks,
    targets: [
      { x: 2, y: 0.8 + 0.4, radius: 0.4 },
      { x: 2, y: hall + 0.35, radius: 0.35 },
      { x: 8.5, y: lookout + 0.35, radius: 0.35 },
      { x: 15.5, y: watch + 0.4, radius: 0.4 },
    ],
  };
}

export const levels: readonly (() => Level)[] = [level1, level2, level3];

export interface GameEvents {
  /** something the player sees changed: state, score, birds, targets */
  change(game: SlingshotGame): void;
}

/** One game of slingshot in one world; `start(level)` rebuilds the world's bodies for a level. */
export class SlingshotGame {
  readonly world: World;
  level = 1;
  state: GameState = 'ready';
  score = 0;
  birdsLeft = 0;
  shots = 0;
  targetsDestroyed = 0;
  readonly targets = new Set<Body>();
  readonly blocks = new Map<Body, Material>();
  bird: Body | null = null;
  /** the flight path of the last bird, for drawing */
  readonly trail: Vec2[] = [];
  sling!: Body;
  /** the static ground, with the level's rocks */
  ground!: Body;
  onChange: ((game: SlingshotGame) => void) | null = null;
  /** true while the loaded bird sits in the sling, not yet shot */
  private loaded = false;
  private spring: DistanceJoint | null = null;
  private hand: MouseJoint | null = null;
  private pullDirection: Vec2 = { x: 1, y: 0 };
  private flightSteps = 0;
  private slowSteps = 0;
  private readonly targetShapes = new Set<ShapeHandle>();

  constructor(world: World = new World()) {
    this.world = world;
    world.on('contactHit', (e) => {
      const speed = e.approachSpeed;
      this.hitBody(e.bodyA, speed);
      this.hitBody(e.bodyB, speed);
    });
    world.on('postStep', () => this.afterStep());
  }

  get levelCount(): number {
    return levels.length;
  }

  /** Builds level `n` (1-based) in the world, removing everything else. */
  start(n = this.level): void {
    const world = this.world;
    this.hand = null;
    this.spring = null;
    this.loaded = false;
    for (const body of [...world.bodies]) world.destroyBody(body);
    this.targets.clear();
    this.targetShapes.clear();
    this.blocks.clear();
    this.trail.length = 0;
    this.level = Math.min(Math.max(1, n), levels.length);
    if (this.level === 1) this.score = 0;
    this.shots = 0;
    this.targetsDestroyed = 0;
    this.birdsLeft = BIRDS_PER_LEVEL;
    const ground = world.createBody({ position: { x: 0, y: 0 } });
    this.ground = ground;
    ground.createShape(Shape.box(40, 0.5, { x: 5, y: -0.5 }), { friction: 0.9 });
    ground.createShape(Shape.box(0.5, 10, { x: 45.5, y: 9.5 }));
    this.sling = world.createBody({ position: ANCHOR });
    const noCollide = { filter: { categoryBits: SLING, maskBits: 0 } };
    this.sling.createShape(Shape.capsule({ x: 0, y: -ANCHOR.y }, { x: 0, y: -0.9 }, 0.12), noCollide);
    this.sling.createShape(Shape.capsule({ x: 0, y: -0.9 }, { x: -0.45, y: 0.25 }, 0.1), noCollide);
    this.sling.createShape(Shape.capsule({ x: 0, y: -0.9 }, { x: 0.45, y: 0.25 }, 0.1), noCollide);
    const level = levels[this.level - 1]();
    for (const t of level.terrain ?? []) {
      ground.createShape(Shape.box(t.halfWidth, t.halfHeight, { x: t.x, y: t.y }, t.angle ?? 0), {
        friction: 0.9,
      });
    }
    for (const b of level.blocks) {
      const m = materials[b.material];
      const body = world.createBody({ type: 'dynamic', position: { x: b.x, y: b.y }, angle: b.angle ?? 0 });
      body.createShape(Shape.box(b.halfWidth, b.halfHeight), {
        density: m.density,
        friction: m.friction,
        restitution: m.restitution,
        enableHitEvents: b.material === 'ice',
      });
      this.blocks.set(body, b.material);
    }
    for (const t of level.targets) {
      const body = world.createBody({ type: 'dynamic', position: { x: t.x, y: t.y } });
      const shape = body.createShape(Shape.circle(t.radius), {
        density: 0.6,
        friction: 0.8,
        enableHitEvents: true,
      });
      this.targets.add(body);
      this.targetShapes.add(shape);
    }
    this.loadBird();
    this.changed();
  }

  get levelName(): string {
    return levels[this.level - 1]().name;
  }

  private loadBird(): void {
    if (this.birdsLeft <= 0) return;
    this.birdsLeft--;
    const bird = this.world.createBody({ type: 'dynamic', position: ANCHOR, bullet: true });
    bird.createShape(Shape.circle(BIRD_RADIUS), { density: 4, friction: 0.6, restitution: 0.3 });
    this.bird = bird;
    this.loaded = true;
    this.spring = this.world.createJoint({
      type: 'distance',
      bodyA: this.sling,
      bodyB: bird,
      length: 0,
      enableSpring: true,
      hertz: 1.3,
      dampingRatio: 0.05,
    });
    this.state = 'ready';
    this.flightSteps = 0;
    this.slowSteps = 0;
  }

  /** True when `point` is on the bird and it may be pulled. */
  canGrab(point: Vec2): boolean {
    if (this.state !== 'ready' || !this.bird) return false;
    const p = this.bird.position;
    return Math.hypot(point.x - p.x, point.y - p.y) < BIRD_RADIUS * 2.5;
  }

  /** Takes hold of the bird at `point`; false when it cannot be pulled now. */
  grab(point: Vec2): boolean {
    if (!this.canGrab(point) || !this.bird) return false;
    this.hand = this.world.createJoint({
      type: 'mouse',
      body: this.bird,
      target: this.clampPull(point),
      maxForce: 2000 * this.bird.mass,
      hertz: 8,
      dampingRatio: 1,
    });
    this.state = 'aiming';
    this.changed();
    return true;
  }

  /** The point the bird is pulled to: at most MAX_PULL from the anchor and above the ground. */
  clampPull(point: Vec2): Vec2 {
    let dx = point.x - ANCHOR.x;
    let dy = point.y - ANCHOR.y;
    const d = Math.hypot(dx, dy);
    if (d > MAX_PULL) {
      dx *= MAX_PULL / d;
      dy *= MAX_PULL / d;
    }
    return { x: ANCHOR.x + dx, y: Math.max(BIRD_RADIUS + 0.1, ANCHOR.y + dy) };
  }

  pull(point: Vec2): void {
    if (this.state !== 'aiming' || !this.hand) return;
    this.hand.setTarget(this.clampPull(point));
  }

  /** Birds not shot yet: the one in the sling and the ones waiting. */
  get birdsUnused(): number {
    return this.birdsLeft + (this.loaded ? 1 : 0);
  }

  /** Lets go: a long enough pull launches the bird, a short one lets it back into the sling. */
  release(): void {
    if (this.hand && this.state !== 'aiming') {
      // the level ended while the bird was held
      this.world.destroyJoint(this.hand);
      this.hand = null;
      return;
    }
    if (this.state !== 'aiming' || !this.hand || !this.bird) return;
    this.world.destroyJoint(this.hand);
    this.hand = null;
    const p = this.bird.position;
    const dx = ANCHOR.x - p.x;
    const dy = ANCHOR.y - p.y;
    const d = Math.hypot(dx, dy);
    if (d < MIN_PULL) {
      this.state = 'ready';
    } else {
      this.pullDirection = { x: dx / d, y: dy / d };
      this.state = 'flying';
      this.loaded = false;
      this.shots++;
      this.trail.length = 0;
      this.flightSteps = 0;
      this.slowSteps = 0;
    }
    this.changed();
  }

  private hitBody(body: Body, speed: number): void {
    if (!body.isValid) return;
    if (this.targets.has(body)) {
      if (speed < TARGET_HIT_SPEED) return;
      this.targets.delete(body);
      this.targetsDestroyed++;
      this.score += TARGET_POINTS;
      this.world.destroyBody(body);
      this.changed();
    } else if (this.blocks.get(body) === 'ice' && speed > ICE_BREAK_SPEED) {
      this.blocks.delete(body);
      this.score += ICE_POINTS;
      this.world.destroyBody(body);
      this.changed();
    }
  }

  private afterStep(): void {
    // targets that fall off the world count as destroyed
    for (const t of this.targets) {
      if (t.position.y < -5) this.hitBody(t, Number.POSITIVE_INFINITY);
    }
    const bird = this.bird;
    if (this.state === 'flying' && bird) {
      const p = bird.position;
      // the spring lets go once the bird passes the anchor
      if (this.spring) {
        const along = (p.x - ANCHOR.x) * this.pullDirection.x + (p.y - ANCHOR.y) * this.pullDirection.y;
        if (along >= 0) {
          this.world.destroyJoint(this.spring);
          this.spring = null;
        }
      } else {
        this.flightSteps++;
        if (this.flightSteps % 3 === 0) this.trail.push(p);
        const v = bird.linearVelocity;
        this.slowSteps = v.x * v.x + v.y * v.y < 0.25 ? this.slowSteps + 1 : 0;
        const gone = p.y < -5 || p.x > 60 || p.x < -30;
        if (gone || this.slowSteps > 45 || this.flightSteps > 420) {
          this.world.destroyBody(bird);
          this.bird = null;
          this.state = 'lost';
          if (this.targets.size > 0 && this.birdsLeft > 0) this.loadBird();
          this.changed();
        }
      }
    }
    if (this.targets.size === 0 && this.state !== 'won') {
      this.state = 'won';
      this.score += BIRD_BONUS * this.birdsUnused;
      this.changed();
    }
  }

  private changed(): void {
    this.onChange?.(this);
  }
}
