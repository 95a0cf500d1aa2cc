import { growF64, growI32 } from '../core/grow';
import { IndexBound } from '../core/index-bound';
import type { BodyStore } from '../store/body-store';
import { BodyState } from '../store/body-store';
import type { ContactStore } from '../store/contact-store';
import type { ShapeStore } from '../store/shape-store';
import { LoadPaths, UNSUPPORTED } from './load-paths';
import type { Softness } from './softness';

// Layout of one contact constraint in `ContactConstraints.data` (doubles). Kept small: the solver
// streams it eight times a step, and a large pile's constraints do not fit in the cache. Enums, not
// consts, for the reason given in body-store.ts.
enum ContactField {
  NX = 0,
  NY = 1,
  FRICTION = 2,
  MA = 3,
  IA = 4,
  MB = 5,
  IB = 6,
  COUNT = 7,
  /** where the contact's softness begins in `ContactConstraints.softness` */
  SOFTNESS = 8,
  /** 1 when the two points are solved as a block: K below is well conditioned */
  BLOCK = 9,
  /** 2x2 normal mass matrix K of two-point manifolds */
  K11 = 10,
  K12 = 11,
  K22 = 12,
  POINTS = 13,
  STRIDE = POINTS + 2 * 12,
}
// Per point, relative to its base. With anchors rA, rB (from the centres of mass), normal n and
// tangent t = (ny, -nx), the solver needs the anchors only through their cross products with n and t:
// the relative normal velocity is (vB - vA) . n + wB (rB x n) - wA (rA x n), and an impulse P turns a
// body by its inverse inertia times r x P.
enum PointField {
  /** rA x n */
  RNA = 0,
  /** rB x n */
  RNB = 1,
  /** rA x t, which is -(rA . n) */
  RTA = 2,
  /** rB x t */
  RTB = 3,
  /**
   * The separation is tracked through the substeps between the contact point moved back onto each
   * shape's core (by the shape's radius and half the separation): these core points turn with the body,
   * and for a circle the core point is its centre, so a fast-spinning ball does not drag its contact
   * point around with it. A body's turn q = (c, s) since the step began moves its core point's offset
   * along n to c (r . n - back) + s (r x n) (back being the distance from the anchor back to the core
   * point); QA and QB hold the cosine terms' coefficients: for A back - rA . n (A's offset counts
   * negatively), for B rB . n + back.
   */
  QA = 4,
  QB = 5,
  /** separation at the start of the step minus the core points' offset along the normal */
  ADJ_SEP = 6,
  NMASS = 7,
  TMASS = 8,
  NIMP = 9,
  TIMP = 10,
  MAX_NIMP = 11,
  /** ContactField.STRIDE counts two of these */
  STRIDE = 12,
}
// Layout of `ContactConstraints.restitution`: read only after the substeps.
enum RestitutionField {
  RESTITUTION = 0,
  /** normal relative velocity of each point before the step (negative when approaching) */
  REL_VEL = 1,
  STRIDE = 3,
}
/** K's condition number above which the two points are solved one after the other */
const MAX_CONDITION = 1000;
/** softness levels of a contact under a heavy load (see stiffenLoadedContacts); level L is 4^L times stiffer */
const LOAD_LEVELS = 9;
/** where the anchored softness begins in `ContactConstraints.softness`: after the contact softness's levels */
const ANCHORED_SOFTNESS = 4 * LOAD_LEVELS;
/**
 * The fastest a stiffened contact may be, as a fraction of the substep rate, seen from its own
 * bodies. Faster, and Gauss-Seidel does not settle the light bodies between two such contacts: at 4
 * substeps of 60 Hz a base-10 pyramid of 1 kg boxes under 1,000 kg stood with its contacts at 120 Hz
 * (half the substep rate) and swayed apart at 240 Hz.
 */
const MAX_LOADED_HERTZ_PER_SUBSTEP_RATE = 0.5;
/** cosine of the steepest angle from the vertical at which a contact still supports a body */
const SUPPORT_COSINE = 0.5;

/** @internal Contact constraints of one step, packed one block per touching contact (no objects). */
export class ContactConstraints {
  count = 0;
  capacity = 0;
  data: Float64Array = new Float64Array(0);
  restitution: Float64Array = new Float64Array(0);
  /** body A, body B and contact slot of each constraint */
  ids: Int32Array = new Int32Array(0);
  /**
   * bias rate, mass scale, impulse scale and compliance (impulse / mass scale) of the contact
   * softness at each load level, then of the anchored softness at each level (4 values each)
   */
  softness: Float64Array = new Float64Array(8 * LOAD_LEVELS);
  /** the substep `softness` was set for (see setContactSoftness) */
  softnessStep = Number.NaN;
  /** the highest level below the limit of setSoftness in `softness`, of the contact and the anchored softness */
  readonly levelCaps = new Int32Array(2);
  /** whether a constraint joins two moving bodies of which one is four or more times heavier */
  heavyPair = false;
  readonly loadPaths = new LoadPaths();
  /** per constraint: its lower body (0: A, 1: B), or -1 when it supports neither (see stiffenLoadedContacts) */
  lower = new Int8Array(0);
  /**
   * the constraints under a heavy load, by the depth of their lower body, lowest first: constraint
   * index * 2, plus 1 when body B is the lower one
   */
  supports = new Int32Array(0);
  supportCount = 0;
  /**
   * how many levels the stiffest support wanted beyond the cap of its softness: its island needs 2^that
   * times the substeps to carry its load as stiffly as it should
   */
  levelExcess = 0;
  /** per constraint, scratch of moveFineConstraints: its index in the part it is moved to */
  newIndex = new Int32Array(0);
  /** per depth: where its supports begin in `supports` (counting sort) */
  depthStart = new Int32Array(0);

  reserve(n: number): void {
    if (n <= this.capacity) return;
    let capacity = Math.max(64, this.capacity);
    while (capacity < n) capacity *= 2;
    this.data = growF64(this.data, capacity * ContactField.STRIDE);
    this.restitution = growF64(this.restitution, capacity * RestitutionField.STRIDE);
    this.ids = growI32(this.ids, capacity * 3);
    // rewritten every step: nothing to keep
    this.lower = new Int8Array(capacity);
    this.supports = growI32(this.supports, capacity);
    this.capacity = capacity;
  }
}

