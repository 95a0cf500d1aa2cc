import { growF64, growI32, growU8 } from '../core/grow';
import { BodyKind, BodyState } from '../store/body-store';
import { HingePaths } from './hinge-paths';
import type { JointContext } from './joint-context';
import { PointRows } from './point-rows';
import type { SolverJoint } from './solver-joint';
import { TreeAxials, type TreeSolve } from './tree-axials';

/*
 * Direct solver for the rigid rows of joints that form a forest (chains, bridges, welded beams,
 * ragdolls, vehicles), after D. Baraff, "Linear-Time Dynamics using Lagrange Multipliers",
 * SIGGRAPH 1996.
 *
 * Gauss-Seidel over soft joints stretches under load: each joint's stiffness follows the mass of its
 * own two bodies, so a 100 kg ball on a chain of 1 kg links, or the root of a cantilever, gives
 * centimetres or metres of error. Here the equality rows of tree-shaped joints are solved exactly:
 * the system
 *
 *     [ M  Jᵀ ] [ Δv ]   [ 0             ]
 *     [ J  0  ] [ μ  ] = [ -(J v + bias) ]      (impulse λ = -μ)
 *
 * is laid out as a tree whose nodes are the dynamic bodies (3 rows) and the joints between two of
 * them (1-3 rows), ordered children before parents and factored as L D Lᵀ with no fill-in, in time
 * linear in the number of joints. A joint to a static or kinematic body would be a leaf with a zero
 * pivot, so its rows join its dynamic body's node instead (one such joint per body; that node's
 * pivot block is then [M J; J 0], which is still invertible without pivoting).
 *
 * Joints that would close a loop, a second grounded joint on one body, and joints on bodies with
 * fixed rotation stay with the iterative solver. The choice is greedy in creation order.
 *
 * Trees that are paths of free hinges (chains, ropes) are handed to HingePaths, which solves the same
 * rows in joint space with less arithmetic.
 */

/**
 * Loop-closing hinges that are solved through the tree (each costs two solves per factorization and
 * a pass over the tree per iteration), and the largest tree size for which that is done.
 */
const MAX_CLOSURES = 8;
const MAX_CLOSURE_NODES = 1024;
/**
 * Clusters of jointed bodies with more independent loops than this (grids, cloth) stay iterative as a
 * whole: a spanning tree of a grid is a long snake, and the many hinges left out of it, solved
 * iteratively against it, converge far worse than plain Gauss-Seidel over all of them.
 */
const MAX_LOOPS = 8;

/**
 * Share of a closing joint's own inverse mass added to its inverse mass through the tree: the tree
 * may not let the joint move at all in some direction (two pinned bars), where that alone is singular.
 */
export const CLOSURE_REGULARIZATION = 0.05;

/** a position correction turning a body further than this (radians) is followed by a second one */
const RESTABILIZE_TURN = 0.1;

/** rows and columns of a node block: a body's 3 plus up to 3 rows of a grounded joint */
enum Block {
  ROWS = 6,
  SIZE = ROWS * ROWS,
}
/** nodeKind of a body's node (a joint's is its index + 1) */
enum NodeKind {
  BODY = 0,
}

/** @internal */
export class JointTree implements TreeSolve {
  /** the joints solved here this step by the body-and-joint tree, in creation order */
  readonly joints: SolverJoint[] = [];
  jointCount = 0;
  /** the tree joints of clusters that are paths of free hinges, solved along their paths */
  readonly paths = new HingePaths();
  /** the active joints with rows for the iterative solver (not in the tree, or with axial rows) */
  readonly iterative: SolverJoint[] = [];
  /** per tree joint: its bodies' slots */
  private slotA = new Int32Array(16);
  private slotB = new Int32Array(16);
  /** per tree joint: rows, Jacobian blocks (rows × 3, stride 3) for A and B, position errors */
  private rows = new Int32Array(16);
  /**
   * per tree joint: 1 when it also iterates (a limit, motor or spring row) and is warm started with
   * all its impulses, 0 when the tree alone solves it (see project)
   */
  private warmed = new Uint8Array(16);
  private jA = new Float64Array(16 * 9);
  private jB = new Float64Array(16 * 9);
  private err = new Float64Array(16 * 3);
  /**
   * per tree row: the fastest its position correction may pull (JointContext.jointPushMaxSpeed, or
   * jointPushMaxTurn for a row of angles alone). Unbounded, a light body spinning near the rotation
   * limit at the end of a long lever, whose anchor leaves its row by the arc it turns in a substep,
   * was pulled back at hundreds of m/s, and the forest it hung in gained energy without bound.
   */
  private pushLimit = new Float64Array(16 * 3);
  /**
   * per tree row: the most its position error is corrected by in one substep (see stabilize): a
   * limit's at the push limits, the others' at JointContext.jointCorrectionMax / MaxTurn
   */
  private correctionLimit = new Float64Array(16 * 3);
  /** per tree row: the error stabilize leaves to the velocity bias (see there); 0 for a limit's */
  private correctionSlop = new Float64Array(16 * 3);
  /** per tree row: 1 for a limit's row (SolverJoint.fillLimitRow) */
  private limitRow = new Uint8Array(16 * 3);

  /**
   * Hinges and rods that would close a loop (a bridge pinned at both ends, a weight hung from two
   * rods) stay iterative, but are solved through the tree: with the effective mass K = J P M⁻¹ Jᵀ
   * (P the projection onto the tree rows) and with their impulse applied as the tree's response to
   * it. Without this the joint that closes the loop carries the load with the stiffness of its own
   * two bodies.
   */
  readonly closures: SolverJoint[] = [];
  private closureNodeA = new Int32Array(MAX_CLOSURES);
  private closureNodeB = new Int32Array(MAX_CLOSURES);
  private closureJA = new Float64Array(MAX_CLOSURES * 9);
  private closureJB = new Float64Array(MAX_CLOSURES * 9);
  private closureErr = new Float64Array(MAX_CLOSURES * 3);
  /** the impulse a closure hands to applyClosure (doubles passed to a call would be boxed) */
  readonly closureImpulse = new Float64Array(2);
  /** per closure row: the velocity change of every body node for a unit impulse on that row */
  private response = new Float64Array(0);
  /** the axial rows of tree joints (limits, motors, springs), solved together through the tree */
  readonly axials = new TreeAxials();
  /** per tree joint: the node holding its rows, the first of them there, and its bodies' nodes */
  private rowNode = new Int32Array(16);
  private rowOffset = new Int32Array(16);
  private nodeOfA = new Int32Array(16);
  private nodeOfB = new Int32Array(16);

  /** per node: joint index + 1 for joint nodes or BODY, dimension, body slot, merged joint, parent */
  private nodeKind = new Int32Array(32);
  private nodeDim = new Int32Array(32);
  private nodeBody = new Int32Array(32);
  private nodeGround = new Int32Array(32);
  private parent = new Int32Array(32);
  /** per node: pivot D and its inverse (Block.ROWS squared), and L = D⁻¹ H to the parent (3 × 3, see factorTree) */
  private d = new Float64Array(32 * Block.SIZE);
  private dInv = new Float64Array(32 * Block.SIZE);
  private l = new Float64Array(32 * 9);
  private x = new Float64Array(32 * Block.ROWS);
  /**
   * working memory of substitute (a node's values) and of invertBlock (a block under elimination);
   * # fields, which are no property keys: the snapshot leaves them out
   */
  readonly #nodeValues = new Float64Array(Block.ROWS);
  readonly #elimination = new Float64Array(Block.SIZE);
  /** the rows' velocity bias (PointRows.boundedBias; a # field too) */
  readonly #pointRows = new PointRows();
  /** @internal the solution vector of substitute (TreeSolve) */
  get solution(): Float64Array {
    return this.x;
  }
  /** @internal */
  readonly rowsPerNode = Block.ROWS;
  /** scratch of buildNodes: the breadth-first order, then each old node's new index */
  private order = new Int32Array(32);
  private rank = new Int32Array(32);
  /** @internal */
  nodeCount = 0;

