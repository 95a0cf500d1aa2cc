import type { MatterProgram } from './program';

export const cloth: MatterProgram = {
  id: 'cloth',
  title: 'Cloth',
  description:
    'A sheet of 20 by 12 particles linked by soft springs, its top row pinned in place, draping over a ball and a box.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Body, Bodies, Composite, Composites, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    // the particles do not collide with each other (one group), only with what is under the sheet
    const sheet = Body.nextGroup(true);
    const columns = 20;
    const clothBody = Composites.softBody(
      160,
      40,
      columns,
      12,
      6,
      6,
      false,
      7,
      {
        friction: 0.0001,
        collisionFilter: { group: sheet },
        render: { visible: false },
      },
      { stiffness: 0.06, render: { type: 'line', anchors: false, strokeStyle: '#d8dce4' } },
    );
    for (let i = 0; i < columns; i++) Body.setStatic(clothBody.bodies[i], true);

    Composite.add(engine.world, [
      clothBody,
      Bodies.circle(300, 360, 60, { isStatic: true, render: { fillStyle: '#5aa9e6' } }),
      Bodies.rectangle(500, 340, 120, 60, { isStatic: true, render: { fillStyle: '#e6a04b' } }),
      Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } }),
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
