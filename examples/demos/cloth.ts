/**
 * A curtain of cloth: a grid of small circles tied by soft distance joints (scenes/soft-bodies.ts),
 * pinned along a rod, painted as a woven sheet of shaded triangles between the circles. A link
 * stretched past TEAR times its rest length is destroyed, and the triangles it bounded are no longer
 * painted: the sheet tears where it is pulled or hit too hard.
 */
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { GRAVITY, groundBody } from '../../scenes/common';
import { addCloth, type Scene, type SceneBody, type SceneJoint } from '../../scenes/index';
import {
  type Body,
  type DistanceJoint,
  type MouseJoint,
  Shape,
  type Vec2,
  type World,
} from '../../src/index';
import type { Demo } from '../demo';
import { capturePointer, drawnPosition, fillSkinnedDisc, stepHook } from '../lib';

const COLUMNS = 25;
const ROWS = 17;
const SPACING = 0.3;
const TOP_LEFT: Vec2 = { x: -3.6, y: 9 };
/** a link tears when stretched beyond this many times its rest length */
export const TEAR = 1.4;
/** the breeze's strongest push, m/s² */
const BREEZE = 2.2;
/** the hand's pull on the cloth, N: enough to tear it */
const GRAB_FORCE = 150;
/** how far from a point of the cloth a press still takes hold of it, m */
const GRAB_REACH = 0.45;

export interface ClothWorld {
  world: World;
  /** the grid's circles, row by row */
  nodes: Body[];
  /** the grid's links: along rows and columns, and both diagonals of each cell */
  links: DistanceJoint[];
  /** the link between two circles (by index in `nodes`), if it was made and is not torn */
  linkOf(a: number, b: number): DistanceJoint | undefined;
}

/** The curtain and its rod over the floor. Exported for the tests. */
export function buildCloth(): ClothWorld {
  const bodies: SceneBody[] = [groundBody(20)];
  const joints: SceneJoint[] = [];
  const first = addCloth(bodies, joints, {
    columns: COLUMNS,
    rows: ROWS,
    spacing: SPACING,
    radius: 0.09,
    hertz: 30,
    dampingRatio: 0.3,
    shearHertz: 3,
    topLeft: TOP_LEFT,
    pinEvery: 2,
  });
  const scene: Scene = { name: 'curtain', gravity: GRAVITY, bodies, joints };
  const built = buildFulcrumWorld(scene);
  const nodes = built.bodies.slice(first);
  const links = built.joints as DistanceJoint[];
  const count = nodes.length;
  const byPair = new Map<number, DistanceJoint>();
  scene.joints.forEach((joint, i) => {
    const a = joint.bodyA - first;
    const b = joint.bodyB - first;
    byPair.set(Math.min(a, b) * count + Math.max(a, b), links[i]);
  });
  const linkOf = (a: number, b: number) => {
    const link = byPair.get(Math.min(a, b) * count + Math.max(a, b));
    return link?.isValid ? link : undefined;
  };
  return { world: built.world, nodes, links, linkOf };
}

/** Destroys every link stretched past TEAR; returns how many tore. */
export function tearOverstretched(world: World, links: DistanceJoint[]): number {
  let torn = 0;
  for (const link of links) {
    if (link.isValid && link.currentLength > TEAR * link.length) {
      world.destroyJoint(link);
      torn++;
    }
  }
  return torn;
}

/** A smooth wave of period 1 between -1 and 1 (a rounded triangle wave: no Math.sin in a force). */
function wave(x: number): number {
  const t = 1 - 4 * Math.abs(x - Math.floor(x) - 0.5);
  return t * (1.5 - 0.5 * t * t);
}

/**
 * The breeze through the window: a sideways push on every circle of `nodes`, N, that swells and turns
 * every few seconds and reaches the hem a moment after the rod. Exported for the tests.
 */
export function blow(nodes: Body[], step: number): void {
  for (let i = 0; i < nodes.length; i++) {
    const node = nodes[i];
    if (node.type !== 'dynamic') continue;
    const row = Math.floor(i / COLUMNS);
    const a = BREEZE * wave(step / 420 - row * 0.02) + 0.4 * BREEZE * wave(step / 130 + (i % COLUMNS) * 0.03);
    node.applyForce({ x: node.mass * a, y: 0 });
  }
}

/** The cloth's colours: a woven stripe every few columns, lit where stretched, shaded where bunched. */
function weaveColor(column: number, row: number, light: number): string {
  const stripe = column % 6 < 2;
  // a darker band along the hem
  const hem = row >= ROWS - 3 ? 0.8 : 1;
  const r = (stripe ? 214 : 168) * hem;
  const g = (stripe ? 182 : 44) * hem;
  const b = (stripe ? 104 : 58) * hem;
  const k = Math.max(0.45, Math.min(1.25, light));
  return `rgb(${Math.round(Math.min(255, r * k))}, ${Math.round(Math.min(255, g * k))}, ${Math.round(Math.min(255, b * k))})`;
}

