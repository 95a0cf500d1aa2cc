import { describe, expect, it } from 'vitest';
import { type Body, FulcrumError, Shape, type ShapeHandle, stateHash, World } from '../../src/index';
import { type WorkerBody, type WorkerShape, WorkerWorld } from '../../src/worker/index';
import { fulcrumErrorMessage } from '../helpers/rejects';
import { workerScript, workerWorlds } from '../helpers/worker-script';
import { type BodyLike, runProgram } from './scene';

/*
 * fulcrum/worker against World: the same calls give the same bits, events, query answers and
 * errors. The worker runs a bundle of the same source (test/helpers/worker-script.ts).
 */

const { open, keep } = workerWorlds();

/** Every number a body reads, exactly. */
function reads(body: BodyLike): number[] {
  const p = body.position;
  const q = body.rotation;
  const v = body.linearVelocity;
  const c = body.worldCenter;
  return [p.x, p.y, q.c, q.s, body.angle, v.x, v.y, body.angularVelocity, c.x, c.y, body.isAwake ? 1 : 0];
}

/** Whether two lists hold the same bits (-0 and 0 told apart). */
function sameBits(a: number[][], b: number[][]): boolean {
  return (
    a.length === b.length &&
    a.every((row, i) => row.length === b[i].length && row.every((x, j) => Object.is(x, b[i][j])))
  );
}

describe('WorkerWorld and World', () => {
  it('give the same state hash and the same bits for the same calls (pyramid, joints, forces, bodies made and destroyed)', async () => {
    const local = new World();
    const localHashes: number[] = [];
    const localBodies = await runProgram<Body>(local, 240, (step) => {
      if (step % 60 === 0) localHashes.push(stateHash(local));
    });

    const remote = await open();
    expect(remote.bufferMode).toBe('shared');
    const remoteHashes: number[] = [];
    const remoteBodies = await runProgram<WorkerBody>(remote, 240, async (step) => {
      if (step % 60 === 0) remoteHashes.push(await remote.stateHash());
    });

    expect(remoteHashes).toEqual(localHashes);
    // the world moved: a hash of a world at rest would prove little
    expect(new Set(localHashes).size).toBe(4);
    expect(remoteBodies.length).toBe(localBodies.length);
    expect(remote.bodyCount).toBe(local.bodyCount);
    expect(sameBits(remoteBodies.map(reads), localBodies.map(reads))).toBe(true);
  });

  it('read the same after each step in transfer mode as in shared mode', async () => {
    const shared = await open();
    const moved = await open({ worker: { buffers: 'transfer' } });
    expect(moved.bufferMode).toBe('transfer');
    const sharedReads: number[][][] = [];
    const sharedBodies = await runProgram<WorkerBody>(shared, 150, (step) => {
      if (step % 25 === 0) sharedReads.push([...shared.bodies].map(reads));
    });
    const movedReads: number[][][] = [];
    const movedBodies = await runProgram<WorkerBody>(moved, 150, (step) => {
      if (step % 25 === 0) movedReads.push([...moved.bodies].map(reads));
    });
    expect(movedReads.length).toBe(6);
    for (let i = 0; i < movedReads.length; i++) expect(sameBits(movedReads[i], sharedReads[i])).toBe(true);
    expect(sameBits(movedBodies.map(reads), sharedBodies.map(reads))).toBe(true);
    expect(await moved.stateHash()).toBe(await shared.stateHash());
  });

  it('blend the last two poses: alpha 0 is where the step began, 1 where it ended', async () => {
    const world = await open();
    world.createBody().createShape(Shape.box(10, 0.5));
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 5 }, angularVelocity: 2 });
    box.createShape(Shape.box(0.5, 0.5));
    // before the first step: the pose it was made with
    expect(box.position).toEqual({ x: 0, y: 5 });
    expect(box.getInterpolatedTransform(0.5)).toEqual({ p: { x: 0, y: 5 }, q: { c: 1, s: 0 } });
    await world.step(1 / 60);
    const before = box.position;
    const turn = box.rotation;
    await world.step(1 / 60);
    const after = box.position;
    const start = box.getInterpolatedTransform(0);
    const end = box.getInterpolatedTransform(1);
    expect([start.p.x, start.p.y, start.q.c, start.q.s]).toEqual([before.x, before.y, turn.c, turn.s]);
    expect(end.p).toEqual(after);
    const mid = box.getInterpolatedTransform(0.5);
    expect(mid.p.y).toBe(before.y + (after.y - before.y) * 0.5);
    expect(Math.hypot(mid.q.c, mid.q.s)).toBeCloseTo(1, 12);
    // teleported: the blend starts from where the body was put, not where it was
    box.setPosition({ x: 3, y: 5 });
    await world.step(1 / 60);
    expect(box.getInterpolatedTransform(0).p).toEqual({ x: 3, y: 5 });
  });
});

