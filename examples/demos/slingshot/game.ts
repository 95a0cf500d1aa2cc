/**
 * The slingshot game without any drawing or DOM: a level's world, the bird held in the sling and
 * launched, the birds' tricks, blocks and targets damaged by hard hits (the world's contactHit
 * events), the score and the stars. The page (demo.ts) adds the pointer, the pictures and the sound;
 * tests and scripts can play it through `grab`, `pull`, `release` and `tap`.
 */
import { type Body, type ContactHitEvent, Shape, type Vec2, World } from '../../../src/index';
import { type BirdKind, type BirdType, birdTypes, DASH_FACTOR, SPLIT_ANGLE } from './birds';
import { type LevelDef, levels, type Material } from './levels';

export type GameState = 'ready' | 'aiming' | 'flying' | 'won' | 'lost';

/** where the bird sits in the sling */
export const ANCHOR: Readonly<Vec2> = { x: 0, y: 2.4 };
/** the farthest the bird's centre can be pulled from the anchor, m */
export const MAX_PULL = 2.2;
/** pulls shorter than this put the bird back in the sling without a shot, m */
export const MIN_PULL = 0.5;
/** launch speed per metre of pull, 1/s: a full pull throws at 18.7 m/s */
export const LAUNCH_GAIN = 8.5;
/** how far from the bird's centre a press still takes it, as a multiple of its radius (fingers are wide) */
const GRAB_REACH = 2.6;
/** the physics step the page runs at, s */
export const STEP = 1 / 60;

export interface MaterialInfo {
  density: number;
  friction: number;
  restitution: number;
  /** impact energy a square metre of it takes before it breaks, J/m² */
  toughness: number;
  points: number;
}

export const materials: Record<Material, MaterialInfo> = {
  wood: { density: 0.7, friction: 0.7, restitution: 0.05, toughness: 70, points: 500 },
  stone: { density: 2.4, friction: 0.9, restitution: 0, toughness: 240, points: 800 },
  ice: { density: 0.9, friction: 0.08, restitution: 0.1, toughness: 22, points: 300 },
};

const TARGET_POINTS = 5000;
const SPARE_BIRD_POINTS = 10000;
/** a target takes the energy of a fall onto rock at this speed, m/s */
const TARGET_SPEED = 3.2;
/** hits slower than this are not reported (resting contacts jiggle), m/s */
const HIT_THRESHOLD = 1.2;
/** a bird slower than this for REST_STEPS steps has finished its flight, m/s */
const REST_SPEED = 0.5;
const REST_STEPS = 40;
/** a bird is taken away this long after its first hit, steps */
const AFTER_HIT_STEPS = 150;
/** the longest a flight lasts, steps */
const FLIGHT_STEPS = 480;
/** bodies below this or beyond the sides have left the world, m */
const FLOOR = -6;
const LEFT_EDGE = -20;
const RIGHT_EDGE = 70;
/** category bits: birds do not hit each other (a split bird's three parts start in one place) */
const BIRD_CATEGORY = 2;

export interface Block {
  body: Body;
  material: Material;
  halfWidth: number;
  halfHeight: number;
  hp: number;
  maxHp: number;
  /** a number of its own, for the art's grain and cracks */
  seed: number;
}

export interface Target {
  body: Body;
  radius: number;
  hp: number;
  maxHp: number;
}

export interface Bird {
  body: Body;
  type: BirdType;
  /** its trick has been used, or it has hit something (no trick after that) */
  spent: boolean;
  /** steps in a row it has been slow */
  slowSteps: number;
  /** steps since its first hit (-1 before) */
  stepsSinceHit: number;
}

/** What happened, for the sound and the dust: positions in metres. */
export type GameEvent =
  | { type: 'launch'; x: number; y: number; strength: number }
  | { type: 'trick'; x: number; y: number; kind: BirdKind }
  | { type: 'hit'; x: number; y: number; material: Material | 'target' | 'bird'; strength: number }
  | {
      type: 'break';
      block: Block;
      x: number;
      y: number;
      angle: number;
      vx: number;
      vy: number;
      points: number;
    }
  | { type: 'pop'; target: Target; x: number; y: number; points: number }
  | { type: 'gone'; x: number; y: number }
  | { type: 'state'; state: GameState };

