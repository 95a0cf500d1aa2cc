import { afterEach, describe, expect, it } from 'vitest';
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { benchmarkScenes, sceneBuilders } from '../../scenes/index';
import { type ContactHitEvent, Shape, stateHash, World, type WorldDef } from '../../src/index';
import type { SolverTeam } from '../../src/parallel/team';
import { workerScript } from '../helpers/worker-script';

/*
 * `new World({ workers })` with a step split by island: each thread solves the islands given to it
 * (bodies joined by contacts), their constraints in the colouring's order, with no barrier between
 * colours. Every body's constraints are on its own thread in the same order as on one thread, so the
 * bits must be one thread's; the events too, in the same order. The team's thresholds are lowered so
 * that the small scenes here are split (with the defaults steps under 500 contacts stay on one
 * thread).
 */

const workerUrl = workerScript('test/worker/fixtures/solver-source-entry.mjs');
const opened: World[] = [];

afterEach(() => {
  for (const world of opened.splice(0)) world.dispose();
});

function teamOf(world: World): SolverTeam {
  return world.core.team as SolverTeam;
}

/** A plain World (`workers` 1) or a team of `workers` threads that splits every step it can by island. */
async function world(workers: number, def: WorldDef = {}): Promise<World> {
  const w = new World(workers > 1 ? { workerUrl, workers, ...def } : def);
  opened.push(w);
  if (workers > 1) {
    expect(await w.workersReady).toBe(workers);
    teamOf(w).minIslands = 1;
    teamOf(w).minConstraints = 1;
    teamOf(w).minPerThread = 1;
  }
  return w;
}

/** `columns` stacks of `height` boxes, each on a static block of its own, spaced apart (no contact between stacks). */
function stacks(
  w: World,
  columns: number,
  height: number,
  options: { heavyTop?: boolean; hits?: boolean } = {},
): void {
  for (let c = 0; c < columns; c++) {
    const x = c * 3;
    w.createBody({ type: 'static', position: { x, y: 0 } }).createShape(Shape.box(1, 0.25));
    for (let k = 0; k < height; k++) {
      const body = w.createBody({
        type: 'dynamic',
        position: { x: x + 0.02 * k, y: 0.75 + k * 1.1 + (c % 3) * 0.4 },
      });
      const heavy = options.heavyTop === true && k === height - 1;
      body.createShape(Shape.box(0.5, 0.5), {
        density: heavy ? 20 : 1,
        restitution: 0.2,
        enableHitEvents: options.hits === true,
      });
    }
  }
}

function hitsOf(w: World): string[] {
  const out: string[] = [];
  w.on('contactHit', (e: ContactHitEvent) => {
    out.push(`${e.bodyA.position.x} ${e.bodyB.position.x} ${e.approachSpeed} ${e.point.x} ${e.point.y}`);
  });
  return out;
}

