// fulcrum/render in Node (no document, Path2D or requestAnimationFrame): what needs a browser says so
// with a FulcrumError; what does not (camera, runner stepping by hand) still works.
import { describe, expect, it } from 'vitest';
import { FulcrumError, Shape, World } from '../../src/index';
import { Camera, CanvasDebugDraw, Render, Runner } from '../../src/render/index';

function thrown(f: () => unknown): unknown {
  try {
    f();
  } catch (e) {
    return e;
  }
  return undefined;
}

describe('fulcrum/render without a browser', () => {
  it('has no DOM here (the premise of these tests)', () => {
    expect(typeof (globalThis as Record<string, unknown>).document).toBe('undefined');
    expect(typeof (globalThis as Record<string, unknown>).Path2D).toBe('undefined');
    expect(typeof (globalThis as Record<string, unknown>).requestAnimationFrame).toBe('undefined');
  });

  it('new Render() throws a FulcrumError that says it needs a browser', () => {
    for (const make of [
      () => new Render(),
      () => new Render({ world: new World() }),
      () => new Render({ canvas: {} as HTMLCanvasElement }),
    ]) {
      const e = thrown(make);
      expect(e).toBeInstanceOf(FulcrumError);
      expect((e as Error).message).toMatch(/^new Render\(\) needs a browser: Path2D is not defined here/);
    }
  });

  it('new CanvasDebugDraw() throws a FulcrumError that says it needs a browser', () => {
    const e = thrown(() => new CanvasDebugDraw({} as CanvasRenderingContext2D));
    expect(e).toBeInstanceOf(FulcrumError);
    expect((e as Error).message).toMatch(/^new CanvasDebugDraw\(\) needs a browser/);
  });

  it('Runner.start() throws a FulcrumError; stepping by hand works and matches the world stepped alone', () => {
    const make = () => {
      const world = new World();
      world.createBody({ type: 'dynamic', position: { x: 0, y: 10 } }).createShape(Shape.circle(0.5));
      return world;
    };
    const world = make();
    const runner = new Runner({ world, dt: 1 / 60 });
    const e = thrown(() => runner.start());
    expect(e).toBeInstanceOf(FulcrumError);
    expect((e as Error).message).toMatch(/^Runner\.start\(\) needs a browser: requestAnimationFrame/);
    expect(runner.running).toBe(false);

    const alone = make();
    for (let i = 0; i < 30; i++) {
      runner.step();
      alone.step(1 / 60);
    }
    expect(runner.stepCount).toBe(30);
    const [a] = world.bodies;
    const [b] = alone.bodies;
    expect(a.position).toEqual(b.position);
    // half a second of free fall from 10 m: 1.25 m (semi-implicit Euler at 1/240 s lags by g t h / 2)
    expect(a.position.y).toBeCloseTo(10 - 0.5 * 10 * 0.5 * 0.5, 1);
  });

  it('Camera needs no DOM', () => {
    const camera = new Camera({ center: { x: 0, y: 0 }, halfHeight: 5 });
    camera.setViewport(200, 100);
    // 100 CSS pixels span 10 m: 10 px a metre; world y up is screen y down
    expect(camera.worldToScreen({ x: 1, y: 1 })).toEqual({ x: 110, y: 40 });
  });
});
