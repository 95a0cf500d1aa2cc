import { describe, expect, it } from 'vitest';
import { createRandom } from '../../scenes/random';
import { type Body, type Joint, Shape, World } from '../../src/index';
import { HingeField } from '../../src/solver/hinge-batch';
import { PathField } from '../../src/solver/hinge-paths';
import { momentum } from '../helpers/world';

// Chains and ropes of free hinges (no limit, motor or spring; each body on at most two) are solved
// along their paths (HingePaths); other trees by the body-and-joint tree. These tests build paths the
// way users do: joints made in any order and either sense, several paths in one world, ends on the
// ground, on a kinematic body or free.

const DT = 1 / 60;
const LINK = 0.5;

function separation(joint: Joint): number {
  const a = joint.anchorA;
  const b = joint.anchorB;
  return Math.hypot(b.x - a.x, b.y - a.y);
}

/**
 * A vertical chain of `count` links of 1 kg, 0.5 m pin to pin, hanging from `top` (its pin at `x`,
 * `y`). Its hinges are created in a shuffled order, each with a random sense (body A the upper or the
 * lower body); `hinges[i]` is the one above link i.
 */
function hangingChain(world: World, top: Body, x: number, y: number, count: number, seed: number) {
  const rng = createRandom(seed);
  const links: Body[] = [];
  for (let i = 0; i < count; i++) {
    const link = world.createBody({ type: 'dynamic', position: { x, y: y - LINK * (i + 0.5) } });
    link.createShape(Shape.box(0.05, LINK / 2), { density: 1 / (0.1 * LINK) });
    links.push(link);
  }
  const order = links.map((_, i) => i);
  for (let i = count - 1; i > 0; i--) {
    const j = rng.int(i + 1);
    [order[i], order[j]] = [order[j], order[i]];
  }
  const hinges: Joint[] = new Array(count);
  const upperIsA: boolean[] = new Array(count);
  for (const i of order) {
    const upper = i === 0 ? top : links[i - 1];
    upperIsA[i] = rng.nextFloat() < 0.5;
    hinges[i] = world.createJoint({
      type: 'revolute',
      bodyA: upperIsA[i] ? upper : links[i],
      bodyB: upperIsA[i] ? links[i] : upper,
      anchor: { x, y: y - LINK * i },
    });
  }
  return { links, hinges, upperIsA };
}

