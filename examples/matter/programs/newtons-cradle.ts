import type { MatterProgram } from './program';

export const newtonsCradle: MatterProgram = {
  id: 'newtons-cradle',
  title: "Newton's cradle",
  description:
    'Five balls on strings, the first pulled aside and let go: the knock should pass through to the last ball and back.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Body, Composite, Composites, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    // five balls of radius 30 hanging 220 px below a bar at y = 120
    const cradle = Composites.newtonsCradle(290, 120, 5, 30, 220);
    for (const ball of cradle.bodies) ball.render.fillStyle = '#d8dce4';
    for (const string of cradle.constraints) string.render.strokeStyle = '#8a92a3';
    // the first ball drawn up to the left along its string's arc, about 50 degrees out
    Body.translate(cradle.bodies[0], { x: -170, y: -78 });
    Composite.add(engine.world, cradle);

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
