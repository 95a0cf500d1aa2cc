// #region example
import { Shape, World } from 'fulcrum';

const world = new World({ gravity: { x: 0, y: -10 } });
const ground = world.createBody();
ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));

// A ball whose bottom starts 5 m above the ground: it lands at sqrt(2 g h) = 10 m/s.
const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 5.5 } });
ball.createShape(Shape.circle(0.5), { enableHitEvents: true });

const log: string[] = [];
const hitSpeeds: number[] = [];
world.on('contactBegin', (e) => log.push(`begin, normal ${e.normal.x} ${e.normal.y}`));
world.on('contactHit', (e) => hitSpeeds.push(e.approachSpeed));
world.on('sleep', (e) => log.push(`sleep ${e.body === ball}`));

for (let i = 0; i < 240; i++) world.step(1 / 60);

// The same events are readable as arrays after each step, until the next step:
world.step(1 / 60);
console.log(world.events.contactBegin.length, log, hitSpeeds); // 0, [begin..., sleep true], [~10]

// #endregion example

export { ball, hitSpeeds, log, world };
