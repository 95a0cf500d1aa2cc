import type { MatterBody } from './body';
import { Body } from './body';
import { Bounds, type MatterBounds } from './bounds';
import { Common } from './common';
import type { MatterConstraint } from './constraint';
import { Events } from './events';
import type { MatterVector } from './vector';

/** A matter.js composite: bodies, constraints and composites, nested. */
export interface MatterComposite {
  id: number;
  type: 'composite';
  parent: MatterComposite | null;
  isModified: boolean;
  bodies: MatterBody[];
  constraints: MatterConstraint[];
  composites: MatterComposite[];
  label: string;
  plugin: Record<string, unknown>;
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
  [key: string]: unknown;
}

type Member =
  | MatterBody
  | MatterComposite
  | MatterConstraint
  | { type: 'mouseConstraint'; id: number; constraint: MatterConstraint };

/** matter.js's `Composite` (and, with `World`, its 0.20 aliases). A plain, mutable module object. */
export const Composite = {
  create(options: Partial<MatterComposite> = {}): MatterComposite {
    return Common.extend(
      {
        id: Common.nextId(),
        type: 'composite',
        parent: null,
        isModified: false,
        bodies: [],
        constraints: [],
        composites: [],
        label: 'Composite',
        plugin: {},
        events: null,
      },
      options,
    ) as MatterComposite;
  },

  /** Marks `composite` modified (and its parents, its children, if asked). */
  setModified(
    composite: MatterComposite,
    isModified: boolean,
    updateParents = false,
    updateChildren = false,
  ): void {
    composite.isModified = isModified;
    if (updateParents && composite.parent) Composite.setModified(composite.parent, isModified, true, false);
    if (updateChildren)
      for (const child of composite.composites) Composite.setModified(child, isModified, false, true);
  },

  /** Adds a body, constraint, composite or mouse constraint, or an array of them. Returns the composite. */
  add(composite: MatterComposite, object: Member | Member[]): MatterComposite {
    const objects = Array.isArray(object) ? object : [object];
    Events.trigger(composite, 'beforeAdd', { object });
    for (const item of objects) {
      switch (item.type) {
        case 'body':
          if ((item as MatterBody).parent !== item) {
            Common.warn(
              'Composite.add: skipped adding a compound body part (you must add its parent instead)',
            );
            break;
          }
          Composite.addBody(composite, item as MatterBody);
          break;
        case 'constraint':
          Composite.addConstraint(composite, item as MatterConstraint);
          break;
        case 'composite':
          Composite.addComposite(composite, item as MatterComposite);
          break;
        case 'mouseConstraint':
          Composite.addConstraint(composite, (item as { constraint: MatterConstraint }).constraint);
          break;
      }
    }
    Events.trigger(composite, 'afterAdd', { object });
    return composite;
  },

  /** Removes a body, constraint or composite (or an array), searching nested composites when `deep`. */
  remove(composite: MatterComposite, object: Member | Member[], deep = false): MatterComposite {
    const objects = Array.isArray(object) ? object : [object];
    Events.trigger(composite, 'beforeRemove', { object });
    for (const item of objects) {
      switch (item.type) {
        case 'body':
          Composite.removeBody(composite, item as MatterBody, deep);
          break;
        case 'constraint':
          Composite.removeConstraint(composite, item as MatterConstraint, deep);
          break;
        case 'composite':
          Composite.removeComposite(composite, item as MatterComposite, deep);
          break;
        case 'mouseConstraint':
          Composite.removeConstraint(composite, (item as { constraint: MatterConstraint }).constraint, deep);
          break;
      }
    }
    Events.trigger(composite, 'afterRemove', { object });
    return composite;
  },

  /** Adds one body (no events). */
  addBody(composite: MatterComposite, body: MatterBody): MatterComposite {
    if (!composite.bodies.includes(body)) composite.bodies.push(body);
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  /** Removes one body, from nested composites too when `deep` (no events); it wakes if it slept. */
  removeBody(composite: MatterComposite, body: MatterBody, deep = false): MatterComposite {
    const index = composite.bodies.indexOf(body);
    if (index !== -1) Composite.removeBodyAt(composite, index);
    if (deep) for (const child of composite.composites) Composite.removeBody(child, body, true);
    return composite;
  },

  removeBodyAt(composite: MatterComposite, position: number): MatterComposite {
    const [body] = composite.bodies.splice(position, 1);
    if (body) Body.set(body, 'isSleeping', false);
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  /** Adds one constraint (no events). */
  addConstraint(composite: MatterComposite, constraint: MatterConstraint): MatterComposite {
    if (!composite.constraints.includes(constraint)) composite.constraints.push(constraint);
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  removeConstraint(composite: MatterComposite, constraint: MatterConstraint, deep = false): MatterComposite {
    const index = composite.constraints.indexOf(constraint);
    if (index !== -1) Composite.removeConstraintAt(composite, index);
    if (deep) for (const child of composite.composites) Composite.removeConstraint(child, constraint, true);
    return composite;
  },

  removeConstraintAt(composite: MatterComposite, position: number): MatterComposite {
    composite.constraints.splice(position, 1);
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  /** Makes `child` a composite of `composite` (no events). */
  addComposite(composite: MatterComposite, child: MatterComposite): MatterComposite {
    if (child !== composite && !composite.composites.includes(child)) {
      child.parent = composite;
      composite.composites.push(child);
    }
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  removeComposite(composite: MatterComposite, child: MatterComposite, deep = false): MatterComposite {
    const index = composite.composites.indexOf(child);
    if (index !== -1) Composite.removeCompositeAt(composite, index);
    if (deep) for (const nested of composite.composites) Composite.removeComposite(nested, child, true);
    return composite;
  },

  removeCompositeAt(composite: MatterComposite, position: number): MatterComposite {
    composite.composites.splice(position, 1);
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  /** Moves `objects` from composite `from` to composite `to`. */
  move(from: MatterComposite, objects: Member | Member[], to: MatterComposite): MatterComposite {
    Composite.remove(from, objects);
    Composite.add(to, objects);
    return from;
  },

  /** Gives every object in the composite a new id. */
  rebase(composite: MatterComposite): MatterComposite {
    const objects: { id: number }[] = [
      ...Composite.allBodies(composite),
      ...Composite.allConstraints(composite),
      ...Composite.allComposites(composite),
    ];
    for (const object of objects) object.id = Common.nextId();
    return composite;
  },

  /** The bounds of every body in the composite and its descendants. */
  bounds(composite: MatterComposite): MatterBounds {
    return Bounds.create(Composite.allBodies(composite).flatMap((body) => body.vertices));
  },

  /** Every body in the composite and its descendants. */
  allBodies(composite: MatterComposite): MatterBody[] {
    return composite.bodies.concat(...composite.composites.map((c) => Composite.allBodies(c)));
  },

  allConstraints(composite: MatterComposite): MatterComposite['constraints'] {
    return composite.constraints.concat(...composite.composites.map((c) => Composite.allConstraints(c)));
  },

  allComposites(composite: MatterComposite): MatterComposite[] {
    return composite.composites.concat(...composite.composites.map((c) => Composite.allComposites(c)));
  },

  /** Removes everything (static bodies stay when `keepStatic`), in nested composites too when `deep`. */
  clear(composite: MatterComposite, keepStatic = false, deep = false): MatterComposite {
    if (deep) for (const child of composite.composites) Composite.clear(child, keepStatic, true);
    composite.bodies = keepStatic ? composite.bodies.filter((b) => b.isStatic) : [];
    composite.constraints = [];
    composite.composites = [];
    Composite.setModified(composite, true, true, false);
    return composite;
  },

  /** The object of `type` with `id` in the composite or its descendants, or null. */
  get(composite: MatterComposite, id: number, type: 'body' | 'constraint' | 'composite'): Member | null {
    const list: Member[] =
      type === 'body'
        ? Composite.allBodies(composite)
        : type === 'constraint'
          ? Composite.allConstraints(composite)
          : Composite.allComposites(composite);
    return list.find((item) => item.id === id) ?? null;
  },

  translate(composite: MatterComposite, translation: MatterVector, recursive = true): MatterComposite {
    for (const body of recursive ? Composite.allBodies(composite) : composite.bodies)
      Body.translate(body, translation);
    return composite;
  },

  rotate(
    composite: MatterComposite,
    rotation: number,
    point: MatterVector,
    recursive = true,
  ): MatterComposite {
    for (const body of recursive ? Composite.allBodies(composite) : composite.bodies)
      Body.rotate(body, rotation, point);
    return composite;
  },

  scale(
    composite: MatterComposite,
    scaleX: number,
    scaleY: number,
    point: MatterVector,
    recursive = true,
  ): MatterComposite {
    for (const body of recursive ? Composite.allBodies(composite) : composite.bodies) {
      const moved = {
        x: point.x + (body.position.x - point.x) * scaleX,
        y: point.y + (body.position.y - point.y) * scaleY,
      };
      Body.setPosition(body, moved);
      Body.scale(body, scaleX, scaleY);
    }
    return composite;
  },
};

/** matter.js 0.20's `World`: a composite, with the old names of Composite's functions. */
export const World = {
  create: Composite.create,
  add: Composite.add,
  remove: Composite.remove,
  clear: Composite.clear,
  addComposite: Composite.add,
  addBody: Composite.add,
  addConstraint: Composite.add,
};
