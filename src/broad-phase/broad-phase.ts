import type { Bounds } from '../math/aabb';
import { DynamicTree, type TreeRayCastVisitor } from './dynamic-tree';
import { IntList } from './int-list';
import type { PairSet } from './pair-set';

/** @internal Body type of a proxy. */
export enum ProxyType {
  STATIC = 0,
  KINEMATIC = 1,
  DYNAMIC = 2,
}

/** @internal Proxy key = (tree proxy id << 2) | type. */
export function proxyKeyType(key: number): ProxyType {
  return (key & 3) as ProxyType;
}

export function proxyKeyId(key: number): number {
  return key >> 2;
}

/** Receives each proxy a ray reaches; see `BroadPhase.rayCast`. */
export interface BroadPhaseRayCastVisitor {
  /** Returns -1 to ignore the proxy, 0 to stop, or a fraction in (0, maxFraction) to clip the ray. */
  rayCastProxy(proxyKey: number, shapeId: number, maxFraction: number): number;
}

/** Translates tree proxy ids into broad-phase keys for the caller's visitor. */
class KeyedRayCastVisitor implements TreeRayCastVisitor {
  target: BroadPhaseRayCastVisitor | null = null;
  type = 0;

  rayCastProxy(proxyId: number, userData: number, maxFraction: number): number {
    return this.target!.rayCastProxy((proxyId << 2) | this.type, userData, maxFraction);
  }
}

/** @internal Decides whether two shapes whose fat boxes overlap may become a pair (see updatePairs). */
export interface PairFilter {
  shouldPair(shapeA: number, shapeB: number): boolean;
}

/** @internal What PairAdmission.begin says of a search. An enum for the reason in store/body-store.ts. */
export enum SearchMode {
  /** every pair found is looked up */
  OPEN = 0,
  /** the shape takes no more pairs that count against it: those go to `block`, not looked up */
  SEALED = 1,
  /** sealed, and every pair with a dynamic shape would count against it: the dynamic tree is not searched */
  CLOSED = 2,
}

/** @internal Chooses which of the new candidate pairs of one proxy's search become pairs (see ContactLimiter). */
export interface PairAdmission {
  /** Starts the search of `shape` (see SearchMode). */
  begin(shape: number): SearchMode;
  /** Whether a pair of `shape` with `other` would count against `shape`. */
  counts(shape: number, other: number): boolean;
  /** Notes a pair that `begin` ruled out, allowed by the filter. */
  block(shape: number, other: number): void;
  /** Whether some shape waits for room; false spares the search asking `refuses`. */
  readonly anyWaiting: boolean;
  /** Whether a pair of `shape` with `other` is refused before it is looked up (`other` has no room). */
  refuses(shape: number, other: number): boolean;
  /**
   * Whether the search of `shape` may look in a smaller box than its fat box, which it then writes
   * in `box` (minX, minY, maxX, maxY): only pairs that near could be admitted, and of the proxies
   * whose fat box overlaps it, only those `isNear` allows are looked at.
   */
  searchBox(shape: number, box: Float64Array): boolean;
  /** Whether `other` is near enough to `shape` (see searchBox). */
  isNear(shape: number, other: number): boolean;
  /** Keeps, of the pairs `out[from, out.length)` found for shape `shape`, those it admits (compacting `out`). */
  admit(shape: number, out: IntList, from: number): void;
}

const ADMIT_ALL: PairAdmission = Object.freeze({
  begin: () => SearchMode.OPEN,
  counts: () => false,
  block() {},
  anyWaiting: false,
  refuses: () => false,
  searchBox: () => false,
  isNear: () => true,
  admit() {},
});

/** @internal Axis-aligned boxes stored by column (the shape store's tight boxes). */
export interface BoxColumns {
  readonly minX: Float64Array;
  readonly minY: Float64Array;
  readonly maxX: Float64Array;
  readonly maxY: Float64Array;
}

/**
 * How many steps' displacement a moving proxy's fat box reaches ahead (2: a chain's swing, a
 * tumbling pile and a rain 0.90-0.99x the step time; 4 made the tumbler's pairs 2,821 -> 3,196, its
 * narrow phase the dearer). An enum for the reason in store/body-store.ts.
 */
enum MotionAhead {
  FACTOR = 2,
}