/** The launch velocity of a bird let go at `p`: along the pull, LAUNCH_GAIN per metre of it. */
export function launchVelocity(p: Vec2, out: Vec2 = { x: 0, y: 0 }): Vec2 {
  out.x = (ANCHOR.x - p.x) * LAUNCH_GAIN;
  out.y = (ANCHOR.y - p.y) * LAUNCH_GAIN;
  return out;
}

/** The point the bird is held at when the hand asks for `p`: at most MAX_PULL from the anchor, above the ground. */
export function clampPull(p: Vec2, radius: number, out: Vec2 = { x: 0, y: 0 }): Vec2 {
  let dx = p.x - ANCHOR.x;
  let dy = p.y - ANCHOR.y;
  const d = Math.hypot(dx, dy);
  if (d > MAX_PULL) {
    dx *= MAX_PULL / d;
    dy *= MAX_PULL / d;
  }
  out.x = ANCHOR.x + dx;
  out.y = Math.max(radius + 0.05, ANCHOR.y + dy);
  return out;
}

/** One game of slingshot in one world; `start(level)` rebuilds the world's bodies for a level. */
export class SlingshotGame {
  readonly world: World;
  level = 1;
  state: GameState = 'ready';
  score = 0;
  /** stars earned on the level just won (0 until then) */
  stars = 0;
  /** the best stars of each level so far (index 0 is level 1) */
  readonly best: number[] = levels.map(() => 0);
  shots = 0;
  targetsDestroyed = 0;
  blocksBroken = 0;
  readonly targets: Target[] = [];
  readonly blocks: Block[] = [];
  /** the bird in the sling (held or not), or null */
  loaded: Bird | null = null;
  /** birds in the air or rolling */
  readonly flying: Bird[] = [];
  /** the kinds of bird still to come after the loaded one */
  readonly queue: BirdKind[] = [];
  /** the scores that earn two and three stars on this level */
  starScores: [number, number] = [0, 0];
  levelDef!: LevelDef;
  /** the static ground, with the level's rocks */
  ground!: Body;
  /** the world points ropes and pins hang from, and the bodies they hold: for the art */
  readonly links: { kind: 'rope' | 'pivot'; anchor: Vec2; body: Body; local: Vec2 }[] = [];
  /** steps since the level started */
  levelSteps = 0;
  /** steps since the last launch */
  flightSteps = 0;
  /** everything the page wants to hear about */
  onEvent: ((e: GameEvent) => void) | null = null;
  private grabOffset: Vec2 = { x: 0, y: 0 };
  private readonly held: Vec2 = { x: 0, y: 0 };
  private readonly blockOf = new Map<Body, Block>();
  private readonly targetOf = new Map<Body, Target>();
  private readonly birdOf = new Map<Body, Bird>();

  constructor() {
    this.world = new World();
    this.world.hitEventThreshold = HIT_THRESHOLD;
    this.world.on('contactHit', (e) => this.onHit(e));
    this.world.on('postStep', () => this.afterStep());
  }

  get levelCount(): number {
    return levels.length;
  }

  /** Birds not shot yet: the one in the sling and the ones waiting. */
  get birdsLeft(): number {
    return this.queue.length + (this.loaded ? 1 : 0);
  }

  /** The bird to follow: the last one launched while it flies, else the loaded one. */
  get bird(): Body | null {
    const n = this.flying.length;
    if (n > 0) return this.flying[n - 1].body;
    return this.loaded?.body ?? null;
  }