/** The highest level whose contact of `hertz` rings at no more than the limit of setSoftness at substep `h`. */
function levelCap(hertz: number, h: number): number {
  let level = 0;
  for (let f = 2 * hertz; f * h <= MAX_LOADED_HERTZ_PER_SUBSTEP_RATE && level < LOAD_LEVELS - 1; f *= 2)
    level++;
  return level;
}

/**
 * Writes `soft`, the softness of a spring of `hertz` at substep `h`, at `at`, then its stiffer levels.
 * A soft contact is a spring and a damper sized to the contact's effective mass m (stiffness m w^2,
 * damping 2 z m w); at level L they are sized to a mass 4^L m: the frequency and damping ratio the
 * contact has for a body 4^L times heavier. With r = 4^-L and a2 = h w (2 z + h w) (see makeSoftness)
 * the bias rate stays w / (2 z + h w), the mass scale becomes a2 / (a2 + r) and the impulse scale
 * r / (a2 + r). Seen from its own bodies a level-L contact rings at 2^L times `hertz`; levels beyond
 * MAX_LOADED_HERTZ_PER_SUBSTEP_RATE repeat the last one below it.
 */
function setSoftness(out: Float64Array, at: number, soft: Softness, hertz: number, h: number): void {
  out[at] = soft.biasRate;
  out[at + 1] = soft.massScale;
  out[at + 2] = soft.impulseScale;
  out[at + 3] = soft.impulseScale / soft.massScale;
  const a2 = soft.massScale / soft.impulseScale;
  // a rigid contact (impulse scale 0) is as stiff as it gets
  const cap = soft.impulseScale > 0 ? levelCap(hertz, h) : 0;
  let r = 1;
  for (let level = 1; level < LOAD_LEVELS; level++) {
    if (level <= cap) r *= 0.25;
    const o = at + 4 * level;
    out[o] = soft.biasRate;
    out[o + 1] = r === 1 ? soft.massScale : a2 / (a2 + r);
    out[o + 2] = r === 1 ? soft.impulseScale : r / (a2 + r);
    out[o + 3] = r === 1 ? out[at + 3] : r / a2;
  }
}

/**
 * Sets the softness of the contacts (`contactSoft`, a spring of `contactHertz` at substep `h`) and of
 * the contacts held like the ground (`anchoredSoft`, twice as fast, see prepareContacts) for the steps
 * to come.
 * @internal
 */
export function setContactSoftness(
  cc: ContactConstraints,
  contactSoft: Softness,
  anchoredSoft: Softness,
  contactHertz: number,
  h: number,
): void {
  setSoftness(cc.softness, 0, contactSoft, contactHertz, h);
  setSoftness(cc.softness, ANCHORED_SOFTNESS, anchoredSoft, 2 * contactHertz, h);
  cc.levelCaps[0] = contactSoft.impulseScale > 0 ? levelCap(contactHertz, h) : 0;
  cc.levelCaps[1] = anchoredSoft.impulseScale > 0 ? levelCap(2 * contactHertz, h) : 0;
}

/** mass ratio from which a contact between two moving bodies is as stiff as one with the ground */
const HEAVY_RATIO = 4;

/**
 * Writes one constraint per contact of `order[from..to)`, in that order, for a constraints list reserved
 * for them. Returns whether one of them joins two moving bodies of which one is four or more times
 * heavier (ContactConstraints.heavyPair). Anchors are taken relative
 * to the centres of mass at the start of the step and stay fixed through the substeps; the separation
 * is updated from the bodies' accumulated motion instead of recomputing the manifold. Contacts with a
 * body that contacts cannot move (no mass, no inertia), or between bodies of very different mass,
 * use the anchored softness, the others the contact softness (see setContactSoftness).
 * @internal
 */