describe('WorkerWorld events', () => {
  /** A ball dropped on a ground, through a sensor; everything it reports, in order, handles named. */
  async function drop<W extends World | WorkerWorld>(world: W, steps: number, log: string[]): Promise<void> {
    const named = (x: { userData: unknown }) => String(x.userData);
    const w = world as World;
    w.on('contactBegin', (e) => {
      log.push(
        `begin ${named(e.shapeA)} ${named(e.shapeB)} ${named(e.bodyA)} ${e.normal.x} ${e.normal.y} ${e.points.map((p) => `${p.x},${p.y}`).join(' ')}`,
      );
    });
    w.on('contactEnd', (e) => log.push(`end ${named(e.shapeA)} ${named(e.shapeB)}`));
    w.on('contactHit', (e) =>
      log.push(`hit ${named(e.shapeA)} ${named(e.shapeB)} ${e.approachSpeed} ${e.point.x} ${e.point.y}`),
    );
    w.on('sensorBegin', (e) => log.push(`sensorBegin ${named(e.sensorShape)} ${named(e.visitorShape)}`));
    w.on('sensorEnd', (e) => log.push(`sensorEnd ${named(e.sensorShape)} ${named(e.visitorShape)}`));
    w.on('sleep', (e) => log.push(`sleep ${named(e.body)}`));
    w.on('wake', (e) => log.push(`wake ${named(e.body)}`));
    const ground = w.createBody({ userData: 'ground' });
    ground.createShape(Shape.box(10, 0.5), { userData: 'groundBox', enableHitEvents: true });
    ground.createShape(Shape.box(1, 1, { x: 0, y: 4 }), { isSensor: true, userData: 'sensor' });
    const ball = w.createBody({ type: 'dynamic', position: { x: 0.2, y: 8 }, userData: 'ball' });
    ball.createShape(Shape.circle(0.5), {
      userData: 'ballShape',
      restitution: 0.6,
      enableHitEvents: true,
      enableSensorEvents: true,
    });
    for (let i = 1; i <= steps; i++) {
      log.push(`step ${i}`);
      await world.step(1 / 60);
    }
  }

  it('arrive batched per step, before its promise resolves, with the worker handles, as World delivers them', async () => {
    const localLog: string[] = [];
    await drop(new World(), 400, localLog);
    const worker = await open();
    const remoteLog: string[] = [];
    await drop(worker, 400, remoteLog);
    for (const kind of ['begin', 'end', 'hit', 'sensorBegin', 'sensorEnd', 'sleep']) {
      expect(localLog.some((line) => line.startsWith(`${kind} `))).toBe(true);
    }
    expect(remoteLog).toEqual(localLog);
  });

  it('name the handles the calls gave, and run before the step resolves', async () => {
    const world = await open();
    const ground = world.createBody();
    const groundShape = ground.createShape(Shape.box(10, 0.5));
    const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 1.2 } });
    const ballShape = ball.createShape(Shape.circle(0.5));
    const seen: unknown[][] = [];
    let resolved = false;
    world.on('contactBegin', (e) => seen.push([e.shapeA, e.shapeB, e.bodyA, e.bodyB, resolved]));
    let step = 0;
    while (seen.length === 0 && step++ < 120)
      await world
        .step(1 / 60)
        .then(() => (resolved = true))
        .then(() => (resolved = false));
    expect(seen.length).toBe(1);
    const [a, b, bodyA, bodyB, afterResolve] = seen[0];
    expect(new Set([a, b])).toEqual(new Set([groundShape, ballShape]));
    expect(bodyA).toBe(a === groundShape ? ground : ball);
    expect(bodyB).toBe(b === groundShape ? ground : ball);
    expect(afterResolve).toBe(false);
  });
});

