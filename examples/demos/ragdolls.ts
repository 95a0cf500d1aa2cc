/**
 * Ragdolls down a flight of stairs: capsule limbs on revolute joints with angle limits
 * (scenes/joint-scenes.ts), pushed off a landing at the top, drawn as little figures. One that has come
 * to rest at the bottom is carried back up and pushed again, so the stairs never run dry.
 */
import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { GRAVITY } from '../../scenes/common';
import { ragdoll, type Scene, type SceneBody, type SceneJoint } from '../../scenes/index';
import type { Body, Transform, Vec2 } from '../../src/index';
import type { Demo } from '../demo';
import { stepHook } from '../lib';

const COUNT = 5;
export const STAIRS = 10;
export const RISE = 0.5;
export const TREAD = 0.8;
/** the landing's top, and where the stairs begin */
export const LANDING: Vec2 = { x: -6.5, y: STAIRS * RISE };
/** the hand's push on a doll on the landing, m/s² */
const SHOVE = 6;
/** steps a doll lies still at the bottom before it is carried up again */
const REST_STEPS = 90;

/** The landing, the stairs down from it and the floor: one static body of boxes. */
function stairs(): SceneBody {
  const shapes: SceneBody['shapes'] = [
    // the landing, from the left wall
    {
      kind: 'box',
      halfWidth: 2,
      halfHeight: LANDING.y / 2 + 0.5,
      center: { x: LANDING.x - 2, y: LANDING.y / 2 - 0.5 },
    },
    { kind: 'box', halfWidth: 0.5, halfHeight: 5, center: { x: LANDING.x - 4.5, y: LANDING.y + 4 } },
    // the floor
    {
      kind: 'box',
      halfWidth: 12,
      halfHeight: 0.5,
      center: { x: LANDING.x + (STAIRS - 1) * TREAD + 12, y: -0.5 },
    },
  ];
  for (let k = 0; k < STAIRS - 1; k++) {
    const top = LANDING.y - RISE * (k + 1);
    shapes.push({
      kind: 'box',
      halfWidth: TREAD / 2,
      halfHeight: (top + 1) / 2,
      center: { x: LANDING.x + TREAD * (k + 0.5), y: (top - 1) / 2 },
    });
  }
  for (const shape of shapes) shape.friction = 0.7;
  return { type: 'static', position: { x: 0, y: 0 }, shapes, tag: 'ground' };
}

const skins = ['#f1c7a5', '#c98e66', '#8d5a3c', '#f4d2b8', '#b07a55'];
const shirts = ['#d9534f', '#4a90d9', '#e8b93c', '#5cb85c', '#9b6bd1'];
const trousers = ['#2f3e5c', '#3b3b3b', '#5a4632', '#27496d', '#4b2f4f'];

interface Doll {
  parts: Body[];
  /** steps it has lain still past the stairs */
  rest: number;
  /** a hand pushes it towards the stairs */
  pushed: boolean;
}

