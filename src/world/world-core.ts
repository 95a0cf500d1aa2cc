import { BroadPhase, type PairFilter, ProxyType } from '../broad-phase/broad-phase';
import { IntList } from '../broad-phase/int-list';
import { PairSet } from '../broad-phase/pair-set';
import {
  JOINT_CORRECTION_MAX_TURN,
  JOINT_PUSH_MAX_TURN,
  JOINT_SLOP_TURN,
  makeSettings,
  type Settings,
} from '../core/settings';
import { packedBounds } from '../geometry/bounds';
import { centroidExtent, maxExtentFrom, minExtent } from '../geometry/extent';
import { computeMass } from '../geometry/mass';
import { Pack } from '../geometry/packed';
import type { Manifold, ManifoldPoint, MassData } from '../geometry/types';
import type { Bounds } from '../math/aabb';
import { makeBounds } from '../math/aabb';
import type { Transform } from '../math/vec2';
import { CollideContext } from '../narrow-phase/collide-context';
import { ContactConstraints } from '../solver/contact-solver';
import type { ContactTeam } from '../solver/contact-team';
import { FineIslands } from '../solver/fine-islands';
import { GraphColoring } from '../solver/graph-color';
import { Anchor, HingeBatch, HingeField } from '../solver/hinge-batch';
import { Islands } from '../solver/island';
import type { JointContext } from '../solver/joint-context';
import { JointTree } from '../solver/joint-tree';
import { PointRows } from '../solver/point-rows';
import type { Softness } from '../solver/softness';
import type { SolverJoint } from '../solver/solver-joint';
import { BodyFlag, BodyKind, BodyStore } from '../store/body-store';
import { ContactFlag, ContactStore } from '../store/contact-store';
import { EventBuffers } from '../store/event-buffers';
import { ShapeFlag, ShapeStore, shouldShapesCollide } from '../store/shape-store';
import { ContactLimiter } from './contact-limit';
import { ContinuousMemory } from './continuous-memory';

/**
 * Scratch transforms of the step, built from classes of their own: V8 keeps the fields of a class
 * instance as unboxed doubles, whereas `{ x, y }` literals share their hidden class with every frozen
 * Vec2 of the geometry, whose fields it stores boxed, so that each write allocated a number.
 */
class ScratchPoint {
  x = 0;
  y = 0;
}

class ScratchRot {
  c = 1;
  s = 0;
}

function makeScratchTransform(): Transform {
  return { p: new ScratchPoint(), q: new ScratchRot() };
}

/** A manifold point of its own class, for the reason above. */
class ScratchManifoldPoint implements ManifoldPoint {
  x = 0;
  y = 0;
  separation = 0;
  id = 0;
}

/**
 * A world's working memory for the step's stages and the mass and bounds updates: written before it
 * is read in every use, so it is not state (the snapshot skips it) and no module holds any.
 * @internal
 */
export class WorkingMemory {
  /**
   * A joint's step data as Joint.prepareBase works it out: a hinge record (H layout, see HingeBatch),
   * its anchors (Anchor layout) and its bodies' slots.
   */
  readonly jointRecord = new Float64Array(HingeField.STRIDE);
  readonly jointAnchors = new Float64Array(Anchor.STRIDE);
  readonly jointIds = new Int32Array(2);
  /** The joints' point rows' maths (an object holding no state: see PointRows). */
  readonly pointRows = new PointRows();
  /** The narrow phase's manifold. */
  readonly manifold: Manifold = {
    normalX: 0,
    normalY: 0,
    pointCount: 0,
    points: [new ScratchManifoldPoint(), new ScratchManifoldPoint()],
  };
  /** The collide calls' hints, results and working memory. */
  readonly collide = new CollideContext();
  readonly bounds: Bounds = makeBounds();
  readonly mass: MassData = { mass: 0, centerX: 0, centerY: 0, inertia: 0 };
  /** The sweeps of continuous collision and the bullets of the current step. */
  readonly continuous = new ContinuousMemory();
  /** The substep's contact softness and the anchored one (see setSoftnessFor in solve.ts). */
  readonly contactSoftness: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  readonly anchoredSoftness: Softness = { biasRate: 0, massScale: 1, impulseScale: 0 };
  /** A body's displacement over the step, handed to BroadPhase.moveProxy for each of its shapes. */
  readonly proxyMotion = new Float64Array(2);
}

