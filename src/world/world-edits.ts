import { FulcrumError } from '../core/errors';
import { type Geometry, ShapeKind } from '../geometry/types';
import { BodyFlag, BodyKind, BodyState } from '../store/body-store';
import { ContactFlag } from '../store/contact-store';
import type { WorldCore } from './world-core';

/*
 * Changes to a world between steps that reach across its stores (bodies, shapes, contacts, islands,
 * proxies); the public handles call them with slots.
 */

/**
 * Throws unless a body may take kind `kind` (named `type`) given whether it holds a segment shape:
 * a dynamic body cannot. changeBodyKind checks with it, and fulcrum/worker on the calling thread.
 */
export function checkKindChange(kind: BodyKind, hasSegment: boolean, type: string): void {
  if (kind === BodyKind.DYNAMIC && hasSegment) {
    throw new FulcrumError(
      `type: a body with a segment shape cannot be 'dynamic', got ${JSON.stringify(type)}`,
    );
  }
}

/**
 * Gives body `b` the kind `kind` (`type` is the name the caller gave, for the error): its contacts and
 * proxies are made anew, as a body of another kind has other pairs and lives in another tree.
 */
export function changeBodyKind(core: WorldCore, b: number, kind: BodyKind, type: string): void {
  const bodies = core.bodies;
  if (bodies.kind[b] === kind) return;
  const shapes = core.shapes;
  if (kind === BodyKind.DYNAMIC) {
    let segment = false;
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
      if (shapes.kind[s] === ShapeKind.SEGMENT) segment = true;
    }
    checkKindChange(kind, segment, type);
  }
  core.wakeTouching(b);
  core.islands.remove(bodies, b);
  for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
    core.destroyShapeContacts(s, true, true);
    core.destroyProxy(s);
  }
  bodies.kind[b] = kind;
  bodies.awakeEpoch++;
  if (kind === BodyKind.STATIC) {
    bodies.flags[b] &= ~BodyFlag.AWAKE;
    const st = b * BodyState.STRIDE;
    bodies.state[st + BodyState.VX] = 0;
    bodies.state[st + BodyState.VY] = 0;
    bodies.state[st + BodyState.W] = 0;
  } else {
    bodies.flags[b] |= BodyFlag.AWAKE;
    bodies.sleepTime[b] = 0;
  }
  core.updateMass(b);
  for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) core.createProxy(s, true);
}

/** Puts body `b` and every body it touches (transitively) to sleep as one island. */
export function sleepIsland(core: WorldCore, b: number): void {
  const bodies = core.bodies;
  if (bodies.kind[b] === BodyKind.STATIC) return;
  core.wake(b); // leave any island it was in, so the new island is complete
  const contacts = core.contacts;
  const members: number[] = [b];
  const seen = new Set<number>(members);
  for (let i = 0; i < members.length; i++) {
    const x = members[i];
    for (let e = bodies.contactHead[x]; e !== -1; e = contacts.edgeNext[e]) {
      const c = e >> 1;
      if ((contacts.flags[c] & ContactFlag.TOUCHING) === 0) continue;
      const other = contacts.bodyA[c] === x ? contacts.bodyB[c] : contacts.bodyA[c];
      if (bodies.kind[other] !== BodyKind.DYNAMIC || seen.has(other)) continue;
      seen.add(other);
      core.wake(other);
      members.push(other);
    }
  }
  members.sort((p, q) => p - q);
  core.islands.sleepGroup(bodies, members);
}

/**
 * Gives shape `s` a new geometry: its contacts end (the touching ones report their ends) and are
 * found anew from its new proxy next step. The body's mass is the caller's to update, once for all
 * the shapes it changes.
 */
export function replaceShapeGeometry(core: WorldCore, s: number, geometry: Geometry): void {
  core.destroyShapeContacts(s, true, true);
  core.destroyProxy(s);
  core.shapes.setGeometry(s, geometry);
  core.createProxy(s, true);
}
