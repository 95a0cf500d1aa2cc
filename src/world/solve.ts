import { growF64, growI32 } from '../core/grow';
import { IndexBound } from '../core/index-bound';
import {
  CONTACT_DAMPING_RATIO,
  CONTACT_HERTZ,
  JOINT_DAMPING_RATIO,
  JOINT_HERTZ,
  MAX_ROTATION_PER_SUBSTEP,
} from '../core/settings';
import {
  clampVelocity,
  integratePositions,
  integrateVelocities,
  prepareVelocityUpdate,
  VelocityUpdate,
} from '../solver/body-solver';
import {
  applyRestitution,
  type ContactConstraints,
  moveFineConstraints,
  prepareContacts as prepareContactConstraints,
  restoreFineConstraints,
  setContactSoftness,
  solveContacts,
  solveSupports,
  stiffenLoadedContacts,
  storeImpulses,
  warmStartContacts,
} from '../solver/contact-solver';
import { MAX_FINE_FACTOR } from '../solver/fine-islands';
import type { GraphColoring } from '../solver/graph-color';
import type { Islands } from '../solver/island';
import { makeSoftness } from '../solver/softness';
import type { SolverJoint } from '../solver/solver-joint';
import { BodyFlag, BodyKind, BodyState, type BodyStore } from '../store/body-store';
import { ContactFlag, type ContactStore } from '../store/contact-store';
import { ShapeFlag } from '../store/shape-store';
import { deferBullet, solveContinuous } from './continuous';
import type { WorkingMemory, WorldCore } from './world-core';

/** @internal Lists the awake non-static bodies by ascending slot. */
export function collectAwakeBodies(core: WorldCore): void {
  const bodies = core.bodies;
  if (core.awake.length < bodies.slotCount) core.awake = growI32(core.awake, bodies.capacity);
  core.awakeCount = listAwakeBodies(bodies, core.awake);
}

/*
 * A long loop in a function called once a step runs in on-stack-replaced code, compiled while the
 * function's first call is still in the loop. V8 (Node 20) keeps reusing that code although it
 * deoptimizes at the first statement after the loop that had not run yet when it was compiled: every
 * step, for good. So such loops sit in functions of their own that end with the loop (or return).
 */
function listAwakeBodies(bodies: BodyStore, awake: Int32Array): number {
  let count = 0;
  for (let b = 0, n = bodies.slotCount; b < n; b++) {
    if (
      bodies.alive[b] !== 0 &&
      (bodies.flags[b] & BodyFlag.AWAKE) !== 0 &&
      bodies.kind[b] !== BodyKind.STATIC
    ) {
      awake[count++] = b;
    }
  }
  return count;
}

/**
 * Prepares the joints that have an awake body, in creation order: the tree takes its joints, then
 * the plain hinges go to the hinge batch and the others prepare themselves.
 */
function prepareJoints(core: WorldCore, h: number): void {
  const bodies = core.bodies;
  const ctx = core.jointContext;
  ctx.state = bodies.state;
  ctx.invMass = bodies.invMass;
  ctx.invInertia = bodies.invInertia;
  ctx.cx = bodies.cx;
  ctx.cy = bodies.cy;
  ctx.qc = bodies.qc;
  ctx.qs = bodies.qs;
  ctx.lcx = bodies.lcx;
  ctx.lcy = bodies.lcy;
  ctx.poseEpoch = core.poseEpoch;
  // the softness follows from the substep alone: worked out again only when it changes (a function
  // called once a step may stay in the interpreter, which puts every double it makes on the heap)
  if (ctx.h !== h) makeSoftness(JOINT_HERTZ, JOINT_DAMPING_RATIO, h, ctx.jointSoftness);
  ctx.h = h;
  ctx.invH = 1 / h;
  ctx.warmSpeedLimit = 2 * core.settings.maxLinearSpeed;
  ctx.warmTurnLimit = (2 * MAX_ROTATION_PER_SUBSTEP) / h;
  ctx.jointPushMaxSpeed = core.settings.jointPushMaxSpeed;
  ctx.jointCorrectionMax = core.settings.jointCorrectionMax;
  ctx.jointSlop = core.settings.linearSlop;
  const active = core.activeJoints;
  // listed anew only when a joint was made or destroyed or a body slept or woke (a pass over every
  // joint and a comparison of the lists in the tree's build: 3 % of a 40 x 40 hinge grid's step)
  const listed = core.activeListedAt === core.jointListEpoch && core.activeListedAwake === bodies.awakeEpoch;
  if (!listed) listActiveJoints(core.joints, bodies.flags, active);
  core.activeListedAt = core.jointListEpoch;
  core.activeListedAwake = bodies.awakeEpoch;
  const rebuilt = core.jointTree.build(
    active,
    !listed,
    bodies.kind,
    bodies.invMass,
    bodies.invInertia,
    core.jointEpoch,
  );
  core.hingeBatch.prepare(active, core.jointTree.iterative, ctx, rebuilt);
  core.jointTree.prepare(ctx);
}

