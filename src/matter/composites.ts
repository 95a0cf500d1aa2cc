import { Bodies, type BodiesOptions } from './bodies';
import { Body, type MatterBody } from './body';
import { Common } from './common';
import { Composite, type MatterComposite } from './composite';
import { Constraint, type ConstraintOptions } from './constraint';

type Place = (
  x: number,
  y: number,
  column: number,
  row: number,
  lastBody: MatterBody | undefined,
  i: number,
) => MatterBody | null | undefined;

/** The width and height of a body's bounds. */
function size(body: MatterBody): { width: number; height: number } {
  return { width: body.bounds.max.x - body.bounds.min.x, height: body.bounds.max.y - body.bounds.min.y };
}

/** matter.js's `Composites`: ready-made composites, laid out as matter lays them. A plain, mutable module object. */
export const Composites = {
  /**
   * A grid of `columns` by `rows` bodies made by `callback`, each placed with its bounds' top left
   * corner where the previous one's right edge ended plus `columnGap` (rows `rowGap` apart, each as
   * high as its tallest body).
   */
  stack(
    x: number,
    y: number,
    columns: number,
    rows: number,
    columnGap: number,
    rowGap: number,
    callback: Place,
  ): MatterComposite {
    const stack = Composite.create({ label: 'Stack' });
    let cy = y;
    let lastBody: MatterBody | undefined;
    let i = 0;
    for (let row = 0; row < rows; row++) {
      let cx = x;
      let tallest = 0;
      for (let column = 0; column < columns; column++) {
        const body = callback(cx, cy, column, row, lastBody, i);
        if (!body) {
          cx += columnGap;
          continue;
        }
        const { width, height } = size(body);
        tallest = Math.max(tallest, height);
        Body.translate(body, { x: width * 0.5, y: height * 0.5 });
        cx = body.bounds.max.x + columnGap;
        Composite.add(stack, body);
        lastBody = body;
        i++;
      }
      cy += tallest + rowGap;
    }
    return stack;
  },

  /**
   * A stack cut to a pyramid: the bottom row `columns` wide, each row above one body narrower at
   * both ends, at most `rows` rows.
   */
  pyramid(
    x: number,
    y: number,
    columns: number,
    rows: number,
    columnGap: number,
    rowGap: number,
    callback: Place,
  ): MatterComposite {
    const levels = Math.min(rows, Math.ceil(columns / 2));
    return Composites.stack(x, y, columns, rows, columnGap, rowGap, (_sx, sy, column, row, lastBody, i) => {
      if (row > levels) return null;
      const fromTop = levels - row;
      if (column < fromTop || column > columns - 1 - fromTop) return null;
      const lastWidth = lastBody ? size(lastBody).width : 0;
      // the first body was placed before any width was known: move it to its column now
      if (i === 1 && lastBody)
        Body.translate(lastBody, { x: (column + (columns % 2 === 1 ? 1 : -1)) * lastWidth, y: 0 });
      const offset = lastBody ? column * lastWidth : 0;
      return callback(x + offset + column * columnGap, sy, column, fromTop, lastBody, i);
    });
  },

  /**
   * Links each body of `composite` to the next by a constraint from the point at (xOffsetA,
   * yOffsetA) of the first's size from its centre to the point at (xOffsetB, yOffsetB) of the
   * second's.
   */
  chain(
    composite: MatterComposite,
    xOffsetA: number,
    yOffsetA: number,
    xOffsetB: number,
    yOffsetB: number,
    options?: ConstraintOptions,
  ): MatterComposite {
    const bodies = composite.bodies;
    for (let i = 1; i < bodies.length; i++) {
      const bodyA = bodies[i - 1];
      const bodyB = bodies[i];
      const a = size(bodyA);
      const b = size(bodyB);
      Composite.add(
        composite,
        Constraint.create({
          bodyA,
          pointA: { x: a.width * xOffsetA, y: a.height * yOffsetA },
          bodyB,
          pointB: { x: b.width * xOffsetB, y: b.height * yOffsetB },
          ...options,
        }),
      );
    }
    composite.label += ' Chain';
    return composite;
  },

  /**
   * Links the bodies of `composite`, a grid of `columns` by `rows` in row order, to their right and
   * lower neighbours, and across the diagonals when `crossBrace`.
   */
  mesh(
    composite: MatterComposite,
    columns: number,
    rows: number,
    crossBrace: boolean,
    options?: ConstraintOptions,
  ): MatterComposite {
    const bodies = composite.bodies;
    const at = (column: number, row: number) => bodies[column + row * columns];
    const link = (bodyA: MatterBody, bodyB: MatterBody) =>
      Composite.add(composite, Constraint.create({ bodyA, bodyB, ...options }));
    for (let row = 0; row < rows; row++) {
      for (let column = 1; column < columns; column++) link(at(column - 1, row), at(column, row));
      if (row === 0) continue;
      for (let column = 0; column < columns; column++) {
        link(at(column, row - 1), at(column, row));
        if (crossBrace && column > 0) link(at(column - 1, row - 1), at(column, row));
        if (crossBrace && column < columns - 1) link(at(column + 1, row - 1), at(column, row));
      }
    }
    composite.label += ' Mesh';
    return composite;
  },

  /** `number` balls of radius `size` hanging `length` below a bar at y, each on a rigid constraint. */
  newtonsCradle(x: number, y: number, number: number, size: number, length: number): MatterComposite {
    const cradle = Composite.create({ label: 'Newtons Cradle' });
    for (let i = 0; i < number; i++) {
      const cx = x + i * size * 1.9;
      const ball = Bodies.circle(cx, y + length, size, {
        inertia: Number.POSITIVE_INFINITY,
        restitution: 1,
        friction: 0,
        frictionAir: 0.0001,
        slop: 1,
      });
      Composite.add(cradle, ball);
      Composite.add(cradle, Constraint.create({ pointA: { x: cx, y }, bodyB: ball }));
    }
    return cradle;
  },

  /** A car: a rounded body `width` by `height` and two wheels of radius `wheelSize` on pins. */
  car(x: number, y: number, width: number, height: number, wheelSize: number): MatterComposite {
    const group = Body.nextGroup(true);
    const car = Composite.create({ label: 'Car' });
    const body = Bodies.rectangle(x, y, width, height, {
      collisionFilter: { group, category: 1, mask: 0xffffffff },
      chamfer: { radius: height * 0.5 },
      density: 0.0002,
    });
    Composite.add(car, body);
    for (const offset of [-width * 0.5 + 20, width * 0.5 - 20]) {
      const wheel = Bodies.circle(x + offset, y, wheelSize, {
        collisionFilter: { group, category: 1, mask: 0xffffffff },
        friction: 0.8,
      });
      Composite.add(car, wheel);
      Composite.add(
        car,
        Constraint.create({
          bodyB: body,
          pointB: { x: offset, y: 0 },
          bodyA: wheel,
          stiffness: 1,
          length: 0,
        }),
      );
    }
    return car;
  },

  /** A grid of particles meshed by soft constraints (stiffness 0.2 unless `constraintOptions` say). */
  softBody(
    x: number,
    y: number,
    columns: number,
    rows: number,
    columnGap: number,
    rowGap: number,
    crossBrace: boolean,
    particleRadius: number,
    particleOptions?: BodiesOptions,
    constraintOptions?: ConstraintOptions,
  ): MatterComposite {
    const particle = Common.extend({ inertia: Number.POSITIVE_INFINITY }, particleOptions) as BodiesOptions;
    const links = Common.extend(
      { stiffness: 0.2, render: { type: 'line', anchors: false } },
      constraintOptions,
    ) as ConstraintOptions;
    const soft = Composites.stack(x, y, columns, rows, columnGap, rowGap, (px, py) =>
      Bodies.circle(px, py, particleRadius, particle),
    );
    Composites.mesh(soft, columns, rows, crossBrace, links);
    soft.label = 'Soft Body';
    return soft;
  },
};
