import { growU8 } from '../core/grow';
import type { Bounds } from '../math/aabb';
import type { IntList } from './int-list';

/** @internal Receives each proxy whose box a ray reaches; see `DynamicTree.rayCast`. */
export interface TreeRayCastVisitor {
  /** Returns -1 to ignore the proxy, 0 to stop, or a fraction in (0, maxFraction) to clip the ray. */
  rayCastProxy(proxyId: number, userData: number, maxFraction: number): number;
}

/** Node ids: NULL is no node. An enum, not a const, for the reason in store/body-store.ts. */
enum Node {
  NULL = -1,
}
/**
 * Largest allowed height difference between two siblings. 2 rather than 1 (AVL) leaves the perimeter
 * heuristic room to keep nearby boxes together; the height stays below about 1.8·log2(n).
 */
enum Balance {
  SLACK = 2,
}

/**
 * LIMIT: how much worse than right after its last rebuild (see DynamicTree.refitAll) a tree may get and
 * still be refitted in place when many of its proxies moved, instead of rebuilt. SHARE: one leaf in SHARE
 * moved is many. A refit costs about 11 ns a node, a leaf's re-insertion about 1 us (500 leaves: 11 against
 * 127 us for a tumbling drum's 128 moved a step), so refitting pays from a fiftieth of the leaves on; a
 * sixteenth leaves room for the rebuilds a looser tree brings. An enum for the reason above.
 */
enum Refit {
  LIMIT = 1.05,
  SHARE = 16,
}

/**
 * Dynamic AABB tree. Nodes live in typed arrays (structure of arrays) indexed by node id; a proxy id is
 * the id of its leaf and stays valid until destroyed. Insertion picks the sibling by a perimeter cost
 * (the 2D surface-area heuristic). On the way back up, every ancestor is rebalanced by tree rotations
 * (swaps of a child with a grandchild): forced when its children's heights differ by more than SLACK,
 * otherwise only when a swap shrinks the boxes. Heights therefore stay O(log n) even for sorted input.
 * Proxies that move every step take enlargeProxy and settleMoves instead (moved together, or the tree
 * rebuilt when many moved), after Box2D v3's enlarged-box scheme.
 *
 * Not re-entrant: a ray-cast visitor must not modify the tree (queries are fine).
 * @internal
 */
export class DynamicTree {
  /** minX, minY, maxX, maxY per node. */
  private box: Float64Array;
  /** Parent of a used node; next free node for a free one. */
  private parent: Int32Array;
  /** First child, or NULL for a leaf. */
  private child1: Int32Array;
  private child2: Int32Array;
  /** 0 for a leaf, -1 for a free node. */
  private height: Int32Array;
  private userData: Int32Array;
  private root = Node.NULL;
  private freeList = Node.NULL;
  private nodeCount = 0;
  private leafCount = 0;
  private buildLeaves: Int32Array = new Int32Array(0);
  /** rebuild's scratch: each leaf's doubled centre (x, y) by node id */
  private centre: Float64Array = new Float64Array(0);
  /** Leaves moved in place (enlargeProxy) since the last settleMoves, and a flag per node for them. */
  private moved: Int32Array = new Int32Array(16);
  private movedCount = 0;
  private isMoved: Uint8Array;
  /**
   * the tree's shape (see refitAll) right after its last rebuild (0: not known yet). It starts as -0,
   * a double: a whole-number start gives the field V8's small-integer layout, which the first
   * fractional shape changes, and every compiled function that reads a tree is then thrown away.
   */
  private builtShape = -0;
  /**
   * The walks' stacks: working memory, not the tree's state. Private (#) fields are no property keys,
   * so the snapshot, which writes a world's objects key by key, neither writes nor restores them: a
   * query leaves no trace in a world's snapshot. (A ray-cast visitor may query, which is why the two
   * are apart.)
   */
  #queryStack: Int32Array = new Int32Array(64);
  #rayStack: Int32Array = new Int32Array(64);