/** Lists in `active` the joints that have an awake body, in creation order. */
function listActiveJoints(joints: readonly SolverJoint[], flags: Uint8Array, active: SolverJoint[]): void {
  // overwritten in place: `length = 0` would free the array's storage every step and the pushes grow
  // it anew (only a list that shrinks by half or more is trimmed)
  let count = 0;
  for (const joint of joints) {
    if ((flags[joint.slotA] & BodyFlag.AWAKE) === 0 && (flags[joint.slotB] & BodyFlag.AWAKE) === 0) {
      continue;
    }
    active[count++] = joint;
  }
  active.length = count;
}

/** Adds the touching solid contacts that have an awake body to the colouring (see listAwakeBodies). */
function addTouchingContacts(contacts: ContactStore, bodies: BodyStore, coloring: GraphColoring): void {
  for (let c = 0, n = contacts.slotCount; c < n; c++) {
    if (contacts.alive[c] === 0) continue;
    if ((contacts.flags[c] & (ContactFlag.TOUCHING | ContactFlag.SENSOR)) !== ContactFlag.TOUCHING) continue;
    const a = contacts.bodyA[c];
    const b = contacts.bodyB[c];
    if ((bodies.flags[a] & BodyFlag.AWAKE) === 0 && (bodies.flags[b] & BodyFlag.AWAKE) === 0) continue;
    coloring.add(
      c,
      bodies.kind[a] === BodyKind.DYNAMIC ? a : -1,
      bodies.kind[b] === BodyKind.DYNAMIC ? b : -1,
    );
  }
}

/** Sets the softness of the contacts of `cc` for substep `h`, unless it is set for `h` already. */
function setSoftnessFor(work: WorkingMemory, cc: ContactConstraints, h: number): void {
  if (cc.softnessStep === h) return;
  cc.softnessStep = h;
  // a contact spring faster than an eighth of the substep rate makes large piles ring at few
  // substeps (a base-20 pyramid at 2 substeps breathed +-60 mm at 3 Hz for good with a quarter)
  const contactHertz = Math.min(CONTACT_HERTZ, 0.125 / h);
  setContactSoftness(
    cc,
    makeSoftness(contactHertz, CONTACT_DAMPING_RATIO, h, work.contactSoftness),
    makeSoftness(2 * contactHertz, CONTACT_DAMPING_RATIO, h, work.anchoredSoftness),
    contactHertz,
    h,
  );
}

/**
 * Builds one constraint per touching solid contact that has an awake body. Returns whether the
 * world's team (`workers`) took this step's contacts.
 */
function prepareContacts(core: WorldCore, h: number): boolean {
  const contacts = core.contacts;
  const bodies = core.bodies;
  const cc = core.constraints;
  core.team?.rouse();
  setSoftnessFor(core.work, cc, h);
  const coloring = core.coloring;
  coloring.begin(bodies.capacity, contacts.liveCount);
  addTouchingContacts(contacts, bodies, coloring);
  const total = coloring.finish();
  cc.reserve(total);
  cc.count = total;
  const team = core.team;
  let teamed = false;
  if (team?.begin(cc, coloring, contacts, bodies, core.shapes)) {
    teamed = true;
    cc.heavyPair = team.prepare(core.frictionMin);
    // the heavy loads' passes go over the constraints in order: the colouring's, on this thread
    if (cc.heavyPair && team.reordered) teamed = false;
  }
  if (!teamed) {
    const shapes = core.shapes;
    cc.heavyPair = prepareContactConstraints(
      cc,
      coloring.order,
      0,
      total,
      contacts,
      bodies,
      shapes,
      core.frictionMin,
    );
  }
  cc.supportCount = 0;
  cc.levelExcess = 0;
  if (cc.heavyPair) stiffenLoadedContacts(cc, bodies, core.gravityX, core.gravityY);
  return teamed;
}