  /** Builds level `n` (1-based) in the world, removing everything else. */
  start(n = this.level): void {
    const world = this.world;
    for (const body of [...world.bodies]) world.destroyBody(body);
    this.targets.length = 0;
    this.blocks.length = 0;
    this.flying.length = 0;
    this.links.length = 0;
    this.blockOf.clear();
    this.targetOf.clear();
    this.birdOf.clear();
    this.loaded = null;
    this.level = Math.min(Math.max(1, Math.floor(n)), levels.length);
    this.score = 0;
    this.stars = 0;
    this.shots = 0;
    this.targetsDestroyed = 0;
    this.blocksBroken = 0;
    this.levelSteps = 0;
    this.flightSteps = 0;
    const def = levels[this.level - 1]();
    this.levelDef = def;

    const ground = world.createBody({ position: { x: 0, y: 0 } });
    this.ground = ground;
    ground.createShape(Shape.box(45, 0.5, { x: 25, y: -0.5 }), { friction: 0.9 });
    for (const r of def.rocks) {
      ground.createShape(Shape.box(r.halfWidth, r.halfHeight, { x: r.x, y: r.y }, r.angle ?? 0), {
        friction: 0.9,
      });
    }
    let seed = this.level * 7919;
    for (const b of def.blocks) {
      const m = materials[b.material];
      const body = world.createBody({ type: 'dynamic', position: { x: b.x, y: b.y }, angle: b.angle ?? 0 });
      body.createShape(Shape.box(b.halfWidth, b.halfHeight), {
        density: m.density,
        friction: m.friction,
        restitution: m.restitution,
        enableHitEvents: true,
      });
      const hp = m.toughness * 4 * b.halfWidth * b.halfHeight;
      seed = (seed * 48271) % 2147483647;
      const block: Block = {
        body,
        material: b.material,
        halfWidth: b.halfWidth,
        halfHeight: b.halfHeight,
        hp,
        maxHp: hp,
        seed,
      };
      this.blocks.push(block);
      this.blockOf.set(body, block);
    }
    for (const t of def.targets) {
      const body = world.createBody({ type: 'dynamic', position: { x: t.x, y: t.y } });
      body.createShape(Shape.circle(t.radius), { density: 0.6, friction: 0.8, enableHitEvents: true });
      const hp = 0.5 * body.mass * TARGET_SPEED * TARGET_SPEED;
      const target: Target = { body, radius: t.radius, hp, maxHp: hp };
      this.targets.push(target);
      this.targetOf.set(body, target);
    }
    for (const link of def.links) {
      const body = this.blocks[link.block].body;
      if (link.kind === 'rope') {
        const a = link.anchor;
        const p = body.getWorldPoint(link.local);
        world.createJoint({
          type: 'distance',
          bodyA: ground,
          bodyB: body,
          localAnchorA: a,
          localAnchorB: link.local,
          length: Math.hypot(p.x - a.x, p.y - a.y),
        });
        this.links.push({ kind: 'rope', anchor: { x: a.x, y: a.y }, body, local: link.local });
      } else {
        world.createJoint({
          type: 'revolute',
          bodyA: ground,
          bodyB: body,
          anchor: link.anchor,
          enableLimit: true,
          lowerAngle: -link.limit,
          upperAngle: link.limit,
        });
        this.links.push({
          kind: 'pivot',
          anchor: { ...link.anchor },
          body,
          local: body.getLocalPoint(link.anchor),
        });
      }
    }
    const base = def.targets.length * TARGET_POINTS;
    this.starScores = [base + SPARE_BIRD_POINTS, base + 2 * SPARE_BIRD_POINTS];
    this.queue.length = 0;
    this.queue.push(...def.birds);
    this.loadBird();
    this.setState('ready');
  }

  private makeBird(type: BirdType, p: Vec2, kinematic: boolean): Bird {
    const body = this.world.createBody({
      type: kinematic ? 'kinematic' : 'dynamic',
      position: p,
      bullet: true,
      angularDamping: 2,
    });
    body.createShape(Shape.circle(type.radius), {
      density: type.density,
      friction: 0.6,
      restitution: type.restitution,
      enableHitEvents: true,
      filter: { categoryBits: BIRD_CATEGORY, maskBits: 0xfffffffd },
    });
    const bird: Bird = { body, type, spent: false, slowSteps: 0, stepsSinceHit: -1 };
    this.birdOf.set(body, bird);
    return bird;
  }

  private loadBird(): void {
    const kind = this.queue.shift();
    if (kind === undefined) return;
    // held still in the sling until it is launched
    this.loaded = this.makeBird(birdTypes[kind], ANCHOR, true);
  }

  /** True when a press at `point` takes the loaded bird. */
  canGrab(point: Vec2): boolean {
    const bird = this.loaded;
    if (this.state !== 'ready' || !bird) return false;
    const p = bird.body.position;
    return Math.hypot(point.x - p.x, point.y - p.y) < bird.type.radius * GRAB_REACH;
  }

