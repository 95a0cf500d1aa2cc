import type { MatterBody } from './body';
import { Common } from './common';
import type { MatterVector } from './vector';

/**
 * A matter.js constraint: `pointA` and `pointB` are offsets from the bodies' positions (turning with
 * them), or world points where a body is missing; `length` defaults to their distance when made.
 */
export interface MatterConstraint {
  id: number;
  type: 'constraint';
  label: string;
  bodyA: MatterBody | null;
  bodyB: MatterBody | null;
  pointA: MatterVector;
  pointB: MatterVector;
  length: number;
  stiffness: number;
  damping: number;
  angularStiffness: number;
  angleA: number;
  angleB: number;
  render: {
    visible: boolean;
    lineWidth: number;
    strokeStyle: string;
    type: 'line' | 'pin' | 'spring';
    anchors: boolean;
  };
  plugin: Record<string, unknown>;
}

export type ConstraintOptions = Partial<Omit<MatterConstraint, 'render'>> & {
  render?: Partial<MatterConstraint['render']>;
};

/** Marks a mouse constraint's own constraint, which the engine simulates as a Fulcrum mouse joint. */
export function markPointerConstraint(constraint: MatterConstraint): void {
  Object.defineProperty(constraint, '_pointer', { value: true, enumerable: false });
}

export function isPointerConstraint(constraint: MatterConstraint): boolean {
  return (constraint as { _pointer?: boolean })._pointer === true;
}

function distance(a: MatterVector, b: MatterVector): number {
  const dx = a.x - b.x;
  const dy = a.y - b.y;
  return Math.sqrt(dx * dx + dy * dy);
}

/** The world point of an end: the body's position plus the offset, or the offset itself without a body. */
function worldPoint(body: MatterBody | null, point: MatterVector): MatterVector {
  return body ? { x: body.position.x + point.x, y: body.position.y + point.y } : { x: point.x, y: point.y };
}

/** matter.js's `Constraint`. A plain, mutable module object; the engine simulates constraints as Fulcrum joints. */
export const Constraint = {
  create(options: ConstraintOptions): MatterConstraint {
    const pointA = options.pointA ? { x: options.pointA.x, y: options.pointA.y } : { x: 0, y: 0 };
    const pointB = options.pointB ? { x: options.pointB.x, y: options.pointB.y } : { x: 0, y: 0 };
    const bodyA = options.bodyA ?? null;
    const bodyB = options.bodyB ?? null;
    const a = worldPoint(bodyA, pointA);
    const b = worldPoint(bodyB, pointB);
    const length = options.length ?? distance(a, b);
    const stiffness = options.stiffness || (length > 0 ? 1 : 0.7);
    const render = {
      visible: true,
      lineWidth: 2,
      strokeStyle: '#ffffff',
      type: length === 0 && stiffness > 0.1 ? 'pin' : stiffness < 0.9 ? 'spring' : 'line',
      anchors: true,
      ...options.render,
    } as MatterConstraint['render'];
    return {
      ...options,
      id: options.id ?? Common.nextId(),
      type: 'constraint',
      label: options.label ?? 'Constraint',
      bodyA,
      bodyB,
      pointA,
      pointB,
      length,
      stiffness,
      damping: options.damping || 0,
      angularStiffness: options.angularStiffness || 0,
      angleA: bodyA ? bodyA.angle : (options.angleA ?? 0),
      angleB: bodyB ? bodyB.angle : (options.angleB ?? 0),
      render,
      plugin: options.plugin ?? {},
    };
  },

  /** The world point of end A. */
  pointAWorld(constraint: MatterConstraint): MatterVector {
    return worldPoint(constraint.bodyA, constraint.pointA);
  },

  /** The world point of end B. */
  pointBWorld(constraint: MatterConstraint): MatterVector {
    return worldPoint(constraint.bodyB, constraint.pointB);
  },

  /** The distance between the ends now. */
  currentLength(constraint: MatterConstraint): number {
    const a = Constraint.pointAWorld(constraint);
    const b = Constraint.pointBWorld(constraint);
    return distance(a, b);
  },
};
