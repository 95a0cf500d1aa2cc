import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, World } from '../../src/index';
import { Runner } from '../../src/render/runner';
import type { WorkerWorld } from '../../src/worker/index';
import { workerWorlds } from '../helpers/worker-script';

/*
 * fulcrum/render's Runner with a WorkerWorld, driven by tick(now) as the tests of the browser loop
 * are: a frame sends the steps its time asks for and returns without waiting; the steps finish in the
 * worker; the blend factor puts the frame's time past the last finished step.
 */

const DT = 1 / 60;
const FRAME = 1000 * DT;
const { open } = workerWorlds();

/** A ball 10 m up, in a World or a WorkerWorld. */
function drop<W extends World | WorkerWorld>(world: W) {
  const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 10 } });
  ball.createShape(Shape.circle(0.5));
  return ball;
}

/** Resolves once the worker has answered everything sent before (replies come in order). */
const settled = (world: WorkerWorld) => world.stateHash();

describe('Runner with a WorkerWorld', () => {
  it('sends the steps a frame asks for without waiting, and counts them as the worker finishes them', async () => {
    const world = await open();
    const ball = drop(world);
    const runner = new Runner({ world });
    const sent: number[] = [];
    const finished: number[] = [];
    runner.on('beforeStep', () => sent.push(runner.stepCount));
    runner.on('afterStep', () => finished.push(runner.stepCount));
    runner.tick(0);
    runner.tick(1.5 * FRAME);
    // one step sent, none finished: the frame did not wait, and draws the last finished state
    expect(sent).toEqual([0]);
    expect(runner.stepsInFlight).toBe(1);
    expect(runner.stepCount).toBe(0);
    expect(runner.alpha).toBe(1);
    expect(ball.position.y).toBe(10);
    await settled(world);
    expect(runner.stepsInFlight).toBe(0);
    expect(runner.stepCount).toBe(1);
    expect(finished).toEqual([1]);
    expect(world.stepCount).toBe(1);
    expect(runner.stepMs).toBe(world.lastStepMs);
    expect(ball.position.y).toBeLessThan(10);
    // caught up: half a step of time left over, a quarter more: blended 3/4 of the way through the step
    runner.tick(1.75 * FRAME);
    expect(runner.stepsInFlight).toBe(0);
    expect(runner.alpha).toBeCloseTo(0.75, 12);
  });

  it('keeps at most maxStepsInFlight out, and drops the time beyond as a slow frame does', async () => {
    const world = await open();
    drop(world);
    const runner = new Runner({ world, maxStepsPerFrame: 10 });
    runner.tick(0);
    // a quarter of a second: 15 steps due, 2 sent
    runner.tick(250);
    expect(runner.stepsInFlight).toBe(2);
    runner.tick(250 + FRAME);
    expect(runner.stepsInFlight).toBe(2);
    await settled(world);
    expect(runner.stepCount).toBe(2);
    expect(world.stepCount).toBe(2);
  });

  it('moves the ball as the same steps move it in a World here, bit for bit', async () => {
    const world = await open();
    const ball = drop(world);
    const local = new World();
    const twin = drop(local);
    const runner = new Runner({ world });
    let now = 0;
    runner.tick(now);
    while (runner.stepCount < 30) {
      now += FRAME;
      runner.tick(now);
      await settled(world);
    }
    for (let i = 0; i < runner.stepCount; i++) local.step(DT);
    expect(ball.position).toEqual(twin.position);
    expect(ball.linearVelocity).toEqual(twin.linearVelocity);
  });

  it('stops stepping a world whose worker has ended, and keeps the reason; a swapped-out world is forgotten', async () => {
    const world = await open();
    drop(world);
    const runner = new Runner({ world });
    runner.tick(0);
    runner.tick(1.5 * FRAME);
    expect(runner.stepsInFlight).toBe(1);
    world.terminate();
    await Promise.resolve();
    await Promise.resolve();
    expect(runner.failure).toBeInstanceOf(FulcrumError);
    expect(runner.stepsInFlight).toBe(0);
    runner.tick(3 * FRAME);
    expect(runner.stepsInFlight).toBe(0);

    // a new world: the failure was the old world's, and steps of a world swapped out do not count
    const next = await open();
    drop(next);
    const other = await open();
    runner.setWorld(next);
    expect(runner.failure).toBe(null);
    runner.tick(4.5 * FRAME);
    expect(runner.stepsInFlight).toBe(1);
    runner.setWorld(other);
    await settled(next);
    expect(runner.stepCount).toBe(0);
    expect(runner.stepsInFlight).toBe(0);
  });
});
