import * as decomp from 'poly-decomp-es';
import type { MatterProgram } from './program';

// outlines in px, drawn around their own origin
const ARROW = 'L 0 -30 L 30 0 L 12 0 L 12 34 L -12 34 L -12 0 L -30 0';
const CHEVRON = 'L -34 -20 L 0 4 L 34 -20 L 34 4 L 0 28 L -34 4';
const STAR = 'L 0 -34 L 9 -12 L 32 -11 L 14 4 L 20 28 L 0 14 L -20 28 L -14 4 L -32 -11 L -9 -12';
const ELL = 'L -24 -30 L -8 -30 L -8 14 L 26 14 L 26 30 L -24 30';
const CUP = 'L -30 -26 L -16 -26 L -16 12 L 16 12 L 16 -26 L 30 -26 L 30 26 L -30 26';

export const concave: MatterProgram = {
  id: 'concave',
  title: 'Concave shapes',
  description:
    'Arrows, chevrons, stars, L-shapes and cups made with Bodies.fromVertices, each split into convex parts, piling up.',
  run(Matter, { element, width, height }) {
    const {
      Engine,
      Render,
      Runner,
      Bodies,
      Common,
      Composite,
      Composites,
      Vertices,
      Mouse,
      MouseConstraint,
    } = Matter;
    // matter.js splits concave outlines with poly-decomp when it is given one
    Common.setDecomp(decomp);

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const outlines = [ARROW, CHEVRON, STAR, ELL, CUP].map((path) => Vertices.fromPath(path));
    const colours = ['#e6a04b', '#5aa9e6', '#d8dce4', '#c05a5a', '#7bc47f'];
    const shapes = Composites.stack(
      120,
      40,
      6,
      4,
      30,
      20,
      (x: number, y: number, column: number, row: number) => {
        const k = (column + row * 2) % outlines.length;
        return Bodies.fromVertices(x, y, outlines[k], {
          friction: 0.3,
          render: { fillStyle: colours[k], strokeStyle: colours[k], lineWidth: 1 },
        });
      },
    );
    const pegs = [180, 400, 620].map((x) =>
      Bodies.polygon(x, 430, 3, 30, { isStatic: true, angle: Math.PI / 2, render: { fillStyle: '#3a4150' } }),
    );
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    const walls = [
      Bodies.rectangle(-10, 300, 20, 600, { isStatic: true }),
      Bodies.rectangle(810, 300, 20, 600, { isStatic: true }),
    ];
    Composite.add(engine.world, [shapes, ...pegs, ground, ...walls]);

    const mouse = Mouse.create(render.canvas);
    const mouseConstraint = MouseConstraint.create(engine, {
      mouse,
      constraint: { stiffness: 0.2, render: { visible: false } },
    });
    Composite.add(engine.world, mouseConstraint);
    render.mouse = mouse;

    Render.run(render);
    const runner = Runner.create();
    Runner.run(runner, engine);
    return { engine, render, runner, mouseConstraint };
  },
};