  constructor(initialCapacity = 16) {
    const capacity = Math.max(2, initialCapacity);
    this.box = new Float64Array(4 * capacity);
    this.parent = new Int32Array(capacity);
    this.child1 = new Int32Array(capacity);
    this.child2 = new Int32Array(capacity);
    this.height = new Int32Array(capacity);
    this.userData = new Int32Array(capacity);
    this.isMoved = new Uint8Array(capacity);
    this.linkFree(0, capacity);
  }

  get proxyCount(): number {
    return this.leafCount;
  }

  /** Number of node slots; every proxy id is below it. */
  get capacity(): number {
    return this.parent.length;
  }

  createProxy(minX: number, minY: number, maxX: number, maxY: number, userData: number): number {
    this.settleMoves();
    const id = this.allocate();
    this.setBox(id, minX, minY, maxX, maxY);
    this.userData[id] = userData;
    this.insertLeaf(id);
    this.leafCount++;
    return id;
  }

  destroyProxy(id: number): void {
    this.checkProxy(id);
    this.settleMoves();
    this.removeLeaf(id);
    this.release(id);
    this.leafCount--;
  }

  /**
   * Re-inserts the proxy with a new box, the four numbers at `at` in `boxes` (an array, as for
   * queryBox: doubles passed to a call V8 does not inline are boxed, and this runs for every proxy
   * that left its fat box).
   */
  moveProxy(id: number, boxes: Float64Array, at: number): void {
    this.checkProxy(id);
    this.settleMoves();
    this.removeLeaf(id);
    this.setBox(id, boxes[at], boxes[at + 1], boxes[at + 2], boxes[at + 3]);
    this.insertLeaf(id);
  }

  /**
   * Gives the proxy a new box (as moveProxy) without moving its leaf: its ancestors only grow until
   * they hold it, so the tree stays valid for queries, if looser. settleMoves then re-places the
   * leaves moved this way, all at once (a step moves many: a swinging chain, a tumbling pile).
   */
  enlargeProxy(id: number, boxes: Float64Array, at: number): void {
    this.checkProxy(id);
    const minX = boxes[at];
    const minY = boxes[at + 1];
    const maxX = boxes[at + 2];
    const maxY = boxes[at + 3];
    this.setBox(id, minX, minY, maxX, maxY);
    const box = this.box;
    for (let p = this.parent[id]; p !== Node.NULL; p = this.parent[p]) {
      if (this.contains(p, id)) break;
      const o = 4 * p;
      box[o] = Math.min(box[o], minX);
      box[o + 1] = Math.min(box[o + 1], minY);
      box[o + 2] = Math.max(box[o + 2], maxX);
      box[o + 3] = Math.max(box[o + 3], maxY);
    }
    if (this.isMoved[id] === 1) return;
    this.isMoved[id] = 1;
    if (this.movedCount === this.moved.length) this.moved = grown(this.moved, 2 * this.moved.length);
    this.moved[this.movedCount++] = id;
  }

  /**
   * Re-places the leaves enlargeProxy moved: one by one, as moveProxy, or, when a sixteenth of the
   * leaves or more moved (Refit.SHARE), all at once. Then the tree keeps its shape and only its boxes
   * are made tight again (refit), while that leaves it nearly as good as its last rebuild: a swinging
   * chain keeps its neighbours, and a refit costs a tenth of a rebuild (101 links: 0.9 against 9 us).
   * A tumbling pile mixes its bodies and gets rebuilt now and then (18 times in 600 steps for 500
   * boxes in a turning drum), which gives tight boxes everywhere.
   */
  settleMoves(): void {
    const count = this.movedCount;
    if (count === 0) return;
    if (Refit.SHARE * count >= this.leafCount && this.leafCount >= 3) {
      if (this.builtShape > 0 && this.refitAll() <= Refit.LIMIT * this.builtShape) {
        this.forgetMoved();
        return;
      }
      this.rebuild();
      return;
    }
    const moved = this.moved;
    this.forgetMoved();
    for (let i = 0; i < count; i++) {
      const id = moved[i];
      this.removeLeaf(id);
      this.insertLeaf(id);
    }
  }

  getUserData(id: number): number {
    return this.userData[id];
  }

  getMinX(id: number): number {
    return this.box[4 * id];
  }

  getMinY(id: number): number {
    return this.box[4 * id + 1];
  }

