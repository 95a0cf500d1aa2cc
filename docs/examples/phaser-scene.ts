// The members of Phaser this example uses (Phaser is not a dependency of Fulcrum; in a Phaser project
// `scene` is your Phaser.Scene and these come from Phaser's own types).
export interface GameObjectLike {
  setPosition(x: number, y: number): unknown;
  setRotation(radians: number): unknown;
}
export interface SceneLike {
  add: { rectangle(x: number, y: number, width: number, height: number, color: number): GameObjectLike };
}

// #region example
import { type Body, Shape, World } from 'fulcrum';

const SCALE = 50; // pixels per metre
const HEIGHT = 600; // the game's height in pixels: world y = 0 is the bottom edge

export function createPhysics(scene: SceneLike) {
  const world = new World();
  const ground = world.createBody({ position: { x: 8, y: 0.5 } });
  ground.createShape(Shape.box(8, 0.5));
  scene.add.rectangle(8 * SCALE, HEIGHT - 0.5 * SCALE, 16 * SCALE, SCALE, 0x888888);

  const sprites = new Map<Body, GameObjectLike>();
  for (let i = 0; i < 10; i++) {
    const crate = world.createBody({ type: 'dynamic', position: { x: 6 + (i % 3), y: 2 + i }, angle: i });
    crate.createShape(Shape.box(0.4, 0.4));
    sprites.set(crate, scene.add.rectangle(0, 0, 0.8 * SCALE, 0.8 * SCALE, 0xd08040));
  }

  // Call from the scene's update(time, delta): fixed steps, then sprites follow their bodies.
  let accumulator = 0;
  function update(deltaMs: number) {
    accumulator = Math.min(accumulator + deltaMs / 1000, 0.25);
    while (accumulator >= 1 / 60) {
      world.step(1 / 60);
      accumulator -= 1 / 60;
    }
    for (const [body, sprite] of sprites) {
      const p = body.position;
      sprite.setPosition(p.x * SCALE, HEIGHT - p.y * SCALE);
      sprite.setRotation(-body.angle); // Phaser's angles turn clockwise, y down
    }
  }
  return { world, sprites, update };
}
// In a Phaser.Scene: create() { this.physics2d = createPhysics(this); }
//                    update(time, delta) { this.physics2d.update(delta); }
// #endregion example