describe('WorkerWorld queries', () => {
  it('see the commands queued before them, and answer with worker handles as World does', async () => {
    const world = await open();
    const local = new World();
    const build = (w: World | WorkerWorld): unknown[] => {
      const made = [];
      for (let i = 0; i < 5; i++) {
        const body = (w as World).createBody({ position: { x: i * 2, y: 0 } });
        made.push(body.createShape(Shape.box(0.5, 0.5)));
      }
      return made;
    };
    const remoteShapes = build(world) as WorkerShape[];
    const localShapes = build(local) as ShapeHandle[];
    // no step yet: the query goes after the bodies are made
    const point = await world.queryPoint({ x: 4.2, y: 0.1 });
    expect(point).toEqual([remoteShapes[2]]);
    expect(local.queryPoint({ x: 4.2, y: 0.1 })).toEqual([localShapes[2]]);
    const hits = await world.castRayAll({ x: -5, y: 0.25 }, { x: 20, y: 0 });
    const localHits = local.castRayAll({ x: -5, y: 0.25 }, { x: 20, y: 0 });
    expect(hits.map((h) => remoteShapes.indexOf(h.shape))).toEqual([0, 1, 2, 3, 4]);
    expect(hits.map((h) => [h.point, h.normal, h.fraction])).toEqual(
      localHits.map((h) => [h.point, h.normal, h.fraction]),
    );
    expect(hits[0].body).toBe(remoteShapes[0].body);
    // a body moved and one destroyed since: the next queries see both, as World's do
    for (const [w, shapes] of [
      [world, remoteShapes],
      [local, localShapes],
    ] as const) {
      shapes[0].body.setPosition({ x: 20, y: 0 });
      (w as World).destroyBody(shapes[1].body as Body);
    }
    const index = (list: readonly unknown[], shape: unknown) => list.indexOf(shape);
    const first = await world.castRay({ x: -5, y: 0.25 }, { x: 30, y: 0 });
    expect(index(remoteShapes, first?.shape)).toBe(2);
    expect(index(localShapes, local.castRay({ x: -5, y: 0.25 }, { x: 30, y: 0 })?.shape)).toBe(2);
    const aabb = { lowerBound: { x: 19, y: -1 }, upperBound: { x: 21, y: 1 } };
    expect((await world.queryAABB(aabb)).map((s) => index(remoteShapes, s))).toEqual([0]);
    expect(local.queryAABB(aabb).map((s) => index(localShapes, s))).toEqual([0]);
    const swept = await world.castShape(Shape.circle(0.25), { position: { x: 6.2, y: 3 } }, { x: 0, y: -6 });
    const localSwept = local.castShape(Shape.circle(0.25), { position: { x: 6.2, y: 3 } }, { x: 0, y: -6 });
    expect(index(remoteShapes, swept?.shape)).toBe(3);
    expect(index(localShapes, localSwept?.shape)).toBe(3);
    expect([swept?.point, swept?.normal, swept?.fraction]).toEqual([
      localSwept?.point,
      localSwept?.normal,
      localSwept?.fraction,
    ]);
    const overlap = await world.overlapShape(Shape.box(3, 1), { position: { x: 5, y: 0 } });
    const localOverlap = local.overlapShape(Shape.box(3, 1), { position: { x: 5, y: 0 } });
    expect(overlap.map((s) => index(remoteShapes, s))).toEqual([2, 3, 4]);
    expect(localOverlap.map((s) => index(localShapes, s))).toEqual([2, 3, 4]);
  });
});

