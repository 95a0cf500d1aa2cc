import { type BodyDef, type Geometry, Shape, type ShapeDef, type Vec2 } from '../../src/index';

/*
 * One program of calls that a World and a WorkerWorld both take: the same method names, with a
 * step that the World does at once and the WorkerWorld resolves later (awaited either way).
 */

export interface BodyLike {
  readonly position: Vec2;
  readonly angle: number;
  readonly rotation: { c: number; s: number };
  readonly linearVelocity: Vec2;
  readonly angularVelocity: number;
  readonly worldCenter: Vec2;
  readonly isAwake: boolean;
  createShape(geometry: Geometry, def?: ShapeDef): unknown;
  setTransform(position: Vec2, angle: number): void;
  setLinearVelocity(velocity: Vec2): void;
  setAngularVelocity(omega: number): void;
  setType(type: 'static' | 'kinematic' | 'dynamic'): void;
  setAwake(awake: boolean): void;
  applyForce(force: Vec2, point?: Vec2): void;
  applyTorque(torque: number): void;
  applyLinearImpulse(impulse: Vec2, point?: Vec2): void;
  applyAngularImpulse(impulse: number): void;
}

export interface WorldLike<B extends BodyLike> {
  gravity: Vec2;
  createBody(def?: BodyDef): B;
  destroyBody(body: B): void;
  // the joint definition's bodies are the world's own handles
  createJoint(def: never): { readonly isValid: boolean };
  destroyJoint(joint: never): void;
  step(dt: number): unknown;
}

/** The bodies a program made, in order of creation, destroyed ones left out. */
export type Made<B> = B[];

/**
 * A pyramid of 10 rows on a ground, a pendulum of three links on revolute joints, two balls held
 * by a distance joint, a box welded to another, a slider on a prismatic joint; forces, torques and
 * impulses between steps, bullets fired and destroyed, a joint destroyed and one made, a body
 * teleported, made kinematic and dynamic again, gravity turned. `steps` steps of 1/60 s; `after`
 * is called after each step with its number (from 1).
 */
export async function runProgram<B extends BodyLike>(
  world: WorldLike<B>,
  steps: number,
  after: (step: number) => unknown = () => {},
): Promise<Made<B>> {
  const bodies: B[] = [];
  const joint = (def: Record<string, unknown>) => world.createJoint(def as never);
  const make = (def: BodyDef, geometry: Geometry, shape?: ShapeDef): B => {
    const body = world.createBody(def);
    body.createShape(geometry, shape);
    bodies.push(body);
    return body;
  };
  const ground = make({ position: { x: 0, y: -0.5 } }, Shape.box(40, 0.5));
  for (let row = 0; row < 10; row++) {
    for (let i = 0; i < 10 - row; i++) {
      make(
        { type: 'dynamic', position: { x: -5 + row * 0.55 + i * 1.1, y: 0.5 + row * 1.0 } },
        Shape.box(0.5, 0.5),
        { friction: 0.6 },
      );
    }
  }
  const pivot = make({ position: { x: 15, y: 12 } }, Shape.circle(0.2));
  let previous = pivot;
  const links: B[] = [];
  for (let i = 0; i < 3; i++) {
    const link = make(
      { type: 'dynamic', position: { x: 16 + i * 2, y: 12 } },
      Shape.capsule({ x: -1, y: 0 }, { x: 1, y: 0 }, 0.2),
      {
        density: 2,
      },
    );
    joint({ type: 'revolute', bodyA: previous, bodyB: link, anchor: { x: 15 + i * 2, y: 12 } });
    links.push(link);
    previous = link;
  }
  const ballA = make({ type: 'dynamic', position: { x: -15, y: 4 } }, Shape.circle(0.5), {
    restitution: 0.3,
  });
  const ballB = make({ type: 'dynamic', position: { x: -12, y: 6 } }, Shape.circle(0.7));
  const rope = joint({
    type: 'distance',
    bodyA: ballA,
    bodyB: ballB,
    enableSpring: true,
    hertz: 3,
    dampingRatio: 0.2,
  });
  const base = make({ type: 'dynamic', position: { x: 8, y: 1 } }, Shape.box(1, 0.5));
  const top = make(
    { type: 'dynamic', position: { x: 8, y: 2 } },
    Shape.polygon([
      { x: -0.5, y: 0 },
      { x: 0.5, y: 0 },
      { x: 0, y: 0.8 },
    ]),
  );
  joint({ type: 'weld', bodyA: base, bodyB: top, anchor: { x: 8, y: 1.5 }, linearHertz: 5, angularHertz: 5 });
  const slider = make({ type: 'dynamic', position: { x: -8, y: 3 } }, Shape.box(0.4, 0.4));
  joint({
    type: 'prismatic',
    bodyA: ground,
    bodyB: slider,
    anchor: { x: -8, y: 3 },
    axis: { x: 1, y: 0 },
    enableLimit: true,
    lower: -3,
    upper: 3,
    enableMotor: true,
    motorSpeed: 2,
    maxMotorForce: 50,
  });
  const bullets: B[] = [];
  for (let step = 1; step <= steps; step++) {
    if (step % 10 === 0) {
      links[2].applyForce({ x: 0, y: 200 }, { x: 21, y: 12 });
      ballB.applyTorque(5);
      base.applyLinearImpulse({ x: 1, y: 0 });
      slider.applyAngularImpulse(0.1);
    }
    if (step === 30) {
      for (let i = 0; i < 4; i++) {
        const bullet = make(
          {
            type: 'dynamic',
            position: { x: -20, y: 1 + i },
            linearVelocity: { x: 30, y: 2 },
            bullet: i === 0,
          },
          Shape.circle(0.25),
          { density: 4 },
        );
        bullets.push(bullet);
      }
    }
    if (step === 70) {
      world.destroyBody(bullets[1]);
      world.destroyBody(bullets[2]);
      world.destroyBody(bodies[5]);
      bodies.splice(bodies.indexOf(bullets[1]), 1);
      bodies.splice(bodies.indexOf(bullets[2]), 1);
      bodies.splice(5, 1);
    }
    if (step === 90) {
      world.destroyJoint(rope as never);
      const hook = make({ type: 'dynamic', position: { x: -13, y: 9 } }, Shape.box(0.3, 0.3));
      joint({ type: 'revolute', bodyA: hook, bodyB: ballB, anchor: { x: -12.5, y: 8 } });
    }
    if (step === 110) {
      ballA.setTransform({ x: -2, y: 14 }, 0.3);
      ballA.setLinearVelocity({ x: 0, y: -3 });
      top.setType('kinematic');
      top.setAngularVelocity(1);
    }
    if (step === 130) {
      top.setType('dynamic');
      world.gravity = { x: 1, y: -9 };
      bullets[3].setAwake(true);
    }
    await world.step(1 / 60);
    await after(step);
  }
  return bodies;
}