export const clothDemo: Demo = {
  id: 'cloth',
  title: 'Cloth',
  description: `A curtain of 425 small circles tied to their neighbours by soft distance joints (scenes/soft-bodies.ts), pinned along its rod, swaying in a breeze (body.applyForce) and painted as a woven sheet between the circles. A link stretched past ${TEAR} times its length is destroyed (world.destroyJoint) and the sheet tears there. Drag the cloth hard or throw a ball into it; the shapes switch shows the circles.`,
  view: { center: { x: 0, y: 5.4 }, halfHeight: 5 },
  fitWidth: 4.5,
  flags: { shapes: false, joints: false, sleeping: false },
  create: (ctx) => {
    const { world, nodes, links, linkOf } = buildCloth();
    const balls: Body[] = [];
    const radii: number[] = [];
    let torn = 0;
    const throwBall = (heavy: boolean) => {
      const i = balls.length;
      const fromLeft = i % 2 === 0;
      const ball = world.createBody({
        type: 'dynamic',
        position: { x: fromLeft ? -7 : 7, y: 5 - (i % 3) * 0.4 },
        linearVelocity: { x: (fromLeft ? 1 : -1) * (heavy ? 11 : 7), y: heavy ? 6 : 6.5 },
        bullet: true,
      });
      const radius = heavy ? 0.45 : 0.35;
      ball.createShape(Shape.circle(radius), {
        density: heavy ? 30 : 1,
        friction: 0.4,
        restitution: 0.2,
      });
      balls.push(ball);
      radii.push(radius);
    };
    ctx.button('Throw a heavy ball', () => throwBall(true));
    let steps = 0;
    ctx.track(world.on('preStep', () => blow(nodes, steps)));
    ctx.track(
      world.on('postStep', () => {
        steps++;
        // a light ball bumps the curtain once it has settled: it sways, and holds
        if (steps === 10) throwBall(false);
        torn += tearOverstretched(world, links);
      }),
    );

    // the hand: a press on the cloth takes a fistful of it (every circle within reach, each on a mouse
    // joint that keeps its place in the fist), pulled harder than the gallery's drag pulls a body
    const grips: { joint: MouseJoint; offset: Vec2 }[] = [];
    const letGo = () => {
      for (const { joint } of grips.splice(0)) if (joint.isValid) world.destroyJoint(joint);
    };
    const takeHold = (point: Vec2): boolean => {
      letGo();
      for (const node of nodes) {
        if (node.type !== 'dynamic') continue;
        const q = node.position;
        const offset = { x: q.x - point.x, y: q.y - point.y };
        if (offset.x * offset.x + offset.y * offset.y > GRAB_REACH * GRAB_REACH) continue;
        const joint = world.createJoint({
          type: 'mouse',
          body: node,
          target: q,
          maxForce: GRAB_FORCE,
          hertz: 6,
          dampingRatio: 0.7,
        });
        grips.push({ joint, offset });
      }
      return grips.length > 0;
    };
    const pull = (point: Vec2) => {
      for (const { joint, offset } of grips) {
        if (!joint.isValid) continue;
        joint.setTarget({ x: point.x + offset.x, y: point.y + offset.y });
        joint.body.setAwake(true);
      }
    };
    ctx.pointer.filter = (body) => balls.includes(body as Body);
    ctx.track(
      ctx.pointer.on('down', (e) => {
        if (ctx.pointer.pick(e.point)) return;
        if (!takeHold(e.point)) return;
        e.handled = true;
        capturePointer(ctx, e.event);
      }),
    );
    ctx.track(ctx.pointer.on('move', (e) => pull(e.point)));
    ctx.track(ctx.pointer.on('up', letGo));
    ctx.track(letGo);

    // the picture: a room, the rod, the sheet, the balls
    const at = (row: number, column: number) => row * COLUMNS + column;
    const drawn: Vec2[] = nodes.map((n) => n.position);
    const restArea = SPACING * SPACING;
    let wall: CanvasGradient | null = null;
    let ballSkin: CanvasGradient | null = null;
    const path = (c: CanvasRenderingContext2D, corners: number[]) => {
      c.moveTo(drawn[corners[0]].x, drawn[corners[0]].y);
      for (let k = 1; k < corners.length; k++) c.lineTo(drawn[corners[k]].x, drawn[corners[k]].y);
      c.closePath();
    };
    /** Paints cell (row, column): whole, or the triangles of it whose three sides still hold. */
    const cell = (c: CanvasRenderingContext2D, row: number, column: number) => {
      const a = at(row, column);
      const b = at(row, column + 1);
      const e = at(row + 1, column + 1);
      const d = at(row + 1, column);
      const top = linkOf(a, b);
      const right = linkOf(b, e);
      const bottom = linkOf(d, e);
      const left = linkOf(a, d);
      const bd = linkOf(b, d);
      const ae = linkOf(a, e);
      const p = drawn[a];
      const q = drawn[b];
      const r = drawn[e];
      const o = drawn[d];
      // bunched cloth (less area than at rest) falls into shadow; cloth swung aside catches the light
      const area = ((r.x - p.x) * (q.y - o.y) - (r.y - p.y) * (q.x - o.x)) / 2;
      const lean = (p.x - o.x + q.x - r.x) / (2 * SPACING);
      const light = 0.35 + 0.65 * Math.min(1.4, Math.abs(area) / restArea) + 0.45 * lean;
      c.fillStyle = weaveColor(column, row, light);
      c.strokeStyle = c.fillStyle;
      c.beginPath();
      if (top && right && bottom && left && (bd || ae)) path(c, [a, b, e, d]);
      else {
        if (bd && top && left) path(c, [a, b, d]);
        if (bd && right && bottom) path(c, [b, e, d]);
        if (ae && top && right) path(c, [a, b, e]);
        if (ae && bottom && left) path(c, [a, e, d]);
      }
      c.fill();
      c.stroke();
    };
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        const c = render.context;
        const pixel = 1 / render.camera.scale;
        render.setWorldTransform();
        if (!wall) {
          wall = c.createLinearGradient(0, 12, 0, 0);
          wall.addColorStop(0, '#2b2f3a');
          wall.addColorStop(1, '#4a4038');
          ballSkin = c.createRadialGradient(-0.35, 0.35, 0.05, 0, 0, 1);
          ballSkin.addColorStop(0, '#ffd0a8');
          ballSkin.addColorStop(0.5, '#e0703c');
          ballSkin.addColorStop(1, '#7a2e14');
        }
        c.fillStyle = wall;
        c.fillRect(-40, 0, 80, 20);
        // the floor
        c.fillStyle = '#6b4a33';
        c.fillRect(-40, -10, 80, 10);
        c.fillStyle = '#8a6244';
        c.fillRect(-40, -0.12, 80, 0.12);
        for (let i = 0; i < nodes.length; i++) drawn[i] = drawnPosition(ctx.runner, nodes[i]);
        c.lineWidth = pixel;
        c.lineJoin = 'round';
        for (let row = 0; row + 1 < ROWS; row++)
          for (let column = 0; column + 1 < COLUMNS; column++) cell(c, row, column);
        // the warp: a faint thread down each column, where it holds
        c.strokeStyle = 'rgba(40, 10, 16, 0.08)';
        c.beginPath();
        for (let column = 0; column < COLUMNS; column++) {
          for (let row = 0; row + 1 < ROWS; row++) {
            const a = at(row, column);
            const d = at(row + 1, column);
            if (!linkOf(a, d)) continue;
            c.moveTo(drawn[a].x, drawn[a].y);
            c.lineTo(drawn[d].x, drawn[d].y);
          }
        }
        c.stroke();
        // the hem: a darker line along the bottom edge where it is whole
        c.strokeStyle = 'rgba(60, 16, 24, 0.9)';
        c.lineWidth = 3 * pixel;
        c.beginPath();
        for (let column = 0; column + 1 < COLUMNS; column++) {
          const a = at(ROWS - 1, column);
          const b = at(ROWS - 1, column + 1);
          if (!linkOf(a, b)) continue;
          c.moveTo(drawn[a].x, drawn[a].y);
          c.lineTo(drawn[b].x, drawn[b].y);
        }
        c.stroke();
        // the rod and its rings at the pins
        const rodY = TOP_LEFT.y + 0.12;
        const rod = c.createLinearGradient(0, rodY + 0.09, 0, rodY - 0.09);
        rod.addColorStop(0, '#e8d7a0');
        rod.addColorStop(1, '#7a6331');
        c.fillStyle = rod;
        c.fillRect(TOP_LEFT.x - 0.5, rodY - 0.07, (COLUMNS - 1) * SPACING + 1, 0.14);
        c.fillStyle = '#c9a74f';
        for (const x of [TOP_LEFT.x - 0.55, TOP_LEFT.x + (COLUMNS - 1) * SPACING + 0.55]) {
          c.beginPath();
          c.arc(x, rodY, 0.14, 0, 2 * Math.PI);
          c.fill();
        }
        c.strokeStyle = '#d9c07a';
        c.lineWidth = 2 * pixel;
        for (const node of nodes) {
          if (node.type === 'dynamic') continue;
          c.beginPath();
          c.arc(node.position.x, node.position.y + 0.06, 0.08, 0, 2 * Math.PI);
          c.stroke();
        }
        // the balls, lit from the upper left
        for (const [i, ball] of balls.entries()) {
          const p = drawnPosition(ctx.runner, ball);
          fillSkinnedDisc(c, p.x, p.y, radii[i], ballSkin as CanvasGradient);
        }
        render.setScreenTransform();
      }),
    );
    const advance = stepHook(ctx.runner);
    return {
      world,
      nodes,
      balls,
      links,
      torn: () => torn,
      throwBall: () => throwBall(true),
      advance,
    };
  },
};
