import type { MatterBody } from './body';
import { Events } from './events';

/** matter.js's `Sleeping`: put a body to sleep or wake it (the engine's own sleep decides the rest). */
export const Sleeping = {
  /** Sends `body` to sleep or wakes it, with its sleepStart / sleepEnd event. */
  set(body: MatterBody, isSleeping: boolean): void {
    const was = body.isSleeping;
    body.isSleeping = isSleeping;
    if (isSleeping) {
      body.velocity = { x: 0, y: 0 };
      body.angularVelocity = 0;
      body.speed = 0;
      body.angularSpeed = 0;
    }
    body._fulcrum?.setAwake(!isSleeping);
    if (was !== isSleeping) Events.trigger(body, isSleeping ? 'sleepStart' : 'sleepEnd');
  },
};