/**
 * Whether some islands are stepped with finer substeps (see FineIslands): those whose loads want
 * contacts stiffer than the world's substeps allow, by 2^levelExcess times the substeps (at most
 * MAX_FINE_FACTOR). Lists their bodies apart and moves their constraints to FineIslands.constraints.
 */
function splitFineIslands(core: WorldCore): number {
  const cc = core.constraints;
  if (cc.levelExcess === 0) return 1;
  const factor = Math.min(MAX_FINE_FACTOR, 2 ** cc.levelExcess);
  const fine = core.fineIslands;
  if (!fine.split(cc, core.bodies, core.awake, core.awakeCount, core.activeJoints)) return 1;
  moveFineConstraints(cc, fine.fine, fine.constraints, factor);
  return factor;
}

/**
 * The soft step of the islands split off by splitFineIslands, with `subSteps` substeps: contacts only
 * (they have no joints). Their constraints go back to the world's list afterwards.
 */
function solveFineIslands(core: WorldCore, dt: number, subSteps: number, factor: number): void {
  const h = dt / subSteps;
  const invH = 1 / h;
  const fine = core.fineIslands;
  const cc = fine.constraints;
  const bodies = core.bodies;
  const state = bodies.state;
  const settings = core.settings;
  setSoftnessFor(core.work, cc, h);
  prepareVelocityUpdate(bodies, fine.bodies, fine.count, h, core.gravityX, core.gravityY, fine.update);
  for (let i = 0; i < subSteps; i++) {
    integrateVelocities(bodies, fine.bodies, 0, fine.count, fine.update, h, settings.maxLinearSpeed);
    warmStartContacts(cc, state, 0, cc.count);
    solveContacts(cc, state, invH, true, settings.contactPushMaxSpeed, 0, cc.count);
    integratePositions(bodies, fine.bodies, 0, fine.count, h, settings.maxLinearSpeed, i === subSteps - 1);
    solveContacts(cc, state, invH, false, settings.contactPushMaxSpeed, 0, cc.count);
    solveSupports(cc, state, invH);
  }
  restoreFineConstraints(core.constraints, cc, factor);
}

/**
 * The soft step: for each substep integrate velocities, warm start, solve with bias, integrate
 * positions, relax without bias; then restitution and impulses stored for the next step.
 * @internal
 */
