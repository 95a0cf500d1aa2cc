import { BODY_KINDS, BODY_TYPES, type BodyType, type ResolvedBodyDef } from '../api/body';
import { checkShapes, type ShapeDef } from '../api/shape';
import { checkBoolean, FulcrumError, fail } from '../core/errors';
import {
  checkAngle,
  checkCoordinates,
  checkForce,
  checkRange,
  checkRate,
  checkVector,
  Limits,
} from '../core/limits';
import { type Chain, type Concave, type Geometry, ShapeKind } from '../geometry/types';
import type { JointType } from '../joints/registry';
import { blendTransform } from '../math/blend';
import { makeRot, rotAngle } from '../math/rot';
import type { Transform, Vec2 } from '../math/vec2';
import { checkKindChange } from '../world/world-edits';
import { toPlain } from './plain';
import { type BodyCommand, type Plain, type PlainDef, Row } from './protocol';
import type { WorkerWorld } from './worker-world';

/**
 * A body of a WorkerWorld, made at once on the calling thread while the worker makes the body itself
 * at the next step (or query). Its reads (position, velocities, ...) are synchronous and show the
 * state after the last step the world has finished; before its first step, the values it was created
 * with. Its commands are checked here as Body checks them and applied in the worker in order.
 */
export class WorkerBody {
  readonly world: WorkerWorld;
  /** @internal the id the worker knows it by: its row in the state buffer */
  readonly id: number;
  /** @internal tells the rows of this body from those of an earlier body with the same id */
  readonly generation: number;
  userData: unknown;
  /** @internal */
  destroyed = false;
  /** @internal the type as the commands given so far leave it */
  kind: BodyType;
  /** @internal in creation order */
  readonly shapeList: WorkerShape[] = [];
  /** @internal in creation order */
  readonly jointList: WorkerJoint[] = [];
  /** @internal as created (drawn in the bullet colour) */
  bullet: boolean;
  /** the row it reads until a step reports it: the pose and velocities it was created with */
  readonly #initial = new Float64Array(Row.STRIDE);

  /** @internal created by WorkerWorld.createBody, or for a restored world's body (`def` null) */
  constructor(
    world: WorkerWorld,
    id: number,
    generation: number,
    type: BodyType,
    def: ResolvedBodyDef | null,
    userData: unknown,
  ) {
    this.world = world;
    this.id = id;
    this.generation = generation;
    this.kind = type;
    this.userData = userData;
    this.bullet = def?.bullet ?? false;
    if (def === null) return;
    // as World.createBody leaves it (the centre of mass is the origin until the worker knows the shapes)
    const row = this.#initial;
    const q = makeRot(def.angle);
    const moving = type !== 'static';
    row[Row.GENERATION] = generation;
    row[Row.PX] = row[Row.PREV_PX] = row[Row.CX] = def.position.x;
    row[Row.PY] = row[Row.PREV_PY] = row[Row.CY] = def.position.y;
    row[Row.QC] = row[Row.PREV_QC] = q.c;
    row[Row.QS] = row[Row.PREV_QS] = q.s;
    row[Row.VX] = moving ? def.v.x : 0;
    row[Row.VY] = moving ? def.v.y : 0;
    row[Row.W] = moving && !(def.fixedRotation && type === 'dynamic') ? def.w : 0;
    row[Row.AWAKE] = moving && def.awake ? 1 : 0;
  }

  /** @internal throws once the body is destroyed, as Body does */
  check(): void {
    if (this.destroyed) throw new FulcrumError('body has been destroyed');
  }

  get isValid(): boolean {
    return !this.destroyed;
  }

