/**
 * The aiming guide: where the bird would fly if let go now. It is the real flight, computed ahead in
 * a world of its own that holds only a copy of the bird (same gravity, same step, same launch
 * velocity), so its points are the ones the bird will pass through until it first touches something;
 * the bird's circle cast through the level's world cuts the guide where that would happen.
 */
import { type Body, type Geometry, Shape, type Vec2, World } from '../../../src/index';
import type { BirdType } from './birds';
import { launchVelocity, STEP } from './game';

/** the guide looks this far ahead, steps (2 s) */
export const PREVIEW_STEPS = 120;
/** birds are category 2: the guide's cast does not see them */
const NOT_BIRDS = { maskBits: 0xfffffffd };

export class TrajectoryPreview {
  /** x, y of the bird after each step, for `count` steps */
  readonly points = new Float64Array(2 * PREVIEW_STEPS);
  count = 0;
  private readonly world: World;
  private body: Body | null = null;
  private type: BirdType | null = null;
  private circle: Geometry | null = null;
  private readonly pose = { position: { x: 0, y: 0 }, angle: 0 };
  private readonly from: Vec2 = { x: Number.NaN, y: Number.NaN };
  private readonly velocity: Vec2 = { x: 0, y: 0 };
  private readonly segment: Vec2 = { x: 0, y: 0 };

  constructor(gravity: Vec2) {
    this.world = new World({ gravity, enableSleep: false });
  }

  /** Works the guide out for a bird of `type` let go at `from`; nothing to do when nothing changed. */
  update(type: BirdType, from: Vec2, level: World): void {
    if (type === this.type && from.x === this.from.x && from.y === this.from.y) return;
    this.from.x = from.x;
    this.from.y = from.y;
    if (type !== this.type || !this.body) {
      if (this.body) this.world.destroyBody(this.body);
      this.body = this.world.createBody({ type: 'dynamic', position: from, bullet: true, angularDamping: 2 });
      this.body.createShape(Shape.circle(type.radius), { density: type.density });
      this.type = type;
      this.circle = Shape.circle(type.radius);
    }
    const body = this.body;
    body.setTransform(from, 0);
    body.setLinearVelocity(launchVelocity(from, this.velocity));
    body.setAngularVelocity(0);
    let x = from.x;
    let y = from.y;
    let n = 0;
    for (; n < PREVIEW_STEPS; n++) {
      this.world.step(STEP);
      const p = body.position;
      this.segment.x = p.x - x;
      this.segment.y = p.y - y;
      this.pose.position.x = x;
      this.pose.position.y = y;
      const hit = level.castShape(this.circle as Geometry, this.pose, this.segment, NOT_BIRDS);
      if (hit) {
        this.points[2 * n] = x + this.segment.x * hit.fraction;
        this.points[2 * n + 1] = y + this.segment.y * hit.fraction;
        n++;
        break;
      }
      this.points[2 * n] = p.x;
      this.points[2 * n + 1] = p.y;
      x = p.x;
      y = p.y;
    }
    this.count = n;
  }

  /** Forgets the last guide (the next update works it out again). */
  clear(): void {
    this.count = 0;
    this.from.x = Number.NaN;
  }
}