export function solve(core: WorldCore, dt: number): void {
  const subSteps = core.subSteps;
  const h = dt / subSteps;
  const invH = 1 / h;
  const settings = core.settings;
  const ctx = core.jointContext;
  const tree = core.jointTree;
  const hinges = core.hingeBatch;
  // before the joints take the body columns: the team may move them into shared memory
  core.team?.shareBodies(core.bodies);
  prepareJoints(core, h);
  const treeBias = ctx.jointSoftness.biasRate;
  // the joints the tree alone solves are not warm started (see JointTree.project)
  const iterative = hinges.otherIterative;
  const iterativeCount = iterative.length;
  const jointSoft = ctx.jointSoftness;
  // the world's team (`workers`), if it took this step's contacts
  const team = prepareContacts(core, h) ? core.team : null;
  const fineFactor = splitFineIslands(core);
  const bodies = core.bodies;
  const state = bodies.state;
  const cc = core.constraints;
  // Contacts of one colour share no body that contacts move, so the team solves a colour's contacts
  // on several threads at once with the same arithmetic in the same order per body: the same bits.
  // Islands stepped finer take their constraints out of the colour order: those steps stay on one thread.
  const shared = team !== null && fineFactor === 1;
  const pushSpeed = settings.contactPushMaxSpeed;
  // the bodies and constraints stepped here: all but those of the islands stepped finer
  const awake = fineFactor > 1 ? core.fineIslands.coarse : core.awake;
  const awakeCount = fineFactor > 1 ? core.fineIslands.coarseCount : core.awakeCount;
  // the tree projects again after the others only if they act on its bodies
  const coupled = tree.isCoupled(cc.ids, cc.count);
  // a step split by island: each thread integrates the bodies of its islands, which stay in its cache
  const grouped = shared && team.reordered;
  // contacts alone, and no kinematic body that threads share: each thread steps its islands alone
  const alone = grouped && team.groupBodies(awake, awakeCount) && core.activeJoints.length === 0;
  if (!grouped && core.velocityUpdate.length < awakeCount * VelocityUpdate.STRIDE)
    core.velocityUpdate = growF64(core.velocityUpdate, 2 * awakeCount * VelocityUpdate.STRIDE);
  const list = grouped ? team.awake : awake;
  const update = grouped ? team.update : core.velocityUpdate;
  prepareVelocityUpdate(bodies, list, awakeCount, h, core.gravityX, core.gravityY, update);
  if (alone) {
    // each thread its islands through the whole solve below, with no joint between its passes
    const maxSpeed = settings.maxLinearSpeed;
    team.stepIslands(h, invH, subSteps, maxSpeed, pushSpeed, settings.restitutionThreshold);
    reportHits(core, core.coloring.order, 1, 0);
    return;
  }
  for (let i = 0; i < subSteps; i++) {
    if (grouped) team.integrateVelocities(h, settings.maxLinearSpeed);
    else integrateVelocities(bodies, awake, 0, awakeCount, update, h, settings.maxLinearSpeed);
    hinges.warmStart(state, ctx.warmSpeedLimit, ctx.warmTurnLimit);
    for (let j = 0; j < iterativeCount; j++) iterative[j].warmStartGuarded(ctx);
    if (shared) team.warmStart();
    else warmStartContacts(cc, state, 0, cc.count);
    // positions change only in integratePositions: the last substep's relax factorization still holds
    if (i === 0) tree.factor(ctx, true, false);
    tree.project(state, treeBias, true);
    hinges.solve(state, jointSoft, ctx.jointPushMaxSpeed);
    tree.solveAxials(ctx, true);
    for (let j = 0; j < iterativeCount; j++) iterative[j].solve(ctx, true);
    if (shared) team.solve(invH, true, pushSpeed);
    else solveContacts(cc, state, invH, true, pushSpeed, 0, cc.count);
    if (coupled) tree.project(state, treeBias, false);
    if (grouped) team.integratePositions(h, settings.maxLinearSpeed, i === subSteps - 1);
    else integratePositions(bodies, awake, 0, awakeCount, h, settings.maxLinearSpeed, i === subSteps - 1);
    tree.factor(ctx, false, i === subSteps - 1);
    tree.stabilizeSubstep(ctx, settings.maxLinearSpeed * h, MAX_ROTATION_PER_SUBSTEP);
    // The projection is affine, v -> P v + c, with P a projector: when nothing else acts on the tree's
    // bodies before the next substep projects again (with the same factorization; gravity and damping
    // only add and scale), P (P v + g) = P (v + g), and this projection would change nothing then.
    if (coupled || i === subSteps - 1) tree.project(state, 0, false);
    hinges.relax(state, i === subSteps - 1);
    tree.solveAxials(ctx, false);
    for (let j = 0; j < iterativeCount; j++) iterative[j].solve(ctx, false);
    if (shared) team.solve(invH, false, pushSpeed);
    else solveContacts(cc, state, invH, false, pushSpeed, 0, cc.count);
    if (coupled) tree.project(state, 0, false);
    if (cc.supportCount > 0) solveSupports(cc, state, invH);
  }
  if (fineFactor > 1) solveFineIslands(core, dt, fineFactor * subSteps, fineFactor);
  hinges.store(ctx);
  tree.store(ctx);
  if (shared) team.restitution(settings.restitutionThreshold);
  else applyRestitution(cc, state, settings.restitutionThreshold, 0, cc.count);
  if (team !== null) team.store();
  else storeImpulses(cc, core.contacts, 0, cc.count);
  // in the colouring's order: the constraints' may be the islands' (see ContactTeam.reordered)
  if (team?.reordered) reportHits(core, core.coloring.order, 1, 0);
  else reportHits(core, cc.ids, 3, 2);
}

/**
 * Records a hit event per touching contact whose approach speed passed the threshold, the step's
 * contacts taken in the order of `slots[i * stride + at]`.
 */
