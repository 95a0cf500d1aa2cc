import type { MatterProgram } from './program';

export const pyramid: MatterProgram = {
  id: 'pyramid',
  title: 'Pyramid',
  description:
    'Sixty-four boxes in a pyramid eight high: it should settle and stand, the top box staying on the middle line.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Composites, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    // fifteen boxes at the bottom from x = 100 to 700, so the pyramid's axis is x = 400
    const boxes = Composites.pyramid(100, 260, 15, 10, 0, 0, (x: number, y: number) =>
      Bodies.rectangle(x, y, 40, 40, {
        render: { fillStyle: '#5aa9e6', strokeStyle: '#15171d', lineWidth: 1 },
      }),
    );
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    Composite.add(engine.world, [boxes, ground]);

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
