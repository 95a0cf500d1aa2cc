import { describe, expect, it } from 'vitest';
import { createRandom, type Random } from '../../scenes/random';
import { type Body, type Joint, type RevoluteJoint, Shape, stateHash, World } from '../../src/index';

const DT = 1 / 60;

/** Velocity of the material point of `body` that is at world point `p`. */
function pointVelocity(body: Body, p: { x: number; y: number }): { x: number; y: number } {
  const v = body.linearVelocity;
  const w = body.angularVelocity;
  const c = body.worldCenter;
  return { x: v.x - w * (p.y - c.y), y: v.y + w * (p.x - c.x) };
}

/** Sliders' axes in body A's frame, by joint. */
const localAxes = new Map<Joint, { x: number; y: number }>();

/**
 * How fast a joint's constraint is being violated: the relative velocity of its anchors (a hinge),
 * its component along the rod (a rod), or that and the relative turn rate times `length` (a weld);
 * for a slider, how fast B's anchor moves across the axis relative to A (and turns, for a prismatic).
 */
function violationSpeed(joint: Joint, length: number): number {
  const turn = length * Math.abs(joint.bodyB.angularVelocity - joint.bodyA.angularVelocity);
  const localAxis = localAxes.get(joint);
  if (localAxis !== undefined) {
    const axis = joint.bodyA.getWorldVector(localAxis);
    const vA = pointVelocity(joint.bodyA, joint.anchorB);
    const vB = pointVelocity(joint.bodyB, joint.anchorB);
    const across = Math.abs(-(vB.x - vA.x) * axis.y + (vB.y - vA.y) * axis.x);
    return joint.type === 'prismatic' ? Math.max(across, turn) : across;
  }
  const vA = pointVelocity(joint.bodyA, joint.anchorA);
  const vB = pointVelocity(joint.bodyB, joint.anchorB);
  const dx = vB.x - vA.x;
  const dy = vB.y - vA.y;
  if (joint.type === 'distance') {
    const a = joint.anchorA;
    const b = joint.anchorB;
    const d = Math.hypot(b.x - a.x, b.y - a.y);
    return Math.abs((dx * (b.x - a.x) + dy * (b.y - a.y)) / d);
  }
  const point = Math.hypot(dx, dy);
  if (joint.type === 'revolute') return point;
  return Math.max(point, turn);
}

/**
 * A random forest of rigid joints between boxes of very different masses (1:1000) that do not
 * collide, each body joined to one earlier body (or to the ground) by a hinge, a weld, a rod, a
 * prismatic slider or a wheel's axle (both free along their axis).
 */
function randomForest(seed: number, grounded: boolean) {
  const rng = createRandom(seed);
  const world = new World({ gravity: { x: 0, y: grounded ? -10 : 0 }, enableSleep: false });
  const ground = world.createBody();
  const bodies: Body[] = [];
  const joints: Joint[] = [];
  const kinds = ['revolute', 'weld', 'distance', 'prismatic', 'wheel'] as const;
  for (let i = 0; i < 40; i++) {
    const body = world.createBody({
      type: 'dynamic',
      position: { x: rng.range(-4, 4), y: rng.range(-4, 4) },
      angle: rng.range(-3, 3),
      linearVelocity: { x: rng.range(-2, 2), y: rng.range(-2, 2) },
      angularVelocity: rng.range(-2, 2),
    });
    body.createShape(Shape.box(rng.range(0.1, 0.4), rng.range(0.1, 0.4)), {
      density: 10 ** rng.range(-1.5, 1.5),
      filter: { maskBits: 0 },
    });
    const root = i === 0 || (grounded && rng.nextFloat() < 0.1);
    const other = root ? ground : bodies[rng.int(i)];
    if (root && !grounded) {
      bodies.push(body);
      continue;
    }
    const kind = kinds[rng.int(kinds.length)];
    const p = body.position;
    const q = other === ground ? { x: p.x + rng.range(-1, 1), y: p.y + rng.range(-1, 1) } : other.position;
    const anchor = {
      x: 0.5 * (p.x + q.x) + rng.range(-0.3, 0.3),
      y: 0.5 * (p.y + q.y) + rng.range(-0.3, 0.3),
    };
    if (kind === 'distance') {
      joints.push(
        world.createJoint({
          type: 'distance',
          bodyA: other,
          bodyB: body,
          localAnchorA: other.getLocalPoint(anchor),
          localAnchorB: body.getLocalPoint(p),
        }),
      );
    } else if (kind === 'prismatic' || kind === 'wheel') {
      const a = rng.range(-Math.PI, Math.PI);
      const axis = { x: Math.cos(a), y: Math.sin(a) };
      const joint = world.createJoint({ type: kind, bodyA: other, bodyB: body, anchor, axis });
      localAxes.set(joint, other.getLocalVector(axis));
      joints.push(joint);
    } else {
      joints.push(world.createJoint({ type: kind, bodyA: other, bodyB: body, anchor }));
    }
    bodies.push(body);
  }
  return { world, bodies, joints };
}

