import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { both, type M } from '../helpers/matter-both';

/** A stand-in for a canvas of 800 by 600 at the page's origin: it keeps the listeners it is given. */
function fakeCanvas() {
  const listeners = new Map<string, ((event: unknown) => void)[]>();
  return {
    width: 800,
    height: 600,
    clientWidth: 800,
    clientHeight: 600,
    getBoundingClientRect: () => ({ left: 0, top: 0 }),
    getAttribute: () => null,
    addEventListener(type: string, listener: (event: unknown) => void) {
      listeners.set(type, [...(listeners.get(type) ?? []), listener]);
    },
    removeEventListener() {},
    fire(type: string, x: number, y: number) {
      for (const listener of listeners.get(type) ?? [])
        listener({ pageX: x, pageY: y, button: 0, preventDefault() {} });
    },
    /** a touch event: the point in changedTouches, as a browser gives it */
    touch(type: string, x: number, y: number) {
      for (const listener of listeners.get(type) ?? [])
        listener({ changedTouches: [{ pageX: x, pageY: y }], cancelable: true, preventDefault() {} });
    },
  };
}

// matter.js reads the page's scroll from window and document: a page that has not scrolled, for
// these tests only (other test files in the same worker rely on Node having no DOM)
const page = globalThis as unknown as Record<string, unknown>;
beforeAll(() => {
  page.window = { pageXOffset: 0, pageYOffset: 0 };
  page.document = { documentElement: { scrollLeft: 0, scrollTop: 0 }, body: { scrollLeft: 0, scrollTop: 0 } };
});
afterAll(() => {
  delete page.window;
  delete page.document;
});

/** A `width` by `height` box resting on the ground (top at y = 580, centred on x = 400), a mouse constraint on a canvas. */
function boxOnTheGround(Matter: M, width: number, height: number) {
  const engine = Matter.Engine.create();
  const ground = Matter.Bodies.rectangle(400, 590, 800, 20, { isStatic: true });
  const box = Matter.Bodies.rectangle(400, 580 - height / 2, width, height);
  const canvas = fakeCanvas();
  const drag = Matter.MouseConstraint.create(engine, { mouse: Matter.Mouse.create(canvas as never) });
  Matter.Composite.add(engine.world, [ground, box, drag as never]);
  for (let i = 0; i < 30; i++) Matter.Engine.update(engine);
  return { engine, box, canvas, drag };
}

describe('fulcrum/matter Mouse and MouseConstraint', () => {
  it('a drag lifts the box under the mouse toward the pointer, as on matter.js, with the drag events', () => {
    for (const [name, Matter] of both) {
      const { engine, box, canvas, drag } = boxOnTheGround(Matter, 40, 40);
      const seen: string[] = [];
      Matter.Events.on(drag, 'startdrag', () => seen.push('start'));
      Matter.Events.on(drag, 'enddrag', () => seen.push('end'));
      Matter.Events.on(drag, 'mousedown', () => seen.push('down'));
      canvas.fire('mousedown', 400, 560);
      Matter.Engine.update(engine);
      // the pointer goes up 200 px and stays there for 2 s
      for (let i = 1; i <= 20; i++) {
        canvas.fire('mousemove', 400, 560 - 10 * i);
        Matter.Engine.update(engine);
      }
      for (let i = 0; i < 120; i++) Matter.Engine.update(engine);
      // hanging from the pointer at its centre, the box sags a little under its weight
      expect(Math.abs(box.position.x - 400), name).toBeLessThan(5);
      expect(Math.abs(box.position.y - 360), name).toBeLessThan(25);
      canvas.fire('mouseup', 400, 360);
      for (let i = 0; i < 120; i++) Matter.Engine.update(engine);
      expect(Math.abs(box.position.y - 560), name).toBeLessThan(2);
      expect(seen, name).toEqual(['start', 'down', 'end']);
    }
  });
  it('a box grabbed by its corner and lifted is not swung round by the pull (angularStiffness 1), as on matter.js', () => {
    for (const [name, Matter] of both) {
      const { engine, box, canvas } = boxOnTheGround(Matter, 80, 60);
      // near the top left corner, 35 px left of the centre and 25 above it
      canvas.fire('mousedown', 365, 525);
      Matter.Engine.update(engine);
      for (let i = 1; i <= 20; i++) {
        canvas.fire('mousemove', 365, 525 - 10 * i);
        Matter.Engine.update(engine);
      }
      for (let i = 0; i < 120; i++) Matter.Engine.update(engine);
      // hanging by a corner it would turn until its centre was under the pointer (about 0.95 rad)
      expect(Math.abs(box.angle), name).toBeLessThan(0.1);
      expect(Math.abs(box.position.x - 400), name).toBeLessThan(5);
    }
  });
  it('a finger drags as the mouse does (touchstart, touchmove, touchend), as on matter.js', () => {
    for (const [name, Matter] of both) {
      const { engine, box, canvas } = boxOnTheGround(Matter, 40, 40);
      canvas.touch('touchstart', 400, 560);
      Matter.Engine.update(engine);
      for (let i = 1; i <= 20; i++) {
        canvas.touch('touchmove', 400 + 10 * i, 560 - 10 * i);
        Matter.Engine.update(engine);
      }
      for (let i = 0; i < 120; i++) Matter.Engine.update(engine);
      expect(Math.abs(box.position.x - 600), name).toBeLessThan(5);
      expect(Math.abs(box.position.y - 360), name).toBeLessThan(25);
      canvas.touch('touchend', 600, 360);
      for (let i = 0; i < 120; i++) Matter.Engine.update(engine);
      expect(Math.abs(box.position.y - 560), name).toBeLessThan(2);
    }
  });
});
