/**
 * matter.js's `Events`: callbacks kept on the object they are registered on, in `object.events`
 * (name to list), as matter keeps them. A plain, mutable module object.
 */
type Callback = (event: Record<string, unknown>) => void;

export interface MatterEventTarget {
  events?: Record<string, Callback[]> | null;
}

export const Events = {
  /** Calls `callback` on each of the space-separated `eventNames`; returns the callback. */
  on<E extends object = Record<string, unknown>>(
    object: MatterEventTarget,
    eventNames: string,
    callback: (event: E) => void,
  ): (event: E) => void {
    object.events ??= {};
    for (const name of eventNames.split(' ')) {
      (object.events[name] ??= []).push(callback as unknown as Callback);
    }
    return callback;
  },

  /**
   * Removes `callback` from `eventNames` (space separated); without a callback, every callback of
   * those events; with no names, every callback of the object.
   */
  off(object: MatterEventTarget, eventNames?: string | Callback, callback?: Callback): void {
    if (!object.events) return;
    if (typeof eventNames === 'function') {
      callback = eventNames;
      eventNames = Object.keys(object.events).join(' ');
    }
    if (eventNames === undefined) {
      object.events = {};
      return;
    }
    for (const name of eventNames.split(' ')) {
      const callbacks = object.events[name];
      if (!callbacks) continue;
      object.events[name] = callback ? callbacks.filter((c) => c !== callback) : [];
    }
  },

  /**
   * Calls the callbacks of each of `eventNames` on `object` with a copy of `event` that also names
   * the event (`name`) and its `source`.
   */
  trigger(object: MatterEventTarget, eventNames: string, event?: Record<string, unknown>): void {
    const events = object.events;
    if (!events) return;
    for (const name of eventNames.split(' ')) {
      const callbacks = events[name];
      if (!callbacks || callbacks.length === 0) continue;
      const payload = { ...event, name, source: object };
      for (const callback of callbacks.slice()) callback.call(object, payload);
    }
  },
};
