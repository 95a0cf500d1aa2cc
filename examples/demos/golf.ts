/**
 * Mini golf: three holes of slopes, a wall to chip over and a turning windmill. Drag back from the ball
 * and let go: the ball is struck the other way, as hard as the pull is long. The cup holds a sensor
 * shape whose sensorBegin event says the ball is in; the next hole follows.
 */
import { type Body, Shape, type ShapeHandle, type Vec2, World } from '../../src/index';
import type { Demo } from '../demo';
import { capturePointer, drawnPosition, fillSkinnedDisc, stepHook, worldText } from '../lib';

export const BALL_RADIUS = 0.2;
/** the ball's speed per metre of pull, 1/s */
export const SPEED_PER_METRE = 4.5;
/** a longer pull strikes no harder, m */
export const MAX_PULL = 4;
/** a press this close to the ball takes aim, m */
const REACH = 1.6;
const CUP_HALF_WIDTH = 0.34;
const CUP_DEPTH = 0.5;
/** steps the sunk ball rests in the cup before the next hole */
const SUNK_STEPS = 90;

export interface Hole {
  name: string;
  par: number;
  tee: Vec2;
  /** the surface from the left wall to the right one; the cup is cut into it at cupX */
  ground: Vec2[];
  cupX: number;
  /** stone blocks: centre and half sizes */
  walls?: { x: number; y: number; halfWidth: number; halfHeight: number }[];
  /** a windmill's hub and its turning speed, rad/s */
  windmill?: { x: number; y: number; speed: number };
}

export const holes: readonly Hole[] = [
  {
    name: 'Over the hump',
    par: 2,
    tee: { x: -8, y: BALL_RADIUS },
    ground: [
      { x: -10.5, y: 4 },
      { x: -10.5, y: 0 },
      { x: -4, y: 0 },
      { x: -2.5, y: 0.2 },
      { x: -1, y: 0.45 },
      { x: 0, y: 0.5 },
      { x: 1, y: 0.45 },
      { x: 2.5, y: 0.2 },
      { x: 4, y: 0 },
      { x: 5.2, y: -0.3 },
      { x: 6.1, y: -0.4 },
      { x: 7, y: -0.3 },
      { x: 8.5, y: 0.3 },
      { x: 10.5, y: 1.4 },
      { x: 10.5, y: 4 },
    ],
    cupX: 6.1,
  },
  {
    name: 'Chip over the wall',
    par: 3,
    tee: { x: -8.5, y: BALL_RADIUS },
    ground: [
      { x: -10.5, y: 4 },
      { x: -10.5, y: 0 },
      { x: 3, y: 0 },
      { x: 5, y: -0.25 },
      { x: 6.5, y: -0.35 },
      { x: 8, y: -0.2 },
      { x: 10.5, y: 0.8 },
      { x: 10.5, y: 4 },
    ],
    cupX: 6.5,
    walls: [{ x: -1, y: 0.8, halfWidth: 0.3, halfHeight: 0.8 }],
  },
  {
    name: 'The windmill',
    par: 3,
    tee: { x: -8.5, y: BALL_RADIUS },
    ground: [
      { x: -10.5, y: 4 },
      { x: -10.5, y: 0 },
      { x: 2.5, y: 0 },
      { x: 4, y: 0.5 },
      { x: 5.5, y: 0.7 },
      { x: 7, y: 0.7 },
      { x: 8.5, y: 0.9 },
      { x: 10.5, y: 2 },
      { x: 10.5, y: 4 },
    ],
    cupX: 6.6,
    windmill: { x: -1.5, y: 2.1, speed: -1.2 },
  },
];

/** The height of a hole's ground at x (on its polyline, before the cup is cut). */
function groundAt(hole: Hole, x: number): number {
  const g = hole.ground;
  for (let i = 1; i < g.length; i++) {
    const a = g[i - 1];
    const b = g[i];
    if (x >= a.x && x <= b.x && b.x > a.x) return a.y + ((b.y - a.y) * (x - a.x)) / (b.x - a.x);
  }
  return 0;
}