export function prepareContacts(
  cc: ContactConstraints,
  order: Int32Array,
  from: number,
  to: number,
  contacts: ContactStore,
  bodies: BodyStore,
  shapes: ShapeStore,
  frictionMin: boolean,
): boolean {
  let heavyPair = false;
  const d = cc.data;
  const rd = cc.restitution;
  const pointX = contacts.pointX;
  const pointY = contacts.pointY;
  const separation = contacts.separation;
  const normalImpulse = contacts.normalImpulse;
  const tangentImpulse = contacts.tangentImpulse;
  const state = bodies.state;
  const invMass = bodies.invMass;
  const invInertia = bodies.invInertia;
  const cx = bodies.cx;
  const cy = bodies.cy;
  const friction = shapes.friction;
  const restitution = shapes.restitution;
  const radius = shapes.radius;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const c = order[i];
    const a = contacts.bodyA[c];
    const b = contacts.bodyB[c];
    const sA = contacts.shapeA[c];
    const sB = contacts.shapeB[c];
    const mA = invMass[a];
    const iA = invInertia[a];
    const mB = invMass[b];
    const iB = invInertia[b];
    // A body four or more times heavier than the other holds it like the ground does: the soft contact's
    // stiffness follows the light body's mass, and under the heavy one's weight it would sink.
    const heavy = mA >= HEAVY_RATIO * mB || mB >= HEAVY_RATIO * mA;
    const anchored = (mA === 0 && iA === 0) || (mB === 0 && iB === 0) || heavy;
    if (heavy && mA > 0 && mB > 0) heavyPair = true;
    const nx = contacts.normalX[c];
    const ny = contacts.normalY[c];
    const cAx = cx[a];
    const cAy = cy[a];
    const cBx = cx[b];
    const cBy = cy[b];
    const radiusA = radius[sA];
    const radiusB = radius[sB];
    const pointCount = contacts.pointCount[c];
    const base = i * ContactField.STRIDE;
    const rBase = i * RestitutionField.STRIDE;
    cc.ids[i * 3] = a;
    cc.ids[i * 3 + 1] = b;
    cc.ids[i * 3 + 2] = c;
    d[base + ContactField.NX] = nx;
    d[base + ContactField.NY] = ny;
    const frictionA = friction[sA];
    const frictionB = friction[sB];
    d[base + ContactField.FRICTION] = frictionMin
      ? Math.min(frictionA, frictionB)
      : Math.sqrt(frictionA * frictionB);
    d[base + ContactField.MA] = mA;
    d[base + ContactField.IA] = iA;
    d[base + ContactField.MB] = mB;
    d[base + ContactField.IB] = iB;
    d[base + ContactField.COUNT] = pointCount;
    d[base + ContactField.SOFTNESS] = anchored ? ANCHORED_SOFTNESS : 0;
    rd[rBase + RestitutionField.RESTITUTION] = Math.max(restitution[sA], restitution[sB]);
    const sa = a * BodyState.STRIDE;
    const sb = b * BodyState.STRIDE;
    const vAx = state[sa + BodyState.VX];
    const vAy = state[sa + BodyState.VY];
    const wA = state[sa + BodyState.W];
    const vBx = state[sb + BodyState.VX];
    const vBy = state[sb + BodyState.VY];
    const wB = state[sb + BodyState.W];
    const tx = ny;
    const ty = -nx;
    for (let j = 0; j < pointCount; j++) {
      const k = c * 2 + j;
      const p = base + ContactField.POINTS + j * PointField.STRIDE;
      const rAx = pointX[k] - cAx;
      const rAy = pointY[k] - cAy;
      const rBx = pointX[k] - cBx;
      const rBy = pointY[k] - cBy;
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      const rtA = rAx * ty - rAy * tx;
      const rtB = rBx * ty - rBy * tx;
      d[p + PointField.RNA] = rnA;
      d[p + PointField.RNB] = rnB;
      d[p + PointField.RTA] = rtA;
      d[p + PointField.RTB] = rtB;
      // the surfaces are separation/2 either side of the point; the cores a radius further in
      const sep = separation[k];
      const backA = radiusA + 0.5 * sep;
      const backB = radiusB + 0.5 * sep;
      d[p + PointField.QA] = backA + rtA;
      d[p + PointField.QB] = backB - rtB;
      d[p + PointField.ADJ_SEP] = sep - ((rBx - rAx) * nx + (rBy - rAy) * ny + backA + backB);
      const kN = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      d[p + PointField.NMASS] = kN > 0 ? 1 / kN : 0;
      const kT = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      d[p + PointField.TMASS] = kT > 0 ? 1 / kT : 0;
      d[p + PointField.NIMP] = normalImpulse[k];
      d[p + PointField.TIMP] = tangentImpulse[k];
      d[p + PointField.MAX_NIMP] = 0;
      const dvx = vBx - wB * rBy - vAx + wA * rAy;
      const dvy = vBy + wB * rBx - vAy - wA * rAx;
      rd[rBase + RestitutionField.REL_VEL + j] = dvx * nx + dvy * ny;
    }
    d[base + ContactField.BLOCK] = 0;
    if (pointCount === 2) {
      const p1 = base + ContactField.POINTS;
      const p2 = p1 + PointField.STRIDE;
      const rn1A = d[p1 + PointField.RNA];
      const rn1B = d[p1 + PointField.RNB];
      const rn2A = d[p2 + PointField.RNA];
      const rn2B = d[p2 + PointField.RNB];
      const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
      const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
      const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
      const det = k11 * k22 - k12 * k12;
      if (k11 * k11 < MAX_CONDITION * det) {
        d[base + ContactField.K11] = k11;
        d[base + ContactField.K12] = k12;
        d[base + ContactField.K22] = k22;
        d[base + ContactField.BLOCK] = 1;
      }
    }
  }
  return heavyPair;
}

/** @internal Applies the impulses kept from the previous substep (or step) so the solver starts near the answer. */
export function warmStartContacts(
  cc: ContactConstraints,
  state: Float64Array,
  from: number,
  to: number,
): void {
  const d = cc.data;
  const ids = cc.ids;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const base = i * ContactField.STRIDE;
    const sa = (ids[i * 3] & IndexBound.MAX) * BodyState.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * BodyState.STRIDE;
    const mA = d[base + ContactField.MA];
    const iA = d[base + ContactField.IA];
    const mB = d[base + ContactField.MB];
    const iB = d[base + ContactField.IB];
    const nx = d[base + ContactField.NX];
    const ny = d[base + ContactField.NY];
    let vAx = state[sa + BodyState.VX];
    let vAy = state[sa + BodyState.VY];
    let wA = state[sa + BodyState.W];
    let vBx = state[sb + BodyState.VX];
    let vBy = state[sb + BodyState.VY];
    let wB = state[sb + BodyState.W];
    // P = ni * n + ti * t, with t = (ny, -nx); the second point (if any) unrolled, as in solveContacts
    let p = base + ContactField.POINTS;
    let ni = d[p + PointField.NIMP];
    let ti = d[p + PointField.TIMP];
    let Px = ni * nx + ti * ny;
    let Py = ni * ny - ti * nx;
    wA -= iA * (ni * d[p + PointField.RNA] + ti * d[p + PointField.RTA]);
    vAx -= mA * Px;
    vAy -= mA * Py;
    wB += iB * (ni * d[p + PointField.RNB] + ti * d[p + PointField.RTB]);
    vBx += mB * Px;
    vBy += mB * Py;
    if (d[base + ContactField.COUNT] === 2) {
      p += PointField.STRIDE;
      ni = d[p + PointField.NIMP];
      ti = d[p + PointField.TIMP];
      Px = ni * nx + ti * ny;
      Py = ni * ny - ti * nx;
      wA -= iA * (ni * d[p + PointField.RNA] + ti * d[p + PointField.RTA]);
      vAx -= mA * Px;
      vAy -= mA * Py;
      wB += iB * (ni * d[p + PointField.RNB] + ti * d[p + PointField.RTB]);
      vBx += mB * Px;
      vBy += mB * Py;
    }
    state[sa + BodyState.VX] = vAx;
    state[sa + BodyState.VY] = vAy;
    state[sa + BodyState.W] = wA;
    state[sb + BodyState.VX] = vBx;
    state[sb + BodyState.VY] = vBy;
    state[sb + BodyState.W] = wB;
  }
}