function momentum(bodies: Body[]) {
  let px = 0;
  let py = 0;
  for (const b of bodies) {
    const v = b.linearVelocity;
    px += b.mass * v.x;
    py += b.mass * v.y;
  }
  return { px, py };
}

/** A world without sleep: a ground and 30 random boxes and discs (densities 0.1 to 30). */
function randomBodies(rng: Random): { world: World; ground: Body; bodies: Body[] } {
  const world = new World({ enableSleep: false });
  const ground = world.createBody({ position: { x: 0, y: -0.5 } });
  ground.createShape(Shape.box(20, 0.5));
  const bodies: Body[] = [];
  for (let i = 0; i < 30; i++) {
    const body = world.createBody({
      type: 'dynamic',
      position: { x: rng.range(-5, 5), y: rng.range(1, 10) },
      angle: rng.range(-3, 3),
    });
    if (rng.nextFloat() < 0.5) {
      body.createShape(Shape.box(rng.range(0.1, 0.5), rng.range(0.1, 0.5)), {
        density: 10 ** rng.range(-1, 1.5),
      });
    } else {
      body.createShape(Shape.circle(rng.range(0.1, 0.4)), { density: 10 ** rng.range(-1, 1.5) });
    }
    bodies.push(body);
  }
  return { world, ground, bodies };
}

/** Steps 300 times: whether every body stayed finite, and the largest speed and turn rate seen. */
function runNetwork(world: World, bodies: Body[]): { finite: boolean; speed: number; turnRate: number } {
  let finite = true;
  let speed = 0;
  let turnRate = 0;
  for (let s = 0; s < 300; s++) {
    world.step(DT);
    for (const body of bodies) {
      const p = body.position;
      const v = body.linearVelocity;
      if (!Number.isFinite(p.x + p.y + v.x + v.y + body.angularVelocity)) finite = false;
      speed = Math.max(speed, Math.hypot(v.x, v.y));
      turnRate = Math.max(turnRate, Math.abs(body.angularVelocity));
    }
  }
  return { finite, speed, turnRate };
}

