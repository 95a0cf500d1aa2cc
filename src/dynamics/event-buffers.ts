import { IntList } from '../collision/int-list';
import { growF64 } from '../core/grow';
import { ContactFlag, type ContactStore } from './contact-store';
import { ShapeFlag, type ShapeStore } from './shape-store';

/** What a warning is about (see WarningEvent). An enum for the reason in dynamics/body-store.ts. */
export enum WarningCode {
  /** shapes at their contact limit wait for pairs with shapes they overlap */
  CONTACT_LIMIT = 0,
  /** the search for new pairs reached its budget: proxies wait for the next step */
  PAIR_SEARCH = 1,
}

/**
 * Events of one step as plain numbers, recorded without allocation while the step runs and turned
 * into objects only after it, for the handlers and the readable arrays.
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
  /** point x, y, normal x, y, approach speed per hit */
  hitData = new Float64Array(5 * 16);
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
  }

  recordBegin(contacts: ContactStore, c: number, shapes: ShapeStore): void {
    const a = contacts.shapeA[c];
    const b = contacts.shapeB[c];
    if ((contacts.flags[c] & ContactFlag.SENSOR) !== 0) {
      this.recordSensor(this.sensorBegin, shapes, a, b);
    } else if (((shapes.flags[a] | shapes.flags[b]) & ShapeFlag.CONTACT_EVENTS) !== 0) {
      this.contactBegin.push(c);
      this.contactBegin.push2(a, b);
    }
  }

  recordEnd(contacts: ContactStore, c: number, shapes: ShapeStore): void {
    const a = contacts.shapeA[c];
    const b = contacts.shapeB[c];
    if ((contacts.flags[c] & ContactFlag.SENSOR) !== 0) {
      this.recordSensor(this.sensorEnd, shapes, a, b);
    } else if (((shapes.flags[a] | shapes.flags[b]) & ShapeFlag.CONTACT_EVENTS) !== 0) {
      this.contactEnd.push2(a, b);
    }
  }

  private recordSensor(list: IntList, shapes: ShapeStore, a: number, b: number): void {
    const sensor = (shapes.flags[a] & ShapeFlag.SENSOR) !== 0 ? a : b;
    const visitor = sensor === a ? b : a;
    if ((shapes.flags[sensor] & shapes.flags[visitor] & ShapeFlag.SENSOR_EVENTS) !== 0)
      list.push2(sensor, visitor);
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
    if ((i + 1) * 5 > this.hitData.length) this.hitData = growF64(this.hitData, this.hitData.length * 2);
    const d = this.hitData;
    d[i * 5] = px;
    d[i * 5 + 1] = py;
    d[i * 5 + 2] = nx;
    d[i * 5 + 3] = ny;
    d[i * 5 + 4] = speed;
    this.hitShapes.push2(a, b);
  }
}
