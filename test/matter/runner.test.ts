import { describe, expect, it } from 'vitest';
import FulcrumMatter from '../../src/matter/index';
import { type M, RealMatter } from '../helpers/matter-both';

/**
 * Updates per tick when frames come every `frame` ms for `seconds`, by `Runner.tick` driven by hand.
 * The updates take no time by the clock both runners read (Common.now): a runner stops a tick's
 * updates once they have taken its frame's time, and how long they take depends on the machine.
 */
function updatesPerTick(Matter: M, frame: number, seconds: number, options = {}): number[] {
  const now = Matter.Common.now;
  Matter.Common.now = () => 0;
  try {
    return ticks(Matter, frame, seconds, options);
  } finally {
    Matter.Common.now = now;
  }
}

function ticks(Matter: M, frame: number, seconds: number, options: object): number[] {
  const engine = Matter.Engine.create();
  Matter.Composite.add(engine.world, Matter.Bodies.rectangle(0, 0, 10, 10));
  const runner = Matter.Runner.create(options);
  const counts: number[] = [];
  let count = 0;
  Matter.Events.on(runner, 'beforeUpdate', () => count++);
  for (let time = frame; time <= seconds * 1000; time += frame) {
    count = 0;
    Matter.Runner.tick(runner, engine, time);
    counts.push(count);
  }
  return counts;
}

describe('fulcrum/matter Runner steps as matter.js 0.20 steps', () => {
  it('steady frames at 60, 30, 144 and 50 Hz: the same updates on every tick as matter.js', () => {
    for (const frame of [1000 / 60, 1000 / 30, 1000 / 144, 1000 / 50]) {
      const ours = updatesPerTick(FulcrumMatter, frame, 3);
      const theirs = updatesPerTick(RealMatter as M, frame, 3);
      expect(ours).toEqual(theirs);
      // and the simulation keeps time: 60 updates a second of frames, less the first frames' warm-up
      // (the smoothing starts from 1000/60 ms: up to 5 updates at 30 Hz, in matter.js too)
      const total = ours.reduce((a, b) => a + b, 0);
      const expected = (ours.length * frame) / (1000 / 60);
      expect(total).toBeGreaterThanOrEqual(expected - 6);
      expect(total).toBeLessThanOrEqual(expected + 2);
    }
  });

  it('a pause (a hidden tab) is not simulated: the next frame counts as one frame', () => {
    const engine = FulcrumMatter.Engine.create();
    const runner = FulcrumMatter.Runner.create();
    for (let t = 1; t <= 60; t++) FulcrumMatter.Runner.tick(runner, engine, (t * 1000) / 60);
    const before = engine.timing.timestamp;
    FulcrumMatter.Runner.tick(runner, engine, 1000 + 5000);
    expect(engine.timing.timestamp - before).toBeLessThanOrEqual((2 * 1000) / 60 + 1e-9);
  });
});
