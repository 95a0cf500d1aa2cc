import { describe, expect, it } from 'vitest';
import { Shape, stateHash, World } from '../../src/index';
import { Pointer } from '../../src/render/pointer';
import type { WorkerWorld } from '../../src/worker/index';
import { workerScript, workerWorlds } from '../helpers/worker-script';

/*
 * fulcrum/render's Pointer dragging in a WorkerWorld whose worker fails mid-drag: its DOM handlers
 * end the drag quietly rather than throw the world's failure. Node has no DOM: the canvas is a stand-in
 * that records the listeners, and the camera maps canvas pixels to metres one to one.
 */

const { open } = workerWorlds();

/** A canvas and camera enough for Pointer, and a way to send it pointer events. */
function fakeRender(world: WorkerWorld | World) {
  const listeners = new Map<string, (e: unknown) => void>();
  const canvas = {
    style: {} as Record<string, string>,
    offsetWidth: 100,
    offsetHeight: 100,
    clientLeft: 0,
    clientTop: 0,
    addEventListener: (type: string, fn: (e: unknown) => void) => listeners.set(type, fn),
    removeEventListener: (type: string) => listeners.delete(type),
    getBoundingClientRect: () => ({ left: 0, top: 0, width: 100, height: 100 }),
    setPointerCapture: () => {},
  };
  const render = { canvas, camera: { screenToWorld: (x: number, y: number) => ({ x, y }) }, world };
  const send = (type: string, x: number, y: number) =>
    listeners.get(type)!({
      type,
      pointerId: 1,
      pointerType: 'mouse',
      button: 0,
      clientX: x,
      clientY: y,
      defaultPrevented: false,
      preventDefault() {},
    });
  return { render, send };
}

describe('Pointer with a WorkerWorld whose worker fails', () => {
  it('ends the drag quietly at the next pointer event, and starts none after', async () => {
    const world = await open({
      gravity: { x: 0, y: 0 },
      worker: { url: workerScript('test/worker/fixtures/failing-source-entry.mjs') },
    });
    const box = world.createBody({ type: 'dynamic', position: { x: 10, y: 10 } });
    box.createShape(Shape.box(1, 1));
    await world.step(1 / 60);
    const { render, send } = fakeRender(world);
    const pointer = new Pointer<WorkerWorld>({ render: render as never });
    const ended: unknown[] = [];
    pointer.on('dragEnd', (e) => ended.push(e.body));

    send('pointerdown', 10.5, 10.2);
    expect(pointer.body).toBe(box);
    expect(world.joints.map((j) => j.type)).toEqual(['mouse']);
    send('pointermove', 12, 10);
    await world.step(1 / 60);
    expect(world.joints[0].target).toEqual({ x: 12, y: 10 });

    // the fixture's worker throws on a step of 1/8 s
    await expect(world.step(1 / 8)).rejects.toThrow(/worker failed/);
    expect(world.failure).not.toBe(null);
    expect(() => send('pointermove', 13, 10)).not.toThrow();
    expect(pointer.body).toBe(null);
    expect(ended).toEqual([box]);
    expect(() => send('pointerup', 13, 10)).not.toThrow();
    // a press on the body now starts no drag (it pans), and throws nothing
    expect(() => send('pointerdown', 10.5, 10.2)).not.toThrow();
    expect(pointer.body).toBe(null);
    expect(pointer.startDrag(box, { x: 10, y: 10 })).toBe(false);
    expect(() => pointer.destroy()).not.toThrow();
    expect(ended).toEqual([box]);
  });
});

describe('Pointer with a WorkerWorld', () => {
  it('drags with the force limit a World gets (forcePerMass x the mass read from the worker): the same bits', async () => {
    const remote = await open({ gravity: { x: 0, y: -2 } });
    const local = new World({ gravity: { x: 0, y: -2 } });
    for (const world of [remote, local]) {
      world.createBody().createShape(Shape.box(30, 0.5));
      const box = world.createBody({ type: 'dynamic', position: { x: 10, y: 2 } });
      box.createShape(Shape.box(1, 1), { density: 3 });
    }
    await remote.step(1 / 60);
    local.step(1 / 60);
    const drags = [remote, local].map((world) => {
      const { render, send } = fakeRender(world);
      const pointer = new Pointer<WorkerWorld | World>({ render: render as never, forcePerMass: 40 });
      send('pointerdown', 10.5, 2.2);
      return { pointer, send };
    });
    // 12 kg under 2 m/s^2, limited to 40 N/kg x 12 kg x 0.2: the pull to 8 m up is capped
    expect([...remote.bodies][1].mass).toBe(12);
    for (let i = 0; i < 40; i++) {
      for (const drag of drags) drag.send('pointermove', 10.5 + i * 0.05, 2.2 + i * 0.2);
      await remote.step(1 / 60);
      local.step(1 / 60);
    }
    expect(await remote.stateHash()).toBe(stateHash(local));
    for (const drag of drags) drag.pointer.destroy();
  });
});
