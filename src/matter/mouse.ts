import type { MatterVector } from './vector';

/** What a matter.js mouse reads from its element (any DOM element, or an object that acts like one). */
export interface MouseElement {
  addEventListener(type: string, listener: (event: Event) => void, options?: AddEventListenerOptions): void;
  removeEventListener(type: string, listener: (event: Event) => void): void;
  getBoundingClientRect(): { left: number; top: number };
  clientWidth: number;
  clientHeight: number;
  width?: number;
  height?: number;
}

/** A matter.js mouse: the pointer over an element, in the element's (canvas) pixels, scaled and offset. */
export interface MatterMouse {
  element: MouseElement | null;
  absolute: MatterVector;
  position: MatterVector;
  mousedownPosition: MatterVector;
  mouseupPosition: MatterVector;
  offset: MatterVector;
  scale: MatterVector;
  wheelDelta: number;
  button: number;
  pixelRatio: number;
  sourceEvents: {
    mousemove: Event | null;
    mousedown: Event | null;
    mouseup: Event | null;
    mousewheel: Event | null;
  };
  /** the listeners added to the element, to take them off again (not enumerable) */
  _listeners?: [string, (event: Event) => void][];
}

type PointerLike = {
  changedTouches?: ArrayLike<{ pageX: number; pageY: number }>;
  pageX?: number;
  pageY?: number;
  button?: number;
  deltaY?: number;
  cancelable?: boolean;
  preventDefault?: () => void;
};

/** The pointer's point in the element's pixels (its canvas width over its CSS width). */
function relativePosition(event: PointerLike, element: MouseElement, pixelRatio: number): MatterVector {
  const rect = element.getBoundingClientRect();
  const scrollX = typeof window !== 'undefined' ? window.pageXOffset : 0;
  const scrollY = typeof window !== 'undefined' ? window.pageYOffset : 0;
  const touch = event.changedTouches?.[0];
  const pageX = touch ? touch.pageX : (event.pageX ?? 0);
  const pageY = touch ? touch.pageY : (event.pageY ?? 0);
  const x = pageX - rect.left - scrollX;
  const y = pageY - rect.top - scrollY;
  return {
    x: x / ((element.clientWidth / (element.width || element.clientWidth)) * pixelRatio),
    y: y / ((element.clientHeight / (element.height || element.clientHeight)) * pixelRatio),
  };
}

/** matter.js's `Mouse`. A plain, mutable module object. */
export const Mouse = {
  create(element?: MouseElement | null): MatterMouse {
    const mouse: MatterMouse = {
      element: null,
      absolute: { x: 0, y: 0 },
      position: { x: 0, y: 0 },
      mousedownPosition: { x: 0, y: 0 },
      mouseupPosition: { x: 0, y: 0 },
      offset: { x: 0, y: 0 },
      scale: { x: 1, y: 1 },
      wheelDelta: 0,
      button: -1,
      pixelRatio:
        Number(
          (element as unknown as { getAttribute?: (n: string) => string | null })?.getAttribute?.(
            'data-pixel-ratio',
          ),
        ) || 1,
      sourceEvents: { mousemove: null, mousedown: null, mouseup: null, mousewheel: null },
    };
    if (element) Mouse.setElement(mouse, element);
    return mouse;
  },

  /** Listens to `element`'s mouse and touch events (and stops listening to the previous element). */
  setElement(mouse: MatterMouse, element: MouseElement): void {
    if (mouse.element && mouse._listeners) {
      for (const [type, listener] of mouse._listeners) mouse.element.removeEventListener(type, listener);
    }
    mouse.element = element;
    const update = (event: PointerLike) => {
      const p = relativePosition(event, element, mouse.pixelRatio);
      mouse.absolute.x = p.x;
      mouse.absolute.y = p.y;
      mouse.position.x = p.x * mouse.scale.x + mouse.offset.x;
      mouse.position.y = p.y * mouse.scale.y + mouse.offset.y;
    };
    const touch = (event: PointerLike) => {
      if (event.changedTouches && event.cancelable) event.preventDefault?.();
    };
    const listeners: [string, (event: Event) => void][] = [
      [
        'mousemove',
        (event: PointerLike) => {
          update(event);
          touch(event);
          mouse.sourceEvents.mousemove = event as unknown as Event;
        },
      ],
      [
        'mousedown',
        (event: PointerLike) => {
          update(event);
          touch(event);
          mouse.button = event.changedTouches ? 0 : (event.button ?? 0);
          mouse.mousedownPosition = { x: mouse.position.x, y: mouse.position.y };
          mouse.sourceEvents.mousedown = event as unknown as Event;
        },
      ],
      [
        'mouseup',
        (event: PointerLike) => {
          update(event);
          touch(event);
          mouse.button = -1;
          mouse.mouseupPosition = { x: mouse.position.x, y: mouse.position.y };
          mouse.sourceEvents.mouseup = event as unknown as Event;
        },
      ],
      [
        'wheel',
        (event: PointerLike) => {
          mouse.wheelDelta = Math.max(-1, Math.min(1, -(event.deltaY ?? 0)));
          mouse.sourceEvents.mousewheel = event as unknown as Event;
          event.preventDefault?.();
        },
      ],
    ];
    // touches act as the left button
    listeners.push(
      ['touchmove', listeners[0][1]],
      ['touchstart', listeners[1][1]],
      ['touchend', listeners[2][1]],
    );
    for (const [type, listener] of listeners)
      element.addEventListener(type, listener, { passive: type === 'wheel' ? false : undefined });
    Object.defineProperty(mouse, '_listeners', {
      value: listeners,
      writable: true,
      enumerable: false,
      configurable: true,
    });
  },

  /** Forgets the events seen since the last call (the mouse constraint calls it every update). */
  clearSourceEvents(mouse: MatterMouse): void {
    mouse.sourceEvents.mousemove = null;
    mouse.sourceEvents.mousedown = null;
    mouse.sourceEvents.mouseup = null;
    mouse.sourceEvents.mousewheel = null;
    mouse.wheelDelta = 0;
  },

  setOffset(mouse: MatterMouse, offset: MatterVector): void {
    mouse.offset.x = offset.x;
    mouse.offset.y = offset.y;
    mouse.position.x = mouse.absolute.x * mouse.scale.x + mouse.offset.x;
    mouse.position.y = mouse.absolute.y * mouse.scale.y + mouse.offset.y;
  },

  setScale(mouse: MatterMouse, scale: MatterVector): void {
    mouse.scale.x = scale.x;
    mouse.scale.y = scale.y;
    mouse.position.x = mouse.absolute.x * mouse.scale.x + mouse.offset.x;
    mouse.position.y = mouse.absolute.y * mouse.scale.y + mouse.offset.y;
  },
};
