import type { MatterProgram } from './program';

export const car: MatterProgram = {
  id: 'car',
  title: 'Car',
  description: 'Two cars (a body and two pinned wheels each) rolling down a zigzag of slopes under gravity.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Composites, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const slope = { isStatic: true, render: { fillStyle: '#3a4150' } };
    const slopes = [
      Bodies.rectangle(330, 180, 640, 20, { ...slope, angle: 0.12 }),
      Bodies.rectangle(470, 350, 640, 20, { ...slope, angle: -0.12 }),
      Bodies.rectangle(330, 520, 640, 20, { ...slope, angle: 0.08 }),
      Bodies.rectangle(400, 600, 820, 40, slope),
      Bodies.rectangle(790, 480, 20, 200, slope),
    ];
    const small = Composites.car(120, 100, 120, 24, 22);
    const large = Composites.car(330, 60, 170, 34, 30);
    for (const part of small.bodies) part.render.fillStyle = '#e6a04b';
    for (const part of large.bodies) part.render.fillStyle = '#5aa9e6';
    Composite.add(engine.world, [...slopes, small, large]);

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