/**
 * The engine's state and the internal operations that keep it consistent (contacts linked to bodies,
 * proxies in step with shapes, islands). The public `World` validates input and calls into this.
 * @internal
 */
export class WorldCore implements PairFilter {
  readonly settings: Settings;
  readonly bodies = new BodyStore();
  readonly shapes = new ShapeStore();
  readonly contacts = new ContactStore();
  readonly contactLimiter = new ContactLimiter(this);
  readonly broadPhase: BroadPhase;
  readonly pairs = new PairSet(256);
  readonly islands = new Islands();
  readonly constraints = new ContactConstraints();
  readonly coloring = new GraphColoring();
  readonly fineIslands = new FineIslands();
  readonly events = new EventBuffers();
  readonly newPairs = new IntList(256);
  /** awake non-static bodies of the current step, by ascending slot */
  awake = new Int32Array(64);
  awakeCount = 0;
  /** per awake body, the step's constant velocity update (see prepareVelocityUpdate) */
  velocityUpdate = new Float64Array(0);
  gravityX = 0;
  gravityY = -10;
  subSteps = 4;
  enableSleep = true;
  enableContinuous = true;
  /** a contact's friction from its shapes': true for the smaller, false for their geometric mean */
  frictionMin = false;
  hitEventThreshold = 1;
  locked = false;
  /** the threads that solve the contacts with this one (a # field: not a property, so no snapshot) */
  #team: ContactTeam | null = null;
  /** joints in creation order, and each body's joints */
  readonly joints: SolverJoint[] = [];
  readonly bodyJoints: (SolverJoint[] | undefined)[] = [];
  /** joints solved in the current step and what they read */
  readonly activeJoints: SolverJoint[] = [];
  /** counts joints made and destroyed */
  jointListEpoch = 0;
  /**
   * `jointListEpoch` and the bodies' `awakeEpoch` when `activeJoints` was listed: while neither
   * changed, the same joints have an awake body
   */
  activeListedAt = -1;
  activeListedAwake = -1;
  /** the exact solver of the active joints that form a forest */
  readonly jointTree = new JointTree();
  /**
   * Counts the changes that can alter the joint tree's choice besides the set of active joints
   * (which the tree compares itself): joint setters and bodies' mass, inertia or type (updateMass).
   */
  jointEpoch = 0;
  /**
   * Counts the poses and masses set other than by the solver's integration (a body placed by the
   * user or moved back by continuous collision, a mass or centre of mass worked out anew): step data
   * carried from one step to the next holds only while it stays the same (see HingeBatch.relax).
   */
  poseEpoch = 0;
  /** the plain hinges of the current step, solved from flat arrays */
  readonly hingeBatch = new HingeBatch();
  readonly jointContext: JointContext = {
    state: new Float64Array(0),
    invMass: new Float64Array(0),
    invInertia: new Float64Array(0),
    cx: new Float64Array(0),
    cy: new Float64Array(0),
    qc: new Float64Array(0),
    qs: new Float64Array(0),
    lcx: new Float64Array(0),
    lcy: new Float64Array(0),
    h: 0,
    invH: 0,
    warmSpeedLimit: 0,
    warmTurnLimit: 0,
    jointPushMaxSpeed: 0,
    jointPushMaxTurn: JOINT_PUSH_MAX_TURN,
    jointCorrectionMax: 0,
    jointCorrectionMaxTurn: JOINT_CORRECTION_MAX_TURN,
    jointSlop: 0,
    jointSlopTurn: JOINT_SLOP_TURN,
    jointSoftness: { biasRate: 0, massScale: 1, impulseScale: 0 },
    tree: this.jointTree,
    poseEpoch: 0,
  };
  readonly xfA: Transform = makeScratchTransform();
  readonly xfB: Transform = makeScratchTransform();
  /** the body transform refreshShapeBounds passes (an object: doubles passed to a call are boxed) */
  readonly xfBounds: Transform = makeScratchTransform();
  readonly work = new WorkingMemory();

