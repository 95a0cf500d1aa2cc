import type { MatterProgram } from './program';

export const wreckingBall: MatterProgram = {
  id: 'wrecking-ball',
  title: 'Wrecking ball',
  description:
    'A heavy ball on a 300 px rod, let go level with its pivot, swings down into a stack of boxes.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Composites, Constraint, Mouse, MouseConstraint } =
      Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const boxes = Composites.stack(420, 290, 5, 7, 0, 0, (x: number, y: number) =>
      Bodies.rectangle(x, y, 40, 40, {
        render: { fillStyle: '#5aa9e6', strokeStyle: '#15171d', lineWidth: 1 },
      }),
    );
    const pivot = { x: 330, y: 50 };
    const ball = Bodies.circle(pivot.x - 300, pivot.y, 40, {
      density: 0.04,
      frictionAir: 0.005,
      render: { fillStyle: '#8a92a3' },
    });
    const rod = Constraint.create({ pointA: pivot, bodyB: ball, render: { strokeStyle: '#d8dce4' } });
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    Composite.add(engine.world, [boxes, ball, rod, ground]);

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
