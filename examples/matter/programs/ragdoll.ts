import type { MatterComposite } from '../../../src/matter/composite';
import type { MatterNamespace, MatterProgram } from './program';

/** A ragdoll of eight bodies (head, chest, arms and legs in two pieces) pinned at its joints, centred on (x, y). */
function ragdoll(Matter: MatterNamespace, x: number, y: number, colour: string): MatterComposite {
  const { Body, Bodies, Composite, Constraint } = Matter;
  // the pieces of one doll never collide with each other
  const self = Body.nextGroup(true);
  const look = { collisionFilter: { group: self }, render: { fillStyle: colour } };
  const limb = { ...look, chamfer: { radius: 6 } };

  const chest = Bodies.rectangle(x, y, 34, 56, { ...look, chamfer: { radius: 10 } });
  const head = Bodies.circle(x, y - 44, 16, look);
  const upperArmL = Bodies.rectangle(x - 24, y - 6, 12, 30, limb);
  const lowerArmL = Bodies.rectangle(x - 24, y + 26, 12, 30, limb);
  const upperArmR = Bodies.rectangle(x + 24, y - 6, 12, 30, limb);
  const lowerArmR = Bodies.rectangle(x + 24, y + 26, 12, 30, limb);
  const thighL = Bodies.rectangle(x - 9, y + 46, 14, 36, limb);
  const shinL = Bodies.rectangle(x - 9, y + 84, 14, 36, limb);
  const thighR = Bodies.rectangle(x + 9, y + 46, 14, 36, limb);
  const shinR = Bodies.rectangle(x + 9, y + 84, 14, 36, limb);

  /** a soft pin between the world point (px, py) on body a and the same point on body b */
  const joint = (a: typeof chest, b: typeof chest, px: number, py: number) =>
    Constraint.create({
      bodyA: a,
      pointA: { x: px - a.position.x, y: py - a.position.y },
      bodyB: b,
      pointB: { x: px - b.position.x, y: py - b.position.y },
      stiffness: 0.6,
      render: { visible: false },
    });

  const doll = Composite.create({ label: 'Ragdoll' });
  Composite.add(doll, [
    chest,
    head,
    upperArmL,
    lowerArmL,
    upperArmR,
    lowerArmR,
    thighL,
    shinL,
    thighR,
    shinR,
  ]);
  Composite.add(doll, [
    joint(chest, head, x, y - 28),
    joint(chest, upperArmL, x - 24, y - 20),
    joint(upperArmL, lowerArmL, x - 24, y + 10),
    joint(chest, upperArmR, x + 24, y - 20),
    joint(upperArmR, lowerArmR, x + 24, y + 10),
    joint(chest, thighL, x - 9, y + 28),
    joint(thighL, shinL, x - 9, y + 65),
    joint(chest, thighR, x + 9, y + 28),
    joint(thighR, shinR, x + 9, y + 65),
  ]);
  return doll;
}

export const ragdolls: MatterProgram = {
  id: 'ragdoll',
  title: 'Ragdolls',
  description:
    'Four ragdolls, each ten bodies held by soft pins at the joints, tumbling down a flight of steps.',
  run(Matter, { element, width, height }) {
    const { Engine, Render, Runner, Bodies, Composite, Mouse, MouseConstraint } = Matter;

    const engine = Engine.create();
    const render = Render.create({
      element,
      engine,
      options: { width, height, wireframes: false, background: '#15171d' },
    });

    // six steps down to the right, 60 px high and 110 px deep
    const steps = [];
    for (let i = 0; i < 6; i++) {
      const top = 240 + i * 60;
      steps.push(
        Bodies.rectangle(55 + i * 110, top + (600 - top) / 2 + 10, 110, 600 - top + 20, {
          isStatic: true,
          render: { fillStyle: '#3a4150' },
        }),
      );
    }
    steps.push(Bodies.rectangle(735, 600, 150, 40, { isStatic: true, render: { fillStyle: '#3a4150' } }));
    const dolls = [
      ragdoll(Matter, 70, 100, '#e6a04b'),
      ragdoll(Matter, 200, 40, '#5aa9e6'),
      ragdoll(Matter, 330, 120, '#d8dce4'),
      ragdoll(Matter, 450, 60, '#c05a5a'),
    ];
    Composite.add(engine.world, [...steps, ...dolls]);

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