/**
 * One Gauss-Seidel pass over the constraints from `from` to `to`. With `useBias` the soft constraint pushes overlapping
 * shapes apart (at most `maxPushSpeed`); without it (relax pass) only velocities are made consistent,
 * which removes the energy the push added. The two points of a manifold are solved together as a
 * 2x2 block (a small LCP, by trying its four cases), so neither point is favoured by the order of
 * solving: a symmetric stack gets symmetric impulses and does not start to sway.
 * @internal
 */
export function solveContacts(
  cc: ContactConstraints,
  state: Float64Array,
  invH: number,
  useBias: boolean,
  maxPushSpeed: number,
  from: number,
  to: number,
): void {
  const d = cc.data;
  const ids = cc.ids;
  const soft = cc.softness;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const base = i * ContactField.STRIDE;
    const sa = (ids[i * 3] & IndexBound.MAX) * BodyState.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * BodyState.STRIDE;
    const mA = d[base + ContactField.MA];
    const iA = d[base + ContactField.IA];
    const mB = d[base + ContactField.MB];
    const iB = d[base + ContactField.IB];
    const nx = d[base + ContactField.NX];
    const ny = d[base + ContactField.NY];
    const k = d[base + ContactField.SOFTNESS] | 0;
    const biasRate = soft[k];
    const massScale = soft[k + 1];
    const impulseScale = soft[k + 2];
    let vAx = state[sa + BodyState.VX];
    let vAy = state[sa + BodyState.VY];
    let wA = state[sa + BodyState.W];
    let vBx = state[sb + BodyState.VX];
    let vBy = state[sb + BodyState.VY];
    let wB = state[sb + BodyState.W];
    const dpx = state[sb + BodyState.DPX] - state[sa + BodyState.DPX];
    const dpy = state[sb + BodyState.DPY] - state[sa + BodyState.DPY];
    const qAc = state[sa + BodyState.DQC];
    const qAs = state[sa + BodyState.DQS];
    const qBc = state[sb + BodyState.DQC];
    const qBs = state[sb + BodyState.DQS];
    // the anchors' relative motion along the normal, without the anchors: add (qB rB - qA rA) . n
    const dpn = dpx * nx + dpy * ny;
    const count = d[base + ContactField.COUNT] | 0;
    // The block path's normal impulse, not yet applied to the linear velocities: those enter the
    // friction rows only through (vB - vA) . t, which an impulse along n leaves alone (n . t = 0), so
    // they take the normal and the friction impulses at once, at the end; the turns are applied as
    // the impulses are found. This keeps the velocity updates off the chain of dependent arithmetic
    // from the normal solve through the two friction points, whose latency sets the pace of this
    // loop (pyramids 0.95x). The one-point path doing the same was level (a rain over 8 seeds
    // 0.96-1.00x; one seed alone, its pile being chaotic, can come out 1.2x either way).
    let normalImpulse = 0;

    if (d[base + ContactField.BLOCK] === 1) {
      const p1 = base + ContactField.POINTS;
      const p2 = p1 + PointField.STRIDE;
      const rn1A = d[p1 + PointField.RNA];
      const rn1B = d[p1 + PointField.RNB];
      const rn2A = d[p2 + PointField.RNA];
      const rn2B = d[p2 + PointField.RNB];
      // current separations from the motion accumulated since the step began (see PointField.QA)
      const s1 =
        dpn +
        qBc * d[p1 + PointField.QB] +
        qBs * rn1B +
        qAc * d[p1 + PointField.QA] -
        qAs * rn1A +
        d[p1 + PointField.ADJ_SEP];
      const s2 =
        dpn +
        qBc * d[p2 + PointField.QB] +
        qBs * rn2B +
        qAc * d[p2 + PointField.QA] -
        qAs * rn2A +
        d[p2 + PointField.ADJ_SEP];
      const k11 = d[base + ContactField.K11];
      const k12 = d[base + ContactField.K12];
      const k22 = d[base + ContactField.K22];
      // soft terms per point: speculative (s > 0) points may approach until they touch, not further;
      // pushing points follow the soft constraint with bias, or none in the relax pass
      let b1 = 0;
      let g1 = 0;
      if (s1 > 0) b1 = s1 * invH;
      else if (useBias) {
        b1 = Math.max(biasRate * s1, -maxPushSpeed);
        g1 = soft[k + 3] * k11;
      }
      let b2 = 0;
      let g2 = 0;
      if (s2 > 0) b2 = s2 * invH;
      else if (useBias) {
        b2 = Math.max(biasRate * s2, -maxPushSpeed);
        g2 = soft[k + 3] * k22;
      }
      const dvn = (vBx - vAx) * nx + (vBy - vAy) * ny;
      const vn1 = dvn + wB * rn1B - wA * rn1A;
      const vn2 = dvn + wB * rn2B - wA * rn2A;
      const l1 = d[p1 + PointField.NIMP];
      const l2 = d[p2 + PointField.NIMP];
      // Soft block solve: find new impulses x >= 0 with vn' + b + G x = 0 on pushing points, where
      // vn' = vn + K (x - l) and G = diag(is/ms * Kii) is each point's compliance. This is exactly the
      // fixed point of the one-point soft update, so the block and the one-point paths agree.
      const a11 = k11 + g1;
      const a22 = k22 + g2;
      const r1 = -(vn1 + b1) - g1 * l1;
      const r2 = -(vn2 + b2) - g2 * l2;
      const invDet = 1 / (a11 * a22 - k12 * k12);
      // case 1: both points push
      let x1 = l1 + (a22 * r1 - k12 * r2) * invDet;
      let x2 = l2 + (a11 * r2 - k12 * r1) * invDet;
      if (x1 < 0 || x2 < 0) {
        // case 2: only point 1 pushes; point 2 must then be separating
        x1 = l1 + (r1 + k12 * l2) / a11;
        x2 = 0;
        if (x1 < 0 || vn2 + b2 + k12 * (x1 - l1) - k22 * l2 < 0) {
          // case 3: only point 2 pushes
          x1 = 0;
          x2 = l2 + (r2 + k12 * l1) / a22;
          if (x2 < 0 || vn1 + b1 + k12 * (x2 - l2) - k11 * l1 < 0) {
            // case 4: neither
            x2 = 0;
          }
        }
      }
      const dl1 = x1 - l1;
      const dl2 = x2 - l2;
      d[p1 + PointField.NIMP] = x1;
      d[p2 + PointField.NIMP] = x2;
      // the largest increment, read only as "> 0" (hit events). Not Math.max: V8 compiles it to
      // compares and branches the data decides, which mispredict in piles that move; (a + b + |a - b|)
      // / 2 is branch-free and the max to an ulp
      const m1 = d[p1 + PointField.MAX_NIMP];
      d[p1 + PointField.MAX_NIMP] = 0.5 * (m1 + dl1 + Math.abs(m1 - dl1));
      const m2 = d[p2 + PointField.MAX_NIMP];
      d[p2 + PointField.MAX_NIMP] = 0.5 * (m2 + dl2 + Math.abs(m2 - dl2));
      normalImpulse = dl1 + dl2;
      wA -= iA * (rn1A * dl1 + rn2A * dl2);
      wB += iB * (rn1B * dl1 + rn2B * dl2);
    } else {
      // point by point; the second (if any) in the same code (a loop of one or two turns costs more)
      let p = base + ContactField.POINTS;
      for (;;) {
        const rnA = d[p + PointField.RNA];
        const rnB = d[p + PointField.RNB];
        const sep =
          dpn +
          qBc * d[p + PointField.QB] +
          qBs * rnB +
          qAc * d[p + PointField.QA] -
          qAs * rnA +
          d[p + PointField.ADJ_SEP];
        let bias = 0;
        let mScale = 1;
        let iScale = 0;
        if (sep > 0) bias = sep * invH;
        else if (useBias) {
          bias = Math.max(biasRate * sep, -maxPushSpeed);
          mScale = massScale;
          iScale = impulseScale;
        }
        const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * rnB - wA * rnA;
        const old = d[p + PointField.NIMP];
        let impulse = -d[p + PointField.NMASS] * mScale * (vn + bias) - iScale * old;
        // max(y, 0) without a branch (see the block path), exactly: y + |y| is 2y or 0
        const y = old + impulse;
        const next = 0.5 * (y + Math.abs(y));
        impulse = next - old;
        d[p + PointField.NIMP] = next;
        const mm = d[p + PointField.MAX_NIMP];
        d[p + PointField.MAX_NIMP] = 0.5 * (mm + impulse + Math.abs(mm - impulse));
        const Px = impulse * nx;
        const Py = impulse * ny;
        vAx -= mA * Px;
        vAy -= mA * Py;
        wA -= iA * impulse * rnA;
        vBx += mB * Px;
        vBy += mB * Py;
        wB += iB * impulse * rnB;
        if (count === 1 || p !== base + ContactField.POINTS) break;
        p += PointField.STRIDE;
      }
    }

    // friction, point by point (unrolled: a loop of one or two turns cost more than its arithmetic);
    // the relative velocity along t as (vB - vA) . t, which moves only with the friction impulses
    // (by (mA + mB) per unit, t being unit), plus the turns' part
    const friction = d[base + ContactField.FRICTION];
    const tx = ny;
    const ty = -nx;
    let dvt = (vBx - vAx) * tx + (vBy - vAy) * ty;
    let p = base + ContactField.POINTS;
    let rtA = d[p + PointField.RTA];
    let rtB = d[p + PointField.RTB];
    let vt = dvt + wB * rtB - wA * rtA;
    let maxFriction = friction * d[p + PointField.NIMP];
    let old = d[p + PointField.TIMP];
    let next = old - d[p + PointField.TMASS] * vt;
    // biome-ignore lint/complexity/useMathMinMax: compares, as V8 adds NaN and -0 checks to Math.max/min (pyramid 0.99x)
    next = next > maxFriction ? maxFriction : next < -maxFriction ? -maxFriction : next;
    let impulse = next - old;
    let frictionImpulse = impulse;
    d[p + PointField.TIMP] = next;
    wA -= iA * impulse * rtA;
    wB += iB * impulse * rtB;
    if (count === 2) {
      p += PointField.STRIDE;
      rtA = d[p + PointField.RTA];
      rtB = d[p + PointField.RTB];
      dvt += (mA + mB) * impulse;
      vt = dvt + wB * rtB - wA * rtA;
      maxFriction = friction * d[p + PointField.NIMP];
      old = d[p + PointField.TIMP];
      next = old - d[p + PointField.TMASS] * vt;
      // biome-ignore lint/complexity/useMathMinMax: as above
      next = next > maxFriction ? maxFriction : next < -maxFriction ? -maxFriction : next;
      impulse = next - old;
      frictionImpulse += impulse;
      d[p + PointField.TIMP] = next;
      wA -= iA * impulse * rtA;
      wB += iB * impulse * rtB;
    }
    const Px = normalImpulse * nx + frictionImpulse * tx;
    const Py = normalImpulse * ny + frictionImpulse * ty;
    vAx -= mA * Px;
    vAy -= mA * Py;
    vBx += mB * Px;
    vBy += mB * Py;
    state[sa + BodyState.VX] = vAx;
    state[sa + BodyState.VY] = vAy;
    state[sa + BodyState.W] = wA;
    state[sb + BodyState.VX] = vBx;
    state[sb + BodyState.VY] = vBy;
    state[sb + BodyState.W] = wB;
  }
}

