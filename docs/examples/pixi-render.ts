// #region example
import { type Body, Shape, World } from 'fulcrum';
import { Application, Graphics } from 'pixi.js';

const SCALE = 40; // pixels per metre

const world = new World();
const ground = world.createBody({ position: { x: 0, y: -0.5 } });
ground.createShape(Shape.box(8, 0.5));
for (let i = 0; i < 20; i++) {
  const body = world.createBody({ type: 'dynamic', position: { x: (i % 5) - 2, y: 2 + i * 0.6 } });
  body.createShape(i % 2 ? Shape.circle(0.3) : Shape.box(0.3, 0.3));
}

const app = new Application();
await app.init({ width: 800, height: 500, background: '#15171d', preference: 'webgl' });
document.getElementById('app')!.appendChild(app.canvas);

// One Graphics per body, drawn once in metres around the body's origin (y up, flipped by the scale).
const views = new Map<Body, Graphics>();
for (const body of world.bodies) {
  const g = new Graphics();
  for (const shape of body.shapes) {
    const geometry = shape.geometry;
    if (geometry.type === 'circle') g.circle(geometry.center.x, geometry.center.y, geometry.radius);
    else if (geometry.type === 'polygon') g.poly(geometry.vertices.flatMap((v) => [v.x, v.y]));
  }
  g.fill(body.type === 'dynamic' ? 0x4fa3e0 : 0x888888);
  g.scale.set(SCALE, -SCALE);
  app.stage.addChild(g);
  views.set(body, g);
}

// Every frame: one fixed step, then copy each body's position and angle into its Graphics.
let steps = 0;
app.ticker.add(() => {
  world.step(1 / 60);
  steps++;
  for (const [body, g] of views) {
    const p = body.position;
    g.position.set(400 + p.x * SCALE, 450 - p.y * SCALE);
    g.rotation = -body.angle; // y up in the world, y down on screen
  }
});

// #endregion example

export { app, steps, world };
