import type { MatterProgram } from './program';

const IDLE = '#5aa9e6';
const INSIDE = '#e6a04b';

export const sensors: MatterProgram = {
  id: 'sensors',
  title: 'Sensors',
  description:
    'A sensor zone (it detects, it does not collide): balls inside it turn orange on collisionStart, blue again on collisionEnd.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Composites, Events, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    const zone = Bodies.rectangle(400, 470, 360, 180, {
      isSensor: true,
      isStatic: true,
      render: { fillStyle: 'transparent', strokeStyle: INSIDE, lineWidth: 2 },
    });
    const balls = Composites.stack(160, 40, 12, 3, 6, 6, (x: number, y: number) =>
      Bodies.circle(x, y, 16, { restitution: 0.4, render: { fillStyle: IDLE } }),
    );
    const ground = Bodies.rectangle(400, 600, 820, 40, { isStatic: true, render: { fillStyle: '#3a4150' } });
    const walls = [
      Bodies.rectangle(-10, 300, 20, 600, { isStatic: true }),
      Bodies.rectangle(810, 300, 20, 600, { isStatic: true }),
    ];
    Composite.add(engine.world, [zone, balls, ground, ...walls]);

    Events.on(engine, 'collisionStart', (event: { pairs: { bodyA: typeof zone; bodyB: typeof zone }[] }) => {
      for (const { bodyA, bodyB } of event.pairs) {
        if (bodyA === zone) bodyB.render.fillStyle = INSIDE;
        else if (bodyB === zone) bodyA.render.fillStyle = INSIDE;
      }
    });
    Events.on(engine, 'collisionEnd', (event: { pairs: { bodyA: typeof zone; bodyB: typeof zone }[] }) => {
      for (const { bodyA, bodyB } of event.pairs) {
        if (bodyA === zone) bodyB.render.fillStyle = IDLE;
        else if (bodyB === zone) bodyA.render.fillStyle = IDLE;
      }
    });

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
    return { engine, render, runner, mouseConstraint, zone };
  },
};