/**
 * Stiffens the contacts that carry a body much heavier than their own two, and lists them for
 * solveSupports. Called after prepareContacts when `heavyPair` is set (no contact carries such a body
 * otherwise), with the world's gravity, and `supportCount` and `levelExcess` at 0.
 *
 * A soft contact is a spring sized to the effective mass m of its own two bodies: it holds a weight W
 * at an overlap of about W / (m w^2), so under a body many times heavier than both (a 1,000 kg box on
 * 1 kg boxes, directly or through others) it sinks in many times further than it was tuned for, and a
 * stack of 1 kg boxes under 1,000 kg folded into itself. A contact whose upper body carries a mass M
 * (LoadPaths: the heaviest of the upper body and what rests on it) of four or more times m is made 4^L
 * times stiffer, 4^L the largest power of 4 up to M / m: sized to the load, as the contact between two
 * such bodies would be. Only as far as half the substep rate, though (see setSoftness): `levelExcess`
 * says how many levels the stiffest one lacks, and FineIslands steps its island with finer substeps.
 *
 * Such a contact still carries its load only as fast as Gauss-Seidel passes it down: a light body
 * between two of them moves each contact's impulses on by its own small mass, one sweep at a time, and
 * the load rocks on its supports instead of settling. solveSupports therefore follows every relax pass
 * and, from the lowest supports up, stops what is left of each upper body's approach to its lower one,
 * the lower one held fixed, as shock propagation does (Guendelman, Bridson and Fedkiw 2003; Erleben
 * 2007). Those impulses are not kept: at rest the passes before leave nothing to stop, and the
 * contacts carry their true loads (which friction and events read).
 *
 * A contact supports when its normal is within 60 degrees of the vertical; its lower body is the one
 * on the side gravity points to. Contacts with walls thus support nothing, and in a world without
 * gravity no contact is stiffened.
 * @internal
 */