/**
 * How many box overlaps one `updatePairs` may examine: PER_PROXY for each proxy of the broad phase,
 * and at least MIN. Searches stop there, and the proxies not searched yet wait for the next update:
 * shapes that do not overlap find a few dozen boxes around each (the tumbler's drum, 404 in one
 * search, and 2 cm grains poured in a box, 273, are the most seen), but each of n shapes created on one
 * spot finds all n, and one update would examine n^2 overlaps. An enum for the reason above.
 */
enum SearchBudget {
  PER_PROXY = 256,
  MIN = 65536,
}

/**
 * Broad phase: one dynamic tree per body type holding fat boxes (tight box + margin; static proxies
 * get no margin), and a move buffer of proxies whose pairs must be looked for at the next
 * `updatePairs`. Pair rules: dynamic proxies pair with every type; static and kinematic proxies pair
 * only with dynamic ones. Each tree proxy's user data is the shape id.
 * @internal
 */
export class BroadPhase {
  private readonly trees: DynamicTree[] = [new DynamicTree(), new DynamicTree(), new DynamicTree()];
  /** Per tree: index of each proxy in `moveBuffer`, or -1. Sized to the tree's capacity. */
  private readonly moveIndex: Int32Array[] = [new Int32Array(0), new Int32Array(0), new Int32Array(0)];
  /** Proxy keys; -1 marks a proxy destroyed after it was buffered. */
  private readonly moveBuffer = new IntList(64);
  private readonly found = new IntList(64);
  private readonly rayVisitor = new KeyedRayCastVisitor();
  /** proxies the last `updatePairs` left buffered for the next one, and the overlaps it examined (see SearchBudget) */
  deferredCount = 0;
  examinedCount = 0;
  /** what PairAdmission said of the current search: searchBox, begin, anyWaiting */
  private searchNear = false;
  private searchFull = false;
  private searchCrowded = false;
  // Working memory, not state: private (#) fields are no property keys, so the snapshot, which writes
  // a world's objects key by key, leaves them out (a query must leave no trace in it).
  /** the box `query` hands to `queryBox`, and the fat box `moveProxy` hands to the tree */
  #queryBox = new Float64Array(4);
  #fatBox = new Float64Array(4);
  /** the box a search looks in when PairAdmission.searchBox narrows it */
  #nearBox = new Float64Array(4);
  /** the displacement placeProxy passes: zero, never written */
  readonly #noMotion = new Float64Array(2);

  constructor(private readonly aabbMargin: number) {}

  get proxyCount(): number {
    return this.trees[0].proxyCount + this.trees[1].proxyCount + this.trees[2].proxyCount;
  }

  /** How many box overlaps one `updatePairs` may examine (see SearchBudget). */
  get searchBudget(): number {
    return Math.max(SearchBudget.MIN, SearchBudget.PER_PROXY * this.proxyCount);
  }

  /** The shape of the first proxy the last `updatePairs` left buffered, or -1. */
  firstDeferredShape(): number {
    for (let i = 0; i < this.moveBuffer.length; i++) {
      const key = this.moveBuffer.data[i];
      if (key >= 0) return this.trees[key & 3].getUserData(key >> 2);
    }
    return -1;
  }

  /** Whether the trees whose bit (1 << type) is in typeMask hold no proxy. */
  isEmpty(typeMask: number): boolean {
    for (let type = 0; type < 3; type++) {
      if ((typeMask & (1 << type)) !== 0 && this.trees[type].proxyCount > 0) return false;
    }
    return true;
  }

  /** Number of entries in the move buffer (including ones destroyed since). */
  get moveCount(): number {
    return this.moveBuffer.length;
  }

  /** The tree of one body type, for debug drawing and statistics. Do not modify it directly. */
  getTree(type: ProxyType): DynamicTree {
    return this.trees[type];
  }

  /** Adds a proxy for the tight box and returns its key. */
  createProxy(
    minX: number,
    minY: number,
    maxX: number,
    maxY: number,
    bodyType: ProxyType,
    shapeId: number,
    forcePairCreation: boolean,
  ): number {
    const m = bodyType === ProxyType.STATIC ? 0 : this.aabbMargin;
    const tree = this.trees[bodyType];
    const id = tree.createProxy(minX - m, minY - m, maxX + m, maxY + m, shapeId);
    if (this.moveIndex[bodyType].length < tree.capacity) {
      const index = new Int32Array(tree.capacity).fill(-1);
      index.set(this.moveIndex[bodyType]);
      this.moveIndex[bodyType] = index;
    }
    const key = (id << 2) | bodyType;
    if (bodyType !== ProxyType.STATIC || forcePairCreation) this.bufferMove(key);
    return key;
  }