  /** per active joint (build's input): its bodies' slots and whether the tree could take it */
  private activeA = new Int32Array(16);
  private activeB = new Int32Array(16);
  private activeEligible = new Uint8Array(16);
  /** per body slot: union-find parent and its node */
  private root = new Int32Array(64);
  /** per body slot: cluster union-find (not through the ground); at a root, its loops and ground */
  private cluster = new Int32Array(64);
  private loops = new Int32Array(64);
  private clusterGrounded = new Uint8Array(64);
  private counted = new Uint8Array(64);
  /** per body slot: its node in the last build's tree, or -1 (valid until the next build) */
  private bodyNode = new Int32Array(64).fill(-1);
  /** adjacency of the forest as linked lists of edges */
  private adjHead = new Int32Array(32);
  private adjNext = new Int32Array(64);
  private adjTo = new Int32Array(64);
  private visited = new Uint8Array(32);
  /** per body slot: at a cluster's root, whether its tree is a path of free hinges */
  private pathOk = new Uint8Array(64);
  /** per body slot: the tree joints at it (indices into `joints`), -1 for none; set by splitPaths */
  private hingeAt0 = new Int32Array(64);
  private hingeAt1 = new Int32Array(64);
  /** per body slot: 1 for a dynamic body of a path (valid until the next build) */
  private pathBody = new Uint8Array(64);
  /** per tree joint: whether splitPaths placed it on a path */
  private placed = new Uint8Array(16);

  /**
   * Chooses the tree joints among `active` and orders the nodes. Joints chosen get `inTree = true`,
   * the others false. Returns false when the last choice still holds and nothing was redone.
   */
  build(
    active: readonly SolverJoint[],
    relisted: boolean,
    kind: Uint8Array,
    invMass: Float64Array,
    invInertia: Float64Array,
    epoch: number,
  ): boolean {
    // the choice reads only the joints' options and the bodies' kinds and masses: while none of
    // them changed (the world's joint epoch) and the same joints are active (not `relisted`, or
    // relisted the same), the last build holds
    if (this.isBuilt(active, relisted, kind.length, epoch)) return false;
    this.builtEpoch = epoch;
    this.builtBodyCapacity = kind.length;
    this.builtActive.length = 0;
    for (const joint of active) this.builtActive.push(joint);
    if (this.root.length < kind.length) {
      this.root = growI32(this.root, kind.length);
      this.cluster = growI32(this.cluster, kind.length);
      this.loops = growI32(this.loops, kind.length);
      this.clusterGrounded = growU8(this.clusterGrounded, kind.length);
      this.counted = growU8(this.counted, kind.length);
      this.bodyNode = growI32(this.bodyNode, kind.length, -1);
      this.pathOk = growU8(this.pathOk, kind.length);
      this.hingeAt0 = growI32(this.hingeAt0, kind.length);
      this.hingeAt1 = growI32(this.hingeAt1, kind.length);
      this.pathBody = growU8(this.pathBody, kind.length);
    }
    // the last build's bodies leave the tree
    for (let n = 0; n < this.nodeCount; n++)
      if (this.nodeKind[n] === NodeKind.BODY) this.bodyNode[this.nodeBody[n]] = -1;
    for (const joint of this.paths.joints) {
      this.pathBody[joint.slotA] = 0;
      this.pathBody[joint.slotB] = 0;
    }
    this.nodeCount = 0;
    this.joints.length = 0;
    this.closures.length = 0;
    // the ground's entry: a non-dynamic body of the active joints
    let ground = -1;
    for (let j = 0; j < active.length && ground === -1; j++) {
      const joint = active[j];
      if (kind[joint.slotA] !== BodyKind.DYNAMIC) ground = joint.slotA;
      else if (kind[joint.slotB] !== BodyKind.DYNAMIC) ground = joint.slotB;
    }
    if (this.activeA.length < active.length) {
      const cap = Math.max(2 * this.activeA.length, active.length);
      this.activeA = growI32(this.activeA, cap);
      this.activeB = growI32(this.activeB, cap);
      this.activeEligible = growU8(this.activeEligible, cap);
    }
    for (let j = 0; j < active.length; j++) {
      const joint = active[j];
      joint.inTree = false;
      joint.onPath = false;
      joint.closure = false;
      joint.axialEntry0 = -1;
      joint.axialEntry1 = -1;
      const a = joint.slotA;
      const b = joint.slotB;
      this.activeA[j] = a;
      this.activeB[j] = b;
      this.activeEligible[j] = eligible(joint, a, b, kind, invMass, invInertia) ? 1 : 0;
      this.touch(a);
      this.touch(b);
    }
    this.countLoops(active.length, kind);
    for (let j = 0; j < active.length; j++) {
      if (this.activeEligible[j] === 0) continue;
      const joint = active[j];
      const a = this.activeA[j];
      const b = this.activeB[j];
      const dynA = kind[a] === BodyKind.DYNAMIC;
      const dynB = kind[b] === BodyKind.DYNAMIC;
      if (this.loops[this.findCluster(dynA ? a : b)] > MAX_LOOPS) continue;
      // every non-dynamic body counts as one node, the ground, so loops through it are refused too:
      // a bar pinned at both ends is redundant, and its system singular
      const ra = this.find(dynA ? a : ground);
      const rb = this.find(dynB ? b : ground);
      if (ra === rb) {
        if (joint.canCloseLoop() && this.closures.length < MAX_CLOSURES) {
          joint.closure = true;
          this.closures.push(joint);
        }
        continue;
      }
      this.root[ra] = rb;
      joint.inTree = true;
      this.joints.push(joint);
    }
    this.splitPaths(kind);
    this.jointCount = this.joints.length;
    this.iterative.length = 0;
    for (let j = 0; j < active.length; j++) {
      const joint = active[j];
      // a tree joint keeps the limit it holds through a rebuild (the same choice whether or not the
      // tree was rebuilt); others hold none
      if (!joint.inTree) joint.treeLimit = 0;
      if (!joint.inTree || joint.iteratesInTree()) this.iterative.push(joint);
    }
    this.buildNodes(kind);
    this.axials.list(this.joints, this.jointCount, this.nodeCount, this.bodyNode);
    if (this.nodeCount > MAX_CLOSURE_NODES) {
      for (let c = 0; c < this.closures.length; c++) this.closures[c].closure = false;
      this.closures.length = 0;
    }
    for (let c = 0; c < this.closures.length; c++) {
      this.closures[c].closureIndex = c;
      this.closureNodeA[c] = this.bodyNode[this.closures[c].slotA];
      this.closureNodeB[c] = this.bodyNode[this.closures[c].slotB];
    }
    return true;
  }

