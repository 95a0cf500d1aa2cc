/**
 * matter-js, which works in pixels and milliseconds with y down. Mapping, done only here:
 * - length: 1 m = SCALE px (50), y flipped; angles negated (y down turns the other way).
 * - time: Engine.update(engine, dt * 1000) (ms); velocities are px per 1000/60 ms, so
 *   v[px/base step] = v[m/s] * SCALE / 60 and w[rad/base step] = -w[rad/s] / 60.
 * - gravity: matter applies gravity.y * gravity.scale px/ms^2, so with the default scale 0.001,
 *   gravity.y = -g[m/s^2] * SCALE / 1000 (0.5 for g = -10). Checked by the free-fall check.
 * - mass: density per px^2 = density per m^2 / SCALE^2, so masses match in kg.
 * - body.position is the centre of mass; transforms are moved back to the body origin.
 * Settings: matter's defaults (6 position, 4 velocity, 2 constraint iterations, slop 0.05 px), no
 * sleeping (its default), frictionAir 0 instead of 0.01 (no other engine damps by default), friction
 * as the scene says (matter mixes with min), frictionStatic default 0.5.
 * Not native to matter, approximated: capsules are rectangles with fully chamfered (rounded) ends;
 * circles are polygons (up to 25 sides); rounded polygon radius is dropped; segments are 1 px thick
 * rectangles; kinematic bodies are static bodies whose transform the adapter advances each step with
 * Body.setAngle/setPosition(..., updateVelocity = true); revolute joints are zero-length stiff
 * constraints (matter has no pin joint), and since matter constraints do not stop their bodies
 * colliding, every jointed body shares one negative collision group (so jointed bodies never collide
 * with each other, connected or not). Bullets are not mapped.
 * Collision filters: category and mask bits as collisionFilter (a compound body takes its first
 * shape's), overridden for jointed bodies by the shared negative group below.
 */
import Matter, { type MatterBody, type MatterEngine } from 'matter-js';
import { shapeCentroid } from '../../scenes/mass';
import type { Scene, SceneBody, SceneShape, V } from '../../scenes/types';
import { type EngineAdapter, unsupportedJoint } from '../adapter';

/** The part of the `Matter` namespace the adapter uses: matter-js's, or fulcrum/matter's. */
export type MatterModule = Pick<typeof Matter, 'Bodies' | 'Body' | 'Composite' | 'Constraint' | 'Engine'>;

const SCALE = 50;
const JOINT_GROUP = -1;

interface Tracked {
  body: MatterBody | null;
  /** centre of mass in the body frame, px, matter axes */
  com: V;
}

interface Kinematic {
  tracked: Tracked;
  x: number;
  y: number;
  angle: number;
  vx: number;
  vy: number;
  w: number;
}

const toPx = (p: V): V => ({ x: p.x * SCALE, y: -p.y * SCALE });

/** a matter body for one shape, built in the scene body's frame (origin at 0, 0), px and y down */
function part(M: MatterModule, shape: SceneShape): MatterBody {
  const { Bodies, Body } = M;
  const options = {
    density: (shape.density ?? 1) / (SCALE * SCALE),
    friction: shape.friction ?? 0.6,
    restitution: shape.restitution ?? 0,
    frictionAir: 0,
    collisionFilter: {
      group: 0,
      category: shape.filter?.categoryBits ?? 1,
      mask: shape.filter?.maskBits ?? 0xffffffff,
    },
  };
  switch (shape.kind) {
    case 'circle': {
      const c = toPx(shape.center ?? { x: 0, y: 0 });
      return Bodies.circle(c.x, c.y, shape.radius * SCALE, options);
    }
    case 'box': {
      const c = toPx(shape.center ?? { x: 0, y: 0 });
      const box = Bodies.rectangle(
        c.x,
        c.y,
        2 * shape.halfWidth * SCALE,
        2 * shape.halfHeight * SCALE,
        options,
      );
      Body.setAngle(box, -(shape.angle ?? 0));
      return box;
    }
    case 'polygon': {
      const c = toPx(shapeCentroid(shape));
      return Body.create({ ...options, position: c, vertices: shape.points.map(toPx) });
    }
    case 'capsule':
    case 'segment': {
      const dx = shape.p2.x - shape.p1.x;
      const dy = shape.p2.y - shape.p1.y;
      const length = Math.hypot(dx, dy) * SCALE;
      const c = toPx(shapeCentroid(shape));
      const rect =
        shape.kind === 'capsule'
          ? Bodies.rectangle(c.x, c.y, length + 2 * shape.radius * SCALE, 2 * shape.radius * SCALE, {
              ...options,
              chamfer: { radius: shape.radius * SCALE },
            })
          : Bodies.rectangle(c.x, c.y, length, 1, options);
      Body.setAngle(rect, -Math.atan2(dy, dx));
      return rect;
    }
  }
}

