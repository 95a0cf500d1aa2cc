import type { WorkerBody } from '../worker/handles';
import type { WorkerWorld } from '../worker/worker-world';
import {
  type BodyRecord,
  type DrawSource,
  type JointRecord,
  type MotionRecord,
  newBodyRecord,
  newJointRecord,
  newMotionRecord,
  newShapeRecord,
  type ShapeRecord,
} from './draw-source';

/**
 * The drawing source of a WorkerWorld: shapes as its create calls made them (known on this thread),
 * poses from the state its worker last published, joint anchors as the worker reported them once it
 * made the joint. Bodies by id, each body's shapes newest first, as a World's source lists them, so
 * the same scene is drawn in the same order. No contacts or bounding boxes: this thread has none.
 */
export class WorkerDrawSource implements DrawSource {
  private readonly body = newBodyRecord();
  private readonly shape = newShapeRecord();
  private readonly motionRecord = newMotionRecord();
  private readonly joint = newJointRecord();

  constructor(readonly world: WorkerWorld) {}

  private read(body: WorkerBody, out: BodyRecord): BodyRecord {
    out.handle = body;
    out.index = body.id;
    out.type = body.kind;
    out.bullet = body.bullet;
    out.awake = body.isAwake;
    body.readPose(out.transform);
    return out;
  }

  forEachBody(visit: (body: BodyRecord) => void): void {
    for (const body of this.world.bodyList) {
      if (body === undefined || body.destroyed) continue;
      visit(this.read(body, this.body));
    }
  }

  forEachShape(body: BodyRecord, visit: (shape: ShapeRecord) => void): void {
    const shapes = (body.handle as WorkerBody).shapeList;
    const record = this.shape;
    for (let i = shapes.length - 1; i >= 0; i--) {
      const shape = shapes[i];
      record.handle = shape;
      record.geometry = shape.geometry;
      record.sensor = shape.isSensor;
      visit(record);
    }
  }

  motion(body: BodyRecord): MotionRecord {
    const handle = body.handle as WorkerBody;
    const { p, q } = body.transform;
    const center = handle.worldCenter;
    const dx = center.x - p.x;
    const dy = center.y - p.y;
    const m = this.motionRecord;
    m.localCenter.x = q.c * dx + q.s * dy;
    m.localCenter.y = -q.s * dx + q.c * dy;
    const v = handle.linearVelocity;
    m.linearVelocity.x = v.x;
    m.linearVelocity.y = v.y;
    return m;
  }

  forEachJoint(visit: (joint: JointRecord) => void): void {
    const record = this.joint;
    for (const joint of this.world.joints) {
      const anchors = joint.localAnchors;
      // not drawn until the worker has made it and reported where its anchors are
      if (anchors === null) continue;
      const a = this.read(joint.bodyA, record.bodyA).transform;
      const b = this.read(joint.bodyB, record.bodyB).transform;
      record.type = joint.type;
      record.anchorA.x = a.q.c * anchors[0] - a.q.s * anchors[1] + a.p.x;
      record.anchorA.y = a.q.s * anchors[0] + a.q.c * anchors[1] + a.p.y;
      record.anchorB.x = b.q.c * anchors[2] - b.q.s * anchors[3] + b.p.x;
      record.anchorB.y = b.q.s * anchors[2] + b.q.c * anchors[3] + b.p.y;
      record.target = joint.target;
      visit(record);
    }
  }
}
