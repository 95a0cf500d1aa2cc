import { describe, expect, it } from 'vitest';
import Matter from '../../src/matter/index';

/** A canvas whose 2D context writes down what is drawn: the paths' points and each fill's colour. */
function recordingCanvas(width = 800, height = 600) {
  const fills: { style: string; points: [number, number][] }[] = [];
  let path: [number, number][] = [];
  const context = {
    fillStyle: '',
    strokeStyle: '',
    lineWidth: 1,
    globalAlpha: 1,
    transform: [1, 0, 0, 1, 0, 0],
    setTransform(...m: number[]) {
      this.transform = m;
    },
    beginPath() {
      path = [];
    },
    moveTo(x: number, y: number) {
      path.push([x, y]);
    },
    lineTo(x: number, y: number) {
      path.push([x, y]);
    },
    arc(x: number, y: number) {
      path.push([x, y]);
    },
    rect() {},
    closePath() {},
    fill() {
      fills.push({ style: this.fillStyle, points: path });
    },
    stroke() {},
    fillRect() {},
    strokeRect() {},
    translate() {},
    rotate() {},
    drawImage() {},
  };
  const canvas = { width, height, style: {}, getContext: () => context, setAttribute() {} };
  return { canvas, context, fills };
}

describe('fulcrum/matter Render', () => {
  it('fills each body with its fillStyle along its vertices, and lookAt frames the bodies', () => {
    const engine = Matter.Engine.create();
    const box = Matter.Bodies.rectangle(200, 100, 40, 40, { render: { fillStyle: '#ff0000' } as never });
    const ball = Matter.Bodies.circle(400, 100, 20, { render: { fillStyle: '#00ff00' } as never });
    Matter.Composite.add(engine.world, [box, ball]);
    const { canvas, context, fills } = recordingCanvas();
    const render = Matter.Render.create({ canvas: canvas as never, engine, options: { wireframes: false } });
    Matter.Render.world(render);
    const boxFill = fills.find((f) => f.style === '#ff0000');
    expect(boxFill?.points).toEqual(box.vertices.map((v) => [v.x, v.y]));
    // the ball is drawn as the circle it is: one arc about its centre
    expect(fills.find((f) => f.style === '#00ff00')?.points).toEqual([[400, 100]]);
    // lookAt: the two bodies fill the view, padded, at the canvas's aspect ratio (800 / 600)
    Matter.Render.lookAt(render, [box, ball], { x: 10, y: 10 });
    const b = render.bounds;
    expect((b.max.x - b.min.x) / (b.max.y - b.min.y)).toBeCloseTo(800 / 600, 9);
    const width = ball.bounds.max.x + 10 - (box.bounds.min.x - 10); // wider than high: it sets the scale
    expect(b.min.x).toBeCloseTo(170, 9);
    expect(b.max.x).toBeCloseTo(170 + width, 9);
    const transforms: number[][] = [];
    const setTransform = context.setTransform.bind(context);
    context.setTransform = (...m: number[]) => {
      transforms.push(m);
      setTransform(...m);
    };
    Matter.Render.world(render);
    // the background at identity, the bodies with the view's transform, then identity again
    const [sx, , , sy, tx, ty] = transforms[1];
    expect(sx).toBeCloseTo(800 / width, 9);
    expect(sy).toBeCloseTo(800 / width, 9);
    expect(tx).toBeCloseTo(-170 * sx, 9);
    expect(ty).toBeCloseTo(-b.min.y * sy, 9);
    expect(transforms[2]).toEqual([1, 0, 0, 1, 0, 0]);
  });
  it("draws a sprite body's texture at its position and angle, scaled by xScale and yScale about its offset", () => {
    const page = globalThis as unknown as Record<string, unknown>;
    page.Image = class {
      width = 64;
      height = 32;
      src = '';
    };
    try {
      const { canvas, context } = recordingCanvas();
      const calls: unknown[][] = [];
      Object.assign(context, {
        translate: (...args: number[]) => calls.push(['translate', ...args]),
        rotate: (...args: number[]) => calls.push(['rotate', ...args]),
        drawImage: (image: { src: string }, ...args: number[]) =>
          calls.push(['drawImage', image.src, ...args]),
      });
      const engine = Matter.Engine.create();
      const crate = Matter.Bodies.rectangle(200, 100, 128, 16, {
        angle: 0.25,
        render: { sprite: { texture: 'crate.png', xScale: 2, yScale: 0.5 } },
      });
      Matter.Composite.add(engine.world, crate);
      // sprites are drawn when wireframes are off (matter's default is on)
      const render = Matter.Render.create({
        engine,
        canvas: canvas as never,
        options: { wireframes: false } as never,
      });
      Matter.Render.world(render);
      // the image (64 by 32) drawn 128 by 16, centred on the body (offsets 0.5), turned with it
      const rounded = calls.map((call) =>
        call.map((v) => (typeof v === 'number' ? Math.round(v * 1e9) / 1e9 : v)),
      );
      expect(rounded).toEqual([
        ['translate', 200, 100],
        ['rotate', 0.25],
        ['drawImage', 'crate.png', -64, -8, 128, 16],
        ['rotate', -0.25],
        ['translate', -200, -100],
      ]);
    } finally {
      delete page.Image;
    }
  });
});
