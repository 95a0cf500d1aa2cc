import { describe, expect, expectTypeOf, it } from 'vitest';
import {
  DistanceJoint,
  type Joint,
  type JointDef,
  type JointType,
  MotorJoint,
  MouseJoint,
  PrismaticJoint,
  RevoluteJoint,
  WeldJoint,
  WheelJoint,
  World,
} from '../../src/index';
import { JOINT_KINDS } from '../../src/joints/registry';
import { expectRejected as rejects } from '../helpers/rejects';

/*
 * The joint types come from one registry (src/joints/registry.ts): createJoint's typing maps a
 * definition's `type` to its class, the validation and the snapshot's classes read the same list.
 * The typings are checked by the type checker (npx tsc): a line marked @ts-expect-error that type
 * checks fails it.
 */

function twoBodies() {
  const world = new World({ gravity: { x: 0, y: 0 } });
  const a = world.createBody({ type: 'dynamic', position: { x: 0, y: 0 } });
  const b = world.createBody({ type: 'dynamic', position: { x: 1, y: 0 } });
  return { world, a, b };
}

describe('the joint registry', () => {
  it('types createJoint by the definition: the joint of its type, its options only', () => {
    const { world, a, b } = twoBodies();
    const anchor = { x: 0.5, y: 0 };
    const axis = { x: 1, y: 0 };
    const revolute = world.createJoint({ type: 'revolute', bodyA: a, bodyB: b, anchor });
    expectTypeOf(revolute).toEqualTypeOf<RevoluteJoint>();
    revolute.setMotorSpeed(2);
    expect(revolute.motorSpeed).toBe(2);
    expectTypeOf(world.createJoint({ type: 'distance', bodyA: a, bodyB: b })).toEqualTypeOf<DistanceJoint>();
    expectTypeOf(
      world.createJoint({ type: 'prismatic', bodyA: a, bodyB: b, anchor, axis }),
    ).toEqualTypeOf<PrismaticJoint>();
    expectTypeOf(world.createJoint({ type: 'weld', bodyA: a, bodyB: b, anchor })).toEqualTypeOf<WeldJoint>();
    expectTypeOf(
      world.createJoint({ type: 'wheel', bodyA: a, bodyB: b, anchor, axis }),
    ).toEqualTypeOf<WheelJoint>();
    const mouse = world.createJoint({ type: 'mouse', body: b, target: { x: 2, y: 0 } });
    expectTypeOf(mouse).toEqualTypeOf<MouseJoint>();
    mouse.setTarget({ x: 3, y: 0 });
    expectTypeOf(world.createJoint({ type: 'motor', bodyA: a, bodyB: b })).toEqualTypeOf<MotorJoint>();
    // a definition whose type is not known until run time makes a Joint
    const def: JointDef = { type: 'distance', bodyA: a, bodyB: b };
    expectTypeOf(world.createJoint(def)).toMatchTypeOf<Joint>();
    expect(world.createJoint(def)).toBeInstanceOf(DistanceJoint);

    // what a definition of the type does not allow does not type check (and is refused at run time)
    // @ts-expect-error an option misspelt
    const misspelt = () => world.createJoint({ type: 'revolute', bodyA: a, bodyB: b, enableMotr: true });
    rejects(world, misspelt, /enableMotr/);
    // @ts-expect-error a prismatic joint needs its axis
    rejects(world, () => world.createJoint({ type: 'prismatic', bodyA: a, bodyB: b, anchor }), /axis/);
    // @ts-expect-error a mouse joint holds one body
    rejects(world, () => world.createJoint({ type: 'mouse', body: b, target: anchor, bodyA: a }), /bodyA/);
    // @ts-expect-error no such type
    rejects(world, () => world.createJoint({ type: 'hinge', bodyA: a, bodyB: b }), /hinge/);
    // @ts-expect-error a revolute joint has no motor force (a prismatic one has)
    const otherType = () => world.createJoint({ type: 'revolute', bodyA: a, bodyB: b, maxMotorForce: 1 });
    rejects(world, otherType, /maxMotorForce/);
  });

  it('lists every type, each with its class, and names them all when a type is unknown', () => {
    const types: JointType[] = ['distance', 'revolute', 'prismatic', 'weld', 'wheel', 'mouse', 'motor'];
    expect(Object.keys(JOINT_KINDS)).toEqual(types);
    const classes = [
      DistanceJoint,
      RevoluteJoint,
      PrismaticJoint,
      WeldJoint,
      WheelJoint,
      MouseJoint,
      MotorJoint,
    ];
    expect(types.map((type) => JOINT_KINDS[type].jointClass)).toEqual(classes);
    // the snapshot's names of the classes, which are in its bytes
    expect(types.map((type) => JOINT_KINDS[type].className)).toEqual(classes.map((c) => c.name));
    const { world, a, b } = twoBodies();
    for (const joint of types.map((type) => JOINT_KINDS[type]))
      expect(Object.isFrozen(joint.keys)).toBe(true);
    rejects(
      world,
      () => world.createJoint({ type: 'hinge', bodyA: a, bodyB: b } as never),
      /^type must be 'distance', 'revolute', 'prismatic', 'weld', 'wheel', 'mouse' or 'motor', got "hinge"$/,
    );
  });

  it('refuses a type named like a property every object has, with a FulcrumError', () => {
    const { world, a, b } = twoBodies();
    for (const type of ['toString', 'constructor', '__proto__', 'hasOwnProperty']) {
      rejects(world, () => world.createJoint({ type, bodyA: a, bodyB: b } as never), /^type must be /);
    }
  });
});
