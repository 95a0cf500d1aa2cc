import type { World } from '../api/world';
import { checkKnownKeys, fail } from '../core/errors';
import type { Joint } from './joint';
import { JOINT_KINDS, type JointDef, type JointType } from './registry';

/**
 * Validates a joint definition completely and builds the joint of its type (registry.ts); it throws
 * before anything is created, so a bad definition leaves the world as it was.
 * @internal
 */
export function buildJoint(world: World, def: JointDef): Joint {
  if (typeof def !== 'object' || def === null) fail('def', def, 'an object');
  const type = (def as { type?: unknown }).type;
  if (typeof type !== 'string' || !Object.hasOwn(JOINT_KINDS, type)) fail('type', type, typeList());
  const kind = JOINT_KINDS[type as JointType];
  checkKnownKeys('def', def, kind.keys);
  // the kind of the definition's own type: its builder takes that definition
  return (kind.build as (world: World, def: JointDef) => Joint)(world, def);
}

/** The types, quoted, as a list ("'distance', 'revolute', ... or 'motor'"). */
function typeList(): string {
  const types = Object.keys(JOINT_KINDS).map((type) => `'${type}'`);
  return `${types.slice(0, -1).join(', ')} or ${types[types.length - 1]}`;
}