describe('WorkerWorld snapshots', () => {
  it('move to a second WorkerWorld, which steps on bit-identically (and as World.restore does)', async () => {
    const first = await open();
    const bodies = await runProgram<WorkerBody>(first, 100);
    const bytes = await first.snapshot();
    const second = await WorkerWorld.restore(bytes, { url: workerScript(), buffers: 'transfer' });
    keep(second);
    const local = World.restore(bytes);
    expect(second.bodyCount).toBe(first.bodyCount);
    expect(second.joints.length).toBe(first.joints.length);
    expect([...second.bodies].map((b) => b.shapes.map((s) => s.type))).toEqual(
      [...first.bodies].map((b) => b.shapes.map((s) => s.type)),
    );
    expect(sameBits([...second.bodies].map(reads), [...first.bodies].map(reads))).toBe(true);
    // the restored handles take commands: the same push on each world
    const push = (
      list: Iterable<{ applyLinearImpulse(i: { x: number; y: number }): void; type: string }>,
    ) => {
      for (const body of list) if (body.type === 'dynamic') body.applyLinearImpulse({ x: 0.5, y: 1 });
    };
    push(first.bodies);
    push(second.bodies);
    push(local.bodies);
    for (let i = 0; i < 120; i++) {
      await Promise.all([first.step(1 / 60), second.step(1 / 60)]);
      local.step(1 / 60);
    }
    const hash = await first.stateHash();
    expect(await second.stateHash()).toBe(hash);
    expect(stateHash(local)).toBe(hash);
    expect(sameBits([...second.bodies].map(reads), [...first.bodies].map(reads))).toBe(true);
    expect(bodies.length).toBeGreaterThan(60);
  });
});

