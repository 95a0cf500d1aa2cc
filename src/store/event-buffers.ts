import { IntList } from '../broad-phase/int-list';
import { growF64 } from '../core/grow';
import { ContactFlag, type ContactStore } from './contact-store';
import { ShapeFlag, type ShapeStore } from './shape-store';

/** Numbers per begin in `beginData`: normal x, y, point count, then x, y of up to two points. */
export const BEGIN_STRIDE = 7;
/** Numbers per hit in `hitData`: point x, y, normal x, y, approach speed. */
export const HIT_STRIDE = 5;

/** @internal What a warning is about (see WarningEvent). An enum for the reason in store/body-store.ts. */
export enum WarningCode {
  /** shapes at their contact limit wait for pairs with shapes they overlap */
  CONTACT_LIMIT = 0,
  /** the search for new pairs reached its budget: proxies wait for the next step */
  PAIR_SEARCH = 1,
}

/**
 * Events of one step as plain numbers, recorded without allocation while the step runs and turned
 * into objects only after it, for the handlers and the readable arrays.
 *
 * When the step ends, `seal` makes the record self-contained before any user code can run: the
 * begins' normals and points are copied out of the contacts, and each shape named gets its
 * generation, so that the record still says which shapes the events were about after those shapes
 * (and their contacts) are destroyed and their slots reused.
 * @internal
 */
export class EventBuffers {
  /** contact slot, shape A, shape B per begin */
  readonly contactBegin = new IntList();
  /** shape A, shape B per end */
  readonly contactEnd = new IntList();
  /** sensor shape, visitor shape */
  readonly sensorBegin = new IntList();
  readonly sensorEnd = new IntList();
  /** shape A, shape B per hit; the numbers are in hitData */
  readonly hitShapes = new IntList();
  /** HIT_STRIDE numbers per hit */
  hitData = new Float64Array(HIT_STRIDE * 16);
  /** BEGIN_STRIDE numbers per begin, written by seal */
  beginData = new Float64Array(BEGIN_STRIDE * 16);
  /**
   * The generation of each shape named by the lists above, written by seal, in this order: the
   * begins' (A, B), the ends', the sensor begins', the sensor ends', the hits'.
   */
  readonly generations = new IntList();
  /**
   * Ends of pairs dropped between steps (a shape's filter or sensor flag or a body's type changed, a
   * joint forbade the collision): shape A, its generation, shape B, its generation per end. They are
   * reported with the next step (see takePending), so that a pair found again in that step ends
   * before it begins again.
   */
  readonly pendingContactEnd = new IntList();
  /** as pendingContactEnd: sensor shape, its generation, visitor shape, its generation */
  readonly pendingSensorEnd = new IntList();
  /** code, count, limit, example shape (or -1) per warning; at most one of each code a step */
  readonly warningData = new Float64Array(8);
  warningCount = 0;

  clear(): void {
    this.warningCount = 0;
    this.contactBegin.clear();
    this.contactEnd.clear();
    this.sensorBegin.clear();
    this.sensorEnd.clear();
    this.hitShapes.clear();
    this.generations.clear();
  }

  recordBegin(contacts: ContactStore, c: number, shapes: ShapeStore): void {
    const a = contacts.shapeA[c];
    const b = contacts.shapeB[c];
    if ((contacts.flags[c] & ContactFlag.SENSOR) !== 0) {
      this.recordSensor(this.sensorBegin, shapes, a, b, false);
    } else if (((shapes.flags[a] | shapes.flags[b]) & ShapeFlag.CONTACT_EVENTS) !== 0) {
      this.contactBegin.push(c);
      this.contactBegin.push2(a, b);
    }
  }

  /** Records the end of a touching contact; `between` when no step is running (see pendingContactEnd). */
  recordEnd(contacts: ContactStore, c: number, shapes: ShapeStore, between: boolean): void {
    const a = contacts.shapeA[c];
    const b = contacts.shapeB[c];
    if ((contacts.flags[c] & ContactFlag.SENSOR) !== 0) {
      if (between) this.recordSensor(this.pendingSensorEnd, shapes, a, b, true);
      else this.recordSensor(this.sensorEnd, shapes, a, b, false);
    } else if (((shapes.flags[a] | shapes.flags[b]) & ShapeFlag.CONTACT_EVENTS) !== 0) {
      if (between) pushStamped(this.pendingContactEnd, shapes, a, b);
      else this.contactEnd.push2(a, b);
    }
  }

