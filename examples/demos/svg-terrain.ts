import { type Body, parseSvgPath, Shape, type Vec2, type WheelJoint, World } from '../../src/index';
import type { Demo } from '../demo';
import { followWithCamera, onKeys } from '../lib';
import LEVEL from './svg-terrain.svg?raw';

/**
 * The level as an artist would draw it, in an SVG file: the ground is a path in pixels, y down, with
 * every kind of curve (cubic, smooth cubic, quadratic, smooth quadratic, an arc for the dip); the
 * car's body is a closed concave outline (hood, windscreen, roof, boot).
 */
function pathData(id: string): string {
  const d = new DOMParser().parseFromString(LEVEL, 'image/svg+xml').getElementById(id)?.getAttribute('d');
  if (!d) throw new Error(`svg-terrain.svg has no path #${id}`);
  return d;
}

const PIXELS_PER_METRE = 40;
const SPEED = 16;
const TORQUE = 30;

export const svgTerrainDemo: Demo = {
  id: 'svg-terrain',
  title: 'Terrain from SVG',
  description:
    'The level is an SVG file: its ground path (curves, an arc) is read by parseSvgPath and laid as a smooth chain, the car body is a concave outline from the same file. Wheels roll over hundreds of seams without a bump. Drive with the arrow keys or the buttons.',
  view: { center: { x: 8, y: 1 }, halfHeight: 6 },
  create: (ctx) => {
    const world = new World();
    const options = { scale: 1 / PIXELS_PER_METRE, flipY: true, tolerance: 1 };
    const [terrain] = parseSvgPath(pathData('ground'), options);
    // drawn left to right, so reversed: a chain faces right of the way its points run
    const ground = world.createBody({ position: { x: 0, y: 7.5 } });
    const segments = ground.createShape(Shape.chain([...terrain.points].reverse()), { friction: 0.9 });

    const [outline] = parseSvgPath(pathData('car-body'), { scale: 1 / 60, flipY: true, tolerance: 1 });
    const chassis = world.createBody({ type: 'dynamic', position: { x: 3, y: 1.6 } });
    chassis.createShape(Shape.concave(outline.points), { density: 2 });
    const wheels: Body[] = [];
    for (const x of [-0.95, 1.0]) {
      const wheel = world.createBody({ type: 'dynamic', position: { x: 3 + x, y: 1.0 } });
      wheel.createShape(Shape.circle(0.38), { friction: 1.2, density: 1.5 });
      wheels.push(wheel);
    }
    let motorSpeed = -SPEED;
    const joints = wheels.map(
      (wheel) =>
        world.createJoint({
          type: 'wheel',
          bodyA: chassis,
          bodyB: wheel,
          localAnchorA: chassis.getLocalPoint(wheel.position),
          localAnchorB: { x: 0, y: 0 },
          axis: { x: 0, y: 1 },
          enableSpring: true,
          hertz: 4,
          dampingRatio: 0.7,
          enableMotor: true,
          motorSpeed,
          maxMotorTorque: TORQUE,
        }) as WheelJoint,
    );
    const drive = (speed: number) => {
      motorSpeed = speed;
      for (const joint of joints) joint.setMotorSpeed(speed);
      chassis.setAwake(true);
      ctx.setStatus(speed < 0 ? 'drive: forward' : speed > 0 ? 'drive: back' : 'drive: brake');
    };
    ctx.setStatus('drive: forward');
    ctx.button('◀ Back', () => drive(SPEED));
    ctx.button('Brake', () => drive(0));
    ctx.button('Forward ▶', () => drive(-SPEED));
    if (!ctx.preview)
      ctx.track(
        onKeys(['ArrowLeft', 'ArrowRight', 'a', 'd'], (key, down) => {
          if (!down) drive(0);
          else drive(key === 'ArrowRight' || key === 'd' ? -SPEED : SPEED);
        }),
      );
    ctx.render.setBodyStyle(chassis, { color: 0xe0a33a });
    for (const wheel of wheels) ctx.render.setBodyStyle(wheel, { color: 0x3c4250 });

    // the earth under the chain, and the camera following the car
    const earth: Vec2[] = terrain.points.map((p) => ({ x: p.x, y: p.y + 7.5 }));
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        render.setWorldTransform();
        const context = render.context;
        const sky = context.createLinearGradient(0, 12, 0, -4);
        sky.addColorStop(0, '#16243a');
        sky.addColorStop(1, '#2a3f5c');
        context.fillStyle = sky;
        context.fillRect(-20, -20, 100, 40);
        const soil = context.createLinearGradient(0, 4, 0, -6);
        soil.addColorStop(0, '#4f7a3a');
        soil.addColorStop(0.08, '#5b4531');
        soil.addColorStop(1, '#2c2219');
        context.fillStyle = soil;
        context.beginPath();
        context.moveTo(earth[0].x, -20);
        for (const p of earth) context.lineTo(p.x, p.y);
        context.lineTo(earth[earth.length - 1].x, -20);
        context.closePath();
        context.fill();
        render.setScreenTransform();
      }),
    );
    const camera = ctx.render.camera;
    ctx.track(
      followWithCamera(
        ctx,
        world,
        () => ({ x: chassis.position.x + camera.halfHeight * 0.4, y: chassis.position.y + 1 }),
        0.08,
      ),
    );
    return { world, chassis, wheels, segments, speed: () => motorSpeed };
  },
};