  get team(): ContactTeam | null {
    return this.#team;
  }

  set team(team: ContactTeam | null) {
    this.#team = team;
  }

  constructor(lengthUnitsPerMeter: number) {
    this.settings = makeSettings(lengthUnitsPerMeter);
    this.broadPhase = new BroadPhase(this.settings.aabbMargin);
  }

  fillTransform(b: number, xf: Transform): Transform {
    const bodies = this.bodies;
    xf.p.x = bodies.px[b];
    xf.p.y = bodies.py[b];
    xf.q.c = bodies.qc[b];
    xf.q.s = bodies.qs[b];
    return xf;
  }

  /** Refreshes the tight AABB of a shape from its body's transform. */
  refreshShapeBounds(shape: number): void {
    const shapes = this.shapes;
    const b = shapes.body[shape];
    const boundsScratch = this.work.bounds;
    packedBounds(shapes.packed, shape * Pack.STRIDE, this.fillTransform(b, this.xfBounds), boundsScratch);
    shapes.minX[shape] = boundsScratch.minX;
    shapes.minY[shape] = boundsScratch.minY;
    shapes.maxX[shape] = boundsScratch.maxX;
    shapes.maxY[shape] = boundsScratch.maxY;
  }

  createProxy(shape: number, forcePairCreation: boolean): void {
    const shapes = this.shapes;
    const kind = this.bodies.kind[shapes.body[shape]];
    const type =
      kind === BodyKind.STATIC
        ? ProxyType.STATIC
        : kind === BodyKind.KINEMATIC
          ? ProxyType.KINEMATIC
          : ProxyType.DYNAMIC;
    this.refreshShapeBounds(shape);
    shapes.centroidExtent[shape] = centroidExtent(shapes.geometry[shape]!);
    if (type === ProxyType.DYNAMIC) this.contactLimiter.noteDynamic(shapes.centroidExtent[shape]);
    shapes.proxyKey[shape] = this.broadPhase.createProxy(
      shapes.minX[shape],
      shapes.minY[shape],
      shapes.maxX[shape],
      shapes.maxY[shape],
      type,
      shape,
      forcePairCreation,
    );
  }

  destroyProxy(shape: number): void {
    this.broadPhase.destroyProxy(this.shapes.proxyKey[shape]);
    this.shapes.proxyKey[shape] = -1;
  }

  /** After a body was moved by the user: new AABBs, proxies moved (pairs found next step). */
  syncBodyProxies(b: number): void {
    const shapes = this.shapes;
    for (let s = this.bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
      this.refreshShapeBounds(s);
      const key = shapes.proxyKey[s];
      if (!this.broadPhase.placeProxy(key, shapes, s)) {
        this.broadPhase.bufferMove(key);
      }
    }
  }