export function stiffenLoadedContacts(
  cc: ContactConstraints,
  bodies: BodyStore,
  gx: number,
  gy: number,
): void {
  const g = Math.sqrt(gx * gx + gy * gy);
  if (g === 0) return;
  orientContacts(cc, gx / g, gy / g);
  const paths = cc.loadPaths;
  paths.analyze(cc.ids, cc.lower, cc.count, bodies.invMass, bodies.capacity);
  if (cc.depthStart.length < paths.maxDepth + 2)
    cc.depthStart = growI32(cc.depthStart, 2 * paths.maxDepth + 2);
  const depthStart = cc.depthStart;
  depthStart.fill(0, 0, paths.maxDepth + 2);
  countSupports(cc, paths, bodies.invMass, depthStart);
  let start = 0;
  for (let depth = 0; depth <= paths.maxDepth; depth++) {
    const n = depthStart[depth];
    depthStart[depth] = start;
    start += n;
  }
  cc.supportCount = start;
  listSupports(cc, paths, bodies.invMass, depthStart);
}

/** Sets `lower` of each constraint from its normal and the direction of gravity (see listAwakeBodies in solver.ts). */
function orientContacts(cc: ContactConstraints, ux: number, uy: number): void {
  const d = cc.data;
  const lower = cc.lower;
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    // n points from A to B: along gravity, B is under A
    const down =
      d[i * ContactField.STRIDE + ContactField.NX] * ux + d[i * ContactField.STRIDE + ContactField.NY] * uy;
    lower[i] = down >= SUPPORT_COSINE ? 1 : down <= -SUPPORT_COSINE ? 0 : -1;
  }
}

/** The depth of body `b` as the lower body of a support: 0 for a body that does not move. */
function supportDepth(paths: LoadPaths, invMass: Float64Array, b: number): number {
  return invMass[b] > 0 ? paths.depth[b] : 0;
}

/** The supportDepth of the lower body of constraint i, which has one. */
function lowerDepth(cc: ContactConstraints, paths: LoadPaths, invMass: Float64Array, i: number): number {
  return supportDepth(paths, invMass, cc.ids[i * 3 + cc.lower[i]] & IndexBound.MAX);
}

/**
 * The load level of constraint i: 0 when it carries no body four times heavier than its own, else
 * the L of stiffenLoadedContacts.
 */
function loadLevel(cc: ContactConstraints, paths: LoadPaths, invMass: Float64Array, i: number): number {
  const side = cc.lower[i];
  if (side < 0) return 0;
  const l = cc.ids[i * 3 + side] & IndexBound.MAX;
  const u = cc.ids[i * 3 + 1 - side] & IndexBound.MAX;
  const upperDepth = paths.depth[u];
  if (invMass[u] === 0 || upperDepth === UNSUPPORTED || upperDepth <= supportDepth(paths, invMass, l))
    return 0;
  // the carried mass over the effective mass 1 / (1 / mA + 1 / mB)
  const ratio = paths.carried[u] * (invMass[l] + invMass[u]);
  let level = 0;
  for (let scale = 4; scale <= ratio && level < LOAD_LEVELS - 1; scale *= 4) level++;
  return level;
}

/** Counts the loaded constraints per depth of their lower body. */
function countSupports(
  cc: ContactConstraints,
  paths: LoadPaths,
  invMass: Float64Array,
  perDepth: Int32Array,
): void {
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    if (loadLevel(cc, paths, invMass, i) > 0) perDepth[lowerDepth(cc, paths, invMass, i)]++;
  }
}

/** Stiffens the loaded constraints and lists them by the depth of their lower body, from `next`. */
function listSupports(
  cc: ContactConstraints,
  paths: LoadPaths,
  invMass: Float64Array,
  next: Int32Array,
): void {
  const d = cc.data;
  const supports = cc.supports;
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    const level = loadLevel(cc, paths, invMass, i);
    if (level === 0) continue;
    const base = d[i * ContactField.STRIDE + ContactField.SOFTNESS];
    const excess = level - cc.levelCaps[base === 0 ? 0 : 1];
    if (excess > cc.levelExcess) cc.levelExcess = excess;
    d[i * ContactField.STRIDE + ContactField.SOFTNESS] = base + 4 * level;
    supports[next[lowerDepth(cc, paths, invMass, i)]++] = i * 2 + cc.lower[i];
  }
}