describe('joint tree', () => {
  it('free random forests of hinges, welds, rods and sliders: no joint drifts apart; momentum is conserved', () => {
    for (const seed of [1, 2, 3]) {
      const { world, bodies, joints } = randomForest(seed, false);
      const before = momentum(bodies);
      const scale = Math.max(Math.abs(before.px), Math.abs(before.py), 1);
      for (let s = 0; s < 120; s++) {
        world.step(DT);
        // the last thing a step does to the velocities is project them onto the joints' rows
        for (const joint of joints) expect(violationSpeed(joint, 1)).toBeLessThan(1e-9);
      }
      const after = momentum(bodies);
      // the joints' impulses are internal, equal and opposite (angular momentum is not exact: the pair
      // acts at two anchors that are apart by the joint's position error, a torque of that arm)
      expect(Math.abs(after.px - before.px) / scale).toBeLessThan(1e-9);
      expect(Math.abs(after.py - before.py) / scale).toBeLessThan(1e-9);
      // Positions are held by the soft bias, not exactly: within a substep the anchors move along arcs
      // while the rows constrain their velocities on the tangent, a drift of (ω h)² r / 2 per substep
      // (≤ 0.7 mm for ω ≤ 5 rad/s, r ≤ 3 m, h = 1/240 s) that the bias takes back at about a quarter per
      // substep. Measured: 0.11 mm at most.
      for (const joint of joints) {
        if (joint.type === 'revolute' || joint.type === 'weld') {
          const a = joint.anchorA;
          const b = joint.anchorB;
          expect(Math.hypot(b.x - a.x, b.y - a.y)).toBeLessThan(1e-3);
        }
      }
    }
  });

  it('random forests hanging from the ground under gravity: no joint drifts apart', () => {
    for (const seed of [4, 5, 6]) {
      const { world, joints } = randomForest(seed, true);
      for (let s = 0; s < 120; s++) {
        world.step(DT);
        for (const joint of joints) expect(violationSpeed(joint, 1)).toBeLessThan(1e-9);
      }
    }
  });

  it('a network of hinges locked against itself tears apart but never turns to NaN', () => {
    // 35 hinges at random midpoints among 30 boxes and discs: more constraints than the bodies can
    // satisfy together. Box2D v3 blows up on 15 of these 20 seeds as well; what matters is that the
    // world stays finite (without the warm-start guard some of them end in NaN).
    for (let seed = 1; seed <= 20; seed++) {
      const rng = createRandom(seed);
      const { world, ground, bodies: dynamic } = randomBodies(rng);
      const bodies = [ground, ...dynamic];
      for (let k = 0; k < 35; k++) {
        const a = rng.nextFloat() < 0.15 ? 0 : 1 + rng.int(30);
        const b = 1 + rng.int(30);
        if (a === b) continue;
        const pa = bodies[a].position;
        const pb = bodies[b].position;
        const anchor = { x: 0.5 * (pa.x + pb.x), y: 0.5 * (pa.y + pb.y) };
        world.createJoint({ type: 'revolute', bodyA: bodies[a], bodyB: bodies[b], anchor });
      }
      expect(runNetwork(world, dynamic).finite).toBe(true);
    }
  });

  it('a network of every joint type with limits and motors, locked against itself, stays finite and within the speed limits', () => {
    // 40 joints of random types (hinges with limits and motors, sliders, wheels, welds, rods,
    // springs) among 30 bodies, the ground and a turning kinematic bar: the limits are violated
    // by up to 3 rad at the start and the network cannot hold. Before the speed clamp at the
    // position update and the tree projection after each row weighed with the tree's mass, 18 of
    // these 20 seeds ended in NaN (a slider's limit, 60 m apart, weighed with a tree mass 1e5 times
    // its own, drove its bodies past 1e300 m/s within one pass).
    const maxTurnRate = (0.25 * Math.PI * 4) / DT; // the world's rotation limit per substep, 4 substeps
    for (let seed = 1; seed <= 20; seed++) {
      const rng = createRandom(seed);
      const { world, ground, bodies } = randomBodies(rng);
      const bar = world.createBody({ type: 'kinematic', position: { x: 0, y: 6 }, angularVelocity: 0.5 });
      bar.createShape(Shape.box(1, 0.1));
      for (let k = 0; k < 40; k++) {
        const a = rng.nextFloat() < 0.15 ? (rng.nextFloat() < 0.5 ? ground : bar) : bodies[rng.int(30)];
        const b = bodies[rng.int(30)];
        if (a === b) continue;
        const anchor = { x: 0.5 * (a.position.x + b.position.x), y: 0.5 * (a.position.y + b.position.y) };
        const motor = rng.nextFloat() < 0.3;
        const limit = rng.nextFloat() < 0.5;
        const axis = { x: 0, y: 1 };
        const centres = { bodyA: a, bodyB: b, localAnchorA: { x: 0, y: 0 }, localAnchorB: { x: 0, y: 0 } };
        switch (rng.int(7)) {
          case 0:
            world.createJoint({ type: 'revolute', bodyA: a, bodyB: b, anchor });
            break;
          case 1:
            world.createJoint({
              type: 'revolute',
              bodyA: a,
              bodyB: b,
              anchor,
              enableLimit: true,
              lowerAngle: -0.5,
              upperAngle: 0.5,
              enableMotor: motor,
              motorSpeed: 2,
              maxMotorTorque: 20,
            });
            break;
          case 2:
            world.createJoint({
              type: 'prismatic',
              bodyA: a,
              bodyB: b,
              anchor,
              axis,
              enableLimit: limit,
              lower: -0.5,
              upper: 0.5,
              enableMotor: motor,
              motorSpeed: 1,
              maxMotorForce: 100,
            });
            break;
          case 3:
            world.createJoint({
              type: 'wheel',
              bodyA: a,
              bodyB: b,
              anchor,
              axis,
              enableLimit: limit,
              lower: -0.5,
              upper: 0.5,
              enableMotor: motor,
              motorSpeed: 1,
              maxMotorTorque: 50,
            });
            break;
          case 4:
            world.createJoint({ type: 'weld', bodyA: a, bodyB: b, anchor });
            break;
          case 5:
            world.createJoint({ type: 'distance', ...centres });
            break;
          default:
            world.createJoint({
              type: 'distance',
              ...centres,
              enableSpring: true,
              hertz: 3,
              dampingRatio: 0.5,
            });
        }
      }
      const { finite, speed, turnRate } = runNetwork(world, bodies);
      expect(finite).toBe(true);
      expect(speed).toBeLessThanOrEqual(400 * (1 + 1e-12));
      expect(turnRate).toBeLessThanOrEqual(maxTurnRate * (1 + 1e-12));
    }
  });

  it('the cached tree choice gives the same bits as a fresh choice every step, through every change', () => {
    // Between changes the joint tree keeps its last choice of tree joints; this world is stepped once
    // as is and once with a fresh choice forced before every step, through joint setters, new and
    // destroyed joints and bodies, type, mass and fixed-rotation changes, sleep, store growth and a
    // change of time step; the hinges' reaction forces are compared too.
    const script = (world: World, fresh: boolean): number[] => {
      const step = (n: number, dt = DT) => {
        for (let i = 0; i < n; i++) {
          if (fresh) (world as unknown as { core: { jointEpoch: number } }).core.jointEpoch++;
          world.step(dt);
        }
      };
      const ground = world.createBody();
      ground.createShape(Shape.box(20, 0.5, { x: 0, y: -0.5 }));
      const links: Body[] = [];
      const hinges: RevoluteJoint[] = [];
      let prev = ground;
      for (let i = 0; i < 12; i++) {
        const link = world.createBody({ type: 'dynamic', position: { x: 0.5 + i, y: 8 } });
        link.createShape(Shape.box(0.5, 0.1));
        hinges.push(
          world.createJoint({ type: 'revolute', bodyA: prev, bodyB: link, anchor: { x: i, y: 8 } }),
        );
        links.push(link);
        prev = link;
      }
      const hinge = hinges[4];
      // and a 5 x 5 net of hinges (16 loops: solved by Gauss-Seidel, in the hinge batch)
      const net: Body[] = [];
      const netHinges: RevoluteJoint[] = [];
      for (let r = 0; r < 5; r++) {
        for (let c = 0; c < 5; c++) {
          const node = world.createBody({ type: 'dynamic', position: { x: -10 + c, y: 10 - r } });
          node.createShape(Shape.circle(0.2));
          net.push(node);
          const anchor = { x: -10 + c, y: 10 - r };
          if (c > 0)
            netHinges.push(
              world.createJoint({ type: 'revolute', bodyA: net[net.length - 2], bodyB: node, anchor }),
            );
          if (r > 0)
            netHinges.push(
              world.createJoint({ type: 'revolute', bodyA: net[net.length - 6], bodyB: node, anchor }),
            );
          if (r === 0 && (c === 0 || c === 4))
            world.createJoint({ type: 'revolute', bodyA: ground, bodyB: node, anchor });
        }
      }
      const hashes: number[] = [];
      const mark = () => {
        hashes.push(stateHash(world));
        for (const joint of [hinges[1], hinges[7], netHinges[3], netHinges[20]]) {
          hashes.push(joint.getReactionForce().y);
        }
      };
      step(30);
      mark();
      // the swinging chain bends this hinge well past 0.05 rad: the limit acts at once
      hinge.enableLimit(true);
      hinge.setLimits(-0.05, 0.05);
      step(20);
      mark();
      netHinges[5].setMaxMotorTorque(5);
      netHinges[5].enableMotor(true);
      netHinges[5].setMotorSpeed(2);
      step(20);
      netHinges[5].enableMotor(false);
      links[6].setType('static');
      step(20);
      links[6].setType('dynamic');
      step(20);
      mark();
      links[8].setFixedRotation(true);
      step(20);
      links[8].setFixedRotation(false);
      links[2].createShape(Shape.circle(0.3), { density: 20 });
      step(20);
      mark();
      const rope = world.createJoint({
        type: 'distance',
        bodyA: links[11],
        bodyB: ground,
        localAnchorA: { x: 0, y: 0 },
        localAnchorB: { x: 12, y: 0 },
      });
      step(20);
      world.destroyJoint(rope);
      world.destroyBody(links[10]);
      step(20);
      mark();
      for (let i = 0; i < 200; i++) {
        const b = world.createBody({
          type: 'dynamic',
          position: { x: -15 + (i % 20) * 0.6, y: 1 + Math.floor(i / 20) },
        });
        b.createShape(Shape.circle(0.25));
      }
      step(40);
      mark();
      world.enableSleep = true;
      step(300);
      mark();
      links[1].applyLinearImpulse({ x: 0, y: 5 }, links[1].worldCenter);
      step(30);
      mark();
      step(10, DT / 2);
      mark();
      return hashes;
    };
    const cached = script(new World({ enableSleep: false }), false);
    const fresh = script(new World({ enableSleep: false }), true);
    expect(cached).toEqual(fresh);
  });
});
