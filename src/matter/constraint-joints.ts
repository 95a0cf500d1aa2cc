import type { Joint } from '../joints/joint';
import { MouseJoint } from '../joints/mouse-joint';
import { makeRot } from '../math/rot';
import { type MatterBody, VELOCITY_TO_SI } from './body';
import { Constraint, isPointerConstraint, type MatterConstraint } from './constraint';
import type { FulcrumLink, JointRecord } from './simulation';
import type { MatterVector } from './vector';

/** Constraints as Fulcrum joints: rigid ones as pins and rods, soft ones as springs of matter's period. */

/**
 * How many of matter's constraint corrections a soft constraint's period reflects per update, for a
 * small stiffness: (omega dt)^2 is 6.7, 6.7 and 6.3 times the stiffness in the periods matter.js 0.20
 * gives a mass on a spring of stiffness 0.005, 0.02 and 0.05 (34.4, 17.2 and 11.2 updates).
 */
const SPRING_PASSES = 6.6;

/**
 * The Fulcrum joint of a matter constraint, or null while one of its bodies is not in the world.
 * Stiffness 0.9 and over is rigid: a revolute joint for length 0 (a pin), a distance joint (a rod)
 * otherwise. Softer is a distance spring of rest length `length` with matter's feel. matter moves the
 * ends a share of the way to the rest length several times an update (constraint passes before and
 * after the collisions, and the last update's correction carried over), which acts on the position's
 * second difference like a spring with (omega dt)^2 = SPRING_PASSES * stiffness / sqrt(1 - stiffness),
 * dt = 1000/60 ms, whatever the masses: the fitted line for soft springs (periods within 4 % of
 * matter's from 0.002 to 0.05), growing without bound as stiffness nears 1, as matter's repeated
 * passes make a stiff constraint. A chain of eight boxes hanging on pins of stiffness 0.6 then
 * stretches its pins by 0.4 px on average while it swings, as on matter.
 */
function createJoint(link: FulcrumLink, constraint: MatterConstraint): Joint | null {
  const end = (body: MatterBody | null, point: MatterVector) => {
    if (body === null) return { fulcrum: link.anchor, local: { x: point.x, y: point.y } };
    const fulcrum = link.bodies.get(body)?.fulcrum;
    if (!fulcrum) return null;
    const { c, s } = makeRot(body.angle);
    return { fulcrum, local: { x: c * point.x + s * point.y, y: -s * point.x + c * point.y } };
  };
  const a = end(constraint.bodyA, constraint.pointA);
  const b = end(constraint.bodyB, constraint.pointB);
  if (!a || !b || a.fulcrum === b.fulcrum) return null;
  const rigid = constraint.stiffness >= 0.9;
  const stiffness = Math.min(Math.max(constraint.stiffness, 0), 0.9);
  const c = (SPRING_PASSES * stiffness) / Math.sqrt(1 - stiffness);
  const hertz = (Math.sqrt(c) * VELOCITY_TO_SI) / (2 * Math.PI);
  if (constraint.bodyA === null && constraint.bodyB !== null && isPointerConstraint(constraint)) {
    // a mouse constraint's pull of a body to the pointer: a mouse joint, whose target follows pointA
    // (see syncConstraints). matter's mouse constraint has angularStiffness 1, which takes away the
    // turn its pull would give: the joint then holds the centre of mass, pointB away from the pointer
    return link.world.createJoint({
      type: 'mouse',
      body: b.fulcrum,
      target: holdsCentre(constraint) ? constraint.bodyB.position : Constraint.pointBWorld(constraint),
      hertz,
      // a hundred times the body's weight under matter's default gravity (1000 px/s²): the pull is
      // the spring's, not a cap's
      maxForce: 1e5 * Math.max(b.fulcrum.mass, 1e-6),
    });
  }
  if (rigid && constraint.length === 0) {
    return link.world.createJoint({
      type: 'revolute',
      bodyA: a.fulcrum,
      bodyB: b.fulcrum,
      localAnchorA: a.local,
      localAnchorB: b.local,
      // matter's constraints never keep their bodies from colliding (only collision filters do)
      collideConnected: true,
    });
  }
  return link.world.createJoint({
    type: 'distance',
    bodyA: a.fulcrum,
    bodyB: b.fulcrum,
    localAnchorA: a.local,
    localAnchorB: b.local,
    length: constraint.length,
    enableSpring: !rigid,
    hertz: rigid ? 0 : hertz,
    dampingRatio: Math.min(constraint.damping, 1),
    collideConnected: true,
  });
}