/** Copies constraint `i` of `from` to index `k` of `to`, its impulses times `scale`. */
function copyConstraint(
  from: ContactConstraints,
  i: number,
  to: ContactConstraints,
  k: number,
  scale: number,
): void {
  const a = from.data;
  const b = to.data;
  for (let j = 0; j < ContactField.STRIDE; j++)
    b[k * ContactField.STRIDE + j] = a[i * ContactField.STRIDE + j];
  for (let j = 0; j < 2; j++) {
    const p = k * ContactField.STRIDE + ContactField.POINTS + j * PointField.STRIDE;
    b[p + PointField.NIMP] *= scale;
    b[p + PointField.TIMP] *= scale;
  }
  for (let j = 0; j < RestitutionField.STRIDE; j++)
    to.restitution[k * RestitutionField.STRIDE + j] = from.restitution[i * RestitutionField.STRIDE + j];
  for (let j = 0; j < 3; j++) to.ids[k * 3 + j] = from.ids[i * 3 + j];
}

/**
 * Moves the constraints with a body marked in `fine` (a body of an island stepped with `factor` times
 * finer substeps, see FineIslands) from `cc` to `into`, and their supports with them; both keep their
 * order, so each part is still in an order of the colouring (its colours apart from each other) and
 * its supports still lowest first. Impulses are kept between steps per substep of the world's: the
 * moved ones are divided by `factor` here and multiplied back by restoreFineConstraints.
 * @internal
 */
export function moveFineConstraints(
  cc: ContactConstraints,
  fine: Uint8Array,
  into: ContactConstraints,
  factor: number,
): void {
  const n = cc.count;
  into.reserve(n);
  if (cc.newIndex.length < n) cc.newIndex = growI32(cc.newIndex, cc.capacity);
  const ids = cc.ids;
  const newIndex = cc.newIndex;
  let kept = 0;
  let moved = 0;
  for (let i = 0; i < n; i++) {
    if (fine[ids[i * 3]] !== 0 || fine[ids[i * 3 + 1]] !== 0) {
      copyConstraint(cc, i, into, moved, 1 / factor);
      newIndex[i] = -1 - moved++;
    } else {
      // kept <= i: compacting in place never overwrites one still to be read
      if (kept !== i) copyConstraint(cc, i, cc, kept, 1);
      newIndex[i] = kept++;
    }
  }
  cc.count = kept;
  into.count = moved;
  let keptSupports = 0;
  let movedSupports = 0;
  for (let j = 0; j < cc.supportCount; j++) {
    const k = newIndex[cc.supports[j] >> 1];
    const side = cc.supports[j] & 1;
    if (k >= 0) cc.supports[keptSupports++] = k * 2 + side;
    else into.supports[movedSupports++] = (-1 - k) * 2 + side;
  }
  cc.supportCount = keptSupports;
  into.supportCount = movedSupports;
}

/** @internal Appends the constraints of `from` (see moveFineConstraints) to those of `cc`, impulses times `factor`. */
export function restoreFineConstraints(
  cc: ContactConstraints,
  from: ContactConstraints,
  factor: number,
): void {
  const n = cc.count;
  for (let i = 0; i < from.count; i++) copyConstraint(from, i, cc, n + i, factor);
  cc.count = n + from.count;
}

/**
 * After a relax pass: stops the approach of each listed contact's upper body to its lower one, lowest
 * contacts first, the lower body held fixed (see stiffenLoadedContacts). Separated points may approach
 * until they touch, as in solveContacts. The lower body's own motion towards the upper one is not
 * passed on: held fixed, it could otherwise throw the upper body with a speed it never had, and
 * supports that rock would pump energy into the load; they only stop it. The impulses are not kept.
 * @internal
 */
export function solveSupports(cc: ContactConstraints, state: Float64Array, invH: number): void {
  const d = cc.data;
  const ids = cc.ids;
  const supports = cc.supports;
  for (let j = 0, n = cc.supportCount & IndexBound.MAX; j < n; j++) {
    const i = supports[j] >> 1;
    const lowerIsB = (supports[j] & 1) === 1;
    const base = i * ContactField.STRIDE;
    const sa = (ids[i * 3] & IndexBound.MAX) * BodyState.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * BodyState.STRIDE;
    // the lower body takes no impulse: its mass is left out
    const mA = lowerIsB ? d[base + ContactField.MA] : 0;
    const iA = lowerIsB ? d[base + ContactField.IA] : 0;
    const mB = lowerIsB ? 0 : d[base + ContactField.MB];
    const iB = lowerIsB ? 0 : d[base + ContactField.IB];
    const nx = d[base + ContactField.NX];
    const ny = d[base + ContactField.NY];
    let vAx = state[sa + BodyState.VX];
    let vAy = state[sa + BodyState.VY];
    let wA = state[sa + BodyState.W];
    let vBx = state[sb + BodyState.VX];
    let vBy = state[sb + BodyState.VY];
    let wB = state[sb + BodyState.W];
    const dpn =
      (state[sb + BodyState.DPX] - state[sa + BodyState.DPX]) * nx +
      (state[sb + BodyState.DPY] - state[sa + BodyState.DPY]) * ny;
    const qAc = state[sa + BodyState.DQC];
    const qAs = state[sa + BodyState.DQS];
    const qBc = state[sb + BodyState.DQC];
    const qBs = state[sb + BodyState.DQS];
    const dvn = (vBx - vAx) * nx + (vBy - vAy) * ny;
    // the lower body's linear speed towards the upper one along n
    const lowerSpeed = lowerIsB ? -(vBx * nx + vBy * ny) : vAx * nx + vAy * ny;
    const p1 = base + ContactField.POINTS;
    const rn1A = d[p1 + PointField.RNA];
    const rn1B = d[p1 + PointField.RNB];
    const s1 =
      dpn +
      qBc * d[p1 + PointField.QB] +
      qBs * rn1B +
      qAc * d[p1 + PointField.QA] -
      qAs * rn1A +
      d[p1 + PointField.ADJ_SEP];
    // each point's normal velocity, plus the gap it may close in the substep, plus its lower body's
    // approach: what a push x must cancel
    const toward1 = lowerSpeed + (lowerIsB ? -wB * rn1B : wA * rn1A);
    const t1 = dvn + wB * rn1B - wA * rn1A + (s1 > 0 ? s1 * invH : 0) + Math.max(toward1, 0);
    const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
    let x1 = 0;
    let x2 = 0;
    let rn2A = 0;
    let rn2B = 0;
    if (d[base + ContactField.COUNT] === 2) {
      const p2 = p1 + PointField.STRIDE;
      rn2A = d[p2 + PointField.RNA];
      rn2B = d[p2 + PointField.RNB];
      const s2 =
        dpn +
        qBc * d[p2 + PointField.QB] +
        qBs * rn2B +
        qAc * d[p2 + PointField.QA] -
        qAs * rn2A +
        d[p2 + PointField.ADJ_SEP];
      const toward2 = lowerSpeed + (lowerIsB ? -wB * rn2B : wA * rn2A);
      const t2 = dvn + wB * rn2B - wA * rn2A + (s2 > 0 ? s2 * invH : 0) + Math.max(toward2, 0);
      const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
      const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
      const det = k11 * k22 - k12 * k12;
      // the pushes x >= 0 with t + K x >= 0, each zero where its point is left moving apart: both
      // points, then either alone (as solveContacts's block); a K that cannot be inverted well (the
      // upper body cannot turn) takes the points one after the other
      if (k11 * k11 < MAX_CONDITION * det) {
        x1 = (k12 * t2 - k22 * t1) / det;
        x2 = (k12 * t1 - k11 * t2) / det;
        if (x1 < 0 || x2 < 0) {
          x1 = t1 < 0 ? -t1 / k11 : 0;
          x2 = 0;
          if (t2 + k12 * x1 < 0) {
            x1 = 0;
            x2 = t2 < 0 ? -t2 / k22 : 0;
            if (t1 + k12 * x2 < 0) x2 = 0;
          }
        }
      } else {
        x1 = t1 < 0 ? -t1 / k11 : 0;
        const u2 = t2 + k12 * x1;
        x2 = u2 < 0 ? -u2 / k22 : 0;
      }
    } else if (t1 < 0) {
      x1 = -t1 / k11;
    }
    const push = x1 + x2;
    if (push === 0) continue;
    vAx -= mA * push * nx;
    vAy -= mA * push * ny;
    wA -= iA * (rn1A * x1 + rn2A * x2);
    vBx += mB * push * nx;
    vBy += mB * push * ny;
    wB += iB * (rn1B * x1 + rn2B * x2);
    state[sa + BodyState.VX] = vAx;
    state[sa + BodyState.VY] = vAy;
    state[sa + BodyState.W] = wA;
    state[sb + BodyState.VX] = vBx;
    state[sb + BodyState.VY] = vBy;
    state[sb + BodyState.W] = wB;
  }
}

