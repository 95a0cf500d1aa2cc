import { describe, expect, it } from 'vitest';
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { bridge, carOnHills, newtonsCradle, ragdolls, slingshot } from '../../scenes/index';
import { run } from '../helpers/world';

describe('jointed scenes', () => {
  it('the car drives 20 m over bumpy ground without flipping', () => {
    const { world, bodies } = buildFulcrumWorld(carOnHills());
    const chassis = bodies[1];
    let worstTilt = 0;
    run(world, 8, () => {
      worstTilt = Math.max(worstTilt, Math.abs(chassis.angle));
    });
    expect(chassis.position.x).toBeGreaterThan(20);
    expect(worstTilt).toBeLessThan(Math.PI / 4);
    // the wheels stay on their axles: the suspension travel is small
    for (const joint of world.joints) expect(Math.abs(joint.anchorA.x - joint.anchorB.x)).toBeLessThan(0.02);
  });

  it("Newton's cradle passes the momentum through to the last ball", () => {
    const { world, bodies } = buildFulcrumWorld(newtonsCradle());
    const first = bodies[1];
    const last = bodies[5];
    // the pulled ball starts level with the frame, 2 m above its rest height: with restitution 1 the
    // last ball must rise (almost) as high while the first one stops
    let lastTop = 0;
    let firstSpeedAfter = 0;
    run(world, 2, (t) => {
      lastTop = Math.max(lastTop, last.position.y - 2);
      if (t > 1) firstSpeedAfter = Math.max(firstSpeedAfter, Math.abs(first.linearVelocity.x));
    });
    expect(lastTop).toBeGreaterThan(0.9 * 2);
    expect(firstSpeedAfter).toBeLessThan(0.5);
  });

  it('ragdolls and the slingshot settle and fall asleep; the bridge holds its joints', () => {
    for (const scene of [ragdolls(), slingshot(), bridge()]) {
      const { world } = buildFulcrumWorld(scene);
      let worst = 0;
      run(world, 8, (t) => {
        // ragdolls land hard; their joints are judged once they lie still
        if (scene.name === 'ragdolls' && t < 6) return;
        for (const joint of world.joints) {
          if (joint.type !== 'revolute') continue;
          const a = joint.anchorA;
          const b = joint.anchorB;
          worst = Math.max(worst, Math.hypot(a.x - b.x, a.y - b.y));
        }
      });
      expect(worst).toBeLessThan(0.02);
      // the rope bridge has no damping and is still swinging after 8 s
      if (scene.name !== 'bridge') expect(world.awakeBodyCount).toBe(0);
    }
  });
});