/** Whether a mouse constraint's pull leaves its body's turning alone (matter's angularStiffness 1). */
function holdsCentre(constraint: MatterConstraint): boolean {
  return constraint.angularStiffness >= 1;
}

/** Where a mouse constraint's joint pulls to: the pointer, or for one that holds the centre, pointB short of it. */
function pointerTarget(constraint: MatterConstraint): MatterVector {
  const { pointA, pointB } = constraint;
  return holdsCentre(constraint) ? { x: pointA.x - pointB.x, y: pointA.y - pointB.y } : pointA;
}

/** Whether the constraint still is what its joint was made from (a mouse joint's target aside). */
function unchanged(record: JointRecord, constraint: MatterConstraint): boolean {
  const { pointA, pointB } = constraint;
  return (
    record.bodyA === constraint.bodyA &&
    record.bodyB === constraint.bodyB &&
    record.length === constraint.length &&
    record.stiffness === constraint.stiffness &&
    record.damping === constraint.damping &&
    (record.worldA === null || (record.worldA.x === pointA.x && record.worldA.y === pointA.y)) &&
    (record.worldB === null || (record.worldB.x === pointB.x && record.worldB.y === pointB.y))
  );
}

/**
 * Keeps each constraint's joint in step with it before an update: made again when the program changed
 * it (its bodies, as a mouse constraint grabbing or letting go; its length, stiffness or damping; a
 * world point it is pinned to), a mouse joint's target moved to `pointA`.
 */
export function syncConstraints(link: FulcrumLink): void {
  for (const [constraint, record] of link.joints) {
    const pointer = record.joint instanceof MouseJoint;
    if (record.joint !== null && !pointer && !unchanged(record, constraint)) {
      if (record.joint.isValid) link.world.destroyJoint(record.joint);
      record.joint = null;
    }
    if (pointer && (record.bodyA !== constraint.bodyA || record.bodyB !== constraint.bodyB)) {
      if (record.joint?.isValid) link.world.destroyJoint(record.joint);
      record.joint = null;
    }
    if (record.joint === null && (constraint.bodyA !== null || constraint.bodyB !== null)) {
      record.joint = createJoint(link, constraint);
      record.bodyA = constraint.bodyA;
      record.bodyB = constraint.bodyB;
      record.length = constraint.length;
      record.stiffness = constraint.stiffness;
      record.damping = constraint.damping;
      record.worldA = constraint.bodyA === null ? { x: constraint.pointA.x, y: constraint.pointA.y } : null;
      record.worldB = constraint.bodyB === null ? { x: constraint.pointB.x, y: constraint.pointB.y } : null;
    }
    if (record.joint instanceof MouseJoint) record.joint.setTarget(pointerTarget(constraint));
  }
}

/**
 * Turns each constraint's offsets with its bodies, as matter keeps them: by how far each moving body
 * turned in the update just read back (its angle less anglePrev). One pass over the constraints.
 */
export function turnConstraintPoints(link: FulcrumLink): void {
  for (const constraint of link.joints.keys()) {
    turnWith(constraint.bodyA, constraint.pointA);
    turnWith(constraint.bodyB, constraint.pointB);
  }
}

function turnWith(body: MatterBody | null, point: MatterVector): void {
  if (body === null || body.isStatic) return;
  const turned = body.angle - body.anglePrev;
  if (turned === 0) return;
  const { c, s } = makeRot(turned);
  const x = point.x;
  point.x = c * x - s * point.y;
  point.y = s * x + c * point.y;
}

/**
 * Follows the world's constraints: forgets the joints of constraints no longer in it, and notes new
 * ones (made at the next syncConstraints). A joint destroyed with its body is made again once its
 * bodies are back.
 */
export function syncConstraintMembers(link: FulcrumLink, constraints: readonly MatterConstraint[]): void {
  const present = new Set(constraints);
  for (const [constraint, record] of link.joints) {
    if (present.has(constraint)) continue;
    if (record.joint?.isValid) link.world.destroyJoint(record.joint);
    link.joints.delete(constraint);
  }
  for (const constraint of present) {
    if (link.joints.has(constraint)) continue;
    link.joints.set(constraint, {
      joint: null,
      bodyA: null,
      bodyB: null,
      length: 0,
      stiffness: 0,
      damping: 0,
      worldA: null,
      worldB: null,
    });
  }
  for (const record of link.joints.values()) if (record.joint && !record.joint.isValid) record.joint = null;
}
