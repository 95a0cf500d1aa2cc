import { describe, expect, it } from 'vitest';
import { type Body, Shape, World } from '../../src/index';
import type { Transform, Vec2 } from '../../src/math/vec2';
import {
  type DebugDraw,
  type DebugDrawFlags,
  defaultDebugDrawFlags,
  drawWorld,
} from '../../src/render/debug-draw';
import type { AnyWorld, ShapeStyle } from '../../src/render/index';
import { Interpolator } from '../../src/render/interpolation';
import type { WorkerBody } from '../../src/worker/index';
import { workerWorlds } from '../helpers/worker-script';
import { runProgram } from './scene';

/*
 * fulcrum/render's drawing sources: a World and a WorkerWorld that took the same calls give the
 * debug drawing the same calls with the same bits (shapes in local coordinates, their transforms,
 * interpolated or not, joints' anchors, colours and the sleep tint), though the worker world's
 * source reads nothing of an engine on this thread.
 */

const { open } = workerWorlds();

const xfBits = (xf: Transform) => [xf.p.x, xf.p.y, xf.q.c, xf.q.s];
const styleBits = (s: ShapeStyle) => [s.fill ?? -1, s.fillAlpha, s.stroke];
const pointBits = (points: readonly Vec2[]) => points.flatMap((p) => [p.x, p.y]);

/** Every call the drawing makes, as its name and numbers (what it is handed is reused, so copied). */
class Recorder implements DebugDraw {
  readonly calls: (string | number)[][] = [];
  drawPolygon(xf: Transform, vertices: readonly Vec2[], radius: number, style: ShapeStyle): void {
    this.calls.push(['polygon', ...xfBits(xf), ...pointBits(vertices), radius, ...styleBits(style)]);
  }
  drawCircle(xf: Transform, center: Vec2, radius: number, style: ShapeStyle): void {
    this.calls.push(['circle', ...xfBits(xf), center.x, center.y, radius, ...styleBits(style)]);
  }
  drawCapsule(xf: Transform, p1: Vec2, p2: Vec2, radius: number, style: ShapeStyle): void {
    this.calls.push(['capsule', ...xfBits(xf), p1.x, p1.y, p2.x, p2.y, radius, ...styleBits(style)]);
  }
  drawLine(p1: Vec2, p2: Vec2, color: number): void {
    this.calls.push(['line', p1.x, p1.y, p2.x, p2.y, color]);
  }
  drawPoint(p: Vec2, size: number, color: number): void {
    this.calls.push(['point', p.x, p.y, size, color]);
  }
  drawAABB(minX: number, minY: number, maxX: number, maxY: number, color: number): void {
    this.calls.push(['aabb', minX, minY, maxX, maxY, color]);
  }
  drawTransform(xf: Transform): void {
    this.calls.push(['transform', ...xfBits(xf)]);
  }
}

const only = (flags: Partial<DebugDrawFlags>): DebugDrawFlags => ({
  ...defaultDebugDrawFlags,
  shapes: false,
  joints: false,
  sleeping: true,
  ...flags,
});

function record(world: AnyWorld, flags: DebugDrawFlags, interpolator?: Interpolator): Recorder {
  const recorder = new Recorder();
  drawWorld(world, recorder, flags, {
    transformOf: interpolator ? (body, out) => interpolator.transformOf(body, out) : undefined,
  });
  return recorder;
}

/** Whether two call lists hold the same bits (-0 and 0 told apart). */
function expectSameBits(a: (string | number)[][], b: (string | number)[][]): void {
  expect(a.length).toBe(b.length);
  for (let i = 0; i < a.length; i++) {
    const same = a[i].length === b[i].length && a[i].every((x, j) => Object.is(x, b[i][j]));
    if (!same) expect(b[i]).toEqual(a[i]);
  }
}

/** A World whose poses an Interpolator captures before each step, as the Runner does. */
function capturingWorld(interpolator: Interpolator): World {
  const world = new World();
  const step = world.step.bind(world);
  world.step = (dt: number) => {
    interpolator.capture(world);
    step(dt);
  };
  return world;
}

