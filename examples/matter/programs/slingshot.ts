import type { MatterProgram } from './program';

export const slingshot: MatterProgram = {
  id: 'slingshot',
  title: 'Slingshot',
  description:
    'Pull the ball back on its elastic and let go: once it flies past the anchor a new ball is loaded. Knock the tower down.',
  run(Matter, { element, width, height }) {
    const {
      Engine,
      Render,
      Runner,
      Body,
      Bodies,
      Composite,
      Composites,
      Constraint,
      Events,
      Mouse,
      MouseConstraint,
    } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const anchor = { x: 170, y: 430 };
    const ballOptions = { density: 0.004, render: { fillStyle: '#e6a04b' } };
    let ball = Bodies.circle(anchor.x, anchor.y, 18, ballOptions);
    const elastic = Constraint.create({
      pointA: anchor,
      bodyB: ball,
      length: 0.01,
      stiffness: 0.05,
      damping: 0.01,
      render: { strokeStyle: '#d8dce4', lineWidth: 2 },
    });

    const platform = Bodies.rectangle(610, 420, 220, 20, {
      isStatic: true,
      render: { fillStyle: '#3a4150' },
    });
    const tower = Composites.pyramid(520, 245, 7, 6, 0, 0, (x: number, y: number) =>
      Bodies.rectangle(x, y, 26, 40, {
        render: { fillStyle: '#5aa9e6', strokeStyle: '#15171d', lineWidth: 1 },
      }),
    );
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    Composite.add(engine.world, [ground, platform, tower, ball, elastic]);

    const mouse = Mouse.create(render.canvas);
    const mouseConstraint = MouseConstraint.create(engine, {
      mouse,
      constraint: { stiffness: 0.2, render: { visible: false } },
    });
    Composite.add(engine.world, mouseConstraint);
    render.mouse = mouse;

    // released and flown past the anchor: the ball goes free and a new one takes its place
    Events.on(engine, 'afterUpdate', () => {
      if (mouse.button === -1 && (ball.position.x > anchor.x + 20 || ball.position.y < anchor.y - 20)) {
        if (Body.getSpeed(ball) > 40) Body.setSpeed(ball, 40);
        ball = Bodies.circle(anchor.x, anchor.y, 18, ballOptions);
        Composite.add(engine.world, ball);
        elastic.bodyB = ball;
      }
    });

    Render.run(render);
    const runner = Runner.create();
    Runner.run(runner, engine);
    return { engine, render, runner, mouseConstraint, elastic };
  },
};
