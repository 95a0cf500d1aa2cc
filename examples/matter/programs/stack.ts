import type { MatterProgram } from './program';

export const stack: MatterProgram = {
  id: 'stack',
  title: 'Stack',
  description:
    'Forty-two boxes stacked in a wall of six columns: it should stand still until you pull one out.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Composites, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const wall = Composites.stack(250, 290, 6, 7, 0, 0, (x: number, y: number) =>
      Bodies.rectangle(x, y, 50, 40, {
        render: { fillStyle: '#e6a04b', strokeStyle: '#15171d', lineWidth: 1 },
      }),
    );
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    Composite.add(engine.world, [wall, ground]);

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
