import { growF64, growI32 } from '../core/grow';
import { IndexBound } from '../core/index-bound';
import type { BodyStore } from './body-store';
import { S } from './body-store';
import type { ContactStore } from './contact-store';
import type { ShapeStore } from './shape-store';
import type { Softness } from './softness';

// Layout of one contact constraint in `ContactConstraints.data` (doubles). Kept small: the solver
// streams it eight times a step, and a large pile's constraints do not fit in the cache. Enums, not
// consts, for the reason given in body-store.ts.
enum C {
  NX = 0,
  NY = 1,
  FRICTION = 2,
  MA = 3,
  IA = 4,
  MB = 5,
  IB = 6,
  COUNT = 7,
  /** 1 when the contact uses the anchored (ground) softness, 0 for the contact softness */
  ANCHORED = 8,
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
enum P {
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
  /** C.STRIDE counts two of these */
  STRIDE = 12,
}
// Layout of `ContactConstraints.restitution`: read only after the substeps.
enum R {
  RESTITUTION = 0,
  /** normal relative velocity of each point before the step (negative when approaching) */
  REL_VEL = 1,
  STRIDE = 3,
}
/** K's condition number above which the two points are solved one after the other */
const MAX_CONDITION = 1000;

/** Contact constraints of one step, packed one block per touching contact (no objects). */
export class ContactConstraints {
  count = 0;
  capacity = 0;
  data = new Float64Array(0);
  restitution = new Float64Array(0);
  /** body A, body B and contact slot of each constraint */
  ids = new Int32Array(0);
  /** bias rate, mass scale, impulse scale and compliance (impulse / mass scale) of the contact (0..3) and anchored (4..7) softness */
  readonly softness = new Float64Array(8);
  /** the substep `softness` was set for (see setContactSoftness) */
  softnessStep = Number.NaN;

