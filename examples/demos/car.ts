import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { carOnHills } from '../../scenes/index';
import { type Body, Shape, type Vec2, type WheelJoint } from '../../src/index';
import type { Demo } from '../demo';
import { followWithCamera, onKeys } from '../lib';

const LENGTH = 60;
/** wheel speed of the motors, rad/s (negative turns the wheels clockwise: forward) */
const SPEED = 14;
const TORQUE = 40;
type Drive = 'forward' | 'back' | 'brake' | 'coast';

export const carDemo: Demo = {
  id: 'car',
  title: 'Car on hills',
  description:
    'A chassis on two wheel joints: a spring along the suspension axis and a motor turning each wheel (scenes/joint-scenes.ts), over bumps and up a hill. Drive with the arrow keys (or A and D; B brakes) or the buttons.',
  view: { center: { x: 2, y: 2 }, halfHeight: 4.5 },
  create: (ctx) => {
    const scene = carOnHills({ length: LENGTH, motorSpeed: -SPEED });
    const { world, bodies, joints } = buildFulcrumWorld(scene);
    const [ground, chassis, ...wheels] = bodies;
    // walls at both ends, and a few rocks to climb
    ground.createShape(Shape.segment({ x: -10, y: 0 }, { x: -10, y: 6 }));
    ground.createShape(Shape.segment({ x: LENGTH + 20, y: 3 }, { x: LENGTH + 20, y: 9 }));
    for (const [x, r] of [
      [14, 0.5],
      [26, 0.8],
      [38, 0.6],
      [39.2, 0.5],
    ]) {
      ground.createShape(
        Shape.polygon([
          { x: x - 2 * r, y: 0 },
          { x: x + 2 * r, y: 0 },
          { x: x + r, y: r },
          { x: x - r, y: r },
        ]),
      );
    }
    ctx.render.setBodyStyle(chassis, { color: 0xd9695f });
    for (const wheel of wheels) ctx.render.setBodyStyle(wheel, { color: 0x7b8494 });
    // the wheel joints cannot change their motor after creation: a new drive rebuilds them on the
    // same local anchors, so the suspension keeps its rest length
    let wheelJoints = joints as WheelJoint[];
    const anchors = wheels.map((wheel) => chassis.getLocalPoint(wheel.position));
    let drive: Drive = 'forward';
    const setDrive = (next: Drive) => {
      if (next === drive) return;
      drive = next;
      for (const joint of wheelJoints) if (joint.isValid) world.destroyJoint(joint);
      const speed = next === 'forward' ? -SPEED : next === 'back' ? SPEED : 0;
      wheelJoints = wheels.map(
        (wheel: Body, i) =>
          world.createJoint({
            type: 'wheel',
            bodyA: chassis,
            bodyB: wheel,
            localAnchorA: anchors[i],
            localAnchorB: { x: 0, y: 0 },
            axis: chassis.getWorldVector({ x: 0, y: 1 }),
            enableSpring: true,
            hertz: 4,
            dampingRatio: 0.7,
            enableMotor: next !== 'coast',
            motorSpeed: speed,
            maxMotorTorque: next === 'brake' ? TORQUE * 2 : TORQUE,
          }) as WheelJoint,
      );
      chassis.setAwake(true);
      ctx.setStatus(`drive: ${next}`);
    };
    ctx.setStatus('drive: forward');
    ctx.button('◀ Back', () => setDrive('back'));
    ctx.button('Brake', () => setDrive('brake'));
    ctx.button('Coast', () => setDrive('coast'));
    ctx.button('Forward ▶', () => setDrive('forward'));
    if (!ctx.preview)
      ctx.track(
        onKeys(['ArrowLeft', 'ArrowRight', 'a', 'd', 'b'], (key, down) => {
          if (!down) setDrive('coast');
          else if (key === 'ArrowRight' || key === 'd') setDrive('forward');
          else if (key === 'ArrowLeft' || key === 'a') setDrive('back');
          else setDrive('brake');
        }),
      );
    let follow = true;
    const followButton = ctx.button('Camera: follow', () => {
      follow = !follow;
      followButton.textContent = follow ? 'Camera: follow' : 'Camera: free';
    });
    // the earth under the ground's segments (the scene's data gives their end points)
    const outline: Vec2[] = [];
    for (const shape of scene.bodies[0].shapes)
      if (shape.kind === 'segment') outline.push(shape.p1, shape.p2);
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        render.setWorldTransform();
        const context = render.context;
        context.fillStyle = '#2b3226';
        context.beginPath();
        context.moveTo(outline[0].x, -30);
        for (const p of outline) context.lineTo(p.x, p.y);
        context.lineTo(outline[outline.length - 1].x, -30);
        context.closePath();
        context.fill();
        render.setScreenTransform();
      }),
    );
    // keep the car a third of the way across, looking ahead
    const camera = ctx.render.camera;
    ctx.track(
      followWithCamera(
        ctx,
        world,
        () => ({ x: chassis.position.x + camera.halfHeight * 0.5, y: chassis.position.y + 1 }),
        0.1,
        () => follow,
      ),
    );
    return { world, chassis, wheels, drive: () => drive };
  },
};