export const ragdollsDemo: Demo = {
  id: 'ragdolls',
  title: 'Ragdolls',
  description:
    'Ragdolls tumble down a flight of stairs: capsule limbs on revolute joints with angle limits at the hips, knees, shoulders, elbows and neck (scenes/joint-scenes.ts). Each is pushed off the landing; one at rest at the bottom is carried up and pushed again. Drag a ragdoll by any limb; "Push one" sends the next down.',
  view: { center: { x: -2.7, y: 3.3 }, halfHeight: 4.5 },
  fitWidth: 7.1,
  flags: { shapes: false, joints: false, sleeping: false },
  create: (ctx) => {
    const bodies: SceneBody[] = [stairs()];
    const joints: SceneJoint[] = [];
    for (let i = 0; i < COUNT; i++)
      ragdoll(bodies, joints, { x: LANDING.x - 3.4 + 0.75 * i, y: LANDING.y + 0.05 + 0.6 * i });
    const scene: Scene = { name: 'ragdolls-on-stairs', gravity: GRAVITY, bodies, joints };
    const { world, bodies: made } = buildFulcrumWorld(scene);
    // each ragdoll's bodies follow its pelvis in the scene's order
    const dolls: Doll[] = [];
    made.forEach((body, i) => {
      const tag = scene.bodies[i].tag;
      if (tag === 'pelvis') dolls.push({ parts: [], rest: 0, pushed: false });
      if (dolls.length > 0 && tag !== 'ground') dolls[dolls.length - 1].parts.push(body);
    });
    // a push: a shove, then a hand at the back until the doll is over the edge of the landing
    const push = (doll: Doll, speed: number) => {
      for (const part of doll.parts) {
        part.setAwake(true);
        part.setLinearVelocity({ x: speed, y: 0.5 });
      }
      doll.pushed = true;
    };
    ctx.track(
      world.on('preStep', () => {
        for (const doll of dolls) {
          if (!doll.pushed) continue;
          if (doll.parts[0].position.x > LANDING.x + 0.3) {
            doll.pushed = false;
            continue;
          }
          for (const part of doll.parts) part.applyForce({ x: part.mass * SHOVE, y: 0 });
        }
      }),
    );
    // pushed one after another, the nearest the edge first
    const pushAt = dolls.map((_, i) => 15 + 40 * (COUNT - 1 - i));
    let next = 0;
    ctx.button('Push one', () => {
      const doll = dolls[next % dolls.length];
      next++;
      push(doll, 3.5);
    });
    let steps = 0;
    /** carries a doll back to the landing, standing as it lies, and drops it there to be pushed again */
    const carryUp = (doll: Doll, i: number) => {
      const pelvis = doll.parts[0].position;
      const dx = LANDING.x - 2.6 - pelvis.x + 0.3 * (i % 3);
      const dy = LANDING.y + 2.5 - pelvis.y;
      for (const part of doll.parts) {
        const p = part.position;
        part.setTransform({ x: p.x + dx, y: p.y + dy }, part.angle);
        part.setLinearVelocity({ x: 0, y: 0 });
        part.setAngularVelocity(0);
      }
      push(doll, 2.5);
      doll.rest = 0;
    };
    ctx.track(
      world.on('postStep', () => {
        steps++;
        dolls.forEach((doll, i) => {
          if (steps === pushAt[i]) push(doll, 2.5 + 0.3 * i);
          const pelvis = doll.parts[0];
          const v = pelvis.linearVelocity;
          const down = pelvis.position.x > LANDING.x + STAIRS * TREAD - 0.5;
          doll.rest = down && v.x * v.x + v.y * v.y < 0.25 ? doll.rest + 1 : 0;
          if (doll.rest > REST_STEPS || pelvis.position.y < -5) carryUp(doll, i);
        });
      }),
    );

    // the picture: a stairwell, stone stairs, the figures
    const xf: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } };
    const place = (body: Body): Transform =>
      ctx.runner.interpolate
        ? ctx.runner.interpolator.transformOf(body, xf)
        : { p: body.position, q: { c: Math.cos(body.angle), s: Math.sin(body.angle) } };
    /** a capsule limb from its body's local (0, -half) to (0, half) */
    const limb = (c: CanvasRenderingContext2D, body: Body, half: number, radius: number, color: string) => {
      const t = place(body);
      c.strokeStyle = color;
      c.lineWidth = 2 * radius;
      c.beginPath();
      c.moveTo(t.p.x + t.q.s * half, t.p.y - t.q.c * half);
      c.lineTo(t.p.x - t.q.s * half, t.p.y + t.q.c * half);
      c.stroke();
    };
    let wall: CanvasGradient | null = null;
    let stone: CanvasGradient | null = null;
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        const c = render.context;
        const pixel = 1 / render.camera.scale;
        render.setWorldTransform();
        if (!wall) {
          wall = c.createLinearGradient(0, 10, 0, 0);
          wall.addColorStop(0, '#3a3f4b');
          wall.addColorStop(1, '#6b6256');
          stone = c.createLinearGradient(0, 0.25, 0, -0.25);
          stone.addColorStop(0, '#cfc6b4');
          stone.addColorStop(1, '#8f8676');
        }
        c.fillStyle = wall;
        c.fillRect(-40, -2, 80, 30);
        // the banister's posts, for depth
        c.strokeStyle = 'rgba(30, 24, 20, 0.35)';
        c.lineWidth = 0.08;
        c.beginPath();
        for (let k = 0; k < STAIRS; k += 2) {
          const x = LANDING.x + TREAD * (k + 0.5);
          const y = LANDING.y - RISE * k;
          c.moveTo(x, y);
          c.lineTo(x, y + 1.3);
        }
        c.moveTo(LANDING.x, LANDING.y + 1.3);
        c.lineTo(LANDING.x + TREAD * STAIRS, 1.3);
        c.stroke();
        // the stairs: stone blocks with lit treads
        c.fillStyle = '#857b6b';
        c.beginPath();
        c.moveTo(LANDING.x - 10, -3);
        c.lineTo(LANDING.x - 10, LANDING.y);
        for (let k = 0; k < STAIRS; k++) {
          const y = LANDING.y - RISE * k;
          c.lineTo(LANDING.x + TREAD * k, y);
          c.lineTo(LANDING.x + TREAD * k, y - RISE);
        }
        c.lineTo(40, 0);
        c.lineTo(40, -3);
        c.closePath();
        c.fill();
        for (let k = -1; k < STAIRS; k++) {
          const y = k < 0 ? LANDING.y : LANDING.y - RISE * (k + 1);
          const x0 = k < 0 ? LANDING.x - 10 : LANDING.x + TREAD * k;
          const x1 = k < 0 ? LANDING.x : k === STAIRS - 1 ? 40 : LANDING.x + TREAD * (k + 1);
          c.save();
          c.translate(0, y - 0.06);
          c.fillStyle = stone as CanvasGradient;
          c.fillRect(x0, -0.06, x1 - x0 + 0.02, 0.12);
          c.restore();
        }
        c.strokeStyle = 'rgba(40, 32, 26, 0.5)';
        c.lineWidth = 1.5 * pixel;
        c.beginPath();
        for (let k = 0; k < STAIRS; k++) {
          c.moveTo(LANDING.x + TREAD * k, LANDING.y - RISE * k);
          c.lineTo(LANDING.x + TREAD * k, LANDING.y - RISE * (k + 1));
        }
        c.stroke();
        // the figures: far limbs shaded, then the body, the near limbs and the head
        c.lineCap = 'round';
        dolls.forEach((doll, i) => {
          const [pelvis, torso, head, ...sides] = doll.parts;
          const shirt = shirts[i % shirts.length];
          const legs = trousers[i % trousers.length];
          const skin = skins[i % skins.length];
          const side = (k: number, shade: boolean) => {
            const [thigh, shin, arm, forearm] = sides.slice(4 * k, 4 * k + 4);
            c.globalAlpha = shade ? 0.75 : 1;
            limb(c, thigh, 0.18, 0.075, legs);
            limb(c, shin, 0.18, 0.065, legs);
            limb(c, arm, 0.15, 0.055, shirt);
            limb(c, forearm, 0.15, 0.05, skin);
            c.globalAlpha = 1;
          };
          side(0, true);
          limb(c, pelvis, 0.08, 0.13, legs);
          limb(c, torso, 0.18, 0.15, shirt);
          side(1, false);
          // the head: a face that turns with it
          const t = place(head);
          c.save();
          c.transform(t.q.c, t.q.s, -t.q.s, t.q.c, t.p.x, t.p.y);
          c.fillStyle = skin;
          c.beginPath();
          c.arc(0, 0.02, 0.15, 0, 2 * Math.PI);
          c.fill();
          c.fillStyle = '#2a2320';
          c.beginPath();
          c.arc(0, 0.06, 0.155, 0.15 * Math.PI, 0.85 * Math.PI);
          c.fill();
          c.beginPath();
          c.arc(-0.05, 0.01, 0.02, 0, 2 * Math.PI);
          c.arc(0.05, 0.01, 0.02, 0, 2 * Math.PI);
          c.fill();
          c.strokeStyle = '#2a2320';
          c.lineWidth = 1.5 * pixel;
          c.beginPath();
          c.arc(0, -0.02, 0.05, 1.2 * Math.PI, 1.8 * Math.PI);
          c.stroke();
          c.restore();
        });
        render.setScreenTransform();
      }),
    );
    const advance = stepHook(ctx.runner);
    return { world, dolls: dolls.map((d) => d.parts), advance };
  },
};