/** A hole's surface with the cup cut in, left to right. */
function surfaceOf(hole: Hole): Vec2[] {
  const y = groundAt(hole, hole.cupX);
  const left = hole.cupX - CUP_HALF_WIDTH;
  const right = hole.cupX + CUP_HALF_WIDTH;
  const points: Vec2[] = [];
  for (const p of hole.ground) {
    if (p.x > left && points.length > 0 && points[points.length - 1].x <= left) {
      points.push(
        { x: left, y: groundAt(hole, left) },
        { x: left, y: y - CUP_DEPTH },
        { x: right, y: y - CUP_DEPTH },
        { x: right, y: groundAt(hole, right) },
      );
    }
    if (p.x <= left || p.x >= right) points.push(p);
  }
  return points;
}

export interface Course {
  world: World;
  ball: Body;
  /** the current hole's bodies: its ground (with the cup's sensor) and any windmill */
  ground: Body;
  windmill: Body | null;
  cup: ShapeHandle;
  surface: Vec2[];
}

/** Lays out hole `index` in `world` (the last hole's bodies destroyed) and tees the ball up. */
export function layHole(world: World, index: number, ball: Body, previous?: Course): Course {
  if (previous) {
    world.destroyBody(previous.ground);
    if (previous.windmill) world.destroyBody(previous.windmill);
  }
  const hole = holes[index];
  const surface = surfaceOf(hole);
  const ground = world.createBody({ position: { x: 0, y: 0 } });
  // a chain is walked on from its right-hand side: laid right to left, from above
  ground.createShape(Shape.chain([...surface].reverse()), { friction: 0.6, restitution: 0.2 });
  for (const w of hole.walls ?? [])
    ground.createShape(Shape.box(w.halfWidth, w.halfHeight, { x: w.x, y: w.y }), { restitution: 0.4 });
  const cupY = groundAt(hole, hole.cupX) - CUP_DEPTH;
  const cup = ground.createShape(Shape.box(CUP_HALF_WIDTH - 0.06, 0.2, { x: hole.cupX, y: cupY + 0.2 }), {
    isSensor: true,
  });
  let windmill: Body | null = null;
  if (hole.windmill) {
    const m = hole.windmill;
    windmill = world.createBody({ type: 'kinematic', position: m, angularVelocity: m.speed });
    windmill.createShape(Shape.box(1.9, 0.12), { restitution: 0.3 });
    windmill.createShape(Shape.box(0.12, 1.9), { restitution: 0.3 });
  }
  ball.setTransform(hole.tee, 0);
  ball.setLinearVelocity({ x: 0, y: 0 });
  ball.setAngularVelocity(0);
  ball.setAwake(true);
  return { world, ball, ground, windmill, cup, surface };
}

/** A golf ball. */
export function makeBall(world: World): Body {
  const ball = world.createBody({
    type: 'dynamic',
    position: holes[0].tee,
    bullet: true,
    linearDamping: 0.3,
    angularDamping: 0.8,
  });
  ball.createShape(Shape.circle(BALL_RADIUS), { density: 1.5, friction: 0.6, restitution: 0.3 });
  return ball;
}

/** Strikes the ball as a pull from the ball to `hand` asks: the other way, at SPEED_PER_METRE per metre. */
export function strike(ball: Body, hand: Vec2): boolean {
  const p = ball.position;
  const dx = p.x - hand.x;
  const dy = p.y - hand.y;
  const length = Math.hypot(dx, dy);
  if (length < 0.2) return false;
  const speed = (SPEED_PER_METRE * Math.min(length, MAX_PULL)) / length;
  ball.setAwake(true);
  ball.applyLinearImpulse({ x: ball.mass * dx * speed, y: ball.mass * dy * speed });
  return true;
}