  private recordSensor(list: IntList, shapes: ShapeStore, a: number, b: number, stamped: boolean): void {
    const sensor = (shapes.flags[a] & ShapeFlag.SENSOR) !== 0 ? a : b;
    const visitor = sensor === a ? b : a;
    if ((shapes.flags[sensor] & shapes.flags[visitor] & ShapeFlag.SENSOR_EVENTS) === 0) return;
    if (stamped) pushStamped(list, shapes, sensor, visitor);
    else list.push2(sensor, visitor);
  }

  /**
   * Called when a step begins, after clear(): the ends recorded since the last step become this
   * step's first ends, less those naming a shape destroyed since (whose pairs need no end).
   */
  takePending(shapes: ShapeStore): void {
    takeStamped(this.pendingContactEnd, this.contactEnd, shapes);
    takeStamped(this.pendingSensorEnd, this.sensorEnd, shapes);
  }

  recordWarning(code: WarningCode, count: number, limit: number, shape: number): void {
    const d = this.warningData;
    const k = 4 * this.warningCount++;
    d[k] = code;
    d[k + 1] = count;
    d[k + 2] = limit;
    d[k + 3] = shape;
  }

  recordHit(a: number, b: number, px: number, py: number, nx: number, ny: number, speed: number): void {
    const i = this.hitShapes.length / 2;
    if ((i + 1) * HIT_STRIDE > this.hitData.length)
      this.hitData = growF64(this.hitData, this.hitData.length * 2);
    const d = this.hitData;
    const k = i * HIT_STRIDE;
    d[k] = px;
    d[k + 1] = py;
    d[k + 2] = nx;
    d[k + 3] = ny;
    d[k + 4] = speed;
    this.hitShapes.push2(a, b);
  }

  /** Called when the step ends, while every shape and contact named is still alive (see the class doc). */
  seal(contacts: ContactStore, shapes: ShapeStore): void {
    const begins = this.contactBegin;
    const count = begins.length / 3;
    if (count * BEGIN_STRIDE > this.beginData.length) {
      this.beginData = growF64(
        this.beginData,
        Math.max(count, 2 * (this.beginData.length / BEGIN_STRIDE)) * BEGIN_STRIDE,
      );
    }
    const d = this.beginData;
    for (let i = 0; i < count; i++) {
      const c = begins.data[i * 3];
      const k = i * BEGIN_STRIDE;
      const n = contacts.pointCount[c];
      d[k] = contacts.normalX[c];
      d[k + 1] = contacts.normalY[c];
      d[k + 2] = n;
      for (let j = 0; j < 2; j++) {
        d[k + 3 + 2 * j] = j < n ? contacts.pointX[c * 2 + j] : 0;
        d[k + 4 + 2 * j] = j < n ? contacts.pointY[c * 2 + j] : 0;
      }
    }
    const g = this.generations;
    g.clear();
    stampGenerations(g, begins, 3, 1, shapes);
    stampGenerations(g, this.contactEnd, 2, 0, shapes);
    stampGenerations(g, this.sensorBegin, 2, 0, shapes);
    stampGenerations(g, this.sensorEnd, 2, 0, shapes);
    stampGenerations(g, this.hitShapes, 2, 0, shapes);
  }
}

/**
 * Appends to `out` the generations (as int32) of the shape pairs in `list`, whose records are
 * `stride` long with the pair at `first`.
 */
function stampGenerations(
  out: IntList,
  list: IntList,
  stride: number,
  first: number,
  shapes: ShapeStore,
): void {
  const generation = shapes.generation;
  for (let i = first; i < list.length; i += stride) {
    out.push2(generation[list.data[i]] | 0, generation[list.data[i + 1]] | 0);
  }
}

/** Appends shapes `a` and `b` with their generations. */
function pushStamped(list: IntList, shapes: ShapeStore, a: number, b: number): void {
  list.push2(a, shapes.generation[a] | 0);
  list.push2(b, shapes.generation[b] | 0);
}

/** Moves the pairs of `from` (stamped by pushStamped) whose shapes are still the same into `to`. */
function takeStamped(from: IntList, to: IntList, shapes: ShapeStore): void {
  const d = from.data;
  for (let i = 0; i < from.length; i += 4) {
    const a = d[i];
    const b = d[i + 2];
    if (
      shapes.alive[a] !== 0 &&
      shapes.alive[b] !== 0 &&
      (shapes.generation[a] | 0) === d[i + 1] &&
      (shapes.generation[b] | 0) === d[i + 3]
    ) {
      to.push2(a, b);
    }
  }
  from.clear();
}
