// The members of p5 (instance mode) this sketch uses. p5 is not a dependency of Fulcrum; with p5
// installed, type `p` as p5 instead.
export interface P5Like {
  setup: () => void;
  draw: () => void;
  width: number;
  height: number;
  createCanvas(width: number, height: number): unknown;
  background(gray: number): unknown;
  push(): void;
  pop(): void;
  translate(x: number, y: number): void;
  rotate(radians: number): void;
  rectMode(mode: string): void;
  rect(x: number, y: number, width: number, height: number): void;
  circle(x: number, y: number, diameter: number): void;
}

// #region example
import { type Body, Shape, World } from 'fulcrum';

const SCALE = 40; // pixels per metre

export function sketch(p: P5Like) {
  const world = new World();
  const ground = world.createBody({ position: { x: 10, y: 0.5 } });
  ground.createShape(Shape.box(10, 0.5));
  const balls: Body[] = [];
  for (let i = 0; i < 12; i++) {
    const ball = world.createBody({ type: 'dynamic', position: { x: 8 + (i % 4), y: 3 + i } });
    ball.createShape(Shape.circle(0.4), { restitution: 0.4 });
    balls.push(ball);
  }

  p.setup = () => {
    p.createCanvas(800, 400);
    p.rectMode('center');
  };

  p.draw = () => {
    world.step(1 / 60); // p5 draws at 60 frames a second by default
    p.background(240);
    p.push();
    // world metres (y up) to canvas pixels (y down): flip y, scale, origin at the bottom left
    p.translate(0, p.height);
    p.rect(ground.position.x * SCALE, -ground.position.y * SCALE, 20 * SCALE, 1 * SCALE);
    for (const ball of balls) {
      p.push();
      p.translate(ball.position.x * SCALE, -ball.position.y * SCALE);
      p.rotate(-ball.angle);
      p.circle(0, 0, 0.8 * SCALE);
      p.pop();
    }
    p.pop();
  };
  return world;
}
// With p5 loaded (a <script> tag or `import p5 from 'p5'`): new p5(sketch);
// #endregion example
