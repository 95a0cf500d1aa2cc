// drawWorld and the colour text in Node: a recording DebugDraw stands in for the canvas.
import { describe, expect, it } from 'vitest';
import { Shape, World } from '../../../src/index';
import type { Transform, Vec2 } from '../../../src/math/vec2';
import { CssColors, cssColor } from '../../../src/render/color';
import {
  type DebugDraw,
  type DebugDrawFlags,
  defaultDebugDrawFlags,
  drawWorld,
} from '../../../src/render/debug-draw';

interface Line {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  color: number;
}

/** Records lines and points as numbers (the points handed over are reused, so they are copied). */
class Recorder implements DebugDraw {
  readonly lines: Line[] = [];
  readonly points: Vec2[] = [];
  drawPolygon(): void {}
  drawCircle(): void {}
  drawCapsule(): void {}
  drawLine(p1: Vec2, p2: Vec2, color: number): void {
    this.lines.push({ x1: p1.x, y1: p1.y, x2: p2.x, y2: p2.y, color });
  }
  drawPoint(p: Vec2): void {
    this.points.push({ x: p.x, y: p.y });
  }
  drawAABB(): void {}
  drawTransform(): void {}
}

const none: DebugDrawFlags = {
  ...defaultDebugDrawFlags,
  shapes: false,
  joints: false,
  aabbs: false,
  contacts: false,
  contactNormals: false,
  velocities: false,
  centersOfMass: false,
};

/** Draws every body `shift` to the right of where it is. */
function shifted(shift: number) {
  return {
    transformOf(body: { position: Vec2; angle: number }, out: Transform): Transform {
      const p = body.position;
      out.p.x = p.x + shift;
      out.p.y = p.y;
      out.q.c = Math.cos(body.angle);
      out.q.s = Math.sin(body.angle);
      return out;
    },
  };
}

describe('cssColor', () => {
  it('writes #rrggbb, and #rrggbbaa below full alpha (alpha clamped to [0, 1])', () => {
    expect(cssColor(0xff8000)).toBe('#ff8000');
    expect(cssColor(0x00ff00, 0.5)).toBe('#00ff0080');
    expect(cssColor(0x123456, 0)).toBe('#12345600');
    expect(cssColor(0xabcdef, 2)).toBe('#abcdef');
    expect(cssColor(0xabcdef, -1)).toBe('#abcdef00');
  });

  it('gives the same text through a renderer memo, asked once or many times', () => {
    const memo = new CssColors();
    for (let round = 0; round < 2; round++) {
      for (const [color, alpha] of [
        [0xff8000, 1],
        [0x00ff00, 0.5],
        [0x000001, 0.25],
      ]) {
        expect(memo.get(color, alpha)).toBe(cssColor(color, alpha));
      }
    }
  });
});

describe('drawWorld', () => {
  it('draws a segment between its world end points', () => {
    const world = new World();
    world
      .createBody({ position: { x: 1, y: 2 } })
      .createShape(Shape.segment({ x: -1, y: 0 }, { x: 1, y: 0 }));
    const draw = new Recorder();
    drawWorld(world, draw, { ...none, shapes: true });
    expect(draw.lines).toHaveLength(1);
    const line = draw.lines[0];
    expect([line.x1, line.y1, line.x2, line.y2]).toEqual([0, 2, 2, 2]);
  });

  it('draws contact points and a tenth of a second of velocity where transformOf puts the bodies', () => {
    const world = new World();
    world.createBody({ position: { x: 0, y: -1 } }).createShape(Shape.box(5, 1));
    const box = world.createBody({ type: 'dynamic', position: { x: 0, y: 0.5 } });
    box.createShape(Shape.box(0.5, 0.5));
    for (let i = 0; i < 30; i++) world.step(1 / 60);
    const here = new Recorder();
    drawWorld(world, here, { ...none, contacts: true });
    const there = new Recorder();
    drawWorld(world, there, { ...none, contacts: true }, shifted(10));
    // a box resting on the ground touches it at its two bottom corners, at the ground's top (y = 0)
    expect(here.points).toHaveLength(2);
    for (const p of here.points) {
      expect(Math.abs(Math.abs(p.x) - 0.5)).toBeLessThan(0.01);
      expect(Math.abs(p.y)).toBeLessThan(0.01);
    }
    expect(there.points).toEqual(here.points.map((p) => ({ x: p.x + 10, y: p.y })));

    box.setLinearVelocity({ x: 3, y: -2 });
    const moving = new Recorder();
    drawWorld(world, moving, { ...none, velocities: true }, shifted(10));
    expect(moving.lines).toHaveLength(1);
    const line = moving.lines[0];
    const c = box.worldCenter;
    expect(line.x1).toBeCloseTo(c.x + 10, 12);
    expect(line.y1).toBeCloseTo(c.y, 12);
    expect(line.x2 - line.x1).toBeCloseTo(0.3, 12);
    expect(line.y2 - line.y1).toBeCloseTo(-0.2, 12);
  });

  it('draws joint anchors where transformOf puts their bodies', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const a = world.createBody({ position: { x: 0, y: 0 } });
    const b = world.createBody({ type: 'dynamic', position: { x: 2, y: 0 } });
    b.createShape(Shape.circle(0.25));
    world.createJoint({
      type: 'distance',
      bodyA: a,
      bodyB: b,
      localAnchorA: { x: 0.5, y: 0 },
      localAnchorB: { x: 0, y: 0.25 },
    });
    const draw = new Recorder();
    drawWorld(world, draw, { ...none, joints: true }, shifted(10));
    // a distance joint: one line between its anchors, and a dot on each
    expect(draw.lines).toHaveLength(1);
    expect([draw.lines[0].x1, draw.lines[0].y1, draw.lines[0].x2, draw.lines[0].y2]).toEqual([
      10.5, 0, 12, 0.25,
    ]);
    expect(draw.points).toEqual([
      { x: 10.5, y: 0 },
      { x: 12, y: 0.25 },
    ]);
  });
});