/**
 * Restitution after the substeps: points that approached faster than the threshold and carried an
 * impulse get a normal velocity of -restitution times their approach velocity.
 * @internal
 */
export function applyRestitution(
  cc: ContactConstraints,
  state: Float64Array,
  threshold: number,
  from: number,
  to: number,
): void {
  const d = cc.data;
  const ids = cc.ids;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const base = i * ContactField.STRIDE;
    const rBase = i * RestitutionField.STRIDE;
    const restitution = cc.restitution[rBase + RestitutionField.RESTITUTION];
    if (restitution === 0) continue;
    const sa = (ids[i * 3] & IndexBound.MAX) * BodyState.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * BodyState.STRIDE;
    const mA = d[base + ContactField.MA];
    const iA = d[base + ContactField.IA];
    const mB = d[base + ContactField.MB];
    const iB = d[base + ContactField.IB];
    const nx = d[base + ContactField.NX];
    const ny = d[base + ContactField.NY];
    let vAx = state[sa + BodyState.VX];
    let vAy = state[sa + BodyState.VY];
    let wA = state[sa + BodyState.W];
    let vBx = state[sb + BodyState.VX];
    let vBy = state[sb + BodyState.VY];
    let wB = state[sb + BodyState.W];
    const count = d[base + ContactField.COUNT];
    for (let j = 0; j < count; j++) {
      const p = base + ContactField.POINTS + j * PointField.STRIDE;
      const relVel = cc.restitution[rBase + RestitutionField.REL_VEL + j];
      if (relVel > -threshold || d[p + PointField.MAX_NIMP] === 0) continue;
      const rnA = d[p + PointField.RNA];
      const rnB = d[p + PointField.RNB];
      const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * rnB - wA * rnA;
      const old = d[p + PointField.NIMP];
      let impulse = -d[p + PointField.NMASS] * (vn + restitution * relVel);
      const next = Math.max(old + impulse, 0);
      impulse = next - old;
      d[p + PointField.NIMP] = next;
      d[p + PointField.MAX_NIMP] = Math.max(d[p + PointField.MAX_NIMP], impulse);
      const Px = impulse * nx;
      const Py = impulse * ny;
      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * impulse * rnA;
      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * impulse * rnB;
    }
    state[sa + BodyState.VX] = vAx;
    state[sa + BodyState.VY] = vAy;
    state[sa + BodyState.W] = wA;
    state[sb + BodyState.VX] = vBx;
    state[sb + BodyState.VY] = vBy;
    state[sb + BodyState.W] = wB;
  }
}

/** @internal Copies the impulses back to the contacts for warm starting next step and for hit events. */
export function storeImpulses(
  cc: ContactConstraints,
  contacts: ContactStore,
  from: number,
  to: number,
): void {
  const d = cc.data;
  const ids = cc.ids;
  const normalImpulse = contacts.normalImpulse;
  const tangentImpulse = contacts.tangentImpulse;
  const maxNormalImpulse = contacts.maxNormalImpulse;
  const approachSpeed = contacts.approachSpeed;
  for (let i = from, n = to & IndexBound.MAX; i < n; i++) {
    const base = i * ContactField.STRIDE;
    const contact = ids[i * 3 + 2];
    const count = d[base + ContactField.COUNT];
    for (let j = 0; j < count; j++) {
      const p = base + ContactField.POINTS + j * PointField.STRIDE;
      const k = contact * 2 + j;
      normalImpulse[k] = d[p + PointField.NIMP];
      tangentImpulse[k] = d[p + PointField.TIMP];
      maxNormalImpulse[k] = d[p + PointField.MAX_NIMP];
      approachSpeed[k] = -cc.restitution[i * RestitutionField.STRIDE + RestitutionField.REL_VEL + j];
    }
  }
}