  getMaxX(id: number): number {
    return this.box[4 * id + 2];
  }

  getMaxY(id: number): number {
    return this.box[4 * id + 3];
  }

  getBounds(id: number, out: Bounds): Bounds {
    const o = 4 * id;
    out.minX = this.box[o];
    out.minY = this.box[o + 1];
    out.maxX = this.box[o + 2];
    out.maxY = this.box[o + 3];
    return out;
  }

  /** Whether the box of proxy `id` overlaps (or touches) the box of proxy `otherId` of `other`. */
  overlaps(id: number, other: DynamicTree, otherId: number): boolean {
    const a = this.box;
    const b = other.box;
    const i = 4 * id;
    const j = 4 * otherId;
    return !(a[i + 2] < b[j] || b[j + 2] < a[i] || a[i + 3] < b[j + 1] || b[j + 3] < a[i + 1]);
  }

  /** Height of the root (0 for a single leaf, -1 when empty). */
  getHeight(): number {
    return this.root === Node.NULL ? -1 : this.height[this.root];
  }

  /** Sum of the perimeters of the internal nodes divided by the root's perimeter: lower is better. */
  getAreaRatio(): number {
    if (this.root === Node.NULL) return 0;
    const rootPerimeter = this.perimeter(this.root);
    if (rootPerimeter === 0) return 0;
    let total = 0;
    for (let i = 0; i < this.height.length; i++) {
      if (this.height[i] > 0) total += this.perimeter(i);
    }
    return total / rootPerimeter;
  }

  /** Per node: fat box (minX, minY, maxX, maxY), a proxy's at 4 × its id. Read only. */
  get boxes(): Float64Array {
    return this.box;
  }

