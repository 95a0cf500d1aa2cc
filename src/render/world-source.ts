import type { World } from '../api/world';
import { BodyFlag, BodyState } from '../store/body-store';
import { ContactFlag } from '../store/contact-store';
import { ShapeFlag } from '../store/shape-store';
import {
  type BodyRecord,
  type ContactPointRecord,
  type DrawSource,
  type JointRecord,
  type MotionRecord,
  newBodyRecord,
  newJointRecord,
  newMotionRecord,
  newShapeRecord,
  type ShapeRecord,
} from './draw-source';

/** body types by BodyKind */
const TYPES = ['static', 'kinematic', 'dynamic'] as const;

/**
 * The drawing source of a World on this thread: reads its columns (bodies by slot, each body's shapes
 * in the order of its shape list) and never changes them.
 */
export class WorldDrawSource implements DrawSource {
  private readonly body = newBodyRecord();
  private readonly shape = newShapeRecord();
  private readonly motionRecord = newMotionRecord();
  private readonly joint = newJointRecord();
  private readonly contactBody = newBodyRecord();
  private readonly contact: ContactPointRecord = {
    body: this.contactBody,
    point: { x: 0, y: 0 },
    normal: { x: 0, y: 0 },
    separation: 0,
  };

  constructor(readonly world: World) {}

  /** Fills `out` with the body in slot `b`. */
  private read(b: number, out: BodyRecord): BodyRecord {
    const bodies = this.world.core.bodies;
    const kind = bodies.kind[b];
    const flags = bodies.flags[b];
    out.handle = this.world.handles.bodies[b]!;
    out.index = b;
    out.type = TYPES[kind];
    out.bullet = (flags & BodyFlag.BULLET) !== 0;
    out.awake = (flags & BodyFlag.AWAKE) !== 0;
    out.transform.p.x = bodies.px[b];
    out.transform.p.y = bodies.py[b];
    out.transform.q.c = bodies.qc[b];
    out.transform.q.s = bodies.qs[b];
    return out;
  }

  forEachBody(visit: (body: BodyRecord) => void): void {
    const bodies = this.world.core.bodies;
    for (let b = 0; b < bodies.slotCount; b++) {
      if (bodies.alive[b] === 0) continue;
      visit(this.read(b, this.body));
    }
  }

  forEachShape(body: BodyRecord, visit: (shape: ShapeRecord) => void): void {
    const core = this.world.core;
    const shapes = core.shapes;
    const record = this.shape;
    for (let s = core.bodies.shapeHead[body.index]; s !== -1; s = shapes.next[s]) {
      record.handle = this.world.handles.shapes[s]!;
      record.geometry = shapes.geometry[s]!;
      record.sensor = (shapes.flags[s] & ShapeFlag.SENSOR) !== 0;
      visit(record);
    }
  }

  motion(body: BodyRecord): MotionRecord {
    const bodies = this.world.core.bodies;
    const b = body.index;
    const st = b * BodyState.STRIDE;
    const m = this.motionRecord;
    m.localCenter.x = bodies.lcx[b];
    m.localCenter.y = bodies.lcy[b];
    m.linearVelocity.x = bodies.state[st + BodyState.VX];
    m.linearVelocity.y = bodies.state[st + BodyState.VY];
    return m;
  }

  forEachJoint(visit: (joint: JointRecord) => void): void {
    const record = this.joint;
    for (const joint of this.world.joints) {
      this.read(joint.bodyA.slot, record.bodyA);
      this.read(joint.bodyB.slot, record.bodyB);
      const a = joint.anchorA;
      const b = joint.anchorB;
      record.type = joint.type;
      record.anchorA.x = a.x;
      record.anchorA.y = a.y;
      record.anchorB.x = b.x;
      record.anchorB.y = b.y;
      // by type, not instanceof: the render entry may be a separate bundle (CommonJS)
      record.target =
        joint.type === 'mouse' ? (joint as unknown as { target: { x: number; y: number } }).target : null;
      visit(record);
    }
  }

  forEachContactPoint(visit: (point: ContactPointRecord) => void): void {
    const contacts = this.world.core.contacts;
    const record = this.contact;
    for (let c = 0; c < contacts.slotCount; c++) {
      if (contacts.alive[c] === 0) continue;
      const f = contacts.flags[c];
      if ((f & ContactFlag.TOUCHING) === 0 || (f & ContactFlag.SENSOR) !== 0) continue;
      this.read(contacts.bodyA[c], this.contactBody);
      record.normal.x = contacts.normalX[c];
      record.normal.y = contacts.normalY[c];
      const n = contacts.pointCount[c];
      for (let i = 0; i < n; i++) {
        const k = c * 2 + i;
        record.point.x = contacts.pointX[k];
        record.point.y = contacts.pointY[k];
        record.separation = contacts.separation[k];
        visit(record);
      }
    }
  }

  forEachAABB(visit: (minX: number, minY: number, maxX: number, maxY: number) => void): void {
    const shapes = this.world.core.shapes;
    for (let s = 0; s < shapes.slotCount; s++) {
      if (shapes.alive[s] === 0) continue;
      visit(shapes.minX[s], shapes.minY[s], shapes.maxX[s], shapes.maxY[s]);
    }
  }
}