  /**
   * Moves the tree joints of every cluster whose tree is a path of free hinges (each body on at most
   * two, no closure) from `joints` to `paths`, path by path from an end: its grounded hinge, or a body
   * on one hinge, whichever comes first in creation order.
   */
  private splitPaths(kind: Uint8Array): void {
    const joints = this.joints;
    const count = joints.length;
    const pathOk = this.pathOk;
    const at0 = this.hingeAt0;
    const at1 = this.hingeAt1;
    this.paths.clear();
    for (let t = 0; t < count; t++) {
      const joint = joints[t];
      const a = joint.slotA;
      const b = joint.slotB;
      const r = this.findCluster(kind[a] === BodyKind.DYNAMIC ? a : b);
      if (!joint.isFreeHinge()) pathOk[r] = 0;
      for (let side = 0; side < 2; side++) {
        const x = side === 0 ? a : b;
        if (kind[x] !== BodyKind.DYNAMIC) continue;
        if (at0[x] === -1) at0[x] = t;
        else if (at1[x] === -1) at1[x] = t;
        else pathOk[r] = 0;
      }
    }
    for (const joint of this.closures) {
      const a = joint.slotA;
      const b = joint.slotB;
      pathOk[this.findCluster(kind[a] === BodyKind.DYNAMIC ? a : b)] = 0;
    }
    if (this.placed.length < count) this.placed = new Uint8Array(Math.max(2 * this.placed.length, count));
    const placed = this.placed;
    placed.fill(0, 0, count);
    for (let t = 0; t < count; t++) {
      const joint = joints[t];
      const a = joint.slotA;
      const b = joint.slotB;
      if (placed[t] !== 0 || pathOk[this.findCluster(kind[a] === BodyKind.DYNAMIC ? a : b)] === 0) continue;
      // an end of its path: the body before it is the ground or on no other hinge
      let before: number;
      if (kind[a] !== BodyKind.DYNAMIC || at1[a] === -1) before = a;
      else if (kind[b] !== BodyKind.DYNAMIC || at1[b] === -1) before = b;
      else continue;
      if (kind[before] === BodyKind.DYNAMIC) this.pathBody[before] = 1;
      let k = t;
      let start = true;
      for (;;) {
        const hinge = joints[k];
        placed[k] = 1;
        const forward = hinge.slotA === before;
        this.paths.add(hinge, start, forward);
        start = false;
        const after = forward ? hinge.slotB : hinge.slotA;
        if (kind[after] !== BodyKind.DYNAMIC) break;
        this.pathBody[after] = 1;
        const next = at0[after] === k ? at1[after] : at0[after];
        if (next === -1 || placed[next] !== 0) break;
        before = after;
        k = next;
      }
    }
    // the rest stay with the body-and-joint tree, in creation order
    let kept = 0;
    for (let t = 0; t < count; t++) if (placed[t] === 0) joints[kept++] = joints[t];
    joints.length = kept;
  }

  /** the joint epoch, body capacity and active joints of the last build */
  private builtEpoch = -1;
  private builtBodyCapacity = -1;
  private readonly builtActive: SolverJoint[] = [];

  private isBuilt(
    active: readonly SolverJoint[],
    relisted: boolean,
    bodyCapacity: number,
    epoch: number,
  ): boolean {
    if (epoch !== this.builtEpoch || bodyCapacity !== this.builtBodyCapacity) return false;
    if (!relisted) return true;
    const built = this.builtActive;
    if (active.length !== built.length) return false;
    for (let j = 0; j < active.length; j++) if (active[j] !== built[j]) return false;
    return true;
  }

  /**
   * Groups the bodies of eligible joints into clusters (not joined through the ground) and stores, at
   * each cluster's root, its number of independent loops: joints - bodies + 1, or joints - bodies
   * when the cluster is held by a non-dynamic body.
   */
  private countLoops(count: number, kind: Uint8Array): void {
    const loops = this.loops;
    const activeA = this.activeA;
    const activeB = this.activeB;
    const activeEligible = this.activeEligible;
    for (let j = 0; j < count; j++) {
      if (activeEligible[j] === 0) continue;
      const a = activeA[j];
      const b = activeB[j];
      if (kind[a] === BodyKind.DYNAMIC && kind[b] === BodyKind.DYNAMIC) {
        const ra = this.findCluster(a);
        const rb = this.findCluster(b);
        if (ra !== rb) this.cluster[ra] = rb;
      }
    }
    for (let j = 0; j < count; j++) {
      if (activeEligible[j] === 0) continue;
      const a = activeA[j];
      const b = activeB[j];
      const r = this.findCluster(kind[a] === BodyKind.DYNAMIC ? a : b);
      loops[r]++;
      if (kind[a] !== BodyKind.DYNAMIC || kind[b] !== BodyKind.DYNAMIC) this.clusterGrounded[r] = 1;
      for (let side = 0; side < 2; side++) {
        const body = side === 0 ? a : b;
        if (kind[body] !== BodyKind.DYNAMIC || this.counted[body] !== 0) continue;
        this.counted[body] = 1;
        loops[r]--;
      }
    }
    for (let j = 0; j < count; j++) {
      const a = activeA[j];
      const b = activeB[j];
      for (let side = 0; side < 2; side++) {
        const body = side === 0 ? a : b;
        if (this.cluster[body] !== body || this.counted[body] === 2) continue;
        this.counted[body] = 2;
        if (this.clusterGrounded[body] === 0) loops[body]++;
      }
    }
  }

  private findCluster(b: number): number {
    const cluster = this.cluster;
    let r = b;
    while (cluster[r] !== r) r = cluster[r];
    while (cluster[b] !== r) {
      const next = cluster[b];
      cluster[b] = r;
      b = next;
    }
    return r;
  }

  private touch(b: number): void {
    this.pathOk[b] = 1;
    this.hingeAt0[b] = -1;
    this.hingeAt1[b] = -1;
    this.cluster[b] = b;
    this.loops[b] = 0;
    this.clusterGrounded[b] = 0;
    this.counted[b] = 0;
    this.root[b] = b;
  }

  private find(b: number): number {
    const root = this.root;
    let r = b;
    while (root[r] !== r) r = root[r];
    while (root[b] !== r) {
      const next = root[b];
      root[b] = r;
      b = next;
    }
    return r;
  }