  /** The value of `column` in the last state the worker reported for this body. */
  #read(column: Row): number {
    this.check();
    const view = this.world.stateView;
    const r = this.id * Row.STRIDE;
    if (r + Row.STRIDE <= view.length && view[r + Row.GENERATION] === this.generation)
      return view[r + column];
    return this.#initial[column];
  }

  get type(): BodyType {
    this.check();
    return this.kind;
  }

  get position(): Vec2 {
    return { x: this.#read(Row.PX), y: this.#read(Row.PY) };
  }

  get angle(): number {
    return rotAngle(this.#read(Row.QC), this.#read(Row.QS));
  }

  /** rotation as a (cos, sin) pair, exactly as the engine keeps it */
  get rotation(): { c: number; s: number } {
    return { c: this.#read(Row.QC), s: this.#read(Row.QS) };
  }

  get worldCenter(): Vec2 {
    return { x: this.#read(Row.CX), y: this.#read(Row.CY) };
  }

  get linearVelocity(): Vec2 {
    return { x: this.#read(Row.VX), y: this.#read(Row.VY) };
  }

  get angularVelocity(): number {
    return this.#read(Row.W);
  }

  get isAwake(): boolean {
    return this.#read(Row.AWAKE) !== 0;
  }

  /** @internal fills `out` with the pose after the last step, as the engine keeps it (for drawing) */
  readPose(out: Transform): Transform {
    out.p.x = this.#read(Row.PX);
    out.p.y = this.#read(Row.PY);
    out.q.c = this.#read(Row.QC);
    out.q.s = this.#read(Row.QS);
    return out;
  }

  /**
   * The pose to draw the body at, `alpha` of the way from where the last step began (0) to where it
   * ended (1): positions blended linearly, rotations by a normalised linear blend. Output only.
   */
  getInterpolatedTransform(
    alpha: number,
    out: Transform = { p: { x: 0, y: 0 }, q: { c: 1, s: 0 } },
  ): Transform {
    const t = checkRange('alpha', alpha, 0, 1);
    return blendTransform(
      this.#read(Row.PREV_PX),
      this.#read(Row.PREV_PY),
      this.#read(Row.PREV_QC),
      this.#read(Row.PREV_QS),
      this.#read(Row.PX),
      this.#read(Row.PY),
      this.#read(Row.QC),
      this.#read(Row.QS),
      t,
      out,
    );
  }

  /** shapes in creation order */
  get shapes(): WorkerShape[] {
    this.check();
    return this.shapeList.slice();
  }

  /** joints attached to this body, in creation order */
  get joints(): WorkerJoint[] {
    this.check();
    return this.jointList.slice();
  }

  #command(method: BodyCommand, args: Plain[]): void {
    this.world.queue(['body', this.id, method, args]);
  }

  setPosition(position: Vec2): void {
    this.check();
    this.#command('setPosition', [checkCoordinates('position', position)]);
  }

  setAngle(angle: number): void {
    this.check();
    this.#command('setAngle', [checkAngle('angle', angle)]);
  }

  setTransform(position: Vec2, angle: number): void {
    this.check();
    const p = checkCoordinates('position', position);
    this.#command('setTransform', [p, checkAngle('angle', angle)]);
  }

  setLinearVelocity(velocity: Vec2): void {
    this.check();
    this.#command('setLinearVelocity', [checkVector('velocity', velocity, Limits.RATE)]);
  }

  setAngularVelocity(omega: number): void {
    this.check();
    this.#command('setAngularVelocity', [checkRate('angularVelocity', omega)]);
  }

  setType(type: BodyType): void {
    this.check();
    if (!BODY_TYPES.includes(type)) fail('type', type, "'static', 'kinematic' or 'dynamic'");
    if (type !== this.kind) {
      const segment = this.shapeList.some((shape) => shape.geometry.kind === ShapeKind.SEGMENT);
      checkKindChange(BODY_KINDS[type], segment, type);
    }
    this.#command('setType', [type]);
    this.kind = type;
  }

  /** Wakes the body, or puts it and everything it touches to sleep. */
  setAwake(awake: boolean): void {
    this.check();
    this.#command('setAwake', [checkBoolean('awake', awake)]);
  }

  /** Force in newtons at a world point (default: the centre of mass), until the end of the next step. */
  applyForce(force: Vec2, point?: Vec2): void {
    this.check();
    const f = checkVector('force', force, Limits.FORCE);
    this.#command('applyForce', point === undefined ? [f] : [f, checkCoordinates('point', point)]);
  }

  applyTorque(torque: number): void {
    this.check();
    this.#command('applyTorque', [checkForce('torque', torque)]);
  }

  /** Impulse in N·s at a world point (default: the centre of mass). */
  applyLinearImpulse(impulse: Vec2, point?: Vec2): void {
    this.check();
    const i = checkVector('impulse', impulse, Limits.FORCE);
    this.#command('applyLinearImpulse', point === undefined ? [i] : [i, checkCoordinates('point', point)]);
  }

  applyAngularImpulse(impulse: number): void {
    this.check();
    this.#command('applyAngularImpulse', [checkForce('impulse', impulse)]);
  }

  /**
   * Attaches a shape made by `Shape.*` (see Body.createShape): checked here as World checks it, made
   * in the worker at the next step. A concave shape or a chain gives the handles of its pieces.
   */
  createShape(geometry: Concave | Chain, def?: ShapeDef): WorkerShape[];
  createShape(geometry: Geometry, def?: ShapeDef): WorkerShape;
  createShape(geometry: Geometry | Concave | Chain, def?: ShapeDef): WorkerShape | WorkerShape[];
  createShape(geometry: Geometry | Concave | Chain, def?: ShapeDef): WorkerShape | WorkerShape[] {
    this.check();
    const checked = checkShapes(BODY_KINDS[this.kind], geometry, def, this.world.shapeCount);
    const userData = def?.userData;
    const sensor = def?.isSensor === true;
    const parts = checked.parts ?? [checked.geometry!];
    const shapes = parts.map((part) => this.world.addShape(this, part, sensor, userData));
    this.world.queue([
      'createShape',
      this.id,
      shapes.map((s) => s.id),
      geometry as unknown as Plain,
      def === undefined ? undefined : (toPlain(def) as PlainDef),
    ]);
    return checked.parts === null ? shapes[0] : shapes;
  }

  destroyShape(shape: WorkerShape): void {
    this.check();
    if (!(shape instanceof WorkerShape) || shape.body !== this) fail('shape', shape, 'a shape of this body');
    shape.check();
    this.world.queue(['destroyShape', this.id, shape.id]);
    this.world.removeShape(shape);
  }
}

/** A shape of a WorkerBody. */
export class WorkerShape {
  readonly body: WorkerBody;
  /** @internal */
  readonly id: number;
  /** the shape's geometry in its body's frame (a concave shape's piece, a chain's segment) */
  readonly geometry: Geometry;
  /** a sensor detects overlaps and never collides (as made: WorkerShape has no setter yet) */
  readonly isSensor: boolean;
  userData: unknown;
  /** @internal */
  destroyed = false;

  /** @internal */
  constructor(body: WorkerBody, id: number, geometry: Geometry, isSensor: boolean, userData: unknown) {
    this.body = body;
    this.id = id;
    this.geometry = geometry;
    this.isSensor = isSensor;
    this.userData = userData;
  }

  /** @internal */
  check(): void {
    if (this.destroyed) throw new FulcrumError('shape has been destroyed');
  }

  get isValid(): boolean {
    return !this.destroyed;
  }

  get type(): Geometry['type'] {
    this.check();
    return this.geometry.type;
  }
}

/** A joint of a WorkerWorld (a mouse joint's bodyA and bodyB are its one body, as on World). */
export class WorkerJoint {
  readonly world: WorkerWorld;
  /** @internal */
  readonly id: number;
  readonly type: JointType;
  readonly bodyA: WorkerBody;
  readonly bodyB: WorkerBody;
  userData: unknown;
  /** @internal */
  destroyed = false;
  /**
   * @internal the anchors in the bodies' frames (A x, y, B x, y), as the worker made them (defaults
   * may depend on where the bodies were): null until the reply to the batch that made the joint
   */
  localAnchors: Float64Array | null = null;
  /** a mouse joint's target as the commands given so far leave it (null for other joints) */
  #target: Vec2 | null;

  /** @internal */
  constructor(
    world: WorkerWorld,
    id: number,
    type: JointType,
    bodyA: WorkerBody,
    bodyB: WorkerBody,
    target: Vec2 | null,
    userData: unknown,
  ) {
    this.world = world;
    this.id = id;
    this.type = type;
    this.bodyA = bodyA;
    this.bodyB = bodyB;
    this.#target = target === null ? null : { x: target.x, y: target.y };
    this.userData = userData;
  }

  /** A mouse joint's target (world point); null for other joints, and for a restored world's mouse joint. */
  get target(): Vec2 | null {
    this.check();
    return this.#target === null ? null : { x: this.#target.x, y: this.#target.y };
  }

  /** Moves a mouse joint's target and wakes its body, at the next step (see MouseJoint.setTarget). */
  setTarget(target: Vec2): void {
    this.check();
    if (this.type !== 'mouse') throw new FulcrumError(`setTarget: a ${this.type} joint has no target`);
    const t = checkCoordinates('target', target);
    this.world.queue(['joint', this.id, 'setTarget', [t]]);
    this.#target = t;
  }

  /** @internal */
  check(): void {
    if (this.destroyed) throw new FulcrumError('joint has been destroyed');
  }

  get isValid(): boolean {
    return !this.destroyed;
  }
}