  destroyProxy(key: number): void {
    const type = key & 3;
    const id = key >> 2;
    const index = this.moveIndex[type];
    if (id >= 0 && id < index.length && index[id] >= 0) {
      this.moveBuffer.set(index[id], -1);
      index[id] = -1;
    }
    this.trees[type].destroyProxy(id);
  }

  /**
   * Takes the proxy's new tight box, entry `i` of `boxes`, and its expected displacement over the next
   * step, (motion[0], motion[1]) (placeProxy when unknown). The fat box is the tight box grown by the
   * margin and stretched MotionAhead.FACTOR times the displacement ahead, so that a fast body leaves it and
   * looks for pairs every few steps rather than every step (a swinging 100-link chain: 62 to 25 proxies
   * a step; 500 tumbling boxes: 128 to 81). Returns false (and does nothing) while the stored fat box
   * holds the tight box and is nowhere more than the margin and the stretch larger than a new one
   * would be (a box stretched by a fall shrinks back when the body comes to rest: a rain's resting
   * pile would otherwise keep 12 % more pairs for good); otherwise stores the new fat box, buffers the
   * proxy and returns true. (The box comes as columns and an index: four doubles passed to a call V8
   * does not inline are boxed on the heap, and this runs for every moving shape every step.)
   */
  moveProxy(key: number, boxes: BoxColumns, i: number, motion: Float64Array): boolean {
    const minX = boxes.minX[i];
    const minY = boxes.minY[i];
    const maxX = boxes.maxX[i];
    const maxY = boxes.maxY[i];
    const type = key & 3;
    const id = key >> 2;
    const tree = this.trees[type];
    const m = type === ProxyType.STATIC ? 0 : this.aabbMargin;
    const dx = type === ProxyType.STATIC ? 0 : MotionAhead.FACTOR * motion[0];
    const dy = type === ProxyType.STATIC ? 0 : MotionAhead.FACTOR * motion[1];
    const fatMinX = minX - m + Math.min(dx, 0);
    const fatMinY = minY - m + Math.min(dy, 0);
    const fatMaxX = maxX + m + Math.max(dx, 0);
    const fatMaxY = maxY + m + Math.max(dy, 0);
    const slack = m + Math.abs(dx) + Math.abs(dy);
    const oldMinX = tree.getMinX(id);
    const oldMinY = tree.getMinY(id);
    const oldMaxX = tree.getMaxX(id);
    const oldMaxY = tree.getMaxY(id);
    if (
      oldMinX <= minX &&
      oldMinY <= minY &&
      oldMaxX >= maxX &&
      oldMaxY >= maxY &&
      oldMinX >= fatMinX - slack &&
      oldMinY >= fatMinY - slack &&
      oldMaxX <= fatMaxX + slack &&
      oldMaxY <= fatMaxY + slack
    ) {
      return false;
    }
    const fat = this.#fatBox;
    fat[0] = fatMinX;
    fat[1] = fatMinY;
    fat[2] = fatMaxX;
    fat[3] = fatMaxY;
    // moving proxies are re-placed together at the next updatePairs (see DynamicTree.settleMoves)
    if (type === ProxyType.STATIC) tree.moveProxy(id, fat, 0);
    else tree.enlargeProxy(id, fat, 0);
    this.bufferMove(key);
    return true;
  }