  private ensureCapacity(count: number): void {
    if (this.rows.length < count) {
      const cap = Math.max(2 * this.rows.length, count);
      this.rows = growI32(this.rows, cap);
      this.warmed = growU8(this.warmed, cap);
      this.slotA = growI32(this.slotA, cap);
      this.slotB = growI32(this.slotB, cap);
      this.rowNode = growI32(this.rowNode, cap);
      this.rowOffset = growI32(this.rowOffset, cap);
      this.nodeOfA = growI32(this.nodeOfA, cap);
      this.nodeOfB = growI32(this.nodeOfB, cap);
      this.jA = growF64(this.jA, cap * 9);
      this.jB = growF64(this.jB, cap * 9);
      this.err = growF64(this.err, cap * 3);
      this.pushLimit = growF64(this.pushLimit, cap * 3);
      this.correctionLimit = growF64(this.correctionLimit, cap * 3);
      this.correctionSlop = growF64(this.correctionSlop, cap * 3);
      this.limitRow = growU8(this.limitRow, cap * 3);
    }
    const n = 3 * count + 1;
    if (this.nodeKind.length >= n) return;
    const cap = Math.max(2 * this.nodeKind.length, n);
    this.nodeKind = growI32(this.nodeKind, cap);
    this.nodeDim = growI32(this.nodeDim, cap);
    this.nodeBody = growI32(this.nodeBody, cap);
    this.nodeGround = growI32(this.nodeGround, cap);
    this.parent = growI32(this.parent, cap);
    this.order = growI32(this.order, cap);
    this.rank = growI32(this.rank, cap);
    this.adjHead = growI32(this.adjHead, cap);
    this.adjNext = growI32(this.adjNext, 2 * cap);
    this.adjTo = growI32(this.adjTo, 2 * cap);
    this.visited = growU8(this.visited, cap);
    this.d = growF64(this.d, cap * Block.SIZE);
    this.dInv = growF64(this.dInv, cap * Block.SIZE);
    this.l = growF64(this.l, cap * 9);
    this.x = growF64(this.x, cap * Block.ROWS);
  }

  private addEdge(edge: number, from: number, to: number): void {
    this.adjTo[edge] = to;
    this.adjNext[edge] = this.adjHead[from];
    this.adjHead[from] = edge;
  }

  /** The node of dynamic body `b`, made on first use. */
  private nodeFor(b: number, nodes: number): number {
    const node = this.bodyNode[b];
    if (node !== -1) return node;
    this.bodyNode[b] = nodes;
    this.nodeKind[nodes] = NodeKind.BODY;
    this.nodeDim[nodes] = 3;
    this.nodeBody[nodes] = b;
    this.nodeGround[nodes] = -1;
    this.adjHead[nodes] = -1;
    return nodes;
  }

  /** Makes the nodes of the tree joints and their bodies, links them and orders each tree. */
  private buildNodes(kind: Uint8Array): void {
    const count = this.jointCount;
    this.ensureCapacity(count);
    let nodes = 0;
    let edges = 0;
    for (let j = 0; j < count; j++) {
      const joint = this.joints[j];
      const rows = joint.treeRows();
      this.rows[j] = rows;
      this.warmed[j] = joint.iteratesInTree() ? 1 : 0;
      const a = joint.slotA;
      const b = joint.slotB;
      this.slotA[j] = a;
      this.slotB[j] = b;
      let nodeA = -1;
      let nodeB = -1;
      if (kind[a] === BodyKind.DYNAMIC) {
        nodeA = this.nodeFor(a, nodes);
        if (nodeA === nodes) nodes++;
      }
      if (kind[b] === BodyKind.DYNAMIC) {
        nodeB = this.nodeFor(b, nodes);
        if (nodeB === nodes) nodes++;
      }
      this.nodeOfA[j] = nodeA;
      this.nodeOfB[j] = nodeB;
      if (nodeA === -1 || nodeB === -1) {
        // grounded: the rows join the body's node after its 3 velocity rows
        const node = nodeA === -1 ? nodeB : nodeA;
        this.nodeGround[node] = j;
        this.nodeDim[node] = 3 + rows;
        this.rowNode[j] = node;
        this.rowOffset[j] = 3;
        continue;
      }
      const c = nodes++;
      this.nodeKind[c] = j + 1;
      this.nodeDim[c] = rows;
      this.nodeGround[c] = -1;
      this.adjHead[c] = -1;
      this.rowNode[j] = c;
      this.rowOffset[j] = 0;
      this.addEdge(edges++, c, nodeA);
      this.addEdge(edges++, nodeA, c);
      this.addEdge(edges++, c, nodeB);
      this.addEdge(edges++, nodeB, c);
    }
    this.nodeCount = nodes;
    // A breadth-first walk lists parents before children; reversed, it is the elimination order. A
    // tree is rooted at its grounded body if it has one: below any other root, the pivot of the joint
    // above that body would be singular, as the ground already fixes what the joint constrains.
    const visited = this.visited;
    visited.fill(0, 0, nodes);
    const order = this.order;
    let listed = 0;
    for (let k = 0; k < 2 * nodes; k++) {
      const r = k < nodes ? k : k - nodes;
      if (visited[r] !== 0 || (k < nodes && this.nodeGround[r] === -1)) continue;
      visited[r] = 1;
      this.parent[r] = -1;
      const start = listed;
      order[listed++] = r;
      for (let q = start; q < listed; q++) {
        const n = order[q];
        for (let e = this.adjHead[n]; e !== -1; e = this.adjNext[e]) {
          const m = this.adjTo[e];
          if (visited[m] !== 0) continue;
          visited[m] = 1;
          this.parent[m] = n;
          order[listed++] = m;
        }
      }
    }
    this.renumber(listed);
  }

  /**
   * Renumbers the nodes in elimination order, the reverse of the breadth-first `order`, so that the
   * factorization and the substitutions run over the node arrays front to back (children first).
   */
  private renumber(nodes: number): void {
    const order = this.order;
    const rank = this.rank;
    for (let q = 0; q < nodes; q++) rank[order[q]] = nodes - 1 - q;
    const tmp = this.adjHead;
    permute(this.nodeKind, rank, tmp, nodes);
    permute(this.nodeDim, rank, tmp, nodes);
    permute(this.nodeBody, rank, tmp, nodes);
    permute(this.nodeGround, rank, tmp, nodes);
    permute(this.parent, rank, tmp, nodes);
    const parent = this.parent;
    for (let n = 0; n < nodes; n++) if (parent[n] !== -1) parent[n] = rank[parent[n]];
    for (let j = 0; j < this.jointCount; j++) {
      this.rowNode[j] = rank[this.rowNode[j]];
      if (this.nodeOfA[j] !== -1) this.nodeOfA[j] = rank[this.nodeOfA[j]];
      if (this.nodeOfB[j] !== -1) this.nodeOfB[j] = rank[this.nodeOfB[j]];
    }
    for (let n = 0; n < nodes; n++)
      if (this.nodeKind[n] === NodeKind.BODY) this.bodyNode[this.nodeBody[n]] = n;
  }

  /**
   * Whether anything else acts on the tree's bodies in the solver loop: a contact constraint among
   * the `count` of `ids` (body A, body B, contact per constraint) or an iterative joint. When nothing
   * does, one projection per pass leaves the tree rows exact and a second one would change nothing.
   */
  isCoupled(ids: Int32Array, count: number): boolean {
    if (this.jointCount === 0 && this.paths.count === 0) return false;
    for (let i = 0; i < count; i++) {
      if (this.solvesBody(ids[3 * i]) || this.solvesBody(ids[3 * i + 1])) return true;
    }
    for (let j = 0; j < this.iterative.length; j++) {
      const joint = this.iterative[j];
      if (this.solvesBody(joint.slotA) || this.solvesBody(joint.slotB)) return true;
    }
    return false;
  }

  /** Whether dynamic body `b` is on a tree joint (valid until the next build). */
  private solvesBody(b: number): boolean {
    return this.bodyNode[b] !== -1 || this.pathBody[b] !== 0;
  }

  /** Reads the step's data of the path hinges (once a step, before the first factorization). */
  prepare(ctx: JointContext): void {
    this.paths.prepare(ctx);
  }

  /** Hands the path hinges their impulses of the step. */
  store(ctx: JointContext): void {
    this.paths.store(ctx);
  }