  /** Mass, centre of mass, inertia and extents of a body from its shapes. */
  updateMass(b: number): void {
    this.jointEpoch++;
    this.poseEpoch++;
    const bodies = this.bodies;
    const shapes = this.shapes;
    const massScratch = this.work.mass;
    const kind = bodies.kind[b];
    let mass = 0;
    let mx = 0;
    let my = 0;
    let inertiaAtOrigin = 0;
    if (kind === BodyKind.DYNAMIC) {
      for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
        const density = shapes.density[s];
        if (density === 0) continue;
        computeMass(shapes.geometry[s]!, density, massScratch);
        mass += massScratch.mass;
        mx += massScratch.mass * massScratch.centerX;
        my += massScratch.mass * massScratch.centerY;
        inertiaAtOrigin +=
          massScratch.inertia +
          massScratch.mass *
            (massScratch.centerX * massScratch.centerX + massScratch.centerY * massScratch.centerY);
      }
    }
    let lcx = 0;
    let lcy = 0;
    let inertia = 0;
    if (mass > 0) {
      lcx = mx / mass;
      lcy = my / mass;
      inertia = inertiaAtOrigin - mass * (lcx * lcx + lcy * lcy);
    }
    const flags = bodies.flags[b];
    if (kind === BodyKind.DYNAMIC && (flags & BodyFlag.MASS_SET) !== 0) {
      mass = bodies.givenMass[b];
      inertia = bodies.givenInertia[b];
      if ((flags & BodyFlag.CENTER_SET) !== 0) {
        lcx = bodies.givenLcx[b];
        lcy = bodies.givenLcy[b];
      }
    }
    if (kind === BodyKind.DYNAMIC && mass === 0) {
      // a dynamic body always has mass, so that forces and contacts act on it
      mass = 1;
    }
    bodies.mass[b] = kind === BodyKind.DYNAMIC ? mass : 0;
    bodies.invMass[b] = kind === BodyKind.DYNAMIC ? 1 / mass : 0;
    const fixed = (flags & BodyFlag.FIXED_ROTATION) !== 0;
    bodies.inertia[b] = kind === BodyKind.DYNAMIC && !fixed ? inertia : 0;
    bodies.invInertia[b] = kind === BodyKind.DYNAMIC && !fixed && inertia > 0 ? 1 / inertia : 0;
    bodies.lcx[b] = lcx;
    bodies.lcy[b] = lcy;
    bodies.updateCenter(b);
    let maxExtent = 0;
    let minExt = Number.POSITIVE_INFINITY;
    for (let s = bodies.shapeHead[b]; s !== -1; s = shapes.next[s]) {
      const g = shapes.geometry[s]!;
      maxExtent = Math.max(maxExtent, maxExtentFrom(g, lcx, lcy));
      minExt = Math.min(minExt, minExtent(g));
    }
    bodies.maxExtent[b] = maxExtent;
    bodies.minExtent[b] = minExt === Number.POSITIVE_INFINITY ? 0 : minExt;
  }

  /** Wakes a body (and its sleeping island). Static bodies are never awake. */
  wake(b: number): void {
    const bodies = this.bodies;
    if (bodies.kind[b] === BodyKind.STATIC) return;
    this.islands.wake(bodies, b);
  }

  /** Wakes the bodies that touch `b` (its neighbours through touching contacts). */
  wakeTouching(b: number): void {
    const contacts = this.contacts;
    for (let e = this.bodies.contactHead[b]; e !== -1; e = contacts.edgeNext[e]) {
      const c = e >> 1;
      if ((contacts.flags[c] & ContactFlag.TOUCHING) === 0) continue;
      this.wake(contacts.bodyA[c] === b ? contacts.bodyB[c] : contacts.bodyA[c]);
    }
  }

  createContact(shapeA: number, shapeB: number): number {
    const shapes = this.shapes;
    const bodies = this.bodies;
    const contacts = this.contacts;
    const c = contacts.allocate();
    const bodyA = shapes.body[shapeA];
    const bodyB = shapes.body[shapeB];
    contacts.shapeA[c] = shapeA;
    contacts.shapeB[c] = shapeB;
    contacts.bodyA[c] = bodyA;
    contacts.bodyB[c] = bodyB;
    if (((shapes.flags[shapeA] | shapes.flags[shapeB]) & ShapeFlag.SENSOR) !== 0)
      contacts.flags[c] = ContactFlag.SENSOR;
    bodies.contactHead[bodyA] = contacts.linkEdge(c, 0, bodies.contactHead[bodyA]);
    bodies.contactHead[bodyB] = contacts.linkEdge(c, 1, bodies.contactHead[bodyB]);
    this.pairs.set(shapeA, shapeB, c);
    this.contactLimiter.charge(contacts, c);
    return c;
  }

  /** Destroys a contact; a touching one reports its end when `report` is set. */
  destroyContact(c: number, report: boolean): void {
    const contacts = this.contacts;
    const bodies = this.bodies;
    const bodyA = contacts.bodyA[c];
    const bodyB = contacts.bodyB[c];
    if (report && (contacts.flags[c] & ContactFlag.TOUCHING) !== 0) {
      this.events.recordEnd(contacts, c, this.shapes, !this.locked);
    }
    bodies.contactHead[bodyA] = contacts.unlinkEdge(c, 0, bodies.contactHead[bodyA]);
    bodies.contactHead[bodyB] = contacts.unlinkEdge(c, 1, bodies.contactHead[bodyB]);
    this.pairs.delete(contacts.shapeA[c], contacts.shapeB[c]);
    this.contactLimiter.discharge(contacts, c);
    contacts.free(c);
  }

  /**
   * Destroys every contact of one shape: its filter, sensor flag or body type changed (`report`: the
   * touching ones report their ends), or it is going away (no ends: its pairs are over with it).
   */
  destroyShapeContacts(shape: number, wakeOthers: boolean, report: boolean): void {
    const contacts = this.contacts;
    const b = this.shapes.body[shape];
    let e = this.bodies.contactHead[b];
    while (e !== -1) {
      const next = contacts.edgeNext[e];
      const c = e >> 1;
      if (contacts.shapeA[c] === shape || contacts.shapeB[c] === shape) {
        if (wakeOthers) {
          this.wake(contacts.bodyA[c]);
          this.wake(contacts.bodyB[c]);
        }
        this.destroyContact(c, report);
      }
      e = next;
    }
  }

  /**
   * Whether two shapes whose fat boxes overlap get a contact: on different bodies, one of them
   * dynamic, not both sensors, their filters agree and no joint between their bodies forbids it.
   */
  shouldPair(a: number, b: number): boolean {
    const shapes = this.shapes;
    const bodyA = shapes.body[a];
    const bodyB = shapes.body[b];
    if (bodyA === bodyB) return false;
    const kind = this.bodies.kind;
    if (kind[bodyA] !== BodyKind.DYNAMIC && kind[bodyB] !== BodyKind.DYNAMIC) return false;
    if ((shapes.flags[a] & shapes.flags[b] & ShapeFlag.SENSOR) !== 0) return false;
    return shouldShapesCollide(shapes, a, b) && this.jointsAllowCollision(bodyA, bodyB);
  }

  /** False when a joint without collideConnected links the two bodies. */
  jointsAllowCollision(bodyA: number, bodyB: number): boolean {
    const ja = this.bodyJoints[bodyA];
    const jb = this.bodyJoints[bodyB];
    if (ja === undefined || jb === undefined) return true;
    const list = ja.length <= jb.length ? ja : jb;
    for (const j of list) {
      if (j.collideConnected) continue;
      const a = j.slotA;
      const b = j.slotB;
      if ((a === bodyA && b === bodyB) || (a === bodyB && b === bodyA)) return false;
    }
    return true;
  }

  /** Destroys the contacts between two bodies (a joint that forbids their collision was created). */
  destroyContactsBetween(bodyA: number, bodyB: number): void {
    const contacts = this.contacts;
    let e = this.bodies.contactHead[bodyA];
    while (e !== -1) {
      const next = contacts.edgeNext[e];
      const c = e >> 1;
      if (contacts.bodyA[c] === bodyB || contacts.bodyB[c] === bodyB) this.destroyContact(c, true);
      e = next;
    }
  }

  isAwake(b: number): boolean {
    return (this.bodies.flags[b] & BodyFlag.AWAKE) !== 0;
  }
}
