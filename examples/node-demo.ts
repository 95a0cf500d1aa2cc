/**
 * `npm start` until the browser gallery exists: drops a pyramid of 210 boxes, steps it for three
 * seconds and prints its state and the time per step.
 */
import { Shape, World } from '../src/index';

const world = new World();
const ground = world.createBody({ position: { x: 0, y: -1 } });
ground.createShape(Shape.box(30, 1));
const base = 20;
for (let row = 0; row < base; row++) {
  for (let i = 0; i < base - row; i++) {
    const box = world.createBody({
      type: 'dynamic',
      position: { x: i - (base - row - 1) / 2, y: 0.5 + row + 0.2 },
    });
    box.createShape(Shape.box(0.5, 0.5));
  }
}
const ball = world.createBody({
  type: 'dynamic',
  position: { x: -25, y: 2 },
  linearVelocity: { x: 30, y: 3 },
});
ball.createShape(Shape.circle(0.6), { density: 10 });

let hits = 0;
world.on('contactBegin', () => hits++);
const steps = 180;
const start = performance.now();
for (let i = 1; i <= steps; i++) {
  world.step(1 / 60);
  if (i % 30 === 0) {
    const p = ball.position;
    console.log(
      `t=${(i / 60).toFixed(1)} s  ball (${p.x.toFixed(2)}, ${p.y.toFixed(2)})  awake ${world.awakeBodyCount}/${world.bodyCount}  contacts ${world.contactCount}`,
    );
  }
}
const ms = (performance.now() - start) / steps;
console.log(
  `${world.bodyCount} bodies, ${hits} contacts began, ${ms.toFixed(2)} ms per step (Node ${process.version})`,
);