  reserve(n: number): void {
    if (n <= this.capacity) return;
    let capacity = Math.max(64, this.capacity);
    while (capacity < n) capacity *= 2;
    this.data = growF64(this.data, capacity * C.STRIDE);
    this.restitution = growF64(this.restitution, capacity * R.STRIDE);
    this.ids = growI32(this.ids, capacity * 3);
    this.capacity = capacity;
  }
}

function setSoftness(out: Float64Array, at: number, soft: Softness): void {
  out[at] = soft.biasRate;
  out[at + 1] = soft.massScale;
  out[at + 2] = soft.impulseScale;
  out[at + 3] = soft.impulseScale / soft.massScale;
}

/**
 * Sets the softness of the contacts (`contactSoft`) and of the contacts held like the ground
 * (`anchoredSoft`, see prepareContacts) for the steps to come.
 */
export function setContactSoftness(
  cc: ContactConstraints,
  contactSoft: Softness,
  anchoredSoft: Softness,
): void {
  setSoftness(cc.softness, 0, contactSoft);
  setSoftness(cc.softness, 4, anchoredSoft);
}

/** mass ratio from which a contact between two moving bodies is as stiff as one with the ground */
const HEAVY_RATIO = 4;

/**
 * Writes one constraint per contact of `order[0..count)`, in that order. Anchors are taken relative
 * to the centres of mass at the start of the step and stay fixed through the substeps; the separation
 * is updated from the bodies' accumulated motion instead of recomputing the manifold. Contacts with a
 * body that contacts cannot move (no mass, no inertia), or between bodies of very different mass,
 * use the anchored softness, the others the contact softness (see setContactSoftness).
 */
export function prepareContacts(
  cc: ContactConstraints,
  order: Int32Array,
  count: number,
  contacts: ContactStore,
  bodies: BodyStore,
  shapes: ShapeStore,
): void {
  cc.reserve(count);
  // set before the loop, which must end the function (see listAwakeBodies in solver.ts)
  cc.count = count;
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
  for (let i = 0, n = count & IndexBound.MAX; i < n; i++) {
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
    const anchored =
      (mA === 0 && iA === 0) || (mB === 0 && iB === 0) || mA >= HEAVY_RATIO * mB || mB >= HEAVY_RATIO * mA;
    const nx = contacts.normalX[c];
    const ny = contacts.normalY[c];
    const cAx = cx[a];
    const cAy = cy[a];
    const cBx = cx[b];
    const cBy = cy[b];
    const radiusA = radius[sA];
    const radiusB = radius[sB];
    const pointCount = contacts.pointCount[c];
    const base = i * C.STRIDE;
    const rBase = i * R.STRIDE;
    cc.ids[i * 3] = a;
    cc.ids[i * 3 + 1] = b;
    cc.ids[i * 3 + 2] = c;
    d[base + C.NX] = nx;
    d[base + C.NY] = ny;
    d[base + C.FRICTION] = Math.sqrt(friction[sA] * friction[sB]);
    d[base + C.MA] = mA;
    d[base + C.IA] = iA;
    d[base + C.MB] = mB;
    d[base + C.IB] = iB;
    d[base + C.COUNT] = pointCount;
    d[base + C.ANCHORED] = anchored ? 1 : 0;
    rd[rBase + R.RESTITUTION] = Math.max(restitution[sA], restitution[sB]);
    const sa = a * S.STRIDE;
    const sb = b * S.STRIDE;
    const vAx = state[sa + S.VX];
    const vAy = state[sa + S.VY];
    const wA = state[sa + S.W];
    const vBx = state[sb + S.VX];
    const vBy = state[sb + S.VY];
    const wB = state[sb + S.W];
    const tx = ny;
    const ty = -nx;
    for (let j = 0; j < pointCount; j++) {
      const k = c * 2 + j;
      const p = base + C.POINTS + j * P.STRIDE;
      const rAx = pointX[k] - cAx;
      const rAy = pointY[k] - cAy;
      const rBx = pointX[k] - cBx;
      const rBy = pointY[k] - cBy;
      const rnA = rAx * ny - rAy * nx;
      const rnB = rBx * ny - rBy * nx;
      const rtA = rAx * ty - rAy * tx;
      const rtB = rBx * ty - rBy * tx;
      d[p + P.RNA] = rnA;
      d[p + P.RNB] = rnB;
      d[p + P.RTA] = rtA;
      d[p + P.RTB] = rtB;
      // the surfaces are separation/2 either side of the point; the cores a radius further in
      const sep = separation[k];
      const backA = radiusA + 0.5 * sep;
      const backB = radiusB + 0.5 * sep;
      d[p + P.QA] = backA + rtA;
      d[p + P.QB] = backB - rtB;
      d[p + P.ADJ_SEP] = sep - ((rBx - rAx) * nx + (rBy - rAy) * ny + backA + backB);
      const kN = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      d[p + P.NMASS] = kN > 0 ? 1 / kN : 0;
      const kT = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      d[p + P.TMASS] = kT > 0 ? 1 / kT : 0;
      d[p + P.NIMP] = normalImpulse[k];
      d[p + P.TIMP] = tangentImpulse[k];
      d[p + P.MAX_NIMP] = 0;
      const dvx = vBx - wB * rBy - vAx + wA * rAy;
      const dvy = vBy + wB * rBx - vAy - wA * rAx;
      rd[rBase + R.REL_VEL + j] = dvx * nx + dvy * ny;
    }
    d[base + C.BLOCK] = 0;
    if (pointCount === 2) {
      const p1 = base + C.POINTS;
      const p2 = p1 + P.STRIDE;
      const rn1A = d[p1 + P.RNA];
      const rn1B = d[p1 + P.RNB];
      const rn2A = d[p2 + P.RNA];
      const rn2B = d[p2 + P.RNB];
      const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
      const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
      const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
      const det = k11 * k22 - k12 * k12;
      if (k11 * k11 < MAX_CONDITION * det) {
        d[base + C.K11] = k11;
        d[base + C.K12] = k12;
        d[base + C.K22] = k22;
        d[base + C.BLOCK] = 1;
      }
    }
  }
}

/** Applies the impulses kept from the previous substep (or step) so the solver starts near the answer. */
export function warmStartContacts(cc: ContactConstraints, state: Float64Array): void {
  const d = cc.data;
  const ids = cc.ids;
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    const base = i * C.STRIDE;
    const sa = (ids[i * 3] & IndexBound.MAX) * S.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * S.STRIDE;
    const mA = d[base + C.MA];
    const iA = d[base + C.IA];
    const mB = d[base + C.MB];
    const iB = d[base + C.IB];
    const nx = d[base + C.NX];
    const ny = d[base + C.NY];
    let vAx = state[sa + S.VX];
    let vAy = state[sa + S.VY];
    let wA = state[sa + S.W];
    let vBx = state[sb + S.VX];
    let vBy = state[sb + S.VY];
    let wB = state[sb + S.W];
    // P = ni * n + ti * t, with t = (ny, -nx); the second point (if any) unrolled, as in solveContacts
    let p = base + C.POINTS;
    let ni = d[p + P.NIMP];
    let ti = d[p + P.TIMP];
    let Px = ni * nx + ti * ny;
    let Py = ni * ny - ti * nx;
    wA -= iA * (ni * d[p + P.RNA] + ti * d[p + P.RTA]);
    vAx -= mA * Px;
    vAy -= mA * Py;
    wB += iB * (ni * d[p + P.RNB] + ti * d[p + P.RTB]);
    vBx += mB * Px;
    vBy += mB * Py;
    if (d[base + C.COUNT] === 2) {
      p += P.STRIDE;
      ni = d[p + P.NIMP];
      ti = d[p + P.TIMP];
      Px = ni * nx + ti * ny;
      Py = ni * ny - ti * nx;
      wA -= iA * (ni * d[p + P.RNA] + ti * d[p + P.RTA]);
      vAx -= mA * Px;
      vAy -= mA * Py;
      wB += iB * (ni * d[p + P.RNB] + ti * d[p + P.RTB]);
      vBx += mB * Px;
      vBy += mB * Py;
    }
    state[sa + S.VX] = vAx;
    state[sa + S.VY] = vAy;
    state[sa + S.W] = wA;
    state[sb + S.VX] = vBx;
    state[sb + S.VY] = vBy;
    state[sb + S.W] = wB;
  }
}