  /** Takes hold of the bird at `point`, keeping the point's offset from its centre; false when it cannot be taken now. */
  grab(point: Vec2): boolean {
    if (!this.canGrab(point) || !this.loaded) return false;
    const p = this.loaded.body.position;
    this.grabOffset = { x: point.x - p.x, y: point.y - p.y };
    this.setState('aiming');
    return true;
  }

  /** Moves the held bird so that the point it was taken by is at `point` (as far as the band allows). */
  pull(point: Vec2): void {
    const bird = this.loaded;
    if (this.state !== 'aiming' || !bird) return;
    this.held.x = point.x - this.grabOffset.x;
    this.held.y = point.y - this.grabOffset.y;
    const p = clampPull(this.held, bird.type.radius, this.held);
    bird.body.setTransform(p, 0);
  }

  /** Where the held bird is, or null when none is held. */
  get aim(): Vec2 | null {
    return this.state === 'aiming' && this.loaded ? this.loaded.body.position : null;
  }

  /** Lets go: a long enough pull launches the bird at launchVelocity, a short one puts it back. */
  release(): void {
    const bird = this.loaded;
    if (this.state !== 'aiming' || !bird) return;
    const body = bird.body;
    const p = body.position;
    const d = Math.hypot(ANCHOR.x - p.x, ANCHOR.y - p.y);
    if (d < MIN_PULL) {
      body.setTransform(ANCHOR, 0);
      this.setState('ready');
      return;
    }
    body.setType('dynamic');
    body.setLinearVelocity(launchVelocity(p));
    body.setAngularVelocity(0);
    this.loaded = null;
    this.flying.push(bird);
    this.shots++;
    this.flightSteps = 0;
    this.emit({ type: 'launch', x: p.x, y: p.y, strength: d / MAX_PULL });
    this.setState('flying');
  }

  /** A tap while a bird flies: its trick (split in three, or dash), once, before it hits anything. */
  tap(): boolean {
    if (this.state !== 'flying') return false;
    const bird = this.flying[this.flying.length - 1];
    if (!bird || bird.spent || bird.type.ability === 'none') return false;
    bird.spent = true;
    const body = bird.body;
    const v = body.linearVelocity;
    const p = body.position;
    if (bird.type.ability === 'dash') {
      body.setLinearVelocity({ x: v.x * DASH_FACTOR, y: v.y * DASH_FACTOR });
    } else {
      const c = Math.cos(SPLIT_ANGLE);
      const s = Math.sin(SPLIT_ANGLE);
      for (const sign of [1, -1]) {
        const twin = this.makeBird(bird.type, p, false);
        twin.spent = true;
        twin.body.setLinearVelocity({ x: v.x * c - sign * v.y * s, y: sign * v.x * s + v.y * c });
        // the followed bird stays last
        this.flying.splice(this.flying.length - 1, 0, twin);
      }
    }
    this.emit({ type: 'trick', x: p.x, y: p.y, kind: bird.type.kind });
    return true;
  }

  private onHit(e: ContactHitEvent): void {
    const speed = e.approachSpeed;
    const a = e.bodyA;
    const b = e.bodyB;
    // an earlier hit of the same step may have broken one of them
    if (!a.isValid || !b.isValid) return;
    // the impact's energy in the frame of the two bodies' centre of mass: heavy things hit harder
    const ma = a.type === 'dynamic' ? a.mass : 0;
    const mb = b.type === 'dynamic' ? b.mass : 0;
    const reduced = ma > 0 && mb > 0 ? (ma * mb) / (ma + mb) : Math.max(ma, mb);
    const energy = 0.5 * reduced * speed * speed;
    const birdA = this.birdOf.get(a);
    const birdB = this.birdOf.get(b);
    for (const bird of [birdA, birdB]) {
      if (!bird) continue;
      bird.spent = true;
      if (bird.stepsSinceHit < 0) bird.stepsSinceHit = 0;
    }
    this.damage(a, energy, e.point, speed);
    this.damage(b, energy, e.point, speed);
  }

