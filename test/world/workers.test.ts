import { afterEach, describe, expect, it } from 'vitest';
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { benchmarkScenes, sceneBuilders } from '../../scenes/index';
import { FulcrumError, Shape, stateHash, World, type WorldDef } from '../../src/index';
import type { SolverTeam } from '../../src/parallel/team';
import { WorkerWorld } from '../../src/worker/index';
import { workerScript } from '../helpers/worker-script';

/*
 * `new World({ workers })`: the contact passes of a step split over threads by graph colour must give
 * the same bits as one thread, whatever the split. The team's thresholds are lowered to 1 here, so
 * that every colour of these small scenes is split and every step goes through the workers (with the
 * defaults they would leave small steps and colours to the calling thread, which proves nothing).
 */

const workerUrl = workerScript('test/worker/fixtures/solver-source-entry.mjs');
const opened: World[] = [];

afterEach(() => {
  for (const world of opened.splice(0)) world.dispose();
});

function teamOf(world: World): SolverTeam {
  return world.core.team as SolverTeam;
}

async function teamWorld(def: WorldDef): Promise<World> {
  const world = new World({ workerUrl, ...def });
  opened.push(world);
  expect(await world.workersReady).toBe(def.workers);
  expect(world.workers).toBe(def.workers);
  teamOf(world).minConstraints = 1;
  teamOf(world).minPerThread = 1;
  return world;
}

/** A bench scene built in a world of `workers` threads (`workers` 1: a plain World). */
async function sceneWorld(name: string, workers: number, enableSleep = false): Promise<World> {
  const { world } = buildFulcrumWorld(sceneBuilders[name](true), { enableSleep, workers, workerUrl });
  opened.push(world);
  if (workers > 1) {
    expect(await world.workersReady).toBe(workers);
    teamOf(world).minConstraints = 1;
    teamOf(world).minPerThread = 1;
  }
  return world;
}

describe('a world whose contacts several threads solve', () => {
  it.each(benchmarkScenes)('%s (quick size): the same bits as one thread after 300 steps', async (name) => {
    const one = await sceneWorld(name, 1);
    const two = await sceneWorld(name, 2);
    let contactSteps = 0;
    for (let i = 0; i < 300; i++) {
      one.step(1 / 60);
      two.step(1 / 60);
      if (one.core.constraints.count > 0) contactSteps++;
    }
    expect(stateHash(two)).toBe(stateHash(one));
    // every step with a contact went through the workers (the joint grid and the chain have none)
    expect(teamOf(two).parallelSteps).toBe(contactSteps);
    if (name !== 'joint-grid' && name !== 'chain') expect(contactSteps).toBeGreaterThan(200);
  });

  it('bouncing balls, sleep on, three threads: the same bits as one thread', async () => {
    const one = await sceneWorld('mixed-stack', 1, true);
    const three = await sceneWorld('mixed-stack', 3, true);
    for (let i = 0; i < 240; i++) {
      one.step(1 / 60);
      three.step(1 / 60);
    }
    expect(stateHash(three)).toBe(stateHash(one));
    expect(teamOf(three).parallelSteps).toBeGreaterThan(0);
  });

  it('bodies added while it runs (the columns grow and move): the same bits as one thread', async () => {
    const one = new World();
    const two = await teamWorld({ workers: 2 });
    for (const world of [one, two]) {
      world.createBody({ type: 'static' }).createShape(Shape.box(20, 0.5));
    }
    for (let round = 0; round < 6; round++) {
      for (const world of [one, two]) {
        for (let k = 0; k < 40; k++) {
          const body = world.createBody({
            type: 'dynamic',
            position: { x: -10 + (k % 20), y: 2 + round * 3 + Math.floor(k / 20) * 1.2 },
          });
          body.createShape(k % 3 === 0 ? Shape.circle(0.45) : Shape.box(0.45, 0.45), { restitution: 0.3 });
        }
        for (let i = 0; i < 40; i++) world.step(1 / 60);
      }
    }
    expect(two.bodyCount).toBe(241);
    expect(stateHash(two)).toBe(stateHash(one));
    // the snapshot holds the world's state alone: the team is no part of it
    expect(two.snapshot()).toEqual(one.snapshot());
  });

  it('dispose ends the workers; the world goes on, on one thread, with the same bits', async () => {
    const one = await sceneWorld('pyramid', 1);
    const two = await sceneWorld('pyramid', 2);
    for (let i = 0; i < 60; i++) {
      one.step(1 / 60);
      two.step(1 / 60);
    }
    const team = teamOf(two);
    two.dispose();
    expect(two.workers).toBe(1);
    expect(two.core.team).toBe(null);
    for (let i = 0; i < 60; i++) {
      one.step(1 / 60);
      two.step(1 / 60);
    }
    expect(team.parallelSteps).toBe(60);
    expect(stateHash(two)).toBe(stateHash(one));
  });

  it('workers that cannot start: workersReady rejects, the world steps on one thread', async () => {
    const world = new World({
      workers: 2,
      workerUrl: workerScript('test/worker/fixtures/no-such-script.mjs'),
    });
    opened.push(world);
    await expect(world.workersReady).rejects.toThrow(FulcrumError);
    await expect(world.workersReady).rejects.toThrow(/solver workers could not start/);
    expect(world.workers).toBe(1);
    world.createBody({ type: 'dynamic' }).createShape(Shape.circle(0.5));
    world.step(1 / 60);
    expect(world.bodyCount).toBe(1);
  });

  it('a WorkerWorld takes workers for its world: same bits as a World; bad values thrown at the call', async () => {
    const remote = await WorkerWorld.create({ workers: 2, workerUrl, worker: { url: workerScript() } });
    const local = new World();
    // the world in the worker starts its own worker while it steps: empty steps until a step says it ran
    // on two threads (the count of these steps varies; both worlds take the same ones)
    for (let i = 0; i < 100_000 && remote.workers === 1; i++) {
      await remote.step(1 / 60);
      local.step(1 / 60);
    }
    expect(remote.workers).toBe(2);
    for (const world of [remote, local]) {
      world.createBody().createShape(Shape.box(20, 0.5));
      for (let k = 0; k < 600; k++) {
        const body = world.createBody({
          type: 'dynamic',
          position: { x: -12 + (k % 25), y: 1 + Math.floor(k / 25) },
        });
        body.createShape(Shape.box(0.45, 0.45));
      }
    }
    for (let i = 0; i < 90; i++) {
      await remote.step(1 / 60);
      local.step(1 / 60);
    }
    expect(await remote.stateHash()).toBe(stateHash(local));
    remote.terminate();
    // checked at the call, as WorkerWorld.create checks the rest of the definition
    expect(() => WorkerWorld.create({ workers: 0 })).toThrow(FulcrumError);
    expect(() => WorkerWorld.create({ workers: 2, workerUrl: 7 as unknown as string })).toThrow(/workerUrl/);
  });

  it('workers 1 starts none', async () => {
    const world = new World({ workers: 1 });
    expect(await world.workersReady).toBe(1);
    expect(world.core.team).toBe(null);
  });

  it.each([0, 1.5, -2, 65, Number.NaN, '2', null])('workers %s: a FulcrumError naming it', (value) => {
    expect(() => new World({ workers: value as number })).toThrow(FulcrumError);
    expect(() => new World({ workers: value as number })).toThrow(/workers/);
  });

  it('a workerUrl that is neither a URL nor a string: a FulcrumError naming it', () => {
    expect(() => new World({ workers: 2, workerUrl: 42 as unknown as string })).toThrow(/workerUrl/);
  });
});