  /**
   * Takes the tree rows' Jacobians and errors at the bodies' current positions, factors them and
   * updates the closures' effective masses. `first`: the step's first factorization (the paths may
   * have it from the step before); `last`: the step's last.
   */
  factor(ctx: JointContext, first: boolean, last: boolean): void {
    this.paths.pushLimit = ctx.jointPushMaxSpeed;
    if (this.paths.count > 0 && !(first && this.paths.factoredAtStart)) this.paths.factor(ctx.state, last);
    this.factorBodyTree(ctx);
  }

  /** Factors the body-and-joint tree (not the paths) with its closures' and axial rows' masses. */
  private factorBodyTree(ctx: JointContext): void {
    this.factorTree(ctx);
    if (this.closures.length > 0) this.closureMasses(ctx);
    if (this.axials.count > 0) this.axials.factor(ctx, this);
  }

  /** One pass over the axial rows of the tree's joints (see TreeAxials). */
  solveAxials(ctx: JointContext, useBias: boolean): void {
    if (this.axials.count > 0) this.axials.solve(ctx, this, useBias);
  }

  /**
   * Every edge of the tree joins a joint node to a body node, and its block H touches only the body's
   * 3 velocity rows and at most 3 joint rows; a joint with 2 rows has a zero third Jacobian row, so
   * every H, and L = D⁻¹ H, is a 3 × 3 block, and the loops here are unrolled. Only roots can be
   * larger than 3 (a body with its grounded joint's rows): such a node is always a root.
   */
  private factorTree(ctx: JointContext): void {
    const count = this.jointCount;
    if (count === 0) return;
    const jA = this.jA;
    const jB = this.jB;
    this.limitRow.fill(0, 0, 3 * count);
    for (let j = 0; j < count; j++) {
      const rows = this.joints[j].treeFill(ctx, jA, jB, this.err, j, true);
      // a limit the tree holds this substep is one more row (SolverJoint.fillLimitRow)
      if (rows !== this.rows[j]) {
        this.rows[j] = rows;
        this.nodeDim[this.rowNode[j]] = this.rowOffset[j] + rows;
      }
    }
    this.fillPushLimits(ctx, count);
    this.fillPivots(ctx.invMass, ctx.invInertia);
    const nodes = this.nodeCount;
    const parent = this.parent;
    const nodeKind = this.nodeKind;
    const nodeOfA = this.nodeOfA;
    const d = this.d;
    const dInv = this.dInv;
    const l = this.l;
    for (let n = 0; n < nodes; n++) {
      const o = Block.SIZE * n;
      invertBlock(d, dInv, o, this.nodeDim[n], this.#elimination);
      const p = parent[n];
      if (p === -1) continue;
      // H: the Jacobian block of the edge's joint at the edge's body, transposed when the body is
      // the child (rows are the child's, columns the parent's)
      const childIsJoint = nodeKind[n] !== NodeKind.BODY;
      const j = (childIsJoint ? nodeKind[n] : nodeKind[p]) - 1;
      const jac = nodeOfA[j] === (childIsJoint ? p : n) ? jA : jB;
      const m = 9 * j;
      const t = childIsJoint ? 1 : 3;
      const u = childIsJoint ? 3 : 1;
      const h00 = jac[m];
      const h01 = jac[m + t];
      const h02 = jac[m + 2 * t];
      const h10 = jac[m + u];
      const h11 = jac[m + u + t];
      const h12 = jac[m + u + 2 * t];
      const h20 = jac[m + 2 * u];
      const h21 = jac[m + 2 * u + t];
      const h22 = jac[m + 2 * u + 2 * t];
      const i00 = dInv[o];
      const i01 = dInv[o + 1];
      const i02 = dInv[o + 2];
      const i11 = dInv[o + Block.ROWS + 1];
      const i12 = dInv[o + Block.ROWS + 2];
      const i22 = dInv[o + 2 * Block.ROWS + 2];
      // L = D⁻¹ H (D⁻¹ is symmetric)
      const l00 = i00 * h00 + i01 * h10 + i02 * h20;
      const l01 = i00 * h01 + i01 * h11 + i02 * h21;
      const l02 = i00 * h02 + i01 * h12 + i02 * h22;
      const l10 = i01 * h00 + i11 * h10 + i12 * h20;
      const l11 = i01 * h01 + i11 * h11 + i12 * h21;
      const l12 = i01 * h02 + i11 * h12 + i12 * h22;
      const l20 = i02 * h00 + i12 * h10 + i22 * h20;
      const l21 = i02 * h01 + i12 * h11 + i22 * h21;
      const l22 = i02 * h02 + i12 * h12 + i22 * h22;
      const lo = 9 * n;
      l[lo] = l00;
      l[lo + 1] = l01;
      l[lo + 2] = l02;
      l[lo + 3] = l10;
      l[lo + 4] = l11;
      l[lo + 5] = l12;
      l[lo + 6] = l20;
      l[lo + 7] = l21;
      l[lo + 8] = l22;
      // D_p -= Hᵀ L, which is symmetric
      const op = Block.SIZE * p;
      const e00 = h00 * l00 + h10 * l10 + h20 * l20;
      const e01 = h00 * l01 + h10 * l11 + h20 * l21;
      const e02 = h00 * l02 + h10 * l12 + h20 * l22;
      const e11 = h01 * l01 + h11 * l11 + h21 * l21;
      const e12 = h01 * l02 + h11 * l12 + h21 * l22;
      const e22 = h02 * l02 + h12 * l12 + h22 * l22;
      d[op] -= e00;
      d[op + 1] -= e01;
      d[op + 2] -= e02;
      d[op + Block.ROWS] -= e01;
      d[op + Block.ROWS + 1] -= e11;
      d[op + Block.ROWS + 2] -= e12;
      d[op + 2 * Block.ROWS] -= e02;
      d[op + 2 * Block.ROWS + 1] -= e12;
      d[op + 2 * Block.ROWS + 2] -= e22;
    }
  }

  /**
   * Sets each tree row's push limit (a turn rate for a row of angles alone, else a speed) and its
   * correction limit per substep. A limit's row has no position bias in the projections: stabilize
   * pushes it back, by positions alone (see there).
   */
  private fillPushLimits(ctx: JointContext, count: number): void {
    const jA = this.jA;
    const jB = this.jB;
    const push = this.pushLimit;
    const correction = this.correctionLimit;
    const slop = this.correctionSlop;
    const h = ctx.h;
    for (let r = 0; r < 3 * count; r++) {
      const m = 3 * r;
      const angular = jA[m] === 0 && jA[m + 1] === 0 && jB[m] === 0 && jB[m + 1] === 0;
      const speed = angular ? ctx.jointPushMaxTurn : ctx.jointPushMaxSpeed;
      if (this.limitRow[r] !== 0) {
        push[r] = 0;
        correction[r] = speed * h;
        slop[r] = 0;
      } else {
        push[r] = speed;
        correction[r] = angular ? ctx.jointCorrectionMaxTurn : ctx.jointCorrectionMax;
        slop[r] = angular ? ctx.jointSlopTurn : ctx.jointSlop;
      }
    }
  }

  /**
   * @internal while set, the joints keep the limits they hold (SolverJoint.fillLimitRow): a second
   * factorization within a substep (see restabilize) must hold the same rows as the first
   */
  keepLimits = false;

  /** @internal Marks row `row` of tree joint `j` as a limit's (SolverJoint.fillLimitRow). */
  markLimitRow(j: number, row: number): void {
    this.limitRow[3 * j + row] = 1;
  }

  /**
   * Moves the tree's bodies so that its rows' position errors come back within their slop, each by at
   * most its correction limit (a violated limit's by its push per substep): Δx = -M⁻¹ Jᵀ (J M⁻¹ Jᵀ)⁻¹ C,
   * the smallest move in the bodies' masses, with the current factorization (post-stabilization,
   * after Cline and Pai). It moves positions and no velocity, so it adds no energy, unlike the
   * velocity bias: the joints of a spinning body drift apart by the arc its anchors turn within a
   * substep ((ω h)² r / 2), and a 40-link chain uncurling a radian at each limit (its tip turning
   * 40 rad/s) drifted apart by metres though each substep's bias pulled back. Within the slop, the
   * velocity bias still corrects: the moved positions keep velocities tangent to where the bodies
   * were, and a pendulum's rod held by positions alone lost 4 % of its energy a second, where the
   * bias's inward velocity turns the velocity with the rod (to second order in ω h, exactly).
   * Called after the substep's positions were integrated and the tree factored at them; the errors
   * are then taken as corrected for the next projections. Returns the largest turn it gave a body,
   * or -1 when it moved none.
   */
  stabilize(state: Float64Array, limits: boolean, maxMove: number, maxTurn: number): number {
    const count = this.jointCount;
    if (count === 0) return 0;
    const x = this.x;
    x.fill(0, 0, Block.ROWS * this.nodeCount);
    const err = this.err;
    const correction = this.correctionLimit;
    const slop = this.correctionSlop;
    let any = false;
    for (let j = 0; j < count; j++) {
      const o = Block.ROWS * this.rowNode[j] + this.rowOffset[j];
      for (let r = 0; r < 3; r++) {
        const e = 3 * j + r;
        const beyond = err[e] - Math.max(-slop[e], Math.min(err[e], slop[e]));
        const c = Math.max(-correction[e], Math.min(beyond, correction[e]));
        if (c === 0 || (!limits && this.limitRow[e] !== 0)) continue;
        x[o + r] = -c;
        err[e] -= c;
        any = true;
      }
    }
    if (!any) return -1;
    this.substitute();
    // no body further than the speed limits let it move in a substep: near a singular pose the
    // smallest move to a small error can be a large one, and the linear step is meaningless there
    let moved = 0;
    let turned = 0;
    for (let n = 0, nodes = this.nodeCount; n < nodes; n++) {
      if (this.nodeKind[n] !== NodeKind.BODY) continue;
      const o = Block.ROWS * n;
      moved = Math.max(moved, Math.abs(x[o]), Math.abs(x[o + 1]));
      turned = Math.max(turned, Math.abs(x[o + 2]));
    }
    const scale = Math.min(1, maxMove / moved, maxTurn / turned);
    for (let n = 0, nodes = this.nodeCount; n < nodes; n++) {
      if (this.nodeKind[n] !== NodeKind.BODY) continue;
      const o = Block.ROWS * n;
      const s = this.nodeBody[n] * BodyState.STRIDE;
      state[s + BodyState.DPX] += scale * x[o];
      state[s + BodyState.DPY] += scale * x[o + 1];
      // turn by the angle x[o + 2] (see integratePositions)
      const t = scale * x[o + 2];
      const t2 = t * t;
      const rc = 1 - t2 * (0.5 - t2 * (1 / 24 - t2 * (1 / 720 - t2 / 40320)));
      const rs = t * (1 - t2 * (1 / 6 - t2 * (1 / 120 - t2 * (1 / 5040 - t2 / 362880))));
      const c = state[s + BodyState.DQC];
      const sn = state[s + BodyState.DQS];
      const nc = c * rc - sn * rs;
      const ns = sn * rc + c * rs;
      const inv = 1 / Math.sqrt(nc * nc + ns * ns);
      state[s + BodyState.DQC] = nc * inv;
      state[s + BodyState.DQS] = ns * inv;
    }
    return scale * turned;
  }

  /**
   * The substep's position correction (see stabilize), after which the tree is factored again at the
   * new positions, with the same limits held, for the velocity projections that follow. When it
   * turned some body by more than RESTABILIZE_TURN, the linear step left the anchors apart by the
   * arcs they turned (a 40-link chain uncurling at its limits: 3 cm): then its joints' rows (not the
   * limits, already moved) are corrected once more.
   */
  stabilizeSubstep(ctx: JointContext, maxMove: number, maxTurn: number): void {
    const turned = this.stabilize(ctx.state, true, maxMove, maxTurn);
    if (turned < 0) return;
    this.keepLimits = true;
    this.factorBodyTree(ctx);
    if (turned > RESTABILIZE_TURN && this.stabilize(ctx.state, false, maxMove, maxTurn) >= 0) {
      this.factorBodyTree(ctx);
    }
    this.keepLimits = false;
  }

  /**
   * Gives each closure its effective mass through the tree: for each of its rows, the tree's velocity
   * response to that row's impulse, read back through both rows.
   */
  private closureMasses(ctx: JointContext): void {
    const jA = this.closureJA;
    const jB = this.closureJB;
    const x = this.x;
    if (this.response.length === 0)
      this.response = new Float64Array(2 * MAX_CLOSURES * 3 * MAX_CLOSURE_NODES);
    const response = this.response;
    for (let c = 0; c < this.closures.length; c++) {
      const joint = this.closures[c];
      joint.treeFill(ctx, jA, jB, this.closureErr, c, false);
      const nodeA = this.closureNodeA[c];
      const nodeB = this.closureNodeB[c];
      const k = joint.closureMass;
      k.fill(0);
      const rows = joint.treeRows();
      for (let r = 0; r < rows; r++) {
        x.fill(0, 0, Block.ROWS * this.nodeCount);
        const m = 9 * c + 3 * r;
        for (let i = 0; i < 3; i++) {
          if (nodeA !== -1) x[Block.ROWS * nodeA + i] += jA[m + i];
          if (nodeB !== -1) x[Block.ROWS * nodeB + i] += jB[m + i];
        }
        if (this.jointCount > 0) this.substitute();
        const base = (2 * c + r) * 3 * MAX_CLOSURE_NODES;
        for (let n = 0, nodes = this.nodeCount; n < nodes; n++) {
          const o = base + 3 * n;
          const nodeIsBody = this.nodeKind[n] === NodeKind.BODY;
          response[o] = nodeIsBody ? x[Block.ROWS * n] : 0;
          response[o + 1] = nodeIsBody ? x[Block.ROWS * n + 1] : 0;
          response[o + 2] = nodeIsBody ? x[Block.ROWS * n + 2] : 0;
        }
        // K's column r: both rows read the response at the hinge's two bodies (the ground has none)
        for (let side = 0; side < 2; side++) {
          const node = side === 0 ? nodeA : nodeB;
          if (node === -1) continue;
          const jac = side === 0 ? jA : jB;
          const o = base + 3 * node;
          for (let row = 0; row < rows; row++) {
            const q = 9 * c + 3 * row;
            k[2 * row + r] +=
              jac[q] * response[o] + jac[q + 1] * response[o + 1] + jac[q + 2] * response[o + 2];
          }
        }
      }
    }
  }

  /**
   * Applies `closureImpulse` on the rows of closure `c` as the tree's response to it (a rod has one
   * row: its second entry must be 0).
   */
  applyClosure(c: number, state: Float64Array): void {
    const px = this.closureImpulse[0];
    const py = this.closureImpulse[1];
    const response = this.response;
    const bx = 2 * c * 3 * MAX_CLOSURE_NODES;
    const by = bx + 3 * MAX_CLOSURE_NODES;
    for (let n = 0, nodes = this.nodeCount; n < nodes; n++) {
      if (this.nodeKind[n] !== NodeKind.BODY) continue;
      const s = this.nodeBody[n] * BodyState.STRIDE;
      const ox = bx + 3 * n;
      const oy = by + 3 * n;
      state[s + BodyState.VX] += px * response[ox] + py * response[oy];
      state[s + BodyState.VY] += px * response[ox + 1] + py * response[oy + 1];
      state[s + BodyState.W] += px * response[ox + 2] + py * response[oy + 2];
    }
  }

  /**
   * Sets each node's pivot block before elimination: a body's mass and inertia, followed by its
   * grounded joint's rows if it has one; zero for a joint.
   */
  private fillPivots(invMass: Float64Array, invInertia: Float64Array): void {
    const d = this.d;
    for (let n = 0, nodes = this.nodeCount; n < nodes; n++) {
      const o = Block.SIZE * n;
      const isBody = this.nodeKind[n] === NodeKind.BODY;
      const b = this.nodeBody[n];
      const m = isBody ? 1 / invMass[b] : 0;
      d[o] = m;
      d[o + 1] = 0;
      d[o + 2] = 0;
      d[o + Block.ROWS] = 0;
      d[o + Block.ROWS + 1] = m;
      d[o + Block.ROWS + 2] = 0;
      d[o + 2 * Block.ROWS] = 0;
      d[o + 2 * Block.ROWS + 1] = 0;
      d[o + 2 * Block.ROWS + 2] = isBody ? 1 / invInertia[b] : 0;
      const g = this.nodeGround[n];
      if (g === -1) continue;
      const block = this.nodeOfA[g] === n ? this.jA : this.jB;
      const rows = this.rows[g];
      for (let r = 0; r < rows; r++) {
        for (let c = 0; c < 3; c++) {
          const v = block[9 * g + 3 * r + c];
          d[o + Block.ROWS * (3 + r) + c] = v;
          d[o + Block.ROWS * c + 3 + r] = v;
        }
        for (let c = 0; c < rows; c++) d[o + Block.ROWS * (3 + r) + 3 + c] = 0;
      }
    }
  }

  /**
   * Projects the velocities onto the tree rows with the last factorization: afterwards J v = 0, or
   * with `biasRate` > 0, J v = -biasRate C (the position error shrinks at that rate).
   *
   * A joint the tree alone solves is not warm started: the projection would take that impulse out
   * again exactly (it removes every velocity change along the tree rows). The substep's `first`
   * projection then finds its whole impulse, which replaces the one it held; later ones add to it.
   */
  project(state: Float64Array, biasRate: number, first: boolean): void {
    if (this.paths.count > 0) this.paths.project(state, biasRate, first);
    const count = this.jointCount;
    if (count === 0) return;
    const x = this.x;
    x.fill(0, 0, Block.ROWS * this.nodeCount);
    // right-hand side: -(J v + bias) on the joints' rows, 0 on the bodies'; the bias bounded (see pushLimit)
    const jA = this.jA;
    const jB = this.jB;
    const err = this.err;
    const limit = this.pushLimit;
    const pointRows = this.#pointRows;
    for (let j = 0; j < count; j++) {
      const sa = this.slotA[j] * BodyState.STRIDE;
      const sb = this.slotB[j] * BodyState.STRIDE;
      const vAx = state[sa + BodyState.VX];
      const vAy = state[sa + BodyState.VY];
      const wA = state[sa + BodyState.W];
      const vBx = state[sb + BodyState.VX];
      const vBy = state[sb + BodyState.VY];
      const wB = state[sb + BodyState.W];
      // three rows each: a joint with fewer has zero rows after its own (see SolverJoint.clearTreeRows)
      const o = Block.ROWS * this.rowNode[j] + this.rowOffset[j];
      const m = 9 * j;
      const e = 3 * j;
      x[o] = -(
        jA[m] * vAx +
        jA[m + 1] * vAy +
        jA[m + 2] * wA +
        jB[m] * vBx +
        jB[m + 1] * vBy +
        jB[m + 2] * wB +
        pointRows.boundedBias(biasRate, err[e], limit[e])
      );
      x[o + 1] = -(
        jA[m + 3] * vAx +
        jA[m + 4] * vAy +
        jA[m + 5] * wA +
        jB[m + 3] * vBx +
        jB[m + 4] * vBy +
        jB[m + 5] * wB +
        pointRows.boundedBias(biasRate, err[e + 1], limit[e + 1])
      );
      x[o + 2] = -(
        jA[m + 6] * vAx +
        jA[m + 7] * vAy +
        jA[m + 8] * wA +
        jB[m + 6] * vBx +
        jB[m + 7] * vBy +
        jB[m + 8] * wB +
        pointRows.boundedBias(biasRate, err[e + 2], limit[e + 2])
      );
    }
    this.substitute();
    for (let n = 0, nodes = this.nodeCount; n < nodes; n++) {
      if (this.nodeKind[n] !== NodeKind.BODY) continue;
      const o = Block.ROWS * n;
      const s = this.nodeBody[n] * BodyState.STRIDE;
      state[s + BodyState.VX] += x[o];
      state[s + BodyState.VY] += x[o + 1];
      state[s + BodyState.W] += x[o + 2];
    }
    for (let j = 0; j < count; j++) {
      const o = Block.ROWS * this.rowNode[j] + this.rowOffset[j];
      this.joints[j].treeAddImpulse(x, o, first && this.warmed[j] === 0 ? 0 : 1);
    }
  }

  /** @internal Solves L D Lᵀ x = x in place (L in 3 × 3 blocks, see factorTree; nodes children first). */
  substitute(): void {
    const nodes = this.nodeCount;
    const parent = this.parent;
    const x = this.x;
    const l = this.l;
    const dInv = this.dInv;
    // forward, children first: once a node's children are done its value is final; it goes to the
    // parent (x_p -= Lᵀ x_n) and is then scaled by its pivot (x_n = D⁻¹ x_n)
    for (let n = 0; n < nodes; n++) {
      const xn = Block.ROWS * n;
      const o = Block.SIZE * n;
      const x0 = x[xn];
      const x1 = x[xn + 1];
      const x2 = x[xn + 2];
      const p = parent[n];
      if (p !== -1) {
        const xp = Block.ROWS * p;
        const lo = 9 * n;
        x[xp] -= l[lo] * x0 + l[lo + 3] * x1 + l[lo + 6] * x2;
        x[xp + 1] -= l[lo + 1] * x0 + l[lo + 4] * x1 + l[lo + 7] * x2;
        x[xp + 2] -= l[lo + 2] * x0 + l[lo + 5] * x1 + l[lo + 8] * x2;
      }
      const dim = this.nodeDim[n];
      if (dim > 3) {
        const values = this.#nodeValues;
        for (let k = 0; k < dim; k++) values[k] = x[xn + k];
        for (let r = 0; r < dim; r++) {
          let s = 0;
          for (let k = 0; k < dim; k++) s += dInv[o + Block.ROWS * r + k] * values[k];
          x[xn + r] = s;
        }
        continue;
      }
      x[xn] = dInv[o] * x0 + dInv[o + 1] * x1 + dInv[o + 2] * x2;
      x[xn + 1] = dInv[o + Block.ROWS] * x0 + dInv[o + Block.ROWS + 1] * x1 + dInv[o + Block.ROWS + 2] * x2;
      x[xn + 2] =
        dInv[o + 2 * Block.ROWS] * x0 + dInv[o + 2 * Block.ROWS + 1] * x1 + dInv[o + 2 * Block.ROWS + 2] * x2;
    }
    // backward, parents first: x_n -= L x_p
    for (let n = nodes - 1; n >= 0; n--) {
      const p = parent[n];
      if (p === -1) continue;
      const xn = Block.ROWS * n;
      const xp = Block.ROWS * p;
      const lo = 9 * n;
      const x0 = x[xp];
      const x1 = x[xp + 1];
      const x2 = x[xp + 2];
      x[xn] -= l[lo] * x0 + l[lo + 1] * x1 + l[lo + 2] * x2;
      x[xn + 1] -= l[lo + 3] * x0 + l[lo + 4] * x1 + l[lo + 5] * x2;
      x[xn + 2] -= l[lo + 6] * x0 + l[lo + 7] * x1 + l[lo + 8] * x2;
    }
  }
}

/** Moves a[n] to a[rank[n]] for the first `count` entries, through `tmp`. */
function permute(a: Int32Array, rank: Int32Array, tmp: Int32Array, count: number): void {
  for (let n = 0; n < count; n++) tmp[rank[n]] = a[n];
  for (let n = 0; n < count; n++) a[n] = tmp[n];
}

/** Whether the joint has rows for the tree and bodies the tree can take (dynamic ones must turn). */
function eligible(
  joint: SolverJoint,
  a: number,
  b: number,
  kind: Uint8Array,
  invMass: Float64Array,
  invInertia: Float64Array,
): boolean {
  if (joint.treeRows() === 0) return false;
  const dynA = kind[a] === BodyKind.DYNAMIC;
  const dynB = kind[b] === BodyKind.DYNAMIC;
  if (!dynA && !dynB) return false;
  if (dynA && (invInertia[a] === 0 || invMass[a] === 0)) return false;
  if (dynB && (invInertia[b] === 0 || invMass[b] === 0)) return false;
  return true;
}

/**
 * Inverts the symmetric dim × dim block at `o` (stride Block.ROWS) of `m` into `out`: in closed form up to
 * 3 rows, zeroing the rest of the 3 × 3 block, else (a root with its grounded joint's rows) by
 * Gauss-Jordan elimination in natural order. No pivoting is needed here: a block is either positive
 * definite (a body), negative definite (a joint) or a body's positive definite rows followed by its
 * grounded joint's rows, whose Schur complement is negative definite. A zero pivot gives a zero row.
 * `work` holds the block under elimination (Block.SIZE doubles).
 */
function invertBlock(m: Float64Array, out: Float64Array, o: number, dim: number, work: Float64Array): void {
  if (dim === 1) {
    invert1(m, out, o);
    return;
  }
  if (dim === 2) {
    invert2(m, out, o);
    return;
  }
  if (dim === 3) {
    invert3(m, out, o);
    return;
  }
  for (let r = 0; r < dim; r++) {
    for (let c = 0; c < dim; c++) {
      work[Block.ROWS * r + c] = m[o + Block.ROWS * r + c];
      out[o + Block.ROWS * r + c] = r === c ? 1 : 0;
    }
  }
  for (let k = 0; k < dim; k++) {
    const pivot = work[Block.ROWS * k + k];
    const inv = pivot !== 0 ? 1 / pivot : 0;
    for (let c = 0; c < dim; c++) {
      work[Block.ROWS * k + c] *= inv;
      out[o + Block.ROWS * k + c] *= inv;
    }
    for (let r = 0; r < dim; r++) {
      if (r === k) continue;
      const f = work[Block.ROWS * r + k];
      if (f === 0) continue;
      for (let c = 0; c < dim; c++) {
        work[Block.ROWS * r + c] -= f * work[Block.ROWS * k + c];
        out[o + Block.ROWS * r + c] -= f * out[o + Block.ROWS * k + c];
      }
    }
  }
}

/** Inverse of a 1 × 1 block (the row of a rod); the rest of the 3 × 3 block is zero (see factorTree). */
function invert1(m: Float64Array, out: Float64Array, o: number): void {
  const a = m[o];
  out[o] = a !== 0 ? 1 / a : 0;
  out[o + 1] = 0;
  out[o + 2] = 0;
  out[o + Block.ROWS] = 0;
  out[o + Block.ROWS + 1] = 0;
  out[o + Block.ROWS + 2] = 0;
  out[o + 2 * Block.ROWS] = 0;
  out[o + 2 * Block.ROWS + 1] = 0;
  out[o + 2 * Block.ROWS + 2] = 0;
}

/** Closed-form inverse of a symmetric 2 × 2 block (the rows of a hinge). */
function invert2(m: Float64Array, out: Float64Array, o: number): void {
  const a = m[o];
  const b = m[o + 1];
  const c = m[o + Block.ROWS + 1];
  let det = a * c - b * b;
  if (det !== 0) det = 1 / det;
  out[o] = det * c;
  out[o + 1] = -det * b;
  out[o + Block.ROWS] = -det * b;
  out[o + Block.ROWS + 1] = det * a;
  // the third row and column stay zero: the joint's padding row (see factorTree)
  out[o + 2] = 0;
  out[o + Block.ROWS + 2] = 0;
  out[o + 2 * Block.ROWS] = 0;
  out[o + 2 * Block.ROWS + 1] = 0;
  out[o + 2 * Block.ROWS + 2] = 0;
}

/** Closed-form inverse of a symmetric 3 × 3 block (a body, or the rows of a weld), by cofactors. */
function invert3(m: Float64Array, out: Float64Array, o: number): void {
  const a11 = m[o];
  const a12 = m[o + 1];
  const a13 = m[o + 2];
  const a22 = m[o + Block.ROWS + 1];
  const a23 = m[o + Block.ROWS + 2];
  const a33 = m[o + 2 * Block.ROWS + 2];
  const c11 = a22 * a33 - a23 * a23;
  const c12 = a13 * a23 - a12 * a33;
  const c13 = a12 * a23 - a13 * a22;
  let det = a11 * c11 + a12 * c12 + a13 * c13;
  if (det !== 0) det = 1 / det;
  const i12 = det * c12;
  const i13 = det * c13;
  const i23 = det * (a12 * a13 - a11 * a23);
  out[o] = det * c11;
  out[o + 1] = i12;
  out[o + 2] = i13;
  out[o + Block.ROWS] = i12;
  out[o + Block.ROWS + 1] = det * (a11 * a33 - a13 * a13);
  out[o + Block.ROWS + 2] = i23;
  out[o + 2 * Block.ROWS] = i13;
  out[o + 2 * Block.ROWS + 1] = i23;
  out[o + 2 * Block.ROWS + 2] = det * (a11 * a22 - a12 * a12);
}
