import type { MatterProgram } from './program';

export const softBody: MatterProgram = {
  id: 'soft-body',
  title: 'Soft body',
  description:
    'Three grids of balls held by springs along and across: jelly blocks that drop, squash and wobble.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Composites, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const jelly = (x: number, y: number, columns: number, rows: number, radius: number, colour: string) =>
      Composites.softBody(
        x,
        y,
        columns,
        rows,
        0,
        0,
        true,
        radius,
        { friction: 0.05, frictionStatic: 0.1, render: { fillStyle: colour } },
        { render: { strokeStyle: '#8a92a3' } },
      );
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    const ledge = Bodies.rectangle(230, 360, 300, 20, {
      isStatic: true,
      angle: 0.2,
      render: { fillStyle: '#3a4150' },
    });
    Composite.add(engine.world, [
      ground,
      ledge,
      jelly(120, 60, 5, 5, 16, '#e6a04b'),
      jelly(430, 120, 8, 3, 14, '#5aa9e6'),
      jelly(560, 300, 4, 4, 20, '#c05a5a'),
    ]);

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