function createBody(M: MatterModule, b: SceneBody): Tracked {
  const { Body } = M;
  if (b.shapes.length === 0) {
    if (b.type !== 'static') throw new Error('matter adapter: a moving body needs a shape');
    return { body: null, com: { x: 0, y: 0 } };
  }
  const parts = b.shapes.map((shape) => part(M, shape));
  // matter filters the parent bodies: a compound one takes its first shape's filter
  const body =
    parts.length === 1
      ? parts[0]
      : Body.create({ parts, frictionAir: 0, collisionFilter: { ...parts[0].collisionFilter } });
  const com = { x: body.position.x, y: body.position.y };
  const angle = -(b.angle ?? 0);
  const origin = toPx(b.position);
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  Body.setPosition(body, { x: origin.x + c * com.x - s * com.y, y: origin.y + s * com.x + c * com.y });
  Body.setAngle(body, angle);
  if (b.type !== 'dynamic') Body.setStatic(body, true);
  const v = b.linearVelocity ?? { x: 0, y: 0 };
  if (b.type === 'dynamic') {
    Body.setVelocity(body, { x: (v.x * SCALE) / 60, y: (-v.y * SCALE) / 60 });
    Body.setAngularVelocity(body, -(b.angularVelocity ?? 0) / 60);
  }
  return { body, com };
}

/** the origin of a tracked body, px */
function origin(t: Tracked, out: V): V {
  const body = t.body!;
  const c = Math.cos(body.angle);
  const s = Math.sin(body.angle);
  out.x = body.position.x - (c * t.com.x - s * t.com.y);
  out.y = body.position.y - (s * t.com.x + c * t.com.y);
  return out;
}

export class MatterAdapter implements EngineAdapter {
  /** `matter`: the Matter namespace to build with (matter-js by default; fulcrum/matter runs the same code) */
  constructor(private readonly M: MatterModule = Matter) {}

  readonly settings =
    `1 m = ${SCALE} px, defaults (6 position, 4 velocity, 2 constraint iterations), frictionAir 0`;
  private engine: MatterEngine | null = null;
  private tracked: Tracked[] = [];
  private kinematic: Kinematic[] = [];
  private readonly scratch: V = { x: 0, y: 0 };

  async init(): Promise<void> {}

  build(scene: Scene): void {
    this.dispose();
    const { Composite, Constraint, Engine } = this.M;
    const engine = Engine.create({
      enableSleeping: false,
      gravity: { x: (scene.gravity.x * SCALE) / 1000, y: (-scene.gravity.y * SCALE) / 1000, scale: 0.001 },
    });
    this.engine = engine;
    this.tracked = scene.bodies.map((b) => createBody(this.M, b));
    this.kinematic = [];
    scene.bodies.forEach((b, i) => {
      if (b.type !== 'kinematic') return;
      const v = b.linearVelocity ?? { x: 0, y: 0 };
      const p = toPx(b.position);
      const w = -(b.angularVelocity ?? 0);
      const k = {
        tracked: this.tracked[i],
        x: p.x,
        y: p.y,
        angle: -(b.angle ?? 0),
        vx: v.x * SCALE,
        vy: -v.y * SCALE,
        w,
      };
      this.kinematic.push(k);
    });
    const constraints = scene.joints.map((j) => {
      if (j.type !== 'revolute') unsupportedJoint('matter', j.type);
      const a = this.tracked[j.bodyA];
      const b = this.tracked[j.bodyB];
      for (const t of [a, b]) if (t.body) t.body.collisionFilter.group = JOINT_GROUP;
      const anchor = toPx(j.anchor);
      const offset = (t: Tracked): V =>
        t.body ? { x: anchor.x - t.body.position.x, y: anchor.y - t.body.position.y } : anchor;
      return Constraint.create({
        bodyA: a.body ?? undefined,
        bodyB: b.body ?? undefined,
        pointA: offset(a),
        pointB: offset(b),
        length: 0,
        stiffness: 1,
        damping: 0,
      });
    });
    const bodies = this.tracked.flatMap((t) => (t.body ? [t.body] : []));
    Composite.add(engine.world, [...bodies, ...constraints]);
  }

  step(dt: number): void {
    const { Body, Engine } = this.M;
    for (const k of this.kinematic) {
      const body = k.tracked.body!;
      k.x += k.vx * dt;
      k.y += k.vy * dt;
      k.angle += k.w * dt;
      const c = Math.cos(k.angle);
      const s = Math.sin(k.angle);
      const com = k.tracked.com;
      Body.setPosition(body, { x: k.x + c * com.x - s * com.y, y: k.y + s * com.x + c * com.y }, true);
      Body.setAngle(body, k.angle, true);
    }
    Engine.update(this.engine!, dt * 1000);
  }

  readTransforms(out: Float64Array): void {
    for (let i = 0; i < this.tracked.length; i++) {
      const t = this.tracked[i];
      if (!t.body) continue; // a shapeless static anchor: its transform never changes
      const p = origin(t, this.scratch);
      out[3 * i] = p.x / SCALE;
      out[3 * i + 1] = -p.y / SCALE;
      out[3 * i + 2] = -t.body.angle;
    }
  }

  dispose(): void {
    if (this.engine) this.M.Engine.clear(this.engine);
    this.engine = null;
    this.tracked = [];
    this.kinematic = [];
  }
}
