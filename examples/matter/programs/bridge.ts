import type { MatterProgram } from './program';

export const bridge: MatterProgram = {
  id: 'bridge',
  title: 'Bridge',
  description:
    'Twelve planks pinned end to end between two cliffs, with boxes and balls dropped on them: the bridge should sag and hold.',
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
      Mouse,
      MouseConstraint,
    } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    // planks of one group, so that neighbours pinned together do not also push each other apart
    const planks = Body.nextGroup(true);
    const deck = Composites.stack(100, 290, 12, 1, 0, 0, (x: number, y: number) =>
      Bodies.rectangle(x, y, 50, 16, {
        collisionFilter: { group: planks },
        density: 0.004,
        frictionAir: 0.04,
        render: { fillStyle: '#c98b4a' },
      }),
    );
    // each plank's right end pinned to the next one's left end
    Composites.chain(deck, 0.5, 0, -0.5, 0, { stiffness: 1, length: 0, render: { visible: false } });
    const first = deck.bodies[0];
    const last = deck.bodies[deck.bodies.length - 1];
    Composite.add(deck, [
      Constraint.create({
        pointA: { x: 100, y: 298 },
        bodyB: first,
        pointB: { x: -25, y: 0 },
        length: 0,
        stiffness: 1,
      }),
      Constraint.create({
        pointA: { x: 700, y: 298 },
        bodyB: last,
        pointB: { x: 25, y: 0 },
        length: 0,
        stiffness: 1,
      }),
    ]);

    const cliffs = [
      Bodies.rectangle(50, 450, 100, 300, { isStatic: true, render: { fillStyle: '#3a4150' } }),
      Bodies.rectangle(750, 450, 100, 300, { isStatic: true, render: { fillStyle: '#3a4150' } }),
    ];
    const load = Composites.stack(300, 60, 5, 2, 10, 10, (x: number, y: number, column: number) =>
      column % 2 === 0
        ? Bodies.rectangle(x, y, 36, 36, { render: { fillStyle: '#5aa9e6' } })
        : Bodies.circle(x, y, 18, { render: { fillStyle: '#e6a04b' } }),
    );
    Composite.add(engine.world, [deck, ...cliffs, load]);

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
