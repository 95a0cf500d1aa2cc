import { World as FulcrumWorld } from '../api/world';
import { Limits } from '../core/limits';
import { type MatterPairs, refreshCollisions, updatePairs } from './collision-pairs';
import { Common } from './common';
import { Composite, type MatterComposite } from './composite';
import { syncConstraintMembers, syncConstraints, turnConstraintPoints } from './constraint-joints';
import { Events } from './events';
import { type FulcrumLink, readBack, refresh, syncMembers } from './simulation';

export type { MatterPair } from './collision-pairs';

/*
 * The engine runs a Fulcrum world in matter's own coordinates: pixels, y down (so Fulcrum's angles,
 * counter-clockwise in the numbers, turn clockwise on the screen as matter's do). Fulcrum takes
 * seconds where matter takes milliseconds: a matter acceleration of 1 px/ms² is 1e6 px/s², a matter
 * velocity of 1 px per 1000/60 ms is 60 px/s.
 */

/** pixels to the metre where a program has no gravity */
const PIXELS_PER_METRE = 100;
/** the gravity, m/s², that a program's gravity is taken to be */
const EARTH_GRAVITY = 10;
/** px/ms² to px/s² */
const ACCELERATION_TO_SI = 1e6;

export interface MatterEngine {
  world: MatterComposite;
  gravity: { x: number; y: number; scale: number };
  timing: {
    timeScale: number;
    timestamp: number;
    lastDelta: number;
    lastElapsed: number;
    lastUpdatesPerFrame?: number;
  };
  enableSleeping: boolean;
  positionIterations: number;
  velocityIterations: number;
  constraintIterations: number;
  pairs: MatterPairs;
  events: Record<string, ((event: Record<string, unknown>) => void)[]> | null;
  plugin: Record<string, unknown>;
  /** the Fulcrum world underneath and what links it to the matter objects (not enumerable) */
  _fulcrum: FulcrumLink;
}

/**
 * The Fulcrum world of an engine. A matter program gives its scale through its gravity: the world
 * takes the gravity it finds to be 10 m/s² (matter's default, 1000 px/s², makes 100 px a metre), so
 * that the engine's tolerances (contact margins, sleep speeds) fit the program's sizes; 100 px a metre
 * without gravity. Friction mixes as matter's does, the smaller of the two.
 */
function createLink(engine: MatterEngine): FulcrumLink {
  const g = engine.gravity;
  const pull = Math.sqrt(g.x * g.x + g.y * g.y) * Math.abs(g.scale) * ACCELERATION_TO_SI;
  const perMetre = pull > 0 ? pull / EARTH_GRAVITY : PIXELS_PER_METRE;
  const world = new FulcrumWorld({
    lengthUnitsPerMeter: Math.min(Math.max(perMetre, Limits.MIN_UNITS), Limits.MAX_UNITS),
    enableSleep: engine.enableSleeping,
    frictionMixing: 'min',
    // frictionAir's damping (simulation.ts) is worked out for 4
    subSteps: 4,
  });
  return {
    world,
    anchor: world.createBody(),
    joints: new Map(),
    list: [],
    bodies: new Map(),
    state: new Float64Array(8),
    touching: new Map(),
  };
}

/** matter.js's `Engine`: creates and updates a world. A plain, mutable module object. */
export const Engine = {
  create(options: Partial<Omit<MatterEngine, '_fulcrum'>> = {}): MatterEngine {
    const { world: given, ...settings } = options;
    const engine = Common.extend(
      {
        world: given ?? Composite.create({ label: 'World' }),
        gravity: { x: 0, y: 1, scale: 0.001 },
        timing: { timeScale: 1, timestamp: 0, lastDelta: 0, lastElapsed: 0 },
        enableSleeping: false,
        positionIterations: 6,
        velocityIterations: 4,
        constraintIterations: 2,
        pairs: { table: {}, list: [] },
        events: null,
        plugin: {},
      },
      settings,
    ) as unknown as MatterEngine;
    // matter 0.20 keeps its older world.gravity as the same object as engine.gravity
    engine.world.gravity = engine.gravity;
    // made at the first update (or first look), once the program has set its gravity
    let link: FulcrumLink | null = null;
    Object.defineProperty(engine, '_fulcrum', {
      get: () => {
        link ??= createLink(engine);
        return link;
      },
      enumerable: false,
    });
    return engine;
  },

  /**
   * Moves the world on by `delta` milliseconds (default 1000/60) times `timing.timeScale`, and
   * triggers matter's events in matter's order: beforeUpdate, collisionStart, collisionActive,
   * collisionEnd, afterUpdate.
   */
  update(engine: MatterEngine, delta: number = Common._baseDelta): MatterEngine {
    const link = engine._fulcrum;
    const timing = engine.timing;
    const started = Common.now();
    const dt = delta * timing.timeScale;
    timing.timestamp += dt;
    timing.lastDelta = dt;
    const event = { timestamp: timing.timestamp, delta: dt };
    Events.trigger(engine, 'beforeUpdate', event);
    if (engine.world.isModified || link.list.length === 0) {
      syncMembers(link, engine.world);
      syncConstraintMembers(link, Composite.allConstraints(engine.world));
      Composite.setModified(engine.world, false, false, true);
    }
    syncConstraints(link);
    const world = link.world;
    if (world.enableSleep !== engine.enableSleeping) world.enableSleep = engine.enableSleeping;
    const g = engine.gravity;
    const gx = g.x * g.scale * ACCELERATION_TO_SI;
    const gy = g.y * g.scale * ACCELERATION_TO_SI;
    const gravity = world.gravity;
    if (gravity.x !== gx || gravity.y !== gy) world.gravity = { x: gx, y: gy };
    const list = link.list;
    for (let i = 0; i < list.length; i++) {
      const sim = list[i];
      const body = sim.body;
      refresh(sim);
      if (body.isStatic) continue;
      const force = body.force;
      if (force.x !== 0 || force.y !== 0) {
        sim.fulcrum.applyForce({ x: force.x * ACCELERATION_TO_SI, y: force.y * ACCELERATION_TO_SI });
      }
      if (body.torque !== 0) sim.fulcrum.applyTorque(body.torque * ACCELERATION_TO_SI);
    }
    if (dt > 0) world.step(dt / 1000);
    for (let i = 0; i < list.length; i++) if (!list[i].body.isStatic) readBack(list[i], link.state);
    turnConstraintPoints(link);

    // the pairs active before this update and still active after it: built only when listened to
    const listensActive = (engine.events?.collisionActive?.length ?? 0) > 0;
    const changes = updatePairs(engine.pairs, link.touching, world.events, timing.timestamp, listensActive);
    if (listensActive) refreshCollisions(engine.pairs, link);
    if (changes.start.length > 0)
      Events.trigger(engine, 'collisionStart', { pairs: changes.start, ...event });
    if (changes.active.length > 0)
      Events.trigger(engine, 'collisionActive', { pairs: changes.active, ...event });
    if (changes.end.length > 0) Events.trigger(engine, 'collisionEnd', { pairs: changes.end, ...event });
    for (let i = 0; i < list.length; i++) {
      const body = list[i].body;
      body.force.x = 0;
      body.force.y = 0;
      body.torque = 0;
    }
    timing.lastElapsed = Common.now() - started;
    Events.trigger(engine, 'afterUpdate', event);
    return engine;
  },

  /** Forgets the world's collision pairs. */
  clear(engine: MatterEngine): void {
    engine.pairs.table = {};
    engine.pairs.list = [];
    engine._fulcrum.touching.clear();
  },
};
