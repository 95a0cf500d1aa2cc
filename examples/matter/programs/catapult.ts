import type { MatterProgram } from './program';

export const catapult: MatterProgram = {
  id: 'catapult',
  title: 'Catapult',
  description:
    'A plank on a pivot with a ball on its low end; a heavy block falls on the high end and throws the ball.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Body, Bodies, Composite, Constraint, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    // the plank and the post it turns on share a group that never collides with itself
    const frame = Body.nextGroup(true);
    const plank = Bodies.rectangle(400, 500, 360, 16, {
      collisionFilter: { group: frame },
      render: { fillStyle: '#c98b4a' },
    });
    const post = Bodies.trapezoid(400, 550, 60, 60, 0.8, {
      isStatic: true,
      collisionFilter: { group: frame },
      render: { fillStyle: '#3a4150' },
    });
    const pivot = Constraint.create({
      bodyA: plank,
      pointB: { x: 400, y: 500 },
      stiffness: 1,
      length: 0,
      render: { strokeStyle: '#d8dce4' },
    });
    const ball = Bodies.circle(250, 476, 14, { render: { fillStyle: '#e6a04b' } });
    const block = Bodies.rectangle(550, 80, 70, 70, { density: 0.02, render: { fillStyle: '#8a92a3' } });
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    Composite.add(engine.world, [plank, post, pivot, ball, block, ground]);

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
