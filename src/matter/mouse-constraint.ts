import type { MatterBody } from './body';
import { Bounds } from './bounds';
import { Composite } from './composite';
import {
  Constraint,
  type ConstraintOptions,
  type MatterConstraint,
  markPointerConstraint,
} from './constraint';
import type { MatterEngine } from './engine';
import { Events } from './events';
import { type MatterMouse, Mouse, type MouseElement } from './mouse';
import { Sleeping } from './sleeping';
import { Vertices } from './vertices';

/** A matter.js mouse constraint: drags the body under the mouse with a soft constraint. */
export interface MatterMouseConstraint {
  type: 'mouseConstraint';
  id: number;
  mouse: MatterMouse;
  element: MouseElement | null;
  body: MatterBody | null;
  constraint: MatterConstraint;
  collisionFilter: { category: number; mask: number; group: number };
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
}

/** Whether two collision filters let their bodies meet (matter's rule, `Detector.canCollide`). */
export function canCollide(
  a: { category: number; mask: number; group: number },
  b: { category: number; mask: number; group: number },
): boolean {
  if (a.group === b.group && a.group !== 0) return a.group > 0;
  return (a.mask & b.category) !== 0 && (b.mask & a.category) !== 0;
}

/** matter.js's `MouseConstraint`. A plain, mutable module object. */
export const MouseConstraint = {
  /**
   * A mouse constraint for `engine`: `options.mouse` (or a mouse on `options.element`), and
   * `options.constraint` to change the constraint's stiffness or look. It updates before each of
   * the engine's updates.
   */
  create(
    engine: MatterEngine,
    options: {
      mouse?: MatterMouse;
      element?: MouseElement | HTMLElement;
      constraint?: ConstraintOptions;
      collisionFilter?: Partial<MatterMouseConstraint['collisionFilter']>;
    } = {},
  ): MatterMouseConstraint {
    const mouse = options.mouse ?? Mouse.create(options.element ?? null);
    const constraint = Constraint.create({
      label: 'Mouse Constraint',
      pointA: mouse.position,
      pointB: { x: 0, y: 0 },
      length: 0.01,
      stiffness: 0.1,
      angularStiffness: 1,
      ...options.constraint,
      render: { strokeStyle: '#90EE90', lineWidth: 3, ...options.constraint?.render },
    });
    // the constraint follows the mouse: its pointA is the mouse's position object itself
    constraint.pointA = mouse.position;
    markPointerConstraint(constraint);
    const mouseConstraint: MatterMouseConstraint = {
      type: 'mouseConstraint',
      id: constraint.id,
      mouse,
      element: null,
      body: null,
      constraint,
      collisionFilter: { category: 0x0001, mask: 0xffffffff, group: 0, ...options.collisionFilter },
      events: null,
    };
    Events.on(engine, 'beforeUpdate', () => {
      MouseConstraint.update(mouseConstraint, Composite.allBodies(engine.world));
      MouseConstraint._triggerEvents(mouseConstraint);
    });
    return mouseConstraint;
  },

  /** Grabs the body under a pressed mouse, keeps it while the button is down, lets go when it is up. */
  update(mouseConstraint: MatterMouseConstraint, bodies: readonly MatterBody[]): void {
    const { mouse, constraint } = mouseConstraint;
    if (mouse.button !== 0) {
      const body = mouseConstraint.body;
      constraint.bodyB = null;
      mouseConstraint.body = null;
      constraint.pointB = { x: 0, y: 0 };
      if (body) Events.trigger(mouseConstraint, 'enddrag', { mouse, body });
      return;
    }
    if (constraint.bodyB) {
      Sleeping.set(constraint.bodyB, false);
      constraint.pointA = mouse.position;
      return;
    }
    for (const body of bodies) {
      if (
        !Bounds.contains(body.bounds, mouse.position) ||
        !canCollide(body.collisionFilter, mouseConstraint.collisionFilter)
      )
        continue;
      const parts = body.parts.length > 1 ? body.parts.slice(1) : [body];
      if (!parts.some((part) => Vertices.contains(part.vertices, mouse.position))) continue;
      constraint.pointA = mouse.position;
      constraint.bodyB = body;
      mouseConstraint.body = body;
      constraint.pointB = { x: mouse.position.x - body.position.x, y: mouse.position.y - body.position.y };
      constraint.angleB = body.angle;
      Sleeping.set(body, false);
      Events.trigger(mouseConstraint, 'startdrag', { mouse, body });
      break;
    }
  },

  /** Passes the mouse's events of the last update on as the mouse constraint's, then forgets them. */
  _triggerEvents(mouseConstraint: MatterMouseConstraint): void {
    const mouse = mouseConstraint.mouse;
    const events = mouse.sourceEvents;
    if (events.mousemove) Events.trigger(mouseConstraint, 'mousemove', { mouse });
    if (events.mousedown) Events.trigger(mouseConstraint, 'mousedown', { mouse });
    if (events.mouseup) Events.trigger(mouseConstraint, 'mouseup', { mouse });
    Mouse.clearSourceEvents(mouse);
  },
};