  /**
   * As moveProxy, for a proxy whose displacement over the next step is not known (a body placed by
   * the user, a bullet moved back): its fat box reaches no further ahead than the margin.
   */
  placeProxy(key: number, boxes: BoxColumns, i: number): boolean {
    return this.moveProxy(key, boxes, i, this.#noMotion);
  }

  /** Whether the next `updatePairs` looks for new pairs of this proxy. */
  isBuffered(key: number): boolean {
    return this.moveIndex[key & 3][key >> 2] >= 0;
  }

  /** Makes the next `updatePairs` look for new pairs of this proxy. Buffering twice is harmless. */
  bufferMove(key: number): void {
    const index = this.moveIndex[key & 3];
    const id = key >> 2;
    if (index[id] >= 0) return;
    index[id] = this.moveBuffer.length;
    this.moveBuffer.push(key);
  }

  /**
   * Appends to `out` every new candidate pair as two ints (smaller shape id, larger shape id), sorted,
   * and takes the searched proxies out of the move buffer. A pair is a candidate when the fat boxes
   * overlap, at least one proxy is buffered, the types may pair, `existing` does not hold the pair of
   * shape ids, `filter` allows it and `admission` keeps it. (Filtered here, before the sort: a chain's
   * links find their jointed neighbours every time they look, about 40 refused pairs a step, up to
   * 100, in a swinging 100-link chain.) Proxies are searched in the buffer's order until SearchBudget
   * overlaps were examined; the rest stay buffered, in order, for the next update.
   */
  updatePairs(
    existing: PairSet,
    filter: PairFilter,
    out: IntList,
    admission: PairAdmission = ADMIT_ALL,
  ): void {
    for (let type = 0; type < 3; type++) this.trees[type].settleMoves();
    const start = out.length;
    const searched = this.searchMoved(existing, filter, out, admission);
    this.forgetSearched(searched);
    const kept = this.keepUnsearched(searched);
    this.moveBuffer.length = kept;
    this.deferredCount = kept;
    out.sortPairs(start);
  }

  /*
   * updatePairs' three loops are methods of their own that end in a bare return. A world's first step
   * runs each loop thousands of times in one call, so V8 compiles the running loop on the spot (OSR)
   * before any code after it has run; code after the loop in the same function would then have no
   * type feedback and send the compiled loop back to the interpreter in every later step (measured:
   * the 5,050-box pyramid's updatePairs deoptimized 11 times in its first 10 steps).
   */

  /** Searches the buffered proxies in order until the budget is spent; returns how many it took. */
  private searchMoved(existing: PairSet, filter: PairFilter, out: IntList, admission: PairAdmission): number {
    const nearBox = this.#nearBox;
    const buffer = this.moveBuffer;
    const budget = this.searchBudget;
    let examined = 0;
    let searched = 0;
    this.examinedCount = 0;
    for (; searched < buffer.length && examined < budget; searched++) {
      const key = buffer.data[searched];
      if (key < 0) continue;
      const type = key & 3;
      const id = key >> 2;
      const tree = this.trees[type];
      const shapeId = tree.getUserData(id);
      const from = out.length;
      const near = admission.searchBox(shapeId, nearBox);
      const boxes = near ? nearBox : tree.boxes;
      const at = near ? 0 : 4 * id;
      this.searchNear = near;
      const mode = admission.begin(shapeId);
      this.searchFull = mode !== SearchMode.OPEN;
      this.searchCrowded = admission.anyWaiting;
      if (type === ProxyType.DYNAMIC) {
        examined += this.findPairs(
          key,
          shapeId,
          boxes,
          at,
          ProxyType.STATIC,
          existing,
          filter,
          admission,
          out,
        );
        examined += this.findPairs(
          key,
          shapeId,
          boxes,
          at,
          ProxyType.KINEMATIC,
          existing,
          filter,
          admission,
          out,
        );
      }
      if (mode !== SearchMode.CLOSED) {
        examined += this.findPairs(
          key,
          shapeId,
          boxes,
          at,
          ProxyType.DYNAMIC,
          existing,
          filter,
          admission,
          out,
        );
      }
      admission.admit(shapeId, out, from);
      this.examinedCount = examined;
    }
    return searched;
  }

  /** Takes the first `searched` entries of the move buffer out of it. */
  private forgetSearched(searched: number): void {
    const data = this.moveBuffer.data;
    const moveIndex = this.moveIndex;
    for (let i = 0; i < searched; i++) {
      const key = data[i];
      if (key >= 0) moveIndex[key & 3][key >> 2] = -1;
    }
  }

  /** Moves the buffer's entries from `searched` on to its front, in order; returns how many there are. */
  private keepUnsearched(searched: number): number {
    const data = this.moveBuffer.data;
    const length = this.moveBuffer.length;
    const moveIndex = this.moveIndex;
    let kept = 0;
    for (let i = searched; i < length; i++) {
      const key = data[i];
      if (key < 0) continue;
      data[kept] = key;
      moveIndex[key & 3][key >> 2] = kept++;
    }
    return kept;
  }

  /** Appends the shape ids of proxies overlapping the box, from trees whose bit (1 << type) is in typeMask. */
  query(minX: number, minY: number, maxX: number, maxY: number, typeMask: number, out: IntList): void {
    const q = this.#queryBox;
    q[0] = minX;
    q[1] = minY;
    q[2] = maxX;
    q[3] = maxY;
    this.queryBox(q, 0, typeMask, out);
  }

  /** As query, for the box at `at` in `boxes` (see DynamicTree.queryBox). */
  queryBox(boxes: Float64Array, at: number, typeMask: number, out: IntList): void {
    for (let type = 0; type < 3; type++) {
      if ((typeMask & (1 << type)) === 0) continue;
      const tree = this.trees[type];
      // the tree appends proxy ids, turned into shape ids in place: no scratch of the broad phase is
      // touched, so that queries between steps leave the world's state (and its snapshot) as it was
      const start = out.length;
      tree.queryBox(boxes, at, out);
      const data = out.data;
      for (let i = start; i < out.length; i++) data[i] = tree.getUserData(data[i]);
    }
  }

  /**
   * Casts origin + t·translation, t in [0, maxFraction], through the static, kinematic and dynamic trees
   * in that order, carrying the clipped fraction from tree to tree. Returns the final max fraction (0
   * when the visitor stopped the cast). Not re-entrant.
   */
  rayCast(
    originX: number,
    originY: number,
    translationX: number,
    translationY: number,
    maxFraction: number,
    visitor: BroadPhaseRayCastVisitor,
  ): number {
    const adapter = this.rayVisitor;
    adapter.target = visitor;
    for (let type = 0; type < 3 && maxFraction > 0; type++) {
      adapter.type = type;
      maxFraction = this.trees[type].rayCast(
        originX,
        originY,
        translationX,
        translationY,
        maxFraction,
        adapter,
      );
    }
    // left as a world that never cast a ray has it (see queryBox)
    adapter.target = null;
    adapter.type = 0;
    return maxFraction;
  }

  getFatBounds(key: number, out: Bounds): Bounds {
    return this.trees[key & 3].getBounds(key >> 2, out);
  }

  /** Whether the fat boxes of two proxies overlap (or touch). */
  fatBoxesOverlap(keyA: number, keyB: number): boolean {
    return this.trees[keyA & 3].overlaps(keyA >> 2, this.trees[keyB & 3], keyB >> 2);
  }

  getShapeId(key: number): number {
    return this.trees[key & 3].getUserData(key >> 2);
  }

  /** Rebuilds the static tree for query quality, e.g. after loading a level. */
  rebuild(): void {
    this.trees[ProxyType.STATIC].rebuild();
  }

  /** Appends the new candidate pairs of one proxy with the proxies of one tree; returns the overlaps examined. */
  private findPairs(
    key: number,
    shapeId: number,
    boxes: Float64Array,
    at: number,
    type: number,
    existing: PairSet,
    filter: PairFilter,
    admission: PairAdmission,
    out: IntList,
  ): number {
    const found = this.found;
    const tree = this.trees[type];
    const moved = this.moveIndex[type];
    found.clear();
    tree.queryBox(boxes, at, found);
    for (let i = 0; i < found.length; i++) {
      const id = found.data[i];
      const otherKey = (id << 2) | type;
      if (otherKey === key) continue;
      const otherShape = tree.getUserData(id);
      if (this.searchNear && !admission.isNear(shapeId, otherShape)) continue;
      if (this.searchFull && admission.counts(shapeId, otherShape)) {
        if (filter.shouldPair(shapeId, otherShape)) admission.block(shapeId, otherShape);
        continue;
      }
      if (this.searchCrowded && admission.refuses(shapeId, otherShape)) continue;
      // When both proxies are buffered, each finds the other (the pair rules are symmetric): only the
      // one with the larger key reports the pair.
      if (otherKey > key && moved[id] >= 0) continue;
      if (existing.get(shapeId, otherShape) !== -1) continue;
      if (!filter.shouldPair(shapeId, otherShape)) continue;
      if (shapeId < otherShape) out.push2(shapeId, otherShape);
      else out.push2(otherShape, shapeId);
    }
    return found.length;
  }
}
