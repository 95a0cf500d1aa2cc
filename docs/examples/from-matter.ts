// #region example
import { type Body, Shape, type Vec2, World } from 'fulcrum';

// matter.js works in pixels with y down; Fulcrum in metres with y up. matter's default gravity,
// 1000 px/s², is Fulcrum's 10 m/s² at 100 px to the metre, so that scale keeps a scene's timing.
const SCALE = 100; // matter pixels per metre
const HEIGHT = 600; // the canvas height in pixels

const toWorld = (x: number, y: number): Vec2 => ({ x: x / SCALE, y: (HEIGHT - y) / SCALE });
const toPixels = (p: Vec2): Vec2 => ({ x: p.x * SCALE, y: HEIGHT - p.y * SCALE });

// const engine = Engine.create();
const world = new World({ gravity: { x: 0, y: -10 } });

// Bodies.rectangle(400, 590, 800, 20, { isStatic: true }): x, y is the centre, then full sizes
const ground = world.createBody({ position: toWorld(400, 590) });
ground.createShape(Shape.box(800 / 2 / SCALE, 20 / 2 / SCALE));

// Bodies.circle(400, 100, 20, { restitution: 0.5, friction: 0.1 }) and Composite.add(...):
// Fulcrum's bodies are in the world as soon as they are created.
const ball = world.createBody({ type: 'dynamic', position: toWorld(400, 100) });
ball.createShape(Shape.circle(20 / SCALE), { restitution: 0.5, friction: 0.1 });

// Body.setVelocity(ball, { x: 2, y: 0 }): matter's velocity is pixels per 1/60 s step, y down
const setVelocityFromMatter = (body: Body, v: Vec2) =>
  body.setLinearVelocity({ x: (v.x * 60) / SCALE, y: (-v.y * 60) / SCALE });
setVelocityFromMatter(ball, { x: 2, y: 0 });

// Events.on(engine, 'collisionStart', ...) is world.on('contactBegin', ...), one event per pair
let landedAt: Vec2 | null = null;
world.on('contactBegin', (e) => {
  if (landedAt === null && (e.bodyA === ball || e.bodyB === ball)) landedAt = toPixels(ball.position);
});

// Engine.update(engine, 1000 / 60) is world.step(1 / 60): seconds, not milliseconds
for (let i = 0; i < 60; i++) world.step(1 / 60);
// draw at toPixels(body.position), rotated by -body.angle (matter's angles turn clockwise)
// it falls 4.7 m in sqrt(2 x 4.7 / 10) = 0.97 s, moving 120 px/s sideways: x 400 + 116 = 516, and
// y 560, its centre 20 px above the ground's top
console.log(landedAt);

// #endregion example

export { ball, landedAt, toPixels, toWorld };
