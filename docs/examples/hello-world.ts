// #region example
import { Shape, World } from 'fulcrum';

const world = new World({ gravity: { x: 0, y: -10 } });

const ground = world.createBody({ position: { x: 0, y: -1 } }); // static by default
ground.createShape(Shape.box(20, 1));

const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 4 } });
ball.createShape(Shape.circle(0.5), { density: 1, friction: 0.6, restitution: 0.5 });

let touches = 0;
world.on('contactBegin', () => touches++);

for (let i = 0; i < 180; i++) world.step(1 / 60); // three seconds
console.log(ball.position, touches); // y 0.5 to a tenth of a millimetre; 4 touches (it bounces)

// #endregion example

export { ball, touches, world };
