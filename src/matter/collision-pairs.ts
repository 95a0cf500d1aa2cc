import type { WorldEvents } from '../api/events';
import type { ShapeHandle } from '../api/shape';
import type { MatterBody } from './body';
import type { FulcrumLink } from './simulation';
import type { MatterVector } from './vector';

/** A collision pair as matter.js reports it in its collision events. */
export interface MatterPair {
  id: string;
  bodyA: MatterBody;
  bodyB: MatterBody;
  collision: {
    collided: boolean;
    bodyA: MatterBody;
    bodyB: MatterBody;
    parentA: MatterBody;
    parentB: MatterBody;
    normal: MatterVector;
    tangent: MatterVector;
    depth: number;
    supports: MatterVector[];
  };
  isActive: boolean;
  isSensor: boolean;
  timeCreated: number;
  timeUpdated: number;
  friction: number;
  frictionStatic: number;
  restitution: number;
  slop: number;
}

/** An engine's pairs: `table` by id and `list`, as matter keeps them, and how many shape pairs touch in each. */
export interface MatterPairs {
  table: Record<string, MatterPair>;
  list: MatterPair[];
}

/** The pairs an update began, kept on and ended, for matter's three collision events. */
export interface PairChanges {
  start: MatterPair[];
  active: MatterPair[];
  end: MatterPair[];
}

function pairId(a: MatterBody, b: MatterBody): string {
  return a.id < b.id ? `A${a.id}B${b.id}` : `A${b.id}B${a.id}`;
}

function createPair(a: MatterBody, b: MatterBody, timestamp: number): MatterPair {
  return {
    id: pairId(a, b),
    bodyA: a,
    bodyB: b,
    collision: {
      collided: true,
      bodyA: a,
      bodyB: b,
      parentA: a.parent,
      parentB: b.parent,
      normal: { x: 0, y: 0 },
      tangent: { x: 0, y: 0 },
      depth: 0,
      supports: [],
    },
    isActive: true,
    isSensor: a.isSensor || b.isSensor,
    timeCreated: timestamp,
    timeUpdated: timestamp,
    friction: Math.min(a.friction, b.friction),
    frictionStatic: Math.max(a.frictionStatic, b.frictionStatic),
    restitution: Math.max(a.restitution, b.restitution),
    slop: Math.max(a.slop, b.slop),
  };
}

/**
 * How many shape pairs touch between the two parts of each active pair (a concave part is several
 * shapes): a matter pair starts with the first and ends with the last.
 */
export type TouchCounts = Map<object, number>;

function begin(
  pairs: MatterPairs,
  touching: TouchCounts,
  a: MatterBody,
  b: MatterBody,
  timestamp: number,
  changes: PairChanges,
): MatterPair {
  const id = pairId(a, b);
  let pair = pairs.table[id];
  if (pair?.isActive) {
    touching.set(pair, (touching.get(pair) ?? 1) + 1);
    return pair;
  }
  if (pair) {
    pair.isActive = true;
    pair.timeUpdated = timestamp;
  } else {
    pair = createPair(a, b, timestamp);
    pairs.table[id] = pair;
    pairs.list.push(pair);
  }
  touching.set(pair, 1);
  changes.start.push(pair);
  return pair;
}

function end(
  pairs: MatterPairs,
  touching: TouchCounts,
  a: MatterBody,
  b: MatterBody,
  timestamp: number,
  changes: PairChanges,
): void {
  const id = pairId(a, b);
  const pair = pairs.table[id];
  if (!pair?.isActive) return;
  const left = (touching.get(pair) ?? 1) - 1;
  touching.set(pair, left);
  if (left > 0) return;
  touching.delete(pair);
  pair.isActive = false;
  pair.timeUpdated = timestamp;
  changes.end.push(pair);
  delete pairs.table[id];
}

/**
 * A pair's collision as matter gives it, from a contact whose normal runs from the pair's bodyA to its
 * bodyB: matter's normal runs the other way (from B to A), its depth is how far the bodies overlap.
 */
function setCollision(
  pair: MatterPair,
  nx: number,
  ny: number,
  points: readonly MatterVector[],
  depth: number,
): void {
  const collision = pair.collision;
  collision.normal = { x: -nx, y: -ny };
  collision.tangent = { x: ny, y: -nx };
  collision.depth = depth;
  collision.supports = points.map((p) => ({ x: p.x, y: p.y }));
}

/**
 * Brings the collisions of the active pairs up to the last step (normal, depth, supports), from the
 * simulated bodies' contacts, each contact once (from its body A's side, or from B's when A is static).
 */
export function refreshCollisions(pairs: MatterPairs, link: FulcrumLink): void {
  for (const sim of link.list) {
    if (sim.body.isStatic) continue;
    for (const contact of sim.fulcrum.getContacts()) {
      const first = contact.shapeA.body === sim.fulcrum;
      if (!first && contact.shapeA.body.type === 'dynamic') continue;
      const a = contact.shapeA.userData as MatterBody;
      const b = contact.shapeB.userData as MatterBody;
      const pair = pairs.table[pairId(a, b)];
      if (!pair?.isActive) continue;
      let depth = 0;
      for (const p of contact.points) depth = Math.max(depth, -p.separation);
      const { x, y } = contact.normal;
      const points = contact.points.map((p) => p.point);
      if (pair.bodyA === a) setCollision(pair, x, y, points, depth);
      else setCollision(pair, -x, -y, points, depth);
    }
  }
}

/**
 * Turns the contacts and sensor overlaps the last step began and ended into matter's pair changes, in
 * matter's order; `active` (the pairs active before the update and still after it) only when asked.
 */
export function updatePairs(
  pairs: MatterPairs,
  touching: TouchCounts,
  events: WorldEvents,
  timestamp: number,
  withActive: boolean,
): PairChanges {
  const changes: PairChanges = { start: [], active: withActive ? pairs.list.slice() : [], end: [] };
  for (const event of events.contactBegin) {
    const a = (event.shapeA as ShapeHandle).userData as MatterBody;
    const b = (event.shapeB as ShapeHandle).userData as MatterBody;
    const pair = begin(pairs, touching, a, b, timestamp, changes);
    if (pair.bodyA === a) setCollision(pair, event.normal.x, event.normal.y, event.points, 0);
    else setCollision(pair, -event.normal.x, -event.normal.y, event.points, 0);
  }
  for (const event of events.sensorBegin) {
    const a = (event.sensorShape as ShapeHandle).userData as MatterBody;
    const b = (event.visitorShape as ShapeHandle).userData as MatterBody;
    begin(pairs, touching, a, b, timestamp, changes);
  }
  for (const event of events.contactEnd) {
    end(
      pairs,
      touching,
      (event.shapeA as ShapeHandle).userData as MatterBody,
      (event.shapeB as ShapeHandle).userData as MatterBody,
      timestamp,
      changes,
    );
  }
  for (const event of events.sensorEnd) {
    end(
      pairs,
      touching,
      (event.sensorShape as ShapeHandle).userData as MatterBody,
      (event.visitorShape as ShapeHandle).userData as MatterBody,
      timestamp,
      changes,
    );
  }
  if (changes.end.length > 0) pairs.list = pairs.list.filter((pair) => pair.isActive);
  if (withActive) changes.active = changes.active.filter((pair) => pair.isActive);
  return changes;
}