export const golfDemo: Demo = {
  id: 'golf',
  title: 'Golf green',
  description:
    'Mini golf in three holes. Drag back from the ball and let go to putt: the longer the pull, the harder the stroke (body.applyLinearImpulse); aim up to chip the ball over the wall. The cup is a sensor shape whose sensorBegin event tells the ball is in; the windmill is a kinematic body.',
  view: { center: { x: 0, y: 1.5 }, halfHeight: 6 },
  fitWidth: 11,
  flags: { shapes: false, joints: false, sleeping: false },
  create: (ctx) => {
    const world = new World();
    const ball = makeBall(world);
    let hole = 0;
    let course = layHole(world, hole, ball);
    let strokes = 0;
    /** strokes of each hole played */
    const card: number[] = [];
    let sunkAt = -1;
    let steps = 0;
    let shotAt = -1000;
    let aim: Vec2 | null = null;
    const state = {
      hole: () => hole,
      strokes: () => strokes,
      card: () => [...card],
      sunk: () => sunkAt >= 0,
      ready: () => ready(),
    };

    const status = () => {
      const total = card.reduce((a, b) => a + b, 0);
      ctx.setStatus(
        `Hole ${hole + 1} of ${holes.length} (par ${holes[hole].par}) · strokes ${strokes}` +
          (card.length > 0 ? ` · card ${card.join(' ')} = ${total}` : ''),
      );
    };
    status();
    /** steps the ball has been all but still */
    let restSteps = 0;
    /** the ball may be struck: at rest (not just turning on a slope), or a while after the last stroke */
    const ready = () => sunkAt < 0 && (restSteps >= 15 || steps - shotAt > 360);

    ctx.pointer.filter = () => false;
    ctx.track(
      ctx.pointer.on('down', (e) => {
        const p = ball.position;
        const dx = e.point.x - p.x;
        const dy = e.point.y - p.y;
        if (ready() && dx * dx + dy * dy < REACH * REACH) {
          aim = e.point;
          e.handled = true;
          capturePointer(ctx, e.event);
        }
      }),
    );
    ctx.track(
      ctx.pointer.on('move', (e) => {
        if (aim) aim = e.point;
      }),
    );
    ctx.track(
      ctx.pointer.on('up', (e) => {
        if (!aim) return;
        aim = null;
        if (!ready() || !strike(ball, e.point)) return;
        strokes++;
        shotAt = steps;
        restSteps = 0;
        status();
      }),
    );
    ctx.track(
      world.on('sensorBegin', (e) => {
        if (e.sensorShape === course.cup && e.visitorShape.body === ball && sunkAt < 0) {
          sunkAt = steps;
          card.push(strokes);
          const par = holes[hole].par;
          const word =
            strokes === 1 ? 'Hole in one!' : strokes < par ? 'Birdie!' : strokes === par ? 'Par.' : 'In.';
          ctx.setStatus(`${word} Hole ${hole + 1} in ${strokes} stroke${strokes === 1 ? '' : 's'}.`);
        }
      }),
    );
    ctx.track(
      world.on('postStep', () => {
        steps++;
        const v = ball.linearVelocity;
        restSteps = v.x * v.x + v.y * v.y < 0.01 ? restSteps + 1 : 0;
        const p = ball.position;
        // off the course (over a wall): back to the tee, a stroke lost
        if (sunkAt < 0 && (p.y < -3 || Math.abs(p.x) > 12)) {
          strokes++;
          course = layHole(world, hole, ball, course);
          status();
        }
        if (sunkAt >= 0 && steps - sunkAt > SUNK_STEPS) {
          sunkAt = -1;
          hole = (hole + 1) % holes.length;
          if (hole === 0) card.length = 0;
          strokes = 0;
          shotAt = -1000;
          course = layHole(world, hole, ball, course);
          status();
        }
      }),
    );

    // the picture
    let sky: CanvasGradient | null = null;
    let grass: CanvasGradient | null = null;
    let ballSkin: CanvasGradient | null = null;
    const hills = new Path2D();
    hills.moveTo(-30, -10);
    for (let x = -30; x <= 30; x += 0.5)
      hills.lineTo(x, 2.6 + 0.9 * Math.sin(x * 0.31) + 0.5 * Math.sin(x * 0.83 + 1));
    hills.lineTo(30, -10);
    hills.closePath();
    ctx.track(
      ctx.render.on('beforeDraw', ({ render }) => {
        const c = render.context;
        const pixel = 1 / render.camera.scale;
        render.setWorldTransform();
        if (!sky) {
          sky = c.createLinearGradient(0, 9, 0, 0);
          sky.addColorStop(0, '#6fb7e8');
          sky.addColorStop(1, '#d6eef7');
          grass = c.createLinearGradient(0, 1, 0, -1);
          grass.addColorStop(0, '#7bd25a');
          grass.addColorStop(1, '#3f9a3a');
          ballSkin = c.createRadialGradient(-0.35, 0.4, 0.05, 0, 0, 1);
          ballSkin.addColorStop(0, '#ffffff');
          ballSkin.addColorStop(0.6, '#eef0f2');
          ballSkin.addColorStop(1, '#a8adb5');
        }
        // the whole canvas: zoomed out on a narrow screen it reaches far above the course
        const seen = render.camera.visibleBounds();
        c.fillStyle = sky;
        c.fillRect(
          seen.lowerBound.x,
          seen.lowerBound.y,
          seen.upperBound.x - seen.lowerBound.x,
          seen.upperBound.y - seen.lowerBound.y,
        );
        c.fillStyle = '#a9d8a0';
        c.fill(hills);
        const h = holes[hole];
        const surface = course.surface;
        // the soil, then the green's turf along the top
        c.fillStyle = '#7a5a3c';
        c.beginPath();
        c.moveTo(surface[0].x, -10);
        for (const p of surface) c.lineTo(p.x, p.y);
        c.lineTo(surface[surface.length - 1].x, -10);
        c.closePath();
        c.fill();
        c.strokeStyle = grass as CanvasGradient;
        c.lineWidth = 0.3;
        c.lineJoin = 'round';
        c.beginPath();
        for (const [i, p] of surface.entries()) {
          if (i === 0) c.moveTo(p.x, p.y - 0.15);
          else c.lineTo(p.x, p.y - 0.15);
        }
        c.stroke();
        c.strokeStyle = '#4da33f';
        c.lineWidth = 2 * pixel;
        c.stroke();
        // the cup: dark inside, a white rim
        const cupTop = groundAt(h, h.cupX);
        c.fillStyle = '#1f2a1c';
        c.fillRect(h.cupX - CUP_HALF_WIDTH, cupTop - CUP_DEPTH, 2 * CUP_HALF_WIDTH, CUP_DEPTH);
        // the walls: stone
        for (const w of h.walls ?? []) {
          c.fillStyle = '#8d8f96';
          c.fillRect(w.x - w.halfWidth, w.y - w.halfHeight, 2 * w.halfWidth, 2 * w.halfHeight);
          c.strokeStyle = '#5d6068';
          c.lineWidth = 2 * pixel;
          c.strokeRect(w.x - w.halfWidth, w.y - w.halfHeight, 2 * w.halfWidth, 2 * w.halfHeight);
          c.beginPath();
          for (let y = w.y - w.halfHeight + 0.4; y < w.y + w.halfHeight; y += 0.4) {
            c.moveTo(w.x - w.halfWidth, y);
            c.lineTo(w.x + w.halfWidth, y);
          }
          c.stroke();
        }
        // the windmill: a little house and its sails
        if (course.windmill && h.windmill) {
          const m = h.windmill;
          c.fillStyle = '#c9784a';
          c.beginPath();
          c.moveTo(m.x - 0.7, 0);
          c.lineTo(m.x - 0.45, m.y);
          c.lineTo(m.x + 0.45, m.y);
          c.lineTo(m.x + 0.7, 0);
          c.closePath();
          c.fill();
          c.fillStyle = '#8a3f2a';
          c.beginPath();
          c.moveTo(m.x - 0.6, m.y);
          c.lineTo(m.x, m.y + 0.6);
          c.lineTo(m.x + 0.6, m.y);
          c.closePath();
          c.fill();
          const t = ctx.runner.interpolate
            ? ctx.runner.interpolator.transformOf(course.windmill, { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } })
            : {
                p: course.windmill.position,
                q: { c: Math.cos(course.windmill.angle), s: Math.sin(course.windmill.angle) },
              };
          c.save();
          c.transform(t.q.c, t.q.s, -t.q.s, t.q.c, t.p.x, t.p.y);
          for (let k = 0; k < 4; k++) {
            c.fillStyle = '#f1e6cf';
            c.fillRect(0.15, -0.12, 1.75, 0.24);
            c.strokeStyle = '#7a5a3c';
            c.lineWidth = 2 * pixel;
            c.strokeRect(0.15, -0.12, 1.75, 0.24);
            c.rotate(Math.PI / 2);
          }
          c.fillStyle = '#5a3a22';
          c.beginPath();
          c.arc(0, 0, 0.18, 0, 2 * Math.PI);
          c.fill();
          c.restore();
        }
        // the flag
        c.strokeStyle = '#f4f4f4';
        c.lineWidth = 3 * pixel;
        c.beginPath();
        c.moveTo(h.cupX, cupTop - CUP_DEPTH + 0.05);
        c.lineTo(h.cupX, cupTop + 2.6);
        c.stroke();
        const flutter = 0.12 * Math.sin(steps * 0.15);
        c.fillStyle = '#e2483d';
        c.beginPath();
        c.moveTo(h.cupX, cupTop + 2.6);
        c.quadraticCurveTo(h.cupX + 0.6, cupTop + 2.45 + flutter, h.cupX + 1.2, cupTop + 2.3 + flutter);
        c.lineTo(h.cupX, cupTop + 2);
        c.closePath();
        c.fill();
        worldText(c, pixel, { x: h.cupX + 0.55, y: cupTop + 2.35 }, String(hole + 1), '#ffffff', 12);
        // the tee
        c.fillStyle = '#f2c14e';
        c.fillRect(h.tee.x - 0.05, h.tee.y - BALL_RADIUS - 0.12, 0.1, 0.12);
        // the aim: a band from the ball to the hand, and the stroke's arrow the other way
        const b = drawnPosition(ctx.runner, ball);
        if (aim) {
          const dx = b.x - aim.x;
          const dy = b.y - aim.y;
          const length = Math.hypot(dx, dy);
          const power = Math.min(length, MAX_PULL) / MAX_PULL;
          c.strokeStyle = 'rgba(40, 40, 40, 0.6)';
          c.lineWidth = 2 * pixel;
          c.setLineDash([5 * pixel, 4 * pixel]);
          c.beginPath();
          c.moveTo(b.x, b.y);
          c.lineTo(aim.x, aim.y);
          c.stroke();
          c.setLineDash([]);
          if (length > 0.2) {
            const ux = dx / length;
            const uy = dy / length;
            const reach = 0.5 + 3 * power;
            const tip = { x: b.x + ux * reach, y: b.y + uy * reach };
            c.strokeStyle = `hsl(${120 - 120 * power}, 85%, 45%)`;
            c.fillStyle = c.strokeStyle;
            c.lineWidth = 5 * pixel;
            c.beginPath();
            c.moveTo(b.x + ux * 0.3, b.y + uy * 0.3);
            c.lineTo(tip.x - ux * 0.25, tip.y - uy * 0.25);
            c.stroke();
            c.beginPath();
            c.moveTo(tip.x, tip.y);
            c.lineTo(tip.x - ux * 0.4 - uy * 0.22, tip.y - uy * 0.4 + ux * 0.22);
            c.lineTo(tip.x - ux * 0.4 + uy * 0.22, tip.y - uy * 0.4 - ux * 0.22);
            c.closePath();
            c.fill();
            worldText(c, pixel, { x: b.x, y: b.y + 0.7 }, `${Math.round(power * 100)} %`, '#1d2b1a', 13);
          }
        } else if (ready() && strokes === 0) {
          const hint = 'drag back from the ball, let go to putt';
          // beside the ball, but all of it on the canvas (a phone's is narrow)
          c.font = '14px system-ui, sans-serif';
          const half = (c.measureText(hint).width / 2) * pixel + 0.2;
          const { lowerBound, upperBound } = render.camera.visibleBounds();
          const x = Math.min(upperBound.x - half, Math.max(lowerBound.x + half, b.x + 3.4));
          worldText(c, pixel, { x, y: b.y + 1.3 }, hint, '#1d2b1a', 14);
        }
        // the ball and its shadow
        c.fillStyle = 'rgba(0, 0, 0, 0.18)';
        c.beginPath();
        c.ellipse(b.x + 0.05, b.y - BALL_RADIUS + 0.02, BALL_RADIUS, BALL_RADIUS * 0.3, 0, 0, 2 * Math.PI);
        c.fill();
        fillSkinnedDisc(c, b.x, b.y, BALL_RADIUS, ballSkin as CanvasGradient);
        render.setScreenTransform();
      }),
    );
    const advance = stepHook(ctx.runner);
    return { world, ball, state, advance };
  },
};
