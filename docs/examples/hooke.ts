// #region example
import { Shape, World } from 'fulcrum';

/**
 * A spring of stiffness k (N/m) and damping c (N·s/m) between bodies of masses mA and mB (0 for a
 * static body), as Fulcrum's hertz and dampingRatio.
 */
export function springFromHooke(k: number, c: number, massA: number, massB: number) {
  const m = massA === 0 ? massB : massB === 0 ? massA : (massA * massB) / (massA + massB);
  return { hertz: Math.sqrt(k / m) / (2 * Math.PI), dampingRatio: c / (2 * Math.sqrt(k * m)) };
}

const world = new World({ gravity: { x: 0, y: -10 } });
const hook = world.createBody({ position: { x: 0, y: 5 } });
const weight = world.createBody({ type: 'dynamic', position: { x: 0, y: 4 } });
weight.createShape(Shape.box(0.25, 0.25), { density: 8 }); // 0.5 m x 0.5 m x 8 kg/m²: 2 kg

// k = 200 N/m, c = 20 N·s/m, rest length 1 m: it hangs mg / k = 20 / 200 = 0.1 m lower.
const { hertz, dampingRatio } = springFromHooke(200, 20, 0, weight.mass);
world.createJoint({
  type: 'distance',
  bodyA: hook,
  bodyB: weight,
  length: 1,
  enableSpring: true,
  hertz,
  dampingRatio,
});

for (let i = 0; i < 600; i++) world.step(1 / 60);
console.log(hertz, dampingRatio, weight.position.y); // 1.59 Hz, 0.5, 3.9 (stretched by 0.1 m)

// #endregion example

export { dampingRatio, hertz, weight };
