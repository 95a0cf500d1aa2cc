import { type Body, type DistanceJoint, type Joint, Shape, World } from '../../src/index';
import type { Demo } from '../demo';

const LINKS = 24;
const LINK = 0.35;
const LINK_MASS = 1;
const BALL_MASS = 60;
const PIVOT = { x: -6, y: 11 };
const TOWER_X = 4;
const SEGMENTS = 4;
const SEGMENT = 1.2;
const ROD = 0.3;
const RODS = 12;

/** How far any joint of the list is pulled apart: hinges by their anchors, rods by their length. */
function largestGap(joints: readonly Joint[]): number {
  let gap = 0;
  for (const joint of joints) {
    if (joint.type === 'distance') {
      const rod = joint as DistanceJoint;
      gap = Math.max(gap, Math.abs(rod.currentLength - rod.length));
    } else if (joint.type === 'revolute') {
      const a = joint.anchorA;
      const b = joint.anchorB;
      gap = Math.max(gap, Math.hypot(b.x - a.x, b.y - a.y));
    }
  }
  return gap;
}

export const heavyLoadsDemo: Demo = {
  id: 'heavy-loads',
  title: 'Heavy loads',
  description:
    'A 60 kg wrecking ball on a chain of 1 kg links, and a crane: a boom of four locked prismatic segments holding a 40 kg crate on a rope of light rods. Rigid joints that form a tree are solved exactly, so neither the chain nor the rope stretches under a load many times heavier than its links: the status line shows the largest gap of any joint. Drag anything.',
  view: { center: { x: -1, y: 6 }, halfHeight: 8 },
  create: (ctx) => {
    const world = new World();
    const ground = world.createBody();
    ground.createShape(Shape.box(20, 0.5, { x: 0, y: -0.5 }));
    // a wall of boxes for the ball to knock down
    for (let row = 0; row < 6; row++) {
      for (let col = 0; col < 3; col++) {
        const box = world.createBody({
          type: 'dynamic',
          position: { x: -1 + 0.8 * col, y: 0.4 + 0.8 * row },
        });
        box.createShape(Shape.box(0.4, 0.4), { density: 2 });
        ctx.render.setBodyStyle(box, { color: 0xb07a45 });
      }
    }
    // the wrecking ball: a chain of capsules, level at first so that it swings down
    const pivot = world.createBody({ position: PIVOT });
    pivot.createShape(Shape.circle(0.15));
    const chain: Joint[] = [];
    let previous: Body = pivot;
    for (let i = 0; i < LINKS; i++) {
      const link = world.createBody({
        type: 'dynamic',
        position: { x: PIVOT.x - LINK * (i + 0.5), y: PIVOT.y },
      });
      const shape = link.createShape(Shape.capsule({ x: -LINK / 2, y: 0 }, { x: LINK / 2, y: 0 }, 0.05));
      shape.density = LINK_MASS / link.mass;
      ctx.render.setBodyStyle(link, { color: 0x9aa3b5 });
      chain.push(
        world.createJoint({
          type: 'revolute',
          bodyA: previous,
          bodyB: link,
          anchor: { x: PIVOT.x - LINK * i, y: PIVOT.y },
        }),
      );
      previous = link;
    }
    const end = PIVOT.x - LINK * LINKS;
    const ball = world.createBody({ type: 'dynamic', position: { x: end - 0.6, y: PIVOT.y } });
    const ballShape = ball.createShape(Shape.circle(0.6), { friction: 0.4 });
    ballShape.density = BALL_MASS / ball.mass;
    ctx.render.setBodyStyle(ball, { color: 0xd9695f });
    chain.push(
      world.createJoint({ type: 'revolute', bodyA: previous, bodyB: ball, anchor: { x: end, y: PIVOT.y } }),
    );

    // the crane: a tower, a boom of locked sliders, a rope of rods and a crate
    ground.createShape(Shape.box(0.3, 4.5, { x: TOWER_X, y: 4.5 }));
    const top = { x: TOWER_X + 0.3, y: 8.7 };
    previous = ground;
    for (let i = 0; i < SEGMENTS; i++) {
      const segment = world.createBody({
        type: 'dynamic',
        position: { x: top.x + SEGMENT * (i + 0.5), y: top.y },
      });
      segment.createShape(Shape.box(SEGMENT / 2, 0.15 - 0.02 * i), {
        density: 2,
        filter: { groupIndex: -1 },
      });
      ctx.render.setBodyStyle(segment, { color: 0xe0b040 });
      world.createJoint({
        type: 'prismatic',
        bodyA: previous,
        bodyB: segment,
        anchor: { x: top.x + SEGMENT * i, y: top.y },
        axis: { x: 1, y: 0 },
        enableLimit: true,
        lower: 0,
        upper: 0,
      });
      previous = segment;
    }
    const hook = { x: top.x + SEGMENT * SEGMENTS - 0.1, y: top.y };
    const rope: Joint[] = [];
    for (let i = 0; i < RODS; i++) {
      const bead = world.createBody({ type: 'dynamic', position: { x: hook.x, y: hook.y - ROD * (i + 1) } });
      bead.createShape(Shape.circle(0.05), { density: 20, filter: { groupIndex: -1 } });
      ctx.render.setBodyStyle(bead, { color: 0x9aa3b5 });
      rope.push(
        world.createJoint({
          type: 'distance',
          bodyA: previous,
          bodyB: bead,
          localAnchorA: previous.getLocalPoint(i === 0 ? hook : previous.position),
          localAnchorB: { x: 0, y: 0 },
          length: ROD,
        }),
      );
      previous = bead;
    }
    const crate = world.createBody({
      type: 'dynamic',
      position: { x: hook.x, y: hook.y - ROD * (RODS + 1) - 0.5 },
    });
    crate.createShape(Shape.box(0.5, 0.5), { density: 40, filter: { groupIndex: -1 } });
    ctx.render.setBodyStyle(crate, { color: 0x6fb3d9 });
    rope.push(
      world.createJoint({
        type: 'distance',
        bodyA: previous,
        bodyB: crate,
        localAnchorA: { x: 0, y: 0 },
        localAnchorB: { x: 0, y: 0.5 },
        length: ROD,
      }),
    );
    crate.applyLinearImpulse({ x: 80, y: 0 });

    let worst = 0;
    ctx.track(
      world.on('postStep', () => {
        const now = Math.max(largestGap(chain), largestGap(rope));
        worst = Math.max(worst, now);
        ctx.setStatus(
          `largest joint gap now ${(now * 1000).toFixed(2)} mm, worst so far ${(worst * 1000).toFixed(2)} mm`,
        );
      }),
    );
    return { world, ball, crate, chain, rope };
  },
};
