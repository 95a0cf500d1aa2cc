// #region example
import { Shape, World } from 'fulcrum';

const world = new World();
const ground = world.createBody();
ground.createShape(Shape.box(10, 0.5, { x: 0, y: -0.5 }));

// A sensor: it reports what enters and leaves it, and pushes nothing.
const goal = world.createBody({ position: { x: 0, y: 2 } });
goal.createShape(Shape.box(1, 1), { isSensor: true });

const visitors = new Set<string>();
world.on('sensorBegin', (e) => visitors.add(e.visitorShape.body.userData as string));

// Collision filtering: the player's category is 0x2, the ghosts' 0x4; ghosts' masks leave out other
// ghosts, so ghosts pass through each other but land on the ground and on the player. The bits are
// unsigned 32-bit integers: write 0xffffffff - GHOST, not ~GHOST (negative in JavaScript, refused).
const PLAYER = 0x2;
const GHOST = 0x4;
const player = world.createBody({ type: 'dynamic', position: { x: 0, y: 4 }, userData: 'player' });
player.createShape(Shape.box(0.4, 0.4), { filter: { categoryBits: PLAYER } });

const ghostA = world.createBody({ type: 'dynamic', position: { x: 5, y: 1 }, userData: 'ghost A' });
const ghostB = world.createBody({ type: 'dynamic', position: { x: 5, y: 3 }, userData: 'ghost B' });
for (const ghost of [ghostA, ghostB]) {
  ghost.createShape(Shape.circle(0.5), { filter: { categoryBits: GHOST, maskBits: 0xffffffff - GHOST } });
}

for (let i = 0; i < 180; i++) world.step(1 / 60);
// the player fell through the sensor; the two ghosts ended up in one place, on the ground
console.log([...visitors], ghostA.position.y, ghostB.position.y); // ['player'], 0.5, 0.5

// #endregion example

export { ghostA, ghostB, player, visitors };
