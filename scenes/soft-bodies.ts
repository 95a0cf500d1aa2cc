/**
 * Soft things built from rigid bodies and springs: a cloth (a grid of small circles linked by soft
 * distance joints, pinned along its top edge) and soft blobs (rings of circles on springs to a centre).
 */
import { GRAVITY, groundBody } from './common';
import type { Scene, SceneBody, SceneJoint, V } from './types';

export interface ClothOptions {
  /** circles across and down */
  columns?: number;
  rows?: number;
  /** distance between neighbouring circles, m */
  spacing?: number;
  /** radius of each circle, m (less than half the spacing, so neighbours do not touch) */
  radius?: number;
  /** stiffness of the springs along the rows and columns, Hz */
  hertz?: number;
  dampingRatio?: number;
  /** stiffness of the diagonal (shear) springs, Hz; 0 leaves them out */
  shearHertz?: number;
  /** world point of the top-left circle */
  topLeft?: V;
  /** pin every `pinEvery`-th circle of the top row (and always the two corners) */
  pinEvery?: number;
}

/**
 * Adds a cloth to `bodies` and `joints`. The pinned circles of the top row are static; the rest are
 * dynamic. Returns the body index of cell (row, column): `first + row * columns + column`.
 */
export function addCloth(
  bodies: SceneBody[],
  joints: SceneJoint[],
  {
    columns = 16,
    rows = 12,
    spacing = 0.4,
    radius = 0.1,
    hertz = 20,
    dampingRatio = 0.4,
    shearHertz = 6,
    topLeft = { x: (-(columns - 1) * spacing) / 2, y: 9 },
    pinEvery = 3,
  }: ClothOptions = {},
): number {
  const first = bodies.length;
  const index = (row: number, column: number) => first + row * columns + column;
  for (let row = 0; row < rows; row++) {
    for (let column = 0; column < columns; column++) {
      const pinned = row === 0 && (column % pinEvery === 0 || column === columns - 1);
      bodies.push({
        type: pinned ? 'static' : 'dynamic',
        position: { x: topLeft.x + column * spacing, y: topLeft.y - row * spacing },
        shapes: [{ kind: 'circle', radius, density: 2, friction: 0.4 }],
        tag: pinned ? 'pin' : 'cloth',
      });
    }
  }
  const link = (a: number, b: number, rest: number, hz: number) => {
    const pa = bodies[a].position;
    const pb = bodies[b].position;
    joints.push({
      type: 'distance',
      bodyA: a,
      bodyB: b,
      anchorA: pa,
      anchorB: pb,
      length: rest,
      spring: { hertz: hz, dampingRatio },
    });
  };
  const diagonal = spacing * Math.SQRT2;
  for (let row = 0; row < rows; row++) {
    for (let column = 0; column < columns; column++) {
      const self = index(row, column);
      if (column > 0) link(index(row, column - 1), self, spacing, hertz);
      if (row > 0) link(index(row - 1, column), self, spacing, hertz);
      if (shearHertz > 0 && row > 0 && column > 0) {
        link(index(row - 1, column - 1), self, diagonal, shearHertz);
        link(index(row - 1, column), index(row, column - 1), diagonal, shearHertz);
      }
    }
  }
  return first;
}

/** A cloth hanging from pins over the ground, and a few balls to drop on it. */
export function cloth(options: ClothOptions = {}): Scene {
  const bodies: SceneBody[] = [groundBody(20)];
  const joints: SceneJoint[] = [];
  addCloth(bodies, joints, options);
  return {
    name: 'cloth',
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: 5 }, halfHeight: 6 },
  };
}

export interface BlobOptions {
  /** circles around the rim */
  segments?: number;
  /** radius of the rim (through the circles' centres), m */
  radius?: number;
  /** stiffness of the spokes (rim to centre), Hz */
  hertz?: number;
  /** stiffness of the rim (neighbour to neighbour), Hz */
  rimHertz?: number;
  dampingRatio?: number;
  density?: number;
}

/**
 * Adds one soft blob centred on `center`: a centre disc and a ring of circles, each circle on a spring
 * to the centre and to its two neighbours. Returns the body index of the centre.
 */
export function addBlob(
  bodies: SceneBody[],
  joints: SceneJoint[],
  center: V,
  {
    segments = 20,
    radius = 1.1,
    hertz = 4,
    rimHertz = 12,
    dampingRatio = 0.5,
    density = 1,
  }: BlobOptions = {},
): number {
  const hub = bodies.length;
  bodies.push({
    type: 'dynamic',
    position: center,
    shapes: [{ kind: 'circle', radius: radius * 0.3, density }],
    tag: 'blob-centre',
  });
  // rim circles just short of touching their neighbours
  const pitch = 2 * radius * Math.sin(Math.PI / segments);
  const rimRadius = pitch * 0.48;
  for (let i = 0; i < segments; i++) {
    const a = (2 * Math.PI * i) / segments;
    bodies.push({
      type: 'dynamic',
      position: { x: center.x + radius * Math.cos(a), y: center.y + radius * Math.sin(a) },
      shapes: [{ kind: 'circle', radius: rimRadius, density, friction: 0.8 }],
      tag: 'blob-rim',
    });
  }
  for (let i = 0; i < segments; i++) {
    const self = hub + 1 + i;
    const next = hub + 1 + ((i + 1) % segments);
    joints.push({
      type: 'distance',
      bodyA: hub,
      bodyB: self,
      anchorA: center,
      anchorB: bodies[self].position,
      length: radius,
      spring: { hertz, dampingRatio },
    });
    joints.push({
      type: 'distance',
      bodyA: self,
      bodyB: next,
      anchorA: bodies[self].position,
      anchorB: bodies[next].position,
      length: pitch,
      spring: { hertz: rimHertz, dampingRatio },
    });
  }
  return hub;
}

/** `count` soft blobs dropped onto a ramp and a floor. */
export function softBlobs({ count = 4, ...options }: BlobOptions & { count?: number } = {}): Scene {
  const bodies: SceneBody[] = [groundBody(20)];
  const joints: SceneJoint[] = [];
  // the ground body sits at y = -0.5: its shapes' centres are relative to that
  bodies[0].shapes.push(
    { kind: 'box', halfWidth: 4, halfHeight: 0.2, center: { x: -5, y: 4.5 }, angle: -0.3, friction: 0.6 },
    { kind: 'box', halfWidth: 3, halfHeight: 0.2, center: { x: 4, y: 2.7 }, angle: 0.25, friction: 0.6 },
  );
  for (let i = 0; i < count; i++) addBlob(bodies, joints, { x: -7 + 3 * i, y: 8 + 2.5 * (i % 2) }, options);
  return {
    name: 'soft-blobs',
    gravity: GRAVITY,
    bodies,
    joints,
    view: { center: { x: 0, y: 5 }, halfHeight: 6.5 },
  };
}