function reportHits(core: WorldCore, slots: Int32Array, stride: number, at: number): void {
  const cc = core.constraints;
  const contacts = core.contacts;
  const shapes = core.shapes;
  const threshold = core.hitEventThreshold;
  for (let i = 0; i < cc.count; i++) {
    const c = slots[i * stride + at];
    const a = contacts.shapeA[c];
    const b = contacts.shapeB[c];
    if (((shapes.flags[a] | shapes.flags[b]) & ShapeFlag.HIT_EVENTS) === 0) continue;
    let best = -1;
    let speed = threshold;
    for (let j = 0; j < contacts.pointCount[c]; j++) {
      const k = c * 2 + j;
      if (contacts.maxNormalImpulse[k] > 0 && contacts.approachSpeed[k] > speed) {
        speed = contacts.approachSpeed[k];
        best = k;
      }
    }
    if (best === -1) continue;
    core.events.recordHit(
      a,
      b,
      contacts.pointX[best],
      contacts.pointY[best],
      contacts.normalX[c],
      contacts.normalY[c],
      speed,
    );
  }
}

/**
 * Holds the awake dynamic bodies to the speed limits. A loop of its own: in finalizeBodies the clamp
 * was not inlined, and each call boxed its two limits on the heap.
 */
function clampAwakeVelocities(
  bodies: BodyStore,
  awake: Int32Array,
  count: number,
  maxSpeed: number,
  maxW: number,
): void {
  const state = bodies.state;
  for (let i = 0; i < count; i++) {
    const b = awake[i];
    if (bodies.kind[b] === BodyKind.DYNAMIC) clampVelocity(state, b * BodyState.STRIDE, maxSpeed, maxW);
  }
}

/**
 * Writes the new transforms of the awake bodies, resets their step deltas, advances their sleep
 * timers, clears forces and moves their proxies. Ends with its loop (see listAwakeBodies): the
 * bullets it defers are swept by the step after it (the call here deoptimized every step of the
 * 5,050-box pyramid's first 60).
 * @internal
 */
