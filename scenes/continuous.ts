/**
 * Scenes for continuous collision (issue 4): things fast or thin enough to pass through walls in an
 * engine that only checks positions at the end of each step.
 */
import { GRAVITY, groundBody } from './common';
import type { Scene, SceneBody } from './types';

/**
 * A gun's volley: `bullets` balls of 0.1 m at 300 m/s (5 m per step at 60 Hz), flagged as bullets,
 * fired one step apart at `planks` thin dynamic planks (0.1 m thick, 2 m tall, 2 kg) standing on the
 * ground, with a 20 m tall static backstop behind them.
 */
export function bulletsAtPlanks(options: { bullets?: number; planks?: number } = {}): Scene {
  const bulletCount = options.bullets ?? 8;
  const plankCount = options.planks ?? 4;
  const bodies: SceneBody[] = [groundBody(40, 0, 10)];
  for (let i = 0; i < plankCount; i++) {
    bodies.push({
      type: 'dynamic',
      position: { x: 12 + 2 * i, y: 1 },
      shapes: [{ kind: 'box', halfWidth: 0.05, halfHeight: 1, density: 10 }],
      tag: 'plank',
    });
  }
  for (let i = 0; i < bulletCount; i++) {
    bodies.push({
      type: 'dynamic',
      // one behind the other, 5 m (one step) apart, at heights across the planks
      position: { x: -5 * i, y: 0.3 + ((i * 7) % 8) * 0.2 },
      linearVelocity: { x: 300, y: 0 },
      bullet: true,
      shapes: [{ kind: 'circle', radius: 0.05, density: 20 }],
      tag: 'bullet',
    });
  }
  // a tall static backstop behind the planks
  bodies.push({
    type: 'static',
    position: { x: 30, y: 10 },
    shapes: [{ kind: 'box', halfWidth: 0.05, halfHeight: 10 }],
  });
  return {
    name: 'bullets',
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 12, y: 2 }, halfHeight: 6 },
    containment: { lower: { x: -60, y: -1 }, upper: { x: 30, y: 1000 } },
  };
}

/**
 * A thin bar (2.4 m long, 4 cm thick) spinning at 50 rad/s (its tips at 60 m/s, a metre per step)
 * inside a 3 m square of 0.1 m thick static walls, with no gravity.
 */
export function spinningBar(): Scene {
  const wall = (x: number, y: number, halfWidth: number, halfHeight: number): SceneBody => ({
    type: 'static',
    position: { x, y },
    shapes: [{ kind: 'box', halfWidth, halfHeight }],
  });
  return {
    name: 'spinning-bar',
    gravity: { x: 0, y: 0 },
    bodies: [
      wall(-1.55, 0, 0.05, 1.6),
      wall(1.55, 0, 0.05, 1.6),
      wall(0, -1.55, 1.6, 0.05),
      wall(0, 1.55, 1.6, 0.05),
      {
        type: 'dynamic',
        position: { x: 0.2, y: 0 },
        angle: 0.3,
        angularVelocity: 50,
        linearVelocity: { x: 0.5, y: 0.3 },
        shapes: [{ kind: 'box', halfWidth: 1.2, halfHeight: 0.02 }],
        tag: 'bar',
      },
    ],
    joints: [],
    view: { center: { x: 0, y: 0 }, halfHeight: 2 },
    containment: { lower: { x: -1.5, y: -1.5 }, upper: { x: 1.5, y: 1.5 } },
  };
}

/**
 * Balls of 0.1 to 0.4 m released 1,000 m up, already falling at 100 m/s (as if dropped from 1,500 m):
 * they reach a 0.1 m thick ground plate at about 170 m/s, about 3 m per step.
 */
export function highDrop(): Scene {
  const bodies: SceneBody[] = [
    {
      type: 'static',
      position: { x: 0, y: -0.05 },
      shapes: [{ kind: 'box', halfWidth: 10, halfHeight: 0.05 }],
      tag: 'ground',
    },
  ];
  const radii = [0.05, 0.1, 0.15, 0.2];
  radii.forEach((radius, i) => {
    bodies.push({
      type: 'dynamic',
      position: { x: -3 + 2 * i, y: 1000 + i },
      linearVelocity: { x: 0, y: -100 },
      shapes: [{ kind: 'circle', radius, restitution: 0.3 }],
      tag: 'ball',
    });
  });
  return {
    name: 'high-drop',
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: 2 }, halfHeight: 5 },
    containment: { lower: { x: -20, y: -0.1 }, upper: { x: 20, y: 1100 } },
  };
}
