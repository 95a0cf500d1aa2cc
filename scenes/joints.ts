/** Jointed scenes: a grid of circles linked by revolute joints, and a long chain holding a heavy ball. */
import { GRAVITY } from './common';
import type { Scene, SceneBody, SceneJoint } from './types';

/** the grid's circles do not collide with each other (category 2, mask all but 2), as in Box2D's */
const NODE_FILTER = { categoryBits: 2, maskBits: 0xffff & ~2 };

/**
 * `size` x `size` dynamic circles (radius 0.4, density 1) 1 m apart, each linked to its right and
 * lower neighbours by revolute joints at the midpoint; the top row is pinned at the circles' centres
 * to one static body. Body index of cell (row, column) is 1 + row * size + column.
 */
export function jointGrid({ size = 40 }: { size?: number } = {}): Scene {
  const anchor: SceneBody = { type: 'static', position: { x: 0, y: 0 }, shapes: [], tag: 'anchor' };
  const bodies: SceneBody[] = [anchor];
  const joints: SceneJoint[] = [];
  const top = size;
  const index = (row: number, column: number): number => 1 + row * size + column;
  for (let row = 0; row < size; row++) {
    for (let column = 0; column < size; column++) {
      const x = column;
      const y = top - row;
      bodies.push({
        type: 'dynamic',
        position: { x, y },
        shapes: [{ kind: 'circle', radius: 0.4, filter: NODE_FILTER }],
        tag: 'node',
      });
      const self = index(row, column);
      if (row === 0) joints.push({ type: 'revolute', bodyA: 0, bodyB: self, anchor: { x, y } });
      if (column > 0)
        joints.push({ type: 'revolute', bodyA: self - 1, bodyB: self, anchor: { x: x - 0.5, y } });
      if (row > 0)
        joints.push({ type: 'revolute', bodyA: self - size, bodyB: self, anchor: { x, y: y + 0.5 } });
    }
  }
  return {
    name: `joint-grid-${size}`,
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: size / 2, y: top / 2 }, halfHeight: size },
  };
}

const LINK_HALF_LENGTH = 0.25;
const LINK_HALF_THICKNESS = 0.05;
const LINK_DENSITY = 1 / (4 * LINK_HALF_LENGTH * LINK_HALF_THICKNESS); // 1 kg per link
const BALL_RADIUS = 0.5;
const BALL_MASS = 100;

/**
 * A chain of `links` boxes (0.5 m long pin to pin, 1 kg each) joined by revolute joints, hanging from
 * a static anchor at the origin and holding a 100 kg ball (radius 0.5 m) at its free end. The chain
 * starts horizontal (to the right of the anchor) and swings down.
 */
export function chain({ links = 100 }: { links?: number } = {}): Scene {
  const bodies: SceneBody[] = [{ type: 'static', position: { x: 0, y: 0 }, shapes: [], tag: 'anchor' }];
  const joints: SceneJoint[] = [];
  const pitch = 2 * LINK_HALF_LENGTH;
  for (let i = 0; i < links; i++) {
    bodies.push({
      type: 'dynamic',
      position: { x: LINK_HALF_LENGTH + i * pitch, y: 0 },
      shapes: [
        { kind: 'box', halfWidth: LINK_HALF_LENGTH, halfHeight: LINK_HALF_THICKNESS, density: LINK_DENSITY },
      ],
      tag: 'link',
    });
    joints.push({ type: 'revolute', bodyA: i, bodyB: i + 1, anchor: { x: i * pitch, y: 0 } });
  }
  const end = links * pitch;
  bodies.push({
    type: 'dynamic',
    position: { x: end + BALL_RADIUS, y: 0 },
    shapes: [
      { kind: 'circle', radius: BALL_RADIUS, density: BALL_MASS / (Math.PI * BALL_RADIUS * BALL_RADIUS) },
    ],
    tag: 'ball',
  });
  joints.push({ type: 'revolute', bodyA: links, bodyB: links + 1, anchor: { x: end, y: 0 } });
  return {
    name: `chain-${links}`,
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: -end / 2 }, halfHeight: end + 2 },
  };
}