describe('drawing sources of a World and a WorkerWorld', () => {
  it('draw the same shapes, joints and colours with the same bits after the same calls, blended or not', async () => {
    const localBlend = new Interpolator();
    const local = capturingWorld(localBlend);
    await runProgram<Body>(local, 150);
    const remote = await open();
    await runProgram<WorkerBody>(remote, 150);

    const flags = only({ shapes: true, joints: true });
    const now = record(local, flags).calls;
    // 60-odd bodies and 6 joints (three links, a weld, a slider, the hook): a drawing worth comparing
    expect(now.filter((c) => c[0] === 'polygon').length).toBeGreaterThan(50);
    expect(now.filter((c) => c[0] === 'point').length).toBe(12);
    expectSameBits(record(remote, flags).calls, now);

    const remoteBlend = new Interpolator();
    for (const alpha of [0, 0.35, 1]) {
      localBlend.alpha = alpha;
      remoteBlend.alpha = alpha;
      const blended = record(local, flags, localBlend).calls;
      expectSameBits(record(remote, flags, remoteBlend).calls, blended);
    }
    // the blend is drawn: at 0 the bodies are where the last step began, which is not where it ended
    localBlend.alpha = 0;
    expect(record(local, flags, localBlend).calls).not.toEqual(now);
  });

  it('draw sensors, chains, concave pieces, rounded polygons and a mouse joint alike, and the joint only once the worker has made it', async () => {
    const local = new World();
    const remote = await open();
    const build = <B extends { createShape: (...a: never[]) => unknown }>(world: {
      createBody(def: object): B;
      createJoint(def: object): unknown;
    }) => {
      const ground = world.createBody({});
      const shape = ground.createShape as (g: unknown, d?: object) => unknown;
      shape.call(
        ground,
        Shape.chain([
          { x: -10, y: 0 },
          { x: -3, y: -1 },
          { x: 3, y: -1 },
          { x: 10, y: 0 },
        ]),
      );
      shape.call(ground, Shape.box(1, 1, { x: 0, y: 3 }), { isSensor: true });
      const bent = world.createBody({ type: 'dynamic', position: { x: -4, y: 4 }, angle: 0.4 });
      (bent.createShape as (g: unknown) => unknown).call(
        bent,
        Shape.concave([
          { x: 0, y: 0 },
          { x: 2, y: 0 },
          { x: 2, y: 2 },
          { x: 1, y: 0.7 },
          { x: 0, y: 2 },
        ]),
      );
      const round = world.createBody({ type: 'dynamic', position: { x: 4, y: 4 }, bullet: true });
      (round.createShape as (g: unknown) => unknown).call(
        round,
        Shape.polygon(Shape.box(0.5, 0.3).vertices, 0.1),
      );
      const dragged = world.createJoint({ type: 'mouse', body: round, target: { x: 5, y: 6 } });
      return { round, dragged };
    };
    const a = build(local as never) as { dragged: { setTarget(t: Vec2): void } };
    const b = build(remote as never) as { dragged: { setTarget(t: Vec2): void } };
    const flags = only({ shapes: true, joints: true });
    // the worker has not made the mouse joint yet: no anchor to draw it from
    expect(record(remote, flags).calls.filter((c) => c[0] !== 'polygon' && c[0] !== 'line').length).toBe(0);
    for (let i = 0; i < 30; i++) {
      if (i === 10) {
        a.dragged.setTarget({ x: 6, y: 8 });
        b.dragged.setTarget({ x: 6, y: 8 });
      }
      local.step(1 / 60);
      await remote.step(1 / 60);
    }
    const drawn = record(local, flags).calls;
    // a sensor's translucent fill, the chain's 3 segments with their front ticks, the mouse joint's line and two dots
    expect(drawn.some((c) => c[0] === 'polygon' && c[c.length - 2] === 0.18)).toBe(true);
    expect(drawn.filter((c) => c[0] === 'line').length).toBe(7);
    expect(drawn.filter((c) => c[0] === 'point').length).toBe(2);
    expectSameBits(record(remote, flags).calls, drawn);
  });

  it('draw velocities where the bodies go, and centres of mass to rounding (the worker publishes world centres)', async () => {
    const local = new World();
    await runProgram<Body>(local, 60);
    const remote = await open();
    await runProgram<WorkerBody>(remote, 60);
    const flags = only({ velocities: true, centersOfMass: true });
    const drawn = record(local, flags).calls;
    const remoteDrawn = record(remote, flags).calls;
    expect(drawn.length).toBeGreaterThan(100);
    expect(remoteDrawn.length).toBe(drawn.length);
    for (let i = 0; i < drawn.length; i++) {
      expect(remoteDrawn[i][0]).toBe(drawn[i][0]);
      for (let j = 1; j < drawn[i].length; j++) {
        // the centre in the body's frame is worked back from the world centre: a few ulps of metres
        expect(Math.abs((remoteDrawn[i][j] as number) - (drawn[i][j] as number))).toBeLessThan(1e-12);
      }
    }
  });

  it('reads a WorkerBody through an Interpolator as the worker published it', async () => {
    const remote = await open();
    const body = remote.createBody({ type: 'dynamic', position: { x: 0, y: 10 } });
    body.createShape(Shape.circle(0.5));
    await remote.step(1 / 60);
    await remote.step(1 / 60);
    const blend = new Interpolator();
    const out: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
    blend.alpha = 0.5;
    expect(blend.transformOf(body, out)).toEqual(body.getInterpolatedTransform(0.5));
    blend.alpha = 1;
    expect(blend.transformOf(body, out).p).toEqual(body.position);
    // falling: the pose half-way through the step is above the pose at its end
    expect(body.getInterpolatedTransform(0.5).p.y).toBeGreaterThan(body.position.y);
  });
});
