// #region example
import { Shape, World } from 'fulcrum';

// planck: const world = new World({ gravity: Vec2(0, -10) });
const world = new World({ gravity: { x: 0, y: -10 } }); // subSteps: 4 replaces velocity/position iterations

// planck: world.createBody().createFixture(new Edge(Vec2(-40, 0), Vec2(40, 0)), 0);
const ground = world.createBody();
ground.createShape(Shape.segment({ x: -40, y: 0 }, { x: 40, y: 0 }));

// planck: world.createDynamicBody(Vec2(0, 4)).createFixture(new Box(1, 1), { density: 1, friction: 0.3 });
const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 4 } });
box.createShape(Shape.box(1, 1), { density: 1, friction: 0.3 }); // fixture -> shape; half extents as in Box2D

// planck: world.createJoint(new RevoluteJoint({ enableMotor: true, motorSpeed: 1, maxMotorTorque: 100 },
//                                             ground, wheel, Vec2(5, 1)));
const wheel = world.createBody({ type: 'dynamic', position: { x: 5, y: 1 } });
wheel.createShape(Shape.circle(0.5));
world.createJoint({
  type: 'revolute',
  bodyA: ground,
  bodyB: wheel,
  anchor: { x: 5, y: 1 },
  enableMotor: true,
  motorSpeed: 1,
  maxMotorTorque: 100,
});

// planck: world.on('begin-contact', (contact) => ...) runs inside the step; Fulcrum's handlers run
// after it, with shapes and bodies named: { shapeA, shapeB, bodyA, bodyB, normal, points }
let contacts = 0;
world.on('contactBegin', () => contacts++);

// planck: world.step(1 / 60, 8, 3)
for (let i = 0; i < 120; i++) world.step(1 / 60);
console.log(box.position.y, wheel.angularVelocity, contacts); // 1 (resting on the edge), 1 rad/s, 1

// #endregion example

export { box, contacts, wheel };