describe('paths of free hinges', () => {
  it("lays a path hinge's record out as the hinge batch's, then its own fields", () => {
    // HingePaths hands its records to writeStepData and turnStepData, which write H's fields
    expect(PathField.EX).toBe(HingeField.STRIDE);
  });

  it('chains hung in any order and sense: each hinge carries the weight below it, joints exact', () => {
    const world = new World({ enableSleep: false });
    const ceiling = world.createBody();
    const chains = [0, 1, 2].map((k) => hangingChain(world, ceiling, 2 * k, 0, 8 + 4 * k, 11 + k));
    for (let i = 0; i < 180; i++) world.step(DT);
    for (const { links, hinges, upperIsA } of chains) {
      for (let i = 0; i < links.length; i++) {
        // the force on the lower body is the weight of the links from i down: (count - i) 10 N up
        const weight = (links.length - i) * 10;
        const force = hinges[i].getReactionForce();
        expect(force.y).toBeCloseTo(upperIsA[i] ? weight : -weight, 6);
        expect(Math.abs(force.x)).toBeLessThan(1e-9);
        expect(separation(hinges[i])).toBeLessThan(1e-9);
      }
    }
  });

  it('a chain whose link is turned, moved, made heavier off-centre or stopped by a wall pulls its joints together', () => {
    // The paths carry each step's anchors and factorization over to the next step; a pose or a mass
    // set from outside (or by continuous collision) must drop them, else the joints stay apart.
    const maxSeparation = (hinges: Joint[]) => Math.max(...hinges.map(separation));
    const chain = () => {
      const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
      const ceiling = world.createBody();
      const { links, hinges } = hangingChain(world, ceiling, 0, 0, 8, 3);
      for (const link of links) {
        link.setLinearDamping(2);
        link.setAngularDamping(2);
      }
      for (let i = 0; i < 30; i++) world.step(DT);
      return { world, links, hinges };
    };
    const settle = (world: World, hinges: Joint[]) => {
      for (let i = 0; i < 120; i++) world.step(DT);
      return maxSeparation(hinges);
    };
    {
      // turned by 0.3 rad about its centre: its pins 0.25 m from it move 2 x 0.25 sin(0.15) apart
      const { world, links, hinges } = chain();
      expect(maxSeparation(hinges)).toBeLessThan(1e-9);
      links[4].setAngle(0.3);
      expect(maxSeparation(hinges)).toBeCloseTo(0.5 * Math.sin(0.15), 3);
      expect(settle(world, hinges)).toBeLessThan(1e-4);
    }
    {
      const { world, links, hinges } = chain();
      links[4].setPosition({ x: 0.2, y: links[4].position.y });
      expect(maxSeparation(hinges)).toBeGreaterThan(0.19);
      expect(settle(world, hinges)).toBeLessThan(1e-4);
    }
    {
      // a second box beside it: its centre of mass moves, the pins stay on the body; then spun
      const { world, links, hinges } = chain();
      links[4].createShape(Shape.box(0.05, LINK / 2, { x: 0.3, y: 0 }), { density: 1 / (0.1 * LINK) });
      links[4].setAngularVelocity(20);
      for (let i = 0; i < 180; i++) world.step(DT);
      expect(settle(world, hinges)).toBeLessThan(1e-4);
    }
    {
      // thrown sideways at 120 m/s against a wall: continuous collision moves links back in the step
      const { world, links, hinges } = chain();
      world.createBody({ position: { x: 4, y: 0 } }).createShape(Shape.box(0.1, 10));
      for (const link of links) link.setLinearVelocity({ x: 120, y: 0 });
      for (let i = 0; i < 120; i++) world.step(DT);
      expect(settle(world, hinges)).toBeLessThan(1e-4);
      for (const link of links) expect(link.position.x).toBeLessThan(4);
    }
  });

  it('a chain hung from a kinematic hook moving up at 2 m/s moves with it at once, as a rigid rope', () => {
    const world = new World({ enableSleep: false });
    const hook = world.createBody({ type: 'kinematic', linearVelocity: { x: 0, y: 2 } });
    const { links, hinges, upperIsA } = hangingChain(world, hook, 0, 0, 10, 5);
    world.step(DT);
    // an inextensible rope: after one step every link moves at the hook's speed
    for (const link of links) {
      expect(link.linearVelocity.y).toBeCloseTo(2, 9);
      expect(Math.abs(link.linearVelocity.x)).toBeLessThan(1e-12);
    }
    for (let i = 0; i < 59; i++) world.step(DT);
    // at constant speed the hinges carry the weight below them, as at rest; the hook has risen 2 m
    expect(hook.position.y).toBeCloseTo(2, 12);
    for (let i = 0; i < links.length; i++) {
      expect(links[i].linearVelocity.y).toBeCloseTo(2, 9);
      const weight = (links.length - i) * 10;
      expect(hinges[i].getReactionForce().y).toBeCloseTo(upperIsA[i] ? weight : -weight, 6);
      expect(separation(hinges[i])).toBeLessThan(1e-9);
    }
  });

  it('a free chain thrown spinning in zero gravity: as the body-and-joint tree solves it; momentum kept', () => {
    // a hinge with a limit goes to the body-and-joint tree (JointTree), which solves the same rows in
    // body space; a limit of ±50 rad never acts, so both worlds obey the same equations
    const build = (limited: boolean) => {
      const world = new World({ gravity: { x: 0, y: 0 }, enableSleep: false });
      const rng = createRandom(3);
      const links: Body[] = [];
      const hinges: Joint[] = [];
      for (let i = 0; i < 12; i++) {
        const link = world.createBody({
          type: 'dynamic',
          position: { x: LINK * (i + 0.5), y: 0 },
          linearVelocity: { x: rng.range(-1, 1), y: rng.range(-3, 3) },
          angularVelocity: rng.range(-2, 2),
        });
        // links of 1 to 10 kg
        link.createShape(Shape.box(LINK / 2, 0.05), { density: rng.range(1, 10) / (0.1 * LINK) });
        if (i > 0) {
          const forward = rng.nextFloat() < 0.5;
          hinges.push(
            world.createJoint({
              type: 'revolute',
              bodyA: forward ? links[i - 1] : link,
              bodyB: forward ? link : links[i - 1],
              anchor: { x: LINK * i, y: 0 },
              ...(limited ? { enableLimit: true, lowerAngle: -50, upperAngle: 50 } : {}),
            }),
          );
        }
        links.push(link);
      }
      return { world, links, hinges };
    };
    const paths = build(false);
    const tree = build(true);
    // the first step takes out the velocities that would pull the joints apart, by equal and
    // opposite impulses at each hinge
    const before = momentum(paths.links);
    paths.world.step(DT);
    tree.world.step(DT);
    const start = momentum(paths.links);
    let apart = 0;
    let worst = 0;
    for (let i = 0; i < 240; i++) {
      paths.world.step(DT);
      tree.world.step(DT);
      for (let k = 0; k < paths.links.length; k++) {
        const p = paths.links[k].position;
        const q = tree.links[k].position;
        apart = Math.max(apart, Math.hypot(p.x - q.x, p.y - q.y));
      }
      for (const h of paths.hinges) worst = Math.max(worst, separation(h));
    }
    const end = momentum(paths.links);
    // measured: 1e-13 m apart after 4 s of whipping (a different order of the same arithmetic)
    expect(apart).toBeLessThan(1e-9);
    expect(Math.abs(start.px - before.px)).toBeLessThan(1e-9);
    expect(Math.abs(start.py - before.py)).toBeLessThan(1e-9);
    expect(Math.abs(end.px - start.px)).toBeLessThan(1e-9);
    expect(Math.abs(end.py - start.py)).toBeLessThan(1e-9);
    // measured 0.24 mm at the whipping ends and 1 % of the angular momentum, the same in both solvers
    // (the ±P pairs of hinges act at anchors a fraction of a millimetre apart)
    expect(worst).toBeLessThan(1e-3);
    expect(Math.abs(end.l - start.l)).toBeLessThan(0.02 * Math.abs(start.l));
  });
});