export function finalizeBodies(core: WorldCore, dt: number): void {
  const bodies = core.bodies;
  const state = bodies.state;
  const shapes = core.shapes;
  const broad = core.broadPhase;
  const awake = core.awake;
  const sleepSpeed = core.settings.sleepSpeed;
  const enableSleep = core.enableSleep;
  const continuous = core.enableContinuous;
  const invDt = 1 / dt;
  const sweepStart = core.work.continuous.sweepStart;
  const proxyMotion = core.work.proxyMotion;
  // the relax pass after the last position update is not bounded by the substeps' clamps
  clampAwakeVelocities(
    bodies,
    awake,
    core.awakeCount,
    core.settings.maxLinearSpeed,
    MAX_ROTATION_PER_SUBSTEP / (dt / core.subSteps),
  );
  // the columns in locals: the calls in the loop would have them loaded again at every body
  const colQc = bodies.qc;
  const colQs = bodies.qs;
  const colCx = bodies.cx;
  const colCy = bodies.cy;
  const colLcx = bodies.lcx;
  const colLcy = bodies.lcy;
  const colPx = bodies.px;
  const colPy = bodies.py;
  const colFx = bodies.fx;
  const colFy = bodies.fy;
  const colTorque = bodies.torque;
  const colFlags = bodies.flags;
  const colMaxExtent = bodies.maxExtent;
  const colSleepTime = bodies.sleepTime;
  const colMinExtent = bodies.minExtent;
  const colKind = bodies.kind;
  const colShapeHead = bodies.shapeHead;
  const shapeNext = shapes.next;
  const proxyKey = shapes.proxyKey;
  for (let i = 0, n = core.awakeCount & IndexBound.MAX; i < n; i++) {
    const b = awake[i] & IndexBound.MAX;
    const s = b * BodyState.STRIDE;
    const dqc = state[s + BodyState.DQC];
    const dqs = state[s + BodyState.DQS];
    const q0c = colQc[b];
    const q0s = colQs[b];
    let qc = dqc * q0c - dqs * q0s;
    let qs = dqs * q0c + dqc * q0s;
    // both factors are unit to a few ulps (integratePositions renormalised the step's turn): one
    // Newton step for 1 / sqrt(n2) about 1 takes the product back to unit length to rounding,
    // without the square root and division whose latency stalled this loop
    const inv = 0.5 * (3 - (qc * qc + qs * qs));
    qc *= inv;
    qs *= inv;
    const dpx = state[s + BodyState.DPX];
    const dpy = state[s + BodyState.DPY];
    const cx = colCx[b] + dpx;
    const cy = colCy[b] + dpy;
    const lx = colLcx[b];
    const ly = colLcy[b];
    colQc[b] = qc;
    colQs[b] = qs;
    colCx[b] = cx;
    colCy[b] = cy;
    colPx[b] = cx - (qc * lx - qs * ly);
    colPy[b] = cy - (qs * lx + qc * ly);
    const c0x = cx - dpx;
    const c0y = cy - dpy;
    state[s + BodyState.DPX] = 0;
    state[s + BodyState.DPY] = 0;
    state[s + BodyState.DQC] = 1;
    state[s + BodyState.DQS] = 0;
    colFx[b] = 0;
    colFy[b] = 0;
    colTorque[b] = 0;

    const vx = state[s + BodyState.VX];
    const vy = state[s + BodyState.VY];
    const w = state[s + BodyState.W];
    if (colKind[b] === BodyKind.KINEMATIC && (vx !== 0 || vy !== 0 || w !== 0)) {
      // a kinematic body moves as told for as long as it is told: even slowly, even with no shape
      colSleepTime[b] = 0;
    } else if (enableSleep && (colFlags[b] & BodyFlag.ALLOW_SLEEP) !== 0) {
      const speed = Math.sqrt(vx * vx + vy * vy) + colMaxExtent[b] * Math.abs(w);
      // and how fast it moved: a body pushed out of an overlap or back inside a joint limit ends each
      // substep at rest (the relax pass takes back the push's velocity) while it still moves
      const moved = (Math.sqrt(dpx * dpx + dpy * dpy) + colMaxExtent[b] * Math.abs(dqs)) * invDt;
      colSleepTime[b] = speed > sleepSpeed || moved > sleepSpeed ? 0 : colSleepTime[b] + dt;
    } else {
      colSleepTime[b] = 0;
    }

    for (let sh = colShapeHead[b]; sh !== -1; sh = shapeNext[sh]) core.refreshShapeBounds(sh);
    // a body that moved more than half its thickness this step could have passed through a wall
    if (
      continuous &&
      colKind[b] === BodyKind.DYNAMIC &&
      (Math.sqrt(vx * vx + vy * vy) + colMaxExtent[b] * Math.abs(w)) * dt > 0.5 * colMinExtent[b]
    ) {
      sweepStart[0] = c0x;
      sweepStart[1] = c0y;
      sweepStart[2] = q0c;
      sweepStart[3] = q0s;
      if ((colFlags[b] & BodyFlag.BULLET) !== 0) {
        // bullets also sweep against moving bodies, once those are final: see solveBullets
        deferBullet(core, b);
        continue;
      }
      solveContinuous(core, b);
    }
    // the body's displacement at this step's velocity: its boxes reach that far ahead
    proxyMotion[0] = vx * dt;
    proxyMotion[1] = vy * dt;
    for (let sh = colShapeHead[b]; sh !== -1; sh = shapeNext[sh]) {
      broad.moveProxy(proxyKey[sh], shapes, sh, proxyMotion);
    }
  }
}

/** @internal Groups awake dynamic bodies into islands through touching contacts and puts slow islands to sleep. */
export function updateSleep(core: WorldCore): void {
  const bodies = core.bodies;
  const islands = core.islands;
  islands.reset(bodies.capacity, core.awake, core.awakeCount);
  // two loops, two functions that end with them (see listAwakeBodies)
  uniteTouching(core.constraints, bodies.kind, islands);
  uniteJointed(core.activeJoints, bodies.kind, islands);
  islands.sleepIslands(bodies, core.awake, core.awakeCount);
}

/** Unites the dynamic bodies of every touching contact's constraint. */
function uniteTouching(cc: ContactConstraints, kind: Uint8Array, islands: Islands): void {
  for (let i = 0; i < cc.count; i++) {
    const a = cc.ids[i * 3];
    const b = cc.ids[i * 3 + 1];
    if (kind[a] === BodyKind.DYNAMIC && kind[b] === BodyKind.DYNAMIC) islands.union(a, b);
  }
}

/** Unites the dynamic bodies of every active joint. */
function uniteJointed(joints: readonly SolverJoint[], kind: Uint8Array, islands: Islands): void {
  for (let i = 0; i < joints.length; i++) {
    const a = joints[i].slotA;
    const b = joints[i].slotB;
    if (a !== b && kind[a] === BodyKind.DYNAMIC && kind[b] === BodyKind.DYNAMIC) islands.union(a, b);
  }
}