/**
 * One Gauss-Seidel pass over all contacts. With `useBias` the soft constraint pushes overlapping
 * shapes apart (at most `maxPushSpeed`); without it (relax pass) only velocities are made consistent,
 * which removes the energy the push added. The two points of a manifold are solved together as a
 * 2x2 block (a small LCP, by trying its four cases), so neither point is favoured by the order of
 * solving: a symmetric stack gets symmetric impulses and does not start to sway.
 */
export function solveContacts(
  cc: ContactConstraints,
  state: Float64Array,
  invH: number,
  useBias: boolean,
  maxPushSpeed: number,
): void {
  const d = cc.data;
  const ids = cc.ids;
  const soft = cc.softness;
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    const base = i * C.STRIDE;
    const sa = (ids[i * 3] & IndexBound.MAX) * S.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * S.STRIDE;
    const mA = d[base + C.MA];
    const iA = d[base + C.IA];
    const mB = d[base + C.MB];
    const iB = d[base + C.IB];
    const nx = d[base + C.NX];
    const ny = d[base + C.NY];
    const k = d[base + C.ANCHORED] === 1 ? 4 : 0;
    const biasRate = soft[k];
    const massScale = soft[k + 1];
    const impulseScale = soft[k + 2];
    let vAx = state[sa + S.VX];
    let vAy = state[sa + S.VY];
    let wA = state[sa + S.W];
    let vBx = state[sb + S.VX];
    let vBy = state[sb + S.VY];
    let wB = state[sb + S.W];
    const dpx = state[sb + S.DPX] - state[sa + S.DPX];
    const dpy = state[sb + S.DPY] - state[sa + S.DPY];
    const qAc = state[sa + S.DQC];
    const qAs = state[sa + S.DQS];
    const qBc = state[sb + S.DQC];
    const qBs = state[sb + S.DQS];
    // the anchors' relative motion along the normal, without the anchors: add (qB rB - qA rA) . n
    const dpn = dpx * nx + dpy * ny;
    const count = d[base + C.COUNT] | 0;
    // The block path's normal impulse, not yet applied to the linear velocities: those enter the
    // friction rows only through (vB - vA) . t, which an impulse along n leaves alone (n . t = 0), so
    // they take the normal and the friction impulses at once, at the end; the turns are applied as
    // the impulses are found. This keeps the velocity updates off the chain of dependent arithmetic
    // from the normal solve through the two friction points, whose latency sets the pace of this
    // loop (pyramids 0.95x). The one-point path doing the same was level (a rain over 8 seeds
    // 0.96-1.00x; one seed alone, its pile being chaotic, can come out 1.2x either way).
    let normalImpulse = 0;

    if (d[base + C.BLOCK] === 1) {
      const p1 = base + C.POINTS;
      const p2 = p1 + P.STRIDE;
      const rn1A = d[p1 + P.RNA];
      const rn1B = d[p1 + P.RNB];
      const rn2A = d[p2 + P.RNA];
      const rn2B = d[p2 + P.RNB];
      // current separations from the motion accumulated since the step began (see P.QA)
      const s1 = dpn + qBc * d[p1 + P.QB] + qBs * rn1B + qAc * d[p1 + P.QA] - qAs * rn1A + d[p1 + P.ADJ_SEP];
      const s2 = dpn + qBc * d[p2 + P.QB] + qBs * rn2B + qAc * d[p2 + P.QA] - qAs * rn2A + d[p2 + P.ADJ_SEP];
      const k11 = d[base + C.K11];
      const k12 = d[base + C.K12];
      const k22 = d[base + C.K22];
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
      const l1 = d[p1 + P.NIMP];
      const l2 = d[p2 + P.NIMP];
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
      d[p1 + P.NIMP] = x1;
      d[p2 + P.NIMP] = x2;
      // the largest increment, read only as "> 0" (hit events). Not Math.max: V8 compiles it to
      // compares and branches the data decides, which mispredict in piles that move; (a + b + |a - b|)
      // / 2 is branch-free and the max to an ulp
      const m1 = d[p1 + P.MAX_NIMP];
      d[p1 + P.MAX_NIMP] = 0.5 * (m1 + dl1 + Math.abs(m1 - dl1));
      const m2 = d[p2 + P.MAX_NIMP];
      d[p2 + P.MAX_NIMP] = 0.5 * (m2 + dl2 + Math.abs(m2 - dl2));
      normalImpulse = dl1 + dl2;
      wA -= iA * (rn1A * dl1 + rn2A * dl2);
      wB += iB * (rn1B * dl1 + rn2B * dl2);
    } else {
      // point by point; the second (if any) in the same code (a loop of one or two turns costs more)
      let p = base + C.POINTS;
      for (;;) {
        const rnA = d[p + P.RNA];
        const rnB = d[p + P.RNB];
        const sep = dpn + qBc * d[p + P.QB] + qBs * rnB + qAc * d[p + P.QA] - qAs * rnA + d[p + P.ADJ_SEP];
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
        const old = d[p + P.NIMP];
        let impulse = -d[p + P.NMASS] * mScale * (vn + bias) - iScale * old;
        // max(y, 0) without a branch (see the block path), exactly: y + |y| is 2y or 0
        const y = old + impulse;
        const next = 0.5 * (y + Math.abs(y));
        impulse = next - old;
        d[p + P.NIMP] = next;
        const mm = d[p + P.MAX_NIMP];
        d[p + P.MAX_NIMP] = 0.5 * (mm + impulse + Math.abs(mm - impulse));
        const Px = impulse * nx;
        const Py = impulse * ny;
        vAx -= mA * Px;
        vAy -= mA * Py;
        wA -= iA * impulse * rnA;
        vBx += mB * Px;
        vBy += mB * Py;
        wB += iB * impulse * rnB;
        if (count === 1 || p !== base + C.POINTS) break;
        p += P.STRIDE;
      }
    }

    // friction, point by point (unrolled: a loop of one or two turns cost more than its arithmetic);
    // the relative velocity along t as (vB - vA) . t, which moves only with the friction impulses
    // (by (mA + mB) per unit, t being unit), plus the turns' part
    const friction = d[base + C.FRICTION];
    const tx = ny;
    const ty = -nx;
    let dvt = (vBx - vAx) * tx + (vBy - vAy) * ty;
    let p = base + C.POINTS;
    let rtA = d[p + P.RTA];
    let rtB = d[p + P.RTB];
    let vt = dvt + wB * rtB - wA * rtA;
    let maxFriction = friction * d[p + P.NIMP];
    let old = d[p + P.TIMP];
    let next = old - d[p + P.TMASS] * vt;
    // biome-ignore lint/complexity/useMathMinMax: compares, as V8 adds NaN and -0 checks to Math.max/min (pyramid 0.99x)
    next = next > maxFriction ? maxFriction : next < -maxFriction ? -maxFriction : next;
    let impulse = next - old;
    let frictionImpulse = impulse;
    d[p + P.TIMP] = next;
    wA -= iA * impulse * rtA;
    wB += iB * impulse * rtB;
    if (count === 2) {
      p += P.STRIDE;
      rtA = d[p + P.RTA];
      rtB = d[p + P.RTB];
      dvt += (mA + mB) * impulse;
      vt = dvt + wB * rtB - wA * rtA;
      maxFriction = friction * d[p + P.NIMP];
      old = d[p + P.TIMP];
      next = old - d[p + P.TMASS] * vt;
      // biome-ignore lint/complexity/useMathMinMax: as above
      next = next > maxFriction ? maxFriction : next < -maxFriction ? -maxFriction : next;
      impulse = next - old;
      frictionImpulse += impulse;
      d[p + P.TIMP] = next;
      wA -= iA * impulse * rtA;
      wB += iB * impulse * rtB;
    }
    const Px = normalImpulse * nx + frictionImpulse * tx;
    const Py = normalImpulse * ny + frictionImpulse * ty;
    vAx -= mA * Px;
    vAy -= mA * Py;
    vBx += mB * Px;
    vBy += mB * Py;
    state[sa + S.VX] = vAx;
    state[sa + S.VY] = vAy;
    state[sa + S.W] = wA;
    state[sb + S.VX] = vBx;
    state[sb + S.VY] = vBy;
    state[sb + S.W] = wB;
  }
}