describe('WorkerWorld bad input', () => {
  it('throws World’s FulcrumError at the call and queues nothing', async () => {
    const local = new World();
    const world = await open();
    const make = (w: World | WorkerWorld) => {
      const ground = (w as World).createBody();
      ground.createShape(Shape.segment({ x: -5, y: 0 }, { x: 5, y: 0 }));
      const a = (w as World).createBody({ type: 'dynamic', position: { x: 0, y: 2 } });
      a.createShape(Shape.box(0.5, 0.5));
      const b = (w as World).createBody({ type: 'dynamic', position: { x: 2, y: 2 } });
      b.createShape(Shape.circle(0.5));
      const gone = (w as World).createBody({ type: 'dynamic' });
      (w as World).destroyBody(gone);
      return { ground, a, b, gone };
    };
    const L = make(local);
    const R = make(world) as unknown as typeof L;
    const calls: ((w: World, x: typeof L) => unknown)[] = [
      (w) => w.createBody({ type: 'wobbly' as never }),
      (w) => w.createBody({ position: { x: Number.NaN, y: 0 } }),
      (w) => w.createBody({ speed: 1 } as never),
      (w) => w.createBody(null as never),
      (_, x) => x.a.createShape({ type: 'circle', radius: 1 } as never),
      (_, x) => x.a.createShape(Shape.segment({ x: 0, y: 0 }, { x: 1, y: 0 })),
      (_, x) =>
        x.a.createShape(
          Shape.chain(
            [
              { x: 0, y: 0 },
              { x: 1, y: 0 },
            ],
            { loop: false },
          ),
        ),
      (_, x) => x.a.createShape(Shape.box(1, 1), { density: -1 }),
      (_, x) => x.a.createShape(Shape.box(1, 1), { filter: { groupIndex: 0.5 } }),
      (_, x) => x.a.setPosition({ x: Number.POSITIVE_INFINITY, y: 0 }),
      (_, x) => x.a.setAngle(Number.NaN),
      (_, x) => x.a.setTransform({ x: 0, y: 0 }, Number.NaN),
      (_, x) => x.a.setLinearVelocity(null as never),
      (_, x) => x.a.setAngularVelocity(Number.NaN),
      (_, x) => x.a.setType('floating' as never),
      (_, x) => x.ground.setType('dynamic'),
      (_, x) => x.a.setAwake('yes' as never),
      (_, x) => x.a.applyForce({ x: 1e300, y: 0 }),
      (_, x) => x.a.applyForce({ x: 1, y: 0 }, { x: Number.NaN, y: 0 }),
      (_, x) => x.a.applyTorque(Number.NaN),
      (_, x) => x.a.applyLinearImpulse({ x: 0, y: Number.NaN }),
      (_, x) => x.a.applyAngularImpulse(Number.POSITIVE_INFINITY),
      (_, x) => x.gone.setPosition({ x: 0, y: 0 }),
      (_, x) => x.gone.createShape(Shape.circle(1)),
      (w, x) => w.destroyBody(x.gone),
      (w) => w.destroyBody({} as never),
      (w, x) => w.createJoint({ type: 'revolute', bodyA: x.a, bodyB: x.a }),
      (w, x) => w.createJoint({ type: 'hinge', bodyA: x.a, bodyB: x.b } as never),
      (w, x) => w.createJoint({ type: 'distance', bodyA: x.a, bodyB: x.b, minLength: 2, maxLength: 1 }),
      (w, x) =>
        w.createJoint({
          type: 'revolute',
          bodyA: x.a,
          bodyB: x.b,
          anchor: { x: 0, y: 0 },
          localAnchorA: { x: 0, y: 0 },
        }),
      (w, x) => w.createJoint({ type: 'weld', bodyA: x.a, bodyB: x.gone }),
      (w, x) => w.createJoint({ type: 'mouse', body: x.a, target: { x: Number.NaN, y: 0 } }),
      (w, x) => w.createJoint({ type: 'revolute', bodyA: x.a, bodyB: {} as never }),
      (w) => w.destroyJoint({} as never),
      (w) => {
        w.gravity = { x: Number.NaN, y: 0 };
      },
      (w) => w.on('collide' as never, () => {}),
      (w) => w.on('contactBegin', 'handler' as never),
      (w) => w.step(-1),
      (w) => w.step(Number.NaN),
      (w) => w.castRay({ x: Number.NaN, y: 0 }, { x: 1, y: 0 }),
      (w) => w.castRayAll({ x: 0, y: 0 }, { x: 1, y: 0 }, { maskBits: -1 }),
      (w) => w.queryAABB({ lowerBound: { x: 0, y: 0 } } as never),
      (w) => w.queryPoint({ x: 0, y: 0 }, { extra: true } as never),
      (w) => w.castShape({} as never, { position: { x: 0, y: 0 } }, { x: 1, y: 0 }),
      (w) => w.overlapShape(Shape.circle(1), { position: { x: 0, y: 0 }, angle: Number.NaN }),
    ];
    for (const call of calls) {
      const expected = fulcrumErrorMessage(() => call(local, L));
      expect(() => call(world as unknown as World, R)).toThrow(expected);
      try {
        call(world as unknown as World, R);
      } catch (e) {
        expect(e).toBeInstanceOf(FulcrumError);
      }
    }
    // nothing was queued: the worker's world is the one World was left with
    await world.step(1 / 60);
    local.step(1 / 60);
    expect(await world.stateHash()).toBe(stateHash(local));
    expect(world.bodyCount).toBe(local.bodyCount);
  });

  it('throws World’s FulcrumError for a bad world definition, and rejects bytes that are no snapshot with World.restore’s', async () => {
    const bad = [
      { subSteps: 0 },
      { gravity: { x: 0, y: Number.NaN } },
      { frictionMixing: 'max' },
      { units: 2 },
    ];
    for (const def of bad) {
      const expected = fulcrumErrorMessage(() => new World(def as never));
      expect(() => WorkerWorld.create({ ...(def as object), worker: { url: workerScript() } })).toThrow(
        expected,
      );
    }
    expect(() => WorkerWorld.create({ worker: { buffers: 'mirrored' as never } })).toThrow(FulcrumError);
    expect(() => WorkerWorld.restore([1, 2] as never)).toThrow(
      fulcrumErrorMessage(() => World.restore([1, 2] as never)),
    );
    const garbage = new Uint8Array([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]);
    const expected = fulcrumErrorMessage(() => World.restore(garbage));
    const restoring = WorkerWorld.restore(garbage, { url: workerScript() });
    await expect(restoring).rejects.toThrow(expected);
    await expect(restoring).rejects.toBeInstanceOf(FulcrumError);
  });
});

