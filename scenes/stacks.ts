/** Vertical stack, high mass ratio and mixed-shapes stack: small scenes for stability and determinism tests. */
import { dynamicBody, GRAVITY, groundBody, regularPolygon } from './common';
import type { Scene, SceneBody } from './types';

/** `count` boxes of 1 m (1 kg each) stacked on a static ground whose top is y = 0 */
export function verticalStack({ count = 20 }: { count?: number } = {}): Scene {
  const bodies: SceneBody[] = [groundBody(20)];
  for (let i = 0; i < count; i++) {
    bodies.push(dynamicBody({ x: 0, y: 0.5 + i }, { kind: 'box', halfWidth: 0.5, halfHeight: 0.5 }, 'box'));
  }
  return {
    name: 'vertical-stack',
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: count / 2 }, halfHeight: count / 2 + 2 },
  };
}

/** a 100 kg box resting on a 1 kg box of the same size (1 m) on the ground */
export function highMassRatio(): Scene {
  return {
    name: 'mass-ratio',
    gravity: GRAVITY,
    bodies: [
      groundBody(10),
      dynamicBody({ x: 0, y: 0.5 }, { kind: 'box', halfWidth: 0.5, halfHeight: 0.5, density: 1 }, 'light'),
      dynamicBody({ x: 0, y: 1.5 }, { kind: 'box', halfWidth: 0.5, halfHeight: 0.5, density: 100 }, 'heavy'),
    ],
    joints: [],
    view: { center: { x: 0, y: 1 }, halfHeight: 3 },
  };
}

/**
 * Columns of mixed shapes (box, capsule, hexagon, circle, rounded triangle) that topple into each
 * other: every shape pair meets, so the determinism test covers all manifold functions.
 */
export function mixedShapesStack({
  columns = 4,
  height = 6,
}: {
  columns?: number;
  height?: number;
} = {}): Scene {
  const bodies: SceneBody[] = [groundBody(20)];
  const kinds = 5;
  for (let c = 0; c < columns; c++) {
    for (let i = 0; i < height; i++) {
      const x = (c - (columns - 1) / 2) * 1.5 + 0.1 * i;
      const y = 0.55 + 1.1 * i;
      switch ((c + i) % kinds) {
        case 0:
          bodies.push(dynamicBody({ x, y }, { kind: 'box', halfWidth: 0.5, halfHeight: 0.4 }, 'box'));
          break;
        case 1:
          bodies.push(
            dynamicBody(
              { x, y },
              { kind: 'capsule', p1: { x: -0.3, y: 0 }, p2: { x: 0.3, y: 0 }, radius: 0.2 },
              'capsule',
            ),
          );
          break;
        case 2:
          bodies.push(dynamicBody({ x, y }, { kind: 'polygon', points: regularPolygon(6, 0.5) }, 'hexagon'));
          break;
        case 3:
          bodies.push(dynamicBody({ x, y }, { kind: 'circle', radius: 0.45, restitution: 0.2 }, 'circle'));
          break;
        default:
          bodies.push(
            dynamicBody(
              { x, y },
              { kind: 'polygon', points: regularPolygon(3, 0.35), radius: 0.05 },
              'triangle',
              0.3,
            ),
          );
      }
    }
  }
  return {
    name: 'mixed-stack',
    gravity: GRAVITY,
    bodies,
    joints: [],
    view: { center: { x: 0, y: height / 2 }, halfHeight: height },
  };
}