/**
 * Restitution after the substeps: points that approached faster than the threshold and carried an
 * impulse get a normal velocity of -restitution times their approach velocity.
 */
export function applyRestitution(cc: ContactConstraints, state: Float64Array, threshold: number): void {
  const d = cc.data;
  const ids = cc.ids;
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    const base = i * C.STRIDE;
    const rBase = i * R.STRIDE;
    const restitution = cc.restitution[rBase + R.RESTITUTION];
    if (restitution === 0) continue;
    const sa = (ids[i * 3] & IndexBound.MAX) * S.STRIDE;
    const sb = (ids[i * 3 + 1] & IndexBound.MAX) * S.STRIDE;
    const mA = d[base + C.MA];
    const iA = d[base + C.IA];
    const mB = d[base + C.MB];
    const iB = d[base + C.IB];
    const nx = d[base + C.NX];
    const ny = d[base + C.NY];
    let vAx = state[sa + S.VX];
    let vAy = state[sa + S.VY];
    let wA = state[sa + S.W];
    let vBx = state[sb + S.VX];
    let vBy = state[sb + S.VY];
    let wB = state[sb + S.W];
    const count = d[base + C.COUNT];
    for (let j = 0; j < count; j++) {
      const p = base + C.POINTS + j * P.STRIDE;
      const relVel = cc.restitution[rBase + R.REL_VEL + j];
      if (relVel > -threshold || d[p + P.MAX_NIMP] === 0) continue;
      const rnA = d[p + P.RNA];
      const rnB = d[p + P.RNB];
      const vn = (vBx - vAx) * nx + (vBy - vAy) * ny + wB * rnB - wA * rnA;
      const old = d[p + P.NIMP];
      let impulse = -d[p + P.NMASS] * (vn + restitution * relVel);
      const next = Math.max(old + impulse, 0);
      impulse = next - old;
      d[p + P.NIMP] = next;
      d[p + P.MAX_NIMP] = Math.max(d[p + P.MAX_NIMP], impulse);
      const Px = impulse * nx;
      const Py = impulse * ny;
      vAx -= mA * Px;
      vAy -= mA * Py;
      wA -= iA * impulse * rnA;
      vBx += mB * Px;
      vBy += mB * Py;
      wB += iB * impulse * rnB;
    }
    state[sa + S.VX] = vAx;
    state[sa + S.VY] = vAy;
    state[sa + S.W] = wA;
    state[sb + S.VX] = vBx;
    state[sb + S.VY] = vBy;
    state[sb + S.W] = wB;
  }
}

/** Copies the impulses back to the contacts for warm starting next step and for hit events. */
export function storeImpulses(
  cc: ContactConstraints,
  normalImpulse: Float64Array,
  tangentImpulse: Float64Array,
  maxNormalImpulse: Float64Array,
  approachSpeed: Float64Array,
): void {
  const d = cc.data;
  const ids = cc.ids;
  for (let i = 0, n = cc.count & IndexBound.MAX; i < n; i++) {
    const base = i * C.STRIDE;
    const contact = ids[i * 3 + 2];
    const count = d[base + C.COUNT];
    for (let j = 0; j < count; j++) {
      const p = base + C.POINTS + j * P.STRIDE;
      const k = contact * 2 + j;
      normalImpulse[k] = d[p + P.NIMP];
      tangentImpulse[k] = d[p + P.TIMP];
      maxNormalImpulse[k] = d[p + P.MAX_NIMP];
      approachSpeed[k] = -cc.restitution[i * R.STRIDE + R.REL_VEL + j];
    }
  }
}
