import fc from 'fast-check';
import { describe, it } from 'vitest';
import { FulcrumError, Shape, World, type WorldDef } from '../../src/index';
import { firstDifference, Harness, InvariantError } from './harness';
import { initialBodies, type Op, opSequence } from './ops';
import { checkProperty } from './run-property';
import { fuzzing, tame } from './settings';
import { nearPoint, vec } from './values';

/**
 * Cases in the unit run: about 10 s for the sessions on this project's 2-core machine when it is not
 * shared (a failure adds the shrinking, up to a minute); `npm run fuzz` runs many more (settings.ts).
 */
const SESSIONS_IN_CI = 500;
const QUERY_CASES_IN_CI = 50;
/** the unit config's 60 s is too short for a loaded machine or a long shrink; the fuzz config has none */
const TIME_LIMIT = fuzzing ? 0 : 600_000;

/** Every case starts with a wide static ground under the origin, where the ops put most bodies. */
const GROUND: Op = {
  op: 'createBody',
  body: { type: 'static', position: { x: 0, y: -8 } },
  shapes: [{ geometry: { kind: 'box', hw: 30, hh: 1, center: undefined, angle: undefined }, def: {} }],
};

const worldDef: fc.Arbitrary<WorldDef> = fc.record(
  {
    gravity: fc.oneof({ weight: 4, arbitrary: fc.constant({ x: 0, y: -10 }) }, { weight: 1, arbitrary: vec }),
    subSteps: fc.oneof(
      { weight: 4, arbitrary: fc.constant(4) },
      { weight: 1, arbitrary: fc.integer({ min: 1, max: 12 }) },
    ),
    enableSleep: fc.boolean(),
    enableContinuous: fc.boolean(),
    lengthUnitsPerMeter: fc.oneof(
      { weight: 6, arbitrary: fc.constant(1) },
      { weight: 1, arbitrary: fc.constantFrom(0.01, 50, 1e4) },
    ),
  },
  { requiredKeys: [] },
);

const session = fc.record({
  world: worldDef,
  events: tame
    ? fc.constant('handlers' as const)
    : fc.constantFrom<'handlers' | 'arrays'>('handlers', 'arrays'),
  bodies: initialBodies(12),
  ops: opSequence(40),
});

/** Whether `new World(def)` refuses `def` (with a FulcrumError, as it must refuse values beyond the accepted ranges). */
function refusedWorld(def: WorldDef): boolean {
  try {
    new World(def);
    return false;
  } catch (e) {
    if (e instanceof FulcrumError) return true;
    throw e;
  }
}

function sameTrace(what: string, a: readonly (number | string)[], b: readonly (number | string)[]): void {
  const n = Math.max(a.length, b.length);
  for (let i = 0; i < n; i++) {
    if (a[i] !== b[i]) throw new InvariantError(`${what}: traces differ at entry ${i}: ${a[i]} vs ${b[i]}`);
  }
}

describe('API fuzzer (fast-check)', () => {
  it(
    'random sessions keep every invariant after every step and call, and replay to the same bits with and without snapshot/restore',
    async () => {
      await checkProperty(
        'sessions',
        session,
        ({ world, events, bodies, ops }) => {
          if (refusedWorld(world)) return;
          const all = [GROUND, ...bodies, ...ops];
          const checked = new Harness(world, { restore: true, events, check: true });
          checked.run(all);
          const replay = new Harness(world, { restore: true, events, check: false });
          replay.run(all);
          sameTrace('the same ops in a fresh world', checked.trace, replay.trace);
          if (all.some((op) => op.op === 'snapshotRestore')) {
            const unrestored = new Harness(world, { restore: false, events, check: false });
            unrestored.run(all);
            sameTrace('the same ops without the snapshot/restores', checked.trace, unrestored.trace);
          }
        },
        SESSIONS_IN_CI,
      );
    },
    TIME_LIMIT,
  );

  it.skipIf(tame)(
    "queries between steps leave the snapshot's bytes unchanged",
    async () => {
      const queries = fc.array(
        fc.oneof(
          fc.record({ kind: fc.constant('castRay' as const), origin: nearPoint, translation: vec }),
          fc.record({ kind: fc.constant('queryPoint' as const), point: nearPoint }),
          fc.record({ kind: fc.constant('queryAABB' as const), lower: nearPoint, extent: nearPoint }),
          fc.record({ kind: fc.constant('overlapCircle' as const), point: nearPoint }),
          fc.record({ kind: fc.constant('castCircle' as const), origin: nearPoint, translation: vec }),
        ),
        { minLength: 1, maxLength: 4 },
      );
      await checkProperty(
        'queries',
        fc.record({ world: worldDef, ops: opSequence(25), queries }),
        ({ world, ops, queries }) => {
          if (refusedWorld(world)) return;
          const h = new Harness(world, { restore: false, events: 'handlers', check: false });
          h.run([GROUND, ...ops]);
          const w = h.world;
          const before = w.snapshot();
          for (const q of queries) {
            try {
              if (q.kind === 'castRay') w.castRay(q.origin, q.translation);
              else if (q.kind === 'queryPoint') w.queryPoint(q.point);
              else if (q.kind === 'queryAABB')
                w.queryAABB({
                  lowerBound: q.lower,
                  upperBound: { x: q.lower.x + Math.abs(q.extent.x), y: q.lower.y + Math.abs(q.extent.y) },
                });
              else if (q.kind === 'overlapCircle') w.overlapShape(Shape.circle(1), { position: q.point });
              else w.castShape(Shape.circle(0.5), { position: q.origin }, q.translation);
            } catch (e) {
              // a translation beyond the accepted ranges is refused; refused or not, the bytes stay
              if (!(e instanceof FulcrumError)) throw e;
            }
          }
          const at = firstDifference(before, w.snapshot());
          if (at >= 0)
            throw new InvariantError(
              `queries ${JSON.stringify(queries.map((q) => q.kind))} changed the snapshot at byte ${at}`,
            );
        },
        QUERY_CASES_IN_CI,
      );
    },
    TIME_LIMIT,
  );
});