  /**
   * Appends to `out` the id of every proxy whose box overlaps (or touches) the box (minX, minY, maxX,
   * maxY) at `at` in `boxes`: a box in an array, as V8 puts on the heap every double passed to a call
   * it does not inline.
   */
  queryBox(boxes: Float64Array, at: number, out: IntList): void {
    if (this.root === Node.NULL) return;
    const minX = boxes[at];
    const minY = boxes[at + 1];
    const maxX = boxes[at + 2];
    const maxY = boxes[at + 3];
    const stack = this.stackFor(this.#queryStack);
    this.#queryStack = stack;
    const box = this.box;
    const child1 = this.child1;
    const child2 = this.child2;
    let sp = 0;
    stack[sp++] = this.root;
    while (sp > 0) {
      const id = stack[--sp];
      const o = 4 * id;
      if (box[o] > maxX || box[o + 1] > maxY || box[o + 2] < minX || box[o + 3] < minY) continue;
      const c1 = child1[id];
      if (c1 === Node.NULL) {
        out.push(id);
      } else {
        stack[sp++] = c1;
        stack[sp++] = child2[id];
      }
    }
  }

  /**
   * Casts the segment origin + t·translation, t in [0, maxFraction], and calls the visitor for each proxy
   * whose box the (possibly clipped) segment reaches. Returns the final max fraction: 0 when the visitor
   * stopped the cast.
   */
  rayCast(
    originX: number,
    originY: number,
    translationX: number,
    translationY: number,
    maxFraction: number,
    visitor: TreeRayCastVisitor,
  ): number {
    if (this.root === Node.NULL) return maxFraction;
    const stack = this.stackFor(this.#rayStack);
    this.#rayStack = stack;
    // Separating axis perpendicular to the segment: |n·(origin - center)| > |n|·halfExtents culls a box.
    const nx = -translationY;
    const ny = translationX;
    const absNx = Math.abs(nx);
    const absNy = Math.abs(ny);
    let endX = originX + maxFraction * translationX;
    let endY = originY + maxFraction * translationY;
    let segMinX = Math.min(originX, endX);
    let segMinY = Math.min(originY, endY);
    let segMaxX = Math.max(originX, endX);
    let segMaxY = Math.max(originY, endY);
    const box = this.box;
    const child1 = this.child1;
    let sp = 0;
    stack[sp++] = this.root;
    while (sp > 0) {
      const id = stack[--sp];
      const o = 4 * id;
      const minX = box[o];
      const minY = box[o + 1];
      const maxX = box[o + 2];
      const maxY = box[o + 3];
      if (minX > segMaxX || minY > segMaxY || maxX < segMinX || maxY < segMinY) continue;
      const separation =
        Math.abs(nx * (originX - 0.5 * (minX + maxX)) + ny * (originY - 0.5 * (minY + maxY))) -
        0.5 * (absNx * (maxX - minX) + absNy * (maxY - minY));
      if (separation > 0) continue;
      const c1 = child1[id];
      if (c1 !== Node.NULL) {
        stack[sp++] = c1;
        stack[sp++] = this.child2[id];
        continue;
      }
      const value = visitor.rayCastProxy(id, this.userData[id], maxFraction);
      if (value === 0) return 0;
      if (value > 0 && value < maxFraction) {
        maxFraction = value;
        endX = originX + maxFraction * translationX;
        endY = originY + maxFraction * translationY;
        segMinX = Math.min(originX, endX);
        segMinY = Math.min(originY, endY);
        segMaxX = Math.max(originX, endX);
        segMaxY = Math.max(originY, endY);
      }
    }
    return maxFraction;
  }

  /**
   * Rebuilds the whole tree top-down (median split along the wider axis of the leaf centres). Proxy ids
   * and user data are kept. Useful after many inserts, e.g. of static proxies.
   */
  rebuild(): void {
    if (this.leafCount < 3) return;
    this.forgetMoved();
    if (this.buildLeaves.length < this.leafCount) this.buildLeaves = new Int32Array(this.parent.length);
    if (this.centre.length < 2 * this.parent.length) this.centre = new Float64Array(2 * this.parent.length);
    const leaves = this.buildLeaves;
    const centre = this.centre;
    const box = this.box;
    let n = 0;
    for (let i = 0; i < this.height.length; i++) {
      const h = this.height[i];
      if (h === 0) {
        leaves[n++] = i;
        // doubled (min + max): the split only compares them
        centre[2 * i] = box[4 * i] + box[4 * i + 2];
        centre[2 * i + 1] = box[4 * i + 1] + box[4 * i + 3];
      } else if (h > 0) this.release(i);
    }
    this.root = this.build(0, n);
    this.parent[this.root] = Node.NULL;
    // the build's boxes are tight already: the walk only measures the tree's shape
    this.builtShape = this.refitAll();
  }

  /**
   * Makes every internal box the union of its children's again, children first, and returns the
   * tree's shape: the summed perimeters of the internal nodes over the root's, the cost of the boxes
   * a query opens whatever the scene's size. It grows as moving proxies leave their neighbours.
   */
  private refitAll(): number {
    const order =
      this.buildLeaves.length >= this.parent.length ? this.buildLeaves : new Int32Array(this.parent.length);
    this.buildLeaves = order;
    const child1 = this.child1;
    const child2 = this.child2;
    const box = this.box;
    // a walk down lists each node after its parent; backwards, every child comes before its parent
    let listed = 0;
    order[listed++] = this.root;
    for (let q = 0; q < listed; q++) {
      const n = order[q];
      const c1 = child1[n];
      if (c1 === Node.NULL) continue;
      order[listed++] = c1;
      order[listed++] = child2[n];
    }
    let sum = 0;
    for (let q = listed - 1; q >= 0; q--) {
      const n = order[q];
      const c1 = child1[n];
      if (c1 === Node.NULL) continue;
      const a = 4 * c1;
      const b = 4 * child2[n];
      const o = 4 * n;
      const minX = Math.min(box[a], box[b]);
      const minY = Math.min(box[a + 1], box[b + 1]);
      const maxX = Math.max(box[a + 2], box[b + 2]);
      const maxY = Math.max(box[a + 3], box[b + 3]);
      box[o] = minX;
      box[o + 1] = minY;
      box[o + 2] = maxX;
      box[o + 3] = maxY;
      sum += maxX - minX + (maxY - minY);
    }
    const root = this.perimeter(this.root);
    return root > 0 ? sum / root : 0;
  }

  private forgetMoved(): void {
    for (let i = 0; i < this.movedCount; i++) this.isMoved[this.moved[i]] = 0;
    this.movedCount = 0;
  }

  /** Throws if the structure is inconsistent; for tests. */
  validate(): void {
    let leaves = 0;
    let internal = 0;
    if (this.root !== Node.NULL) {
      if (this.parent[this.root] !== Node.NULL) throw new Error('tree: root has a parent');
      const stack = new Int32Array(this.height[this.root] + 2);
      let sp = 0;
      stack[sp++] = this.root;
      while (sp > 0) {
        const id = stack[--sp];
        const h = this.height[id];
        const c1 = this.child1[id];
        const c2 = this.child2[id];
        const o = 4 * id;
        if (!(this.box[o] <= this.box[o + 2] && this.box[o + 1] <= this.box[o + 3])) {
          throw new Error(`tree: node ${id} has an inverted box`);
        }
        if (c1 === Node.NULL) {
          if (h !== 0 || c2 !== Node.NULL) throw new Error(`tree: leaf ${id} has height ${h} or a child`);
          leaves++;
          continue;
        }
        internal++;
        if (this.parent[c1] !== id || this.parent[c2] !== id) throw new Error(`tree: bad parent under ${id}`);
        const h1 = this.height[c1];
        const h2 = this.height[c2];
        if (h !== 1 + Math.max(h1, h2)) throw new Error(`tree: node ${id} has wrong height ${h}`);
        if (Math.abs(h1 - h2) > Balance.SLACK)
          throw new Error(`tree: node ${id} is unbalanced (${h1}, ${h2})`);
        if (!this.contains(id, c1) || !this.contains(id, c2)) {
          throw new Error(`tree: node ${id} does not contain its children`);
        }
        stack[sp++] = c1;
        stack[sp++] = c2;
      }
    }
    if (leaves !== this.leafCount)
      throw new Error(`tree: ${leaves} leaves reachable, ${this.leafCount} expected`);
    if (leaves + internal !== this.nodeCount) throw new Error('tree: unreachable nodes');
    let free = 0;
    for (let i = this.freeList; i !== Node.NULL; i = this.parent[i]) {
      if (this.height[i] !== -1) throw new Error(`tree: free node ${i} is in use`);
      if (++free > this.parent.length) throw new Error('tree: free list has a cycle');
    }
    if (free + this.nodeCount !== this.parent.length) throw new Error('tree: nodes leaked');
  }

  private checkProxy(id: number): void {
    if (!(id >= 0 && id < this.parent.length && this.height[id] === 0)) {
      throw new Error(`DynamicTree: ${id} is not a live proxy id`);
    }
  }

  private setBox(id: number, minX: number, minY: number, maxX: number, maxY: number): void {
    const o = 4 * id;
    this.box[o] = minX;
    this.box[o + 1] = minY;
    this.box[o + 2] = maxX;
    this.box[o + 3] = maxY;
  }

  /** Half the perimeter: the 2D analogue of surface area, up to a constant factor. */
  private perimeter(id: number): number {
    const o = 4 * id;
    return this.box[o + 2] - this.box[o] + (this.box[o + 3] - this.box[o + 1]);
  }

  private contains(outer: number, inner: number): boolean {
    const a = 4 * outer;
    const b = 4 * inner;
    const box = this.box;
    return (
      box[a] <= box[b] && box[a + 1] <= box[b + 1] && box[a + 2] >= box[b + 2] && box[a + 3] >= box[b + 3]
    );
  }

  /** Returns `stack`, or a larger copy if a depth-first walk of the current tree might overflow it. */
  private stackFor(stack: Int32Array): Int32Array {
    const needed = this.height[this.root] + 2;
    return stack.length >= needed ? stack : new Int32Array(2 * needed);
  }

  private allocate(): number {
    if (this.freeList === Node.NULL) this.grow();
    const id = this.freeList;
    this.freeList = this.parent[id];
    this.parent[id] = Node.NULL;
    this.child1[id] = Node.NULL;
    this.child2[id] = Node.NULL;
    this.height[id] = 0;
    this.userData[id] = -1;
    this.nodeCount++;
    return id;
  }

  private release(id: number): void {
    this.parent[id] = this.freeList;
    this.height[id] = -1;
    this.freeList = id;
    this.nodeCount--;
  }

  private grow(): void {
    const old = this.parent.length;
    const capacity = 2 * old;
    const box = new Float64Array(4 * capacity);
    box.set(this.box);
    this.box = box;
    this.parent = grown(this.parent, capacity);
    this.child1 = grown(this.child1, capacity);
    this.child2 = grown(this.child2, capacity);
    this.height = grown(this.height, capacity);
    this.userData = grown(this.userData, capacity);
    this.isMoved = growU8(this.isMoved, capacity);
    this.linkFree(old, capacity);
  }

  /** Puts nodes [from, to) on the free list, lowest id first; the free list must be empty. */
  private linkFree(from: number, to: number): void {
    for (let i = from; i < to; i++) {
      this.parent[i] = i + 1 < to ? i + 1 : Node.NULL;
      this.height[i] = -1;
    }
    this.freeList = from;
  }

  private insertLeaf(leaf: number): void {
    if (this.root === Node.NULL) {
      this.root = leaf;
      this.parent[leaf] = Node.NULL;
      return;
    }
    const sibling = this.findBestSibling(leaf);
    const oldParent = this.parent[sibling];
    const node = this.allocate();
    this.parent[node] = oldParent;
    this.child1[node] = sibling;
    this.child2[node] = leaf;
    this.parent[sibling] = node;
    this.parent[leaf] = node;
    this.replaceChild(oldParent, sibling, node);
    // the new node has no box yet to compare: balance it, then walk up from its parent
    this.balance(node);
    this.refitUp(oldParent);
  }

  private removeLeaf(leaf: number): void {
    if (leaf === this.root) {
      this.root = Node.NULL;
      return;
    }
    const node = this.parent[leaf];
    const grandParent = this.parent[node];
    const sibling = this.child1[node] === leaf ? this.child2[node] : this.child1[node];
    this.parent[sibling] = grandParent;
    this.replaceChild(grandParent, node, sibling);
    this.release(node);
    this.refitUp(grandParent);
  }

  /** Makes `next` take the place of `prev` under `parent` (or as the root when `parent` is NULL). */
  private replaceChild(parent: number, prev: number, next: number): void {
    if (parent === Node.NULL) this.root = next;
    else if (this.child1[parent] === prev) this.child1[parent] = next;
    else this.child2[parent] = next;
  }

  /**
   * Greedy descent on the perimeter cost. Making node X the sibling costs the new parent's perimeter,
   * P(X ∪ L), plus the growth of every ancestor of X. Descending into a child costs at least the growth
   * of X plus the growth of that child plus P(L) (a leaf child's cost is exact: P(child ∪ L)).
   */
  private findBestSibling(leaf: number): number {
    const box = this.box;
    const o = 4 * leaf;
    const minX = box[o];
    const minY = box[o + 1];
    const maxX = box[o + 2];
    const maxY = box[o + 3];
    const leafCost = maxX - minX + (maxY - minY);
    let index = this.root;
    let inherited = 0;
    while (this.child1[index] !== Node.NULL) {
      const combined = this.unionPerimeter(index, minX, minY, maxX, maxY);
      const here = combined + inherited;
      const below = inherited + combined - this.perimeter(index);
      const c1 = this.child1[index];
      const c2 = this.child2[index];
      const cost1 = below + this.descentCost(c1, minX, minY, maxX, maxY, leafCost);
      const cost2 = below + this.descentCost(c2, minX, minY, maxX, maxY, leafCost);
      if (here <= cost1 && here <= cost2) break;
      index = cost1 <= cost2 ? c1 : c2;
      inherited = below;
    }
    return index;
  }

  private descentCost(
    id: number,
    minX: number,
    minY: number,
    maxX: number,
    maxY: number,
    leafCost: number,
  ): number {
    const combined = this.unionPerimeter(id, minX, minY, maxX, maxY);
    return this.child1[id] === Node.NULL ? combined : combined - this.perimeter(id) + leafCost;
  }

  private unionPerimeter(id: number, minX: number, minY: number, maxX: number, maxY: number): number {
    const box = this.box;
    const o = 4 * id;
    return (
      Math.max(box[o + 2], maxX) -
      Math.min(box[o], minX) +
      (Math.max(box[o + 3], maxY) - Math.min(box[o + 1], minY))
    );
  }

  /**
   * Rebalances and refits from `index` up towards the root. Stops at the first node whose box and
   * height come out unchanged: nothing above it changes then (only an optional perimeter swap
   * further up is forgone), and most moves of a proxy end a few levels up instead of at the root.
   */
  private refitUp(index: number): void {
    const box = this.box;
    while (index !== Node.NULL) {
      const o = 4 * index;
      const minX = box[o];
      const minY = box[o + 1];
      const maxX = box[o + 2];
      const maxY = box[o + 3];
      const height = this.height[index];
      this.balance(index);
      if (
        box[o] === minX &&
        box[o + 1] === minY &&
        box[o + 2] === maxX &&
        box[o + 3] === maxY &&
        this.height[index] === height
      ) {
        return;
      }
      index = this.parent[index];
    }
  }

  /**
   * `node` is internal and its two subtrees are balanced. Restores balance at `node` when its children's
   * heights differ by more than SLACK; otherwise applies the grandchild swap that shrinks the perimeter
   * most, if any keeps the balance. Then refits `node`. Nodes never move out of their subtree, so the
   * subtree's root stays `node`.
   */
  private balance(node: number): void {
    const b = this.child1[node];
    const c = this.child2[node];
    const diff = this.height[c] - this.height[b];
    if (diff > Balance.SLACK) this.lift(node, b, c);
    else if (diff < -Balance.SLACK) this.lift(node, c, b);
    else this.improve(node, b, c);
    this.refit(node);
  }

  /**
   * Swaps `light` with a child of `heavy` (a tree rotation). Prefers, among the swaps that leave both
   * levels balanced, the one pairing `light` with the nearer grandchild; if there is none (a leaf was
   * inserted beside a much taller subtree), lifts the taller grandchild and balances the node that
   * received `light` recursively, which pushes `light` down; the recursion depth is bounded by the height.
   */
  private lift(node: number, light: number, heavy: number): void {
    const f = this.child1[heavy];
    const g = this.child2[heavy];
    let up = Node.NULL;
    let best = Number.POSITIVE_INFINITY;
    if (this.swapKeepsBalance(light, f, g)) {
      up = f;
      best = this.pairPerimeter(light, g);
    }
    if (this.swapKeepsBalance(light, g, f) && this.pairPerimeter(light, f) < best) up = g;
    if (up !== Node.NULL) {
      this.swap(node, light, heavy, up);
      this.refit(heavy);
      return;
    }
    this.swap(node, light, heavy, this.height[g] > this.height[f] ? g : f);
    this.balance(heavy);
  }

  /** Applies the grandchild swap of `node` that most reduces the perimeter of the child it changes. */
  private improve(node: number, b: number, c: number): void {
    let bestGain = 0;
    let down = Node.NULL;
    let under = Node.NULL;
    let up = Node.NULL;
    for (let side = 0; side < 2; side++) {
      const u = side === 0 ? b : c;
      const v = side === 0 ? c : b;
      const f = this.child1[v];
      if (f === Node.NULL) continue;
      const g = this.child2[v];
      const perimeter = this.perimeter(v);
      for (let k = 0; k < 2; k++) {
        const x = k === 0 ? f : g;
        const y = k === 0 ? g : f;
        const gain = perimeter - this.pairPerimeter(u, y);
        if (gain > bestGain && this.swapKeepsBalance(u, x, y)) {
          bestGain = gain;
          down = u;
          under = v;
          up = x;
        }
      }
    }
    if (up === Node.NULL) return;
    this.swap(node, down, under, up);
    this.refit(under);
  }

  /** Whether swapping `u` with its nephew `x` (sibling `y` under their parent) keeps both levels balanced. */
  private swapKeepsBalance(u: number, x: number, y: number): boolean {
    const h = this.height;
    const pairHeight = 1 + Math.max(h[u], h[y]);
    return Math.abs(h[u] - h[y]) <= Balance.SLACK && Math.abs(h[x] - pairHeight) <= Balance.SLACK;
  }

  /** Exchanges `down`, a child of `node`, with `up`, a child of `under` (the other child of `node`). */
  private swap(node: number, down: number, under: number, up: number): void {
    if (this.child1[node] === down) this.child1[node] = up;
    else this.child2[node] = up;
    this.parent[up] = node;
    if (this.child1[under] === up) this.child1[under] = down;
    else this.child2[under] = down;
    this.parent[down] = under;
  }

  private pairPerimeter(a: number, b: number): number {
    const o = 4 * b;
    return this.unionPerimeter(a, this.box[o], this.box[o + 1], this.box[o + 2], this.box[o + 3]);
  }

  private refit(index: number): void {
    const box = this.box;
    const a = 4 * this.child1[index];
    const b = 4 * this.child2[index];
    const o = 4 * index;
    box[o] = Math.min(box[a], box[b]);
    box[o + 1] = Math.min(box[a + 1], box[b + 1]);
    box[o + 2] = Math.max(box[a + 2], box[b + 2]);
    box[o + 3] = Math.max(box[a + 3], box[b + 3]);
    this.height[index] = 1 + Math.max(this.height[this.child1[index]], this.height[this.child2[index]]);
  }

  /** Builds a subtree over `buildLeaves[lo, hi)` and returns its root. Recursion depth is log2(n). */
  private build(lo: number, hi: number): number {
    if (hi - lo === 1) return this.buildLeaves[lo];
    const mid = (lo + hi) >> 1;
    this.selectByCentre(lo, hi - 1, mid, this.splitAxis(lo, hi));
    const c1 = this.build(lo, mid);
    const c2 = this.build(mid, hi);
    const node = this.allocate();
    this.child1[node] = c1;
    this.child2[node] = c2;
    this.parent[c1] = node;
    this.parent[c2] = node;
    this.refit(node);
    return node;
  }

  /**
   * The axis (0: x, 1: y) along which the centres of `buildLeaves[lo, hi)` spread most. The choice is
   * kept up to date inside the loop so that nothing follows it but the return: a rebuild's first call
   * spans every leaf, V8 compiles the running loop then (OSR), and code after it with no type feedback
   * yet sent every later call of the recursion back to the interpreter (2,000 deoptimizations in one
   * rebuild of the 5,050-box pyramid).
   */
  private splitAxis(lo: number, hi: number): number {
    const leaves = this.buildLeaves;
    const centre = this.centre;
    let cMinX = Number.POSITIVE_INFINITY;
    let cMinY = Number.POSITIVE_INFINITY;
    let cMaxX = Number.NEGATIVE_INFINITY;
    let cMaxY = Number.NEGATIVE_INFINITY;
    let axis = 0;
    for (let i = lo; i < hi; i++) {
      const o = 2 * leaves[i];
      const cx = centre[o];
      const cy = centre[o + 1];
      cMinX = Math.min(cMinX, cx);
      cMaxX = Math.max(cMaxX, cx);
      cMinY = Math.min(cMinY, cy);
      cMaxY = Math.max(cMaxY, cy);
      axis = cMaxX - cMinX >= cMaxY - cMinY ? 0 : 1;
    }
    return axis;
  }

  /** Quickselect on `buildLeaves[l..r]` so that position k holds the k-th smallest centre on the axis. */
  private selectByCentre(l: number, r: number, k: number, axis: number): void {
    const leaves = this.buildLeaves;
    const centre = this.centre;
    while (l < r) {
      const pivot = centre[2 * leaves[(l + r) >> 1] + axis];
      let i = l;
      let j = r;
      while (i <= j) {
        while (centre[2 * leaves[i] + axis] < pivot) i++;
        while (centre[2 * leaves[j] + axis] > pivot) j--;
        if (i <= j) {
          const t = leaves[i];
          leaves[i++] = leaves[j];
          leaves[j--] = t;
        }
      }
      if (k <= j) r = j;
      else if (k >= i) l = i;
      else return;
    }
  }
}

function grown(array: Int32Array, capacity: number): Int32Array {
  const next = new Int32Array(capacity);
  next.set(array);
  return next;
}
