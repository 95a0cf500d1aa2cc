import { QueryMemory } from '../query/query-memory';
import type { WorldCore } from '../world/world-core';
import type { Body } from './body';
import { EventDispatcher } from './events';
import type { ShapeHandle } from './shape';

/**
 * The public layer's side of one world: the handle object of each live body and shape slot, the
 * events that name them, and the queries' working memory. Handles reach the engine through `core` and each other through this table,
 * never through the World facade. Internal: public types reach it only through internal members.
 */
export class WorldHandles {
  /** @internal */
  readonly core: WorldCore;
  /** @internal */
  readonly bodies: (Body | undefined)[] = [];
  /** @internal */
  readonly shapes: (ShapeHandle | undefined)[] = [];
  /**
   * The events and their handlers: not state, so not enumerable, which keeps it out of snapshots.
   * A restored world's table may be a new object (the snapshot can reach it first through a joint's
   * body rather than from the World), and gets its own dispatcher on first use.
   * @internal
   */
  declare private events: EventDispatcher | undefined;
  /** The queries' working memory, for the same reasons and made the same way as the dispatcher. */
  declare private queryScratch: QueryMemory | undefined;

  /** @internal */
  constructor(core: WorldCore) {
    this.core = core;
  }

  /** @internal */
  get dispatcher(): EventDispatcher {
    if (this.events === undefined) {
      Object.defineProperty(this, 'events', { value: new EventDispatcher(this), enumerable: false });
    }
    return this.events!;
  }

  /** @internal */
  get queryMemory(): QueryMemory {
    if (this.queryScratch === undefined) {
      Object.defineProperty(this, 'queryScratch', { value: new QueryMemory(), enumerable: false });
    }
    return this.queryScratch!;
  }
}