  private damage(body: Body, energy: number, at: Vec2, speed: number): void {
    if (!body.isValid || this.state === 'won') return;
    const block = this.blockOf.get(body);
    if (block) {
      block.hp -= energy;
      this.emit({ type: 'hit', x: at.x, y: at.y, material: block.material, strength: speed });
      if (block.hp <= 0) this.breakBlock(block);
      return;
    }
    const target = this.targetOf.get(body);
    if (target) {
      target.hp -= energy;
      this.emit({ type: 'hit', x: at.x, y: at.y, material: 'target', strength: speed });
      if (target.hp <= 0) this.popTarget(target);
      return;
    }
    if (this.birdOf.has(body))
      this.emit({ type: 'hit', x: at.x, y: at.y, material: 'bird', strength: speed });
  }

  private breakBlock(block: Block): void {
    const body = block.body;
    const p = body.position;
    const v = body.linearVelocity;
    const points = materials[block.material].points;
    this.blocks.splice(this.blocks.indexOf(block), 1);
    this.blockOf.delete(body);
    for (let i = this.links.length - 1; i >= 0; i--) if (this.links[i].body === body) this.links.splice(i, 1);
    this.score += points;
    this.blocksBroken++;
    this.emit({ type: 'break', block, x: p.x, y: p.y, angle: body.angle, vx: v.x, vy: v.y, points });
    this.world.destroyBody(body);
  }

  private popTarget(target: Target): void {
    const body = target.body;
    const p = body.position;
    this.targets.splice(this.targets.indexOf(target), 1);
    this.targetOf.delete(body);
    this.score += TARGET_POINTS;
    this.targetsDestroyed++;
    this.emit({ type: 'pop', target, x: p.x, y: p.y, points: TARGET_POINTS });
    this.world.destroyBody(body);
  }

  private afterStep(): void {
    this.levelSteps++;
    for (let i = this.targets.length - 1; i >= 0; i--) {
      const t = this.targets[i];
      if (t.body.position.y < FLOOR) this.popTarget(t);
    }
    for (let i = this.blocks.length - 1; i >= 0; i--) {
      const block = this.blocks[i];
      if (block.body.position.y < FLOOR) this.breakBlock(block);
    }
    if (this.state === 'flying') this.followFlight();
    if (this.targets.length === 0 && this.state !== 'won') this.win();
  }

  private followFlight(): void {
    this.flightSteps++;
    for (let i = this.flying.length - 1; i >= 0; i--) {
      const bird = this.flying[i];
      const p = bird.body.position;
      const v = bird.body.linearVelocity;
      bird.slowSteps = v.x * v.x + v.y * v.y < REST_SPEED * REST_SPEED ? bird.slowSteps + 1 : 0;
      if (bird.stepsSinceHit >= 0) bird.stepsSinceHit++;
      const out = p.y < FLOOR || p.x < LEFT_EDGE || p.x > RIGHT_EDGE;
      const done = bird.slowSteps > REST_STEPS || bird.stepsSinceHit > AFTER_HIT_STEPS;
      if (out || done || this.flightSteps > FLIGHT_STEPS) {
        this.removeBird(i);
      }
    }
    if (this.flying.length > 0) return;
    if (this.targets.length === 0) return;
    if (this.queue.length > 0) {
      this.loadBird();
      this.setState('ready');
    } else {
      this.setState('lost');
    }
  }

  private removeBird(i: number): void {
    const bird = this.flying[i];
    const p = bird.body.position;
    this.flying.splice(i, 1);
    this.birdOf.delete(bird.body);
    this.emit({ type: 'gone', x: p.x, y: p.y });
    this.world.destroyBody(bird.body);
  }

  private win(): void {
    const spare = this.birdsLeft;
    this.score += SPARE_BIRD_POINTS * spare;
    this.stars = 1 + (this.score >= this.starScores[0] ? 1 : 0) + (this.score >= this.starScores[1] ? 1 : 0);
    this.best[this.level - 1] = Math.max(this.best[this.level - 1], this.stars);
    this.setState('won');
  }

  private setState(state: GameState): void {
    this.state = state;
    this.emit({ type: 'state', state });
  }

  private emit(e: GameEvent): void {
    this.onEvent?.(e);
  }
}
