/**
 * Child-process probe for garbage.test.ts: builds one scene, warms it up, and prints the bytes the
 * step allocates, per step, as JSON. A fresh process, because in a test worker that has run other
 * files the engine's code carries their type feedback and can be deoptimised mid-measurement (the
 * interpreter boxes every double), which made the figure swing from 1 KB to 76 KB a step.
 */
import { Session } from 'node:inspector';
import { type Body, Shape, World } from '../../src/index';
import { groundWorld, pyramid } from '../helpers/world';

/**
 * Bytes allocated by `run`, from V8's sampling heap profiler counting the objects the garbage
 * collector has already taken too (it samples about one allocation per `interval` bytes).
 */
async function allocatedBytes(run: () => void, interval = 256): Promise<number> {
  const session = new Session();
  session.connect();
  const post = (method: string, params?: object) =>
    new Promise<unknown>((resolve, reject) =>
      session.post(method, params, (error, result) => (error ? reject(error) : resolve(result))),
    );
  await post('HeapProfiler.enable');
  await post('HeapProfiler.startSampling', {
    samplingInterval: interval,
    includeObjectsCollectedByMinorGC: true,
    includeObjectsCollectedByMajorGC: true,
  });
  run();
  const { profile } = (await post('HeapProfiler.stopSampling')) as {
    profile: { head: { selfSize: number; callFrame: { url: string }; children: unknown[] } };
  };
  session.disconnect();
  // the inspector's own messages (about 88 KB a session, the profile's hand-over) are not the step's
  let total = 0;
  const walk = (node: { selfSize: number; callFrame: { url: string }; children: unknown[] }) => {
    if (node.callFrame.url === 'node:inspector') return;
    total += node.selfSize;
    for (const child of node.children) walk(child as typeof node);
  };
  walk(profile.head);
  return total;
}

function hingeNetWorld(size: number): World {
  const world = new World({ enableSleep: false });
  const anchor = world.createBody();
  const nodes: Body[] = [];
  for (let row = 0; row < size; row++) {
    for (let column = 0; column < size; column++) {
      const position = { x: column, y: size - row };
      const node = world.createBody({ type: 'dynamic', position });
      node.createShape(Shape.circle(0.4));
      nodes.push(node);
      if (row === 0) world.createJoint({ type: 'revolute', bodyA: anchor, bodyB: node, anchor: position });
      if (column > 0) {
        const at = { x: column - 0.5, y: size - row };
        world.createJoint({ type: 'revolute', bodyA: nodes[nodes.length - 2], bodyB: node, anchor: at });
      }
      if (row > 0) {
        const at = { x: column, y: size - row + 0.5 };
        world.createJoint({
          type: 'revolute',
          bodyA: nodes[nodes.length - 1 - size],
          bodyB: node,
          anchor: at,
        });
      }
    }
  }
  return world;
}

const scenes: Record<string, () => World> = {
  pyramid: () => {
    const { world } = groundWorld({ enableSleep: false });
    pyramid(world, 20);
    return world;
  },
  'hinge net': () => hingeNetWorld(20),
  // the heavy-load passes: stiffened contacts, supports, an island stepped with finer substeps
  'loaded pyramid': () => {
    const { world } = groundWorld({ enableSleep: false });
    pyramid(world, 10);
    const load = world.createBody({ type: 'dynamic', position: { x: 0, y: 10.5 } });
    load.createShape(Shape.box(0.5, 0.5), { density: 1000 });
    return world;
  },
};

const name = process.argv[2] ?? 'pyramid';
const world = scenes[name]();
// optimised code first: the interpreter and the compiler allocate while warming up
for (let i = 0; i < 300; i++) world.step(1 / 60);
// The least of a few windows: now and then V8 has not yet installed a hot function's optimised code
// after the warm-up (it enters only the compiled loop from baseline code, and a few hundred steps on
// it is done: 4.5 KB, then 37 KB, then 0.3 KB a step in one run of the hinge net). That is the JIT
// warming up, not the step's steady state, which is what this measures.
const steps = 60;
let least = Number.POSITIVE_INFINITY;
for (let window = 0; window < 6; window++) {
  const bytes = await allocatedBytes(() => {
    for (let i = 0; i < steps; i++) world.step(1 / 60);
  });
  least = Math.min(least, bytes / steps);
}
process.stdout.write(JSON.stringify({ name, perStep: least }));