describe('a step split by island over the threads', () => {
  it.each(benchmarkScenes)(
    "%s (quick size), split wherever the islands allow: one thread's bits",
    async (name) => {
      const one = buildFulcrumWorld(sceneBuilders[name](true), { enableSleep: false }).world;
      opened.push(one);
      const two = buildFulcrumWorld(sceneBuilders[name](true), {
        enableSleep: false,
        workers: 2,
        workerUrl,
      }).world;
      opened.push(two);
      expect(await two.workersReady).toBe(2);
      teamOf(two).minIslands = 1;
      teamOf(two).minConstraints = 1;
      teamOf(two).minPerThread = 1;
      for (let i = 0; i < 300; i++) {
        one.step(1 / 60);
        two.step(1 / 60);
      }
      expect(stateHash(two)).toBe(stateHash(one));
      if (name === 'many-pyramids') expect(teamOf(two).islandSteps).toBe(300);
    },
  );

  it('separate stacks dropped with hit events: the same bits and the same hits in the same order, every step', async () => {
    const one = await world(1);
    const two = await world(2);
    stacks(one, 12, 4, { hits: true });
    stacks(two, 12, 4, { hits: true });
    const hitsOne = hitsOf(one);
    const hitsTwo = hitsOf(two);
    for (let i = 0; i < 180; i++) {
      one.step(1 / 60);
      two.step(1 / 60);
      expect(hitsTwo).toEqual(hitsOne);
    }
    // the drops hit, every stack more than once: the comparison above compared something
    expect(hitsOne.length).toBeGreaterThan(12 * 2);
    expect(stateHash(two)).toBe(stateHash(one));
    // split by island once the stacks landed (before, some had no contact and the rest split unevenly)
    expect(teamOf(two).islandSteps).toBeGreaterThan(60);
  });

  it("three threads, sleep on: one thread's bits while islands fall asleep", async () => {
    const one = await world(1, { enableSleep: true });
    const three = await world(3, { enableSleep: true });
    stacks(one, 10, 3);
    stacks(three, 10, 3);
    for (let i = 0; i < 400; i++) {
      one.step(1 / 60);
      three.step(1 / 60);
    }
    expect(stateHash(three)).toBe(stateHash(one));
    expect(teamOf(three).islandSteps).toBeGreaterThan(30);
    // the stacks slept: their steps stopped going to the team
    expect(one.core.awakeCount).toBe(0);
  });

  it("a heavy box on each stack (the heavy loads' passes): one thread's bits", async () => {
    const one = await world(1);
    const two = await world(2);
    stacks(one, 8, 3, { heavyTop: true });
    stacks(two, 8, 3, { heavyTop: true });
    let heavySteps = 0;
    for (let i = 0; i < 240; i++) {
      one.step(1 / 60);
      two.step(1 / 60);
      if (one.core.constraints.heavyPair) heavySteps++;
    }
    expect(heavySteps).toBeGreaterThan(100);
    expect(stateHash(two)).toBe(stateHash(one));
  });

  it("joints between the contact passes, and a kinematic paddle that every thread's islands touch: one thread's bits", async () => {
    const build = (w: World) => {
      stacks(w, 8, 2);
      // a pendulum over each stack: a joint acts between the contact passes
      for (let c = 0; c < 8; c += 2) {
        const anchor = w.createBody({ type: 'static', position: { x: c * 3 - 1.5, y: 6 } });
        const bob = w.createBody({ type: 'dynamic', position: { x: c * 3 - 3.5, y: 6 } });
        bob.createShape(Shape.circle(0.3), { density: 3 });
        w.createJoint({ type: 'revolute', bodyA: anchor, bodyB: bob, anchor: { x: c * 3 - 1.5, y: 6 } });
      }
      // a kinematic bar sweeping through every stack's top box
      const paddle = w.createBody({
        type: 'kinematic',
        position: { x: -4, y: 2.3 },
        linearVelocity: { x: 3, y: 0 },
      });
      paddle.createShape(Shape.box(0.2, 0.2));
    };
    const one = await world(1);
    const two = await world(2);
    build(one);
    build(two);
    for (let i = 0; i < 300; i++) {
      one.step(1 / 60);
      two.step(1 / 60);
    }
    expect(stateHash(two)).toBe(stateHash(one));
    // (steps whose islands could not be shared evenly, as the paddle topples the stacks, stay on one thread)
    expect(teamOf(two).islandSteps).toBeGreaterThan(60);
  });

  it('the order grown in a step the team did not take reaches the workers before the next it takes', async () => {
    // a review found it: the split's order array grew in a step whose islands could not be shared,
    // and a later split, with no other column grown, had the workers read the old, shorter one (NaN)
    const one = await world(1, { enableSleep: false });
    const two = await world(2, { enableSleep: false });
    const team = teamOf(two);
    const pile = (w: World, n: number) => {
      const boxes = [];
      for (let k = 0; k < n; k++) {
        const b = w.createBody({ type: 'dynamic', position: { x: 30, y: 0.75 + k } });
        b.createShape(Shape.box(0.5, 0.5));
        boxes.push(b);
      }
      return boxes;
    };
    const both = [one, two];
    const steps = (n: number) => {
      for (let i = 0; i < n; i++) for (const w of both) w.step(1 / 60);
    };
    // every store grown to its largest while the team stays idle
    team.minIslands = 1e9;
    team.minConstraints = 1e9;
    for (const w of both) {
      // four stacks of three boxes resting on their blocks (no fall: every step can be split)
      for (let c = 0; c < 4; c++) {
        w.createBody({ type: 'static', position: { x: c * 3, y: 0 } }).createShape(Shape.box(1, 0.25));
        for (let k = 0; k < 3; k++) {
          w.createBody({ type: 'dynamic', position: { x: c * 3, y: 0.75 + k } }).createShape(
            Shape.box(0.5, 0.5),
          );
        }
      }
      w.createBody({ type: 'static', position: { x: 30, y: 0 } }).createShape(Shape.box(3, 0.25));
    }
    let piles = both.map((w) => pile(w, 40));
    steps(30);
    both.forEach((w, i) => {
      for (const b of piles[i]) w.destroyBody(b);
    });
    steps(30);
    // the stacks alone: split by island, the order posted at its first length
    team.minIslands = 1;
    steps(30);
    const split = team.islandSteps;
    expect(split).toBe(30);
    // a tall pile: not split evenly, the order grows
    piles = both.map((w) => pile(w, 40));
    steps(5);
    // most of it gone: split again, on the grown order
    both.forEach((w, i) => {
      for (const b of piles[i].slice(8)) w.destroyBody(b);
    });
    steps(40);
    expect(team.islandSteps).toBeGreaterThan(split);
    expect(two.core.bodies.state.every((v) => !Number.isNaN(v))).toBe(true);
    expect(stateHash(two)).toBe(stateHash(one));
  });
});