describe('a WorkerWorld whose worker fails', () => {
  const crashing = () => workerScript('test/worker/fixtures/failing-source-entry.mjs');

  it('rejects every waiting promise when the worker throws, and refuses what comes after', async () => {
    const world = await open({ worker: { url: crashing() } });
    const ball = world.createBody({ type: 'dynamic' });
    ball.createShape(Shape.circle(1));
    await world.step(1 / 60);
    // the fixture throws on a step of 1/8 s
    const step = world.step(1 / 8);
    const query = world.queryPoint({ x: 0, y: 0 });
    const hash = world.stateHash();
    for (const waiting of [step, query, hash]) {
      await expect(waiting).rejects.toBeInstanceOf(FulcrumError);
      await expect(waiting).rejects.toThrow(/worker failed: .*thrown in the worker/);
    }
    expect(() => world.createBody()).toThrow(/worker failed/);
    await expect(world.step(1 / 60)).rejects.toThrow(/worker failed/);
  });

  it('rejects every waiting promise when the worker exits', async () => {
    const world = await open({ worker: { url: crashing() } });
    await world.step(1 / 60);
    // the fixture exits with code 7 on a step of 1/4 s
    const step = world.step(1 / 4);
    const snapshot = world.snapshot();
    await expect(step).rejects.toThrow(/exited with code 7/);
    await expect(snapshot).rejects.toThrow(/exited with code 7/);
  });

  it('fails when the worker leaves a request unanswered for requestTimeoutMs, as when it crashes', async () => {
    const world = await open({ worker: { url: crashing(), requestTimeoutMs: Number.POSITIVE_INFINITY } });
    const ball = world.createBody({ type: 'dynamic' });
    ball.createShape(Shape.circle(1));
    await world.step(1 / 60);
    expect(world.failure).toBe(null);
    // the fixture never answers a step of 1/5 s, nor anything after it
    const step = world.step(1 / 5);
    const query = world.queryPoint({ x: 0, y: 0 });
    // counted from here, for what waits
    world.requestTimeoutMs = 100;
    const message = /worker: the world's worker did not answer within 100 ms \(requestTimeoutMs\)/;
    for (const waiting of [step, query]) {
      await expect(waiting).rejects.toBeInstanceOf(FulcrumError);
      await expect(waiting).rejects.toThrow(message);
    }
    expect(world.failure).toBeInstanceOf(FulcrumError);
    expect(world.failure?.message).toMatch(message);
    expect(() => ball.setLinearDamping(1)).toThrow(message);
    await expect(world.step(1 / 60)).rejects.toThrow(message);
    // the reads keep the last state the worker gave
    expect(ball.position.y).toBeLessThan(0);
  });

  it('fails when the worker spins on a request, and ends that worker', async () => {
    const world = await open({ worker: { url: crashing() } });
    expect(world.requestTimeoutMs).toBe(10_000);
    await world.step(1 / 60);
    // the fixture loops for ever on a step of 1/3 s; terminate stops it (else the test run would not end)
    const step = world.step(1 / 3);
    const hash = world.stateHash();
    world.requestTimeoutMs = 100;
    await expect(step).rejects.toThrow(/did not answer within 100 ms/);
    await expect(hash).rejects.toThrow(/did not answer within 100 ms/);
  });

  it('refuses a request timeout that is not a positive number of milliseconds', async () => {
    for (const bad of [0, -1, Number.NaN, '10', null]) {
      expect(() =>
        WorkerWorld.create({ worker: { url: workerScript(), requestTimeoutMs: bad as never } }),
      ).toThrow(`worker.requestTimeoutMs must be a positive number of milliseconds, or Infinity, got`);
    }
    const world = await open({ worker: { requestTimeoutMs: 2 ** 40 } });
    expect(world.requestTimeoutMs).toBe(2 ** 40);
    // longer than a timer can wait: never (a timer of that length would fire at once)
    for (let i = 0; i < 3; i++) await world.step(1 / 60);
    expect(world.failure).toBe(null);
    world.requestTimeoutMs = Number.POSITIVE_INFINITY;
    expect(() => {
      world.requestTimeoutMs = -5;
    }).toThrow('requestTimeoutMs must be a positive number of milliseconds, or Infinity, got -5');
    expect(world.requestTimeoutMs).toBe(Number.POSITIVE_INFINITY);
    await world.step(1 / 60);
    expect(world.failure).toBe(null);
  });

  it('rejects what waits when terminated, and says so', async () => {
    const world = await open();
    const step = world.step(1 / 60);
    world.terminate();
    await expect(step).rejects.toThrow('worker: the world has been terminated');
    expect(() => world.createBody()).toThrow('worker: the world has been terminated');
    expect(world.failure?.message).toBe('worker: the world has been terminated');
  });
});
