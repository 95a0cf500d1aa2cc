import {
  BODY_KINDS,
  BODY_TYPES,
  type BodyType,
  type ContactPointData,
  checkScaleFactor,
  type MassData,
  type ResolvedBodyDef,
} from '../api/body';
import { checkGeometryFor, checkShapes, type Filter, type RayCastResult, type ShapeDef } from '../api/shape';
import { checkBoolean, FulcrumError, fail } from '../core/errors';
import {
  checkAngle,
  checkCoordinates,
  checkDensity,
  checkForce,
  checkNonNegativeRate,
  checkRange,
  checkRate,
  checkVector,
  Limits,
} from '../core/limits';
import { computeShapeBounds } from '../geometry/bounds';
import { Pack } from '../geometry/packed';
import { rayCastGeometry, testPoint } from '../geometry/raycast';
import { localScale, scaleGeometry } from '../geometry/scale-geometry';
import { type Chain, type Concave, type Geometry, makeRayHit, ShapeKind } from '../geometry/types';
import type { JointType } from '../joints/registry';
import { type AABB, makeBounds } from '../math/aabb';
import { blendTransform } from '../math/blend';
import { makeRot, rotAngle } from '../math/rot';
import { makeTransform, type Transform, type Vec2 } from '../math/vec2';
import { checkKindChange } from '../world/world-edits';
import { toPlain } from './plain';
import {
  type BodyCommand,
  type BodySettings,
  type JointCommand,
  JointRead,
  type Plain,
  type PlainDef,
  Row,
  type ShapeSetting,
  type ShapeSettings,
} from './protocol';
import type { WorkerWorld } from './worker-world';

/** A touching contact of a WorkerBody (see Body.getContacts), with worker handles. */
export interface WorkerContactData {
  shapeA: WorkerShape;
  shapeB: WorkerShape;
  /** unit normal, from shape A to shape B */
  normal: Vec2;
  points: ContactPointData[];
}

/**
 * A body of a WorkerWorld, made at once on the calling thread while the worker makes the body itself
 * at the next step (or query). Its reads (position, velocities, ...) are synchronous and show the
 * state after the last step the world has finished; before its first step, the values it was created
 * with (the mass data too: a new body's shapes count from its first step). Its settings (damping,
 * gravity scale, flags) read as the commands given so far leave them. Its commands are checked here
 * as Body checks them and applied in the worker in order.
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
  /** the settings as the commands given so far leave them */
  readonly #settings: BodySettings;
  /** the row it reads until a step reports it: the pose and velocities it was created with */
  readonly #initial = new Float64Array(Row.STRIDE);

  /** @internal created by WorkerWorld.createBody, or for a restored world's body (`def` null) */
  constructor(
    world: WorkerWorld,
    id: number,
    generation: number,
    type: BodyType,
    def: ResolvedBodyDef | null,
    settings: BodySettings,
    userData: unknown,
  ) {
    this.world = world;
    this.id = id;
    this.generation = generation;
    this.kind = type;
    this.userData = userData;
    this.#settings = settings;
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
    // a body without shapes: a dynamic one weighs 1 kg, as on World
    row[Row.MASS] = type === 'dynamic' ? 1 : 0;
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

  /**
   * Writes the body's state after the last step into `out` from `offset`, as Body.readState: the
   * centre of mass x, y; the rotation's cosine and sine; the linear velocity x, y; the angular
   * velocity; 1 if awake, else 0.
   */
  readState(out: Float64Array, offset = 0): void {
    this.check();
    out[offset] = this.#read(Row.CX);
    out[offset + 1] = this.#read(Row.CY);
    out[offset + 2] = this.#read(Row.QC);
    out[offset + 3] = this.#read(Row.QS);
    out[offset + 4] = this.#read(Row.VX);
    out[offset + 5] = this.#read(Row.VY);
    out[offset + 6] = this.#read(Row.W);
    out[offset + 7] = this.#read(Row.AWAKE);
  }

  /** A point of the body's frame in world coordinates, at the pose after the last step. */
  getWorldPoint(localPoint: Vec2): Vec2 {
    this.check();
    const p = checkCoordinates('localPoint', localPoint);
    const c = this.#read(Row.QC);
    const s = this.#read(Row.QS);
    return { x: c * p.x - s * p.y + this.#read(Row.PX), y: s * p.x + c * p.y + this.#read(Row.PY) };
  }

  /** A world point in the body's frame, at the pose after the last step. */
  getLocalPoint(worldPoint: Vec2): Vec2 {
    this.check();
    const p = checkCoordinates('worldPoint', worldPoint);
    const c = this.#read(Row.QC);
    const s = this.#read(Row.QS);
    const dx = p.x - this.#read(Row.PX);
    const dy = p.y - this.#read(Row.PY);
    return { x: c * dx + s * dy, y: -s * dx + c * dy };
  }

  /** A vector of the body's frame in world axes, at the rotation after the last step. */
  getWorldVector(localVector: Vec2): Vec2 {
    this.check();
    const v = checkCoordinates('localVector', localVector);
    const c = this.#read(Row.QC);
    const s = this.#read(Row.QS);
    return { x: c * v.x - s * v.y, y: s * v.x + c * v.y };
  }

  /** A world vector in the body's axes, at the rotation after the last step. */
  getLocalVector(worldVector: Vec2): Vec2 {
    this.check();
    const v = checkCoordinates('worldVector', worldVector);
    const c = this.#read(Row.QC);
    const s = this.#read(Row.QS);
    return { x: c * v.x + s * v.y, y: -s * v.x + c * v.y };
  }

  /** Velocity of a world point attached to the body, after the last step. */
  getLinearVelocityAt(worldPoint: Vec2): Vec2 {
    this.check();
    const p = checkCoordinates('worldPoint', worldPoint);
    const w = this.#read(Row.W);
    return {
      x: this.#read(Row.VX) - w * (p.y - this.#read(Row.CY)),
      y: this.#read(Row.VY) + w * (p.x - this.#read(Row.CX)),
    };
  }

  /** mass in kg, after the last step (see Body.mass) */
  get mass(): number {
    return this.#read(Row.MASS);
  }

  /** rotational inertia about the centre of mass, after the last step */
  get inertia(): number {
    return this.#read(Row.INERTIA);
  }

  /** the centre of mass in the body's frame, after the last step */
  get localCenter(): Vec2 {
    return { x: this.#read(Row.LCX), y: this.#read(Row.LCY) };
  }

  get linearDamping(): number {
    this.check();
    return this.#settings.linearDamping;
  }

  get angularDamping(): number {
    this.check();
    return this.#settings.angularDamping;
  }

  get gravityScale(): number {
    this.check();
    return this.#settings.gravityScale;
  }

  get fixedRotation(): boolean {
    this.check();
    return this.#settings.fixedRotation;
  }

  get bullet(): boolean {
    this.check();
    return this.#settings.bullet;
  }

  get allowSleep(): boolean {
    this.check();
    return this.#settings.allowSleep;
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

  setLinearDamping(damping: number): void {
    this.check();
    this.#command('setLinearDamping', [checkNonNegativeRate('linearDamping', damping)]);
    this.#settings.linearDamping = damping;
  }

  setAngularDamping(damping: number): void {
    this.check();
    this.#command('setAngularDamping', [checkNonNegativeRate('angularDamping', damping)]);
    this.#settings.angularDamping = damping;
  }

  setGravityScale(scale: number): void {
    this.check();
    this.#command('setGravityScale', [checkRate('gravityScale', scale)]);
    this.#settings.gravityScale = scale;
  }

  setFixedRotation(fixed: boolean): void {
    this.check();
    this.#command('setFixedRotation', [checkBoolean('fixedRotation', fixed)]);
    this.#settings.fixedRotation = fixed;
  }

  setBullet(bullet: boolean): void {
    this.check();
    this.#command('setBullet', [checkBoolean('bullet', bullet)]);
    this.#settings.bullet = bullet;
  }

  setAllowSleep(allow: boolean): void {
    this.check();
    this.#command('setAllowSleep', [checkBoolean('allowSleep', allow)]);
    this.#settings.allowSleep = allow;
  }

  /**
   * Gives the body a mass, an inertia and optionally a centre of mass in place of its shapes' (see
   * Body.setMassData); `mass`, `inertia` and `localCenter` read them after the next step.
   */
  setMassData(data: MassData): void {
    this.check();
    this.#command('setMassData', [this.world.checkMassData(data)]);
  }

  /**
   * Scales the body's shapes by `factor` about the world `point` (default: the centre of mass), as
   * Body.scale does, at the next step. It is checked here as Body.scale checks it, at the pose after
   * the last step; the worker checks it again at its pose then (commands queued before it may have
   * moved the body), and a scale it refuses rejects that request's promise and changes nothing. The
   * shapes' `geometry` reads the scaled geometries from the reply to that request on, the mass data
   * after the next step.
   */
  scale(factor: number | Vec2, point?: Vec2): void {
    this.check();
    const sx = checkScaleFactor('factor', typeof factor === 'number' ? factor : factor?.x, factor);
    const sy = typeof factor === 'number' ? sx : checkScaleFactor('factor', factor.y, factor);
    const p = point === undefined ? this.worldCenter : checkCoordinates('point', point);
    checkCoordinates('factor', {
      x: p.x + sx * (this.#read(Row.PX) - p.x),
      y: p.y + sy * (this.#read(Row.PY) - p.y),
    });
    const m = localScale(sx, sy, this.#read(Row.QC), this.#read(Row.QS));
    for (const shape of this.shapeList) scaleGeometry(shape.geometry, m, 'factor');
    const f = typeof factor === 'number' ? factor : { x: sx, y: sy };
    this.#command('scale', point === undefined ? [f] : [f, { x: p.x, y: p.y }]);
  }

  /** Goes back to the mass data the body's shapes give (see Body.resetMassData). */
  resetMassData(): void {
    this.check();
    this.#command('resetMassData', []);
  }

  /**
   * The body's touching contacts (see Body.getContacts), as the worker's world has them after the
   * commands queued before this call: as of the last step, less those of shapes destroyed since.
   */
  getContacts(): Promise<WorkerContactData[]> {
    this.check();
    return this.world.bodyContacts(this);
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
    const d = checked.def;
    const parts = checked.parts ?? [checked.geometry!];
    const shapes = parts.map((part) =>
      this.world.addShape(
        this,
        part,
        {
          friction: d.friction,
          restitution: d.restitution,
          density: d.density,
          filter: d.filter,
          isSensor: def?.isSensor === true,
          enableHitEvents: def?.enableHitEvents === true,
        },
        d.userData,
      ),
    );
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

/**
 * A shape of a WorkerBody. Its settings read as the commands given so far leave them; its setters are
 * checked here as ShapeHandle's are and applied in the worker in order.
 */
export class WorkerShape {
  readonly body: WorkerBody;
  /** @internal */
  readonly id: number;
  userData: unknown;
  /** @internal the geometry, until setGeometry or a scale of the body replaces it */
  current: Geometry;
  /** @internal the batch that carries the last setGeometry (see WorkerWorld.queueSeq), or -1 */
  geometrySeq = -1;
  /** @internal */
  destroyed = false;
  readonly #settings: ShapeSettings;

  /** @internal */
  constructor(body: WorkerBody, id: number, geometry: Geometry, settings: ShapeSettings, userData: unknown) {
    this.body = body;
    this.id = id;
    this.current = geometry;
    this.#settings = settings;
    this.userData = userData;
  }

  /** @internal */
  check(): void {
    if (this.destroyed) throw new FulcrumError('shape has been destroyed');
  }

  get isValid(): boolean {
    return !this.destroyed;
  }

  /**
   * The shape's geometry in its body's frame (a concave shape's piece, a chain's segment): the one
   * `setGeometry` gave it at once; after `body.scale`, the worker's from the reply to the request that
   * carried the scale.
   */
  get geometry(): Geometry {
    return this.current;
  }

  get type(): Geometry['type'] {
    this.check();
    return this.current.type;
  }

  /** Tight world AABB at the body's pose after the last step (see ShapeHandle.getAABB). */
  getAABB(): AABB {
    this.check();
    const xf = this.body.readPose(makeTransform());
    const b = computeShapeBounds(this.current, xf, makeBounds(), new Float64Array(Pack.STRIDE));
    return { lowerBound: { x: b.minX, y: b.minY }, upperBound: { x: b.maxX, y: b.maxY } };
  }

  /** Whether the shape holds `point`, at the body's pose after the last step. */
  testPoint(point: Vec2): boolean {
    this.check();
    const p = checkCoordinates('point', point);
    return testPoint(this.current, this.body.readPose(makeTransform()), p.x, p.y);
  }

  /** Ray from `origin` along `translation` against the shape at the body's pose after the last step; null when it misses. */
  rayCast(origin: Vec2, translation: Vec2): RayCastResult | null {
    this.check();
    const o = checkCoordinates('origin', origin);
    const t = checkCoordinates('translation', translation);
    const hit = makeRayHit();
    if (!rayCastGeometry(this.current, this.body.readPose(makeTransform()), o.x, o.y, t.x, t.y, hit))
      return null;
    return {
      point: { x: hit.pointX, y: hit.pointY },
      normal: { x: hit.normalX, y: hit.normalY },
      fraction: hit.fraction,
    };
  }

  /**
   * Gives the shape another geometry (see ShapeHandle.setGeometry), checked here as World checks it;
   * `geometry` reads it at once, the body's mass data after the next step.
   */
  setGeometry(geometry: Geometry): void {
    this.check();
    checkGeometryFor(BODY_KINDS[this.body.kind], geometry);
    const world = this.body.world;
    world.queue(['shapeGeometry', this.id, geometry as unknown as Plain]);
    this.current = geometry;
    this.geometrySeq = world.queueSeq;
  }

  #set<K extends ShapeSetting>(setting: K, value: ShapeSettings[K]): void {
    this.body.world.queue(['shape', this.id, setting, value]);
    this.#settings[setting] = value;
  }

  get friction(): number {
    this.check();
    return this.#settings.friction;
  }

  set friction(value: number) {
    this.check();
    this.#set('friction', checkNonNegativeRate('friction', value));
  }

  get restitution(): number {
    this.check();
    return this.#settings.restitution;
  }

  set restitution(value: number) {
    this.check();
    this.#set('restitution', checkNonNegativeRate('restitution', value));
  }

  get density(): number {
    this.check();
    return this.#settings.density;
  }

  /** The body's mass data follows in the worker at once, and reads here after the next step. */
  set density(value: number) {
    this.check();
    this.#set('density', checkDensity('density', value));
  }

  get filter(): Filter {
    this.check();
    const f = this.#settings.filter;
    return { categoryBits: f.categoryBits, maskBits: f.maskBits, groupIndex: f.groupIndex };
  }

  /** As ShapeHandle's: what is not given takes its default, and the shape's contacts are found again. */
  set filter(value: Partial<Filter>) {
    this.check();
    this.#set('filter', this.body.world.checkFilter(value));
  }

  /** a sensor detects overlaps and never collides */
  get isSensor(): boolean {
    this.check();
    return this.#settings.isSensor;
  }

  set isSensor(value: boolean) {
    this.check();
    this.#set('isSensor', checkBoolean('isSensor', value));
  }

  get enableHitEvents(): boolean {
    this.check();
    return this.#settings.enableHitEvents;
  }

  set enableHitEvents(value: boolean) {
    this.check();
    this.#set('enableHitEvents', checkBoolean('enableHitEvents', value));
  }
}

/**
 * A joint of a WorkerWorld (a mouse joint's bodyA and bodyB are its one body, as on World). It has
 * the setters of every joint type; each is checked here as that type's joint checks it (on a joint of
 * the same type that the calling thread keeps for checking) and applied in the worker in order. A
 * setter that the joint's type does not have throws a FulcrumError.
 */
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
  /** the reads of the last step (see JointRead), or of when the joint was made; null until a reply has them */
  #reads: Float64Array | null = null;
  /** a distance joint's length or a revolute joint's motor speed, once a setter has given it */
  #setting: number | null = null;

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

  /** @internal takes the joint's row of a reply's `joints` (see JointRead) */
  adoptReads(rows: readonly number[], at: number): void {
    this.#reads ??= new Float64Array(JointRead.STRIDE);
    for (let i = 0; i < JointRead.STRIDE; i++) this.#reads[i] = rows[at + i];
  }

  /** A read of the last step; `name` names it in the error thrown before the worker has sent any. */
  #read(name: string, column: JointRead): number {
    this.check();
    if (this.#reads === null) {
      throw new FulcrumError(
        `${name}: the joint's reads come from the worker with the reply to the request that made it; await a step first`,
      );
    }
    return this.#reads[column];
  }

  /** Throws unless the joint is of one of `types`, as a call of a method its type lacks would. */
  #only(name: string, types: readonly JointType[]): void {
    if (!types.includes(this.type)) throw new FulcrumError(`${name}: a ${this.type} joint has no ${name}`);
  }

  /** Anchor on body A in world coordinates, after the last step (see Joint.anchorA). */
  get anchorA(): Vec2 {
    return { x: this.#read('anchorA', JointRead.AX), y: this.#read('anchorA', JointRead.AY) };
  }

  /** Anchor on body B in world coordinates, after the last step. */
  get anchorB(): Vec2 {
    return { x: this.#read('anchorB', JointRead.BX), y: this.#read('anchorB', JointRead.BY) };
  }

  /** Force (N) the joint applied to body B over the last substep of the last step. */
  getReactionForce(): Vec2 {
    return {
      x: this.#read('getReactionForce', JointRead.FX),
      y: this.#read('getReactionForce', JointRead.FY),
    };
  }

  /** Torque (N·m) the joint applied to body B over the last substep of the last step. */
  getReactionTorque(): number {
    return this.#read('getReactionTorque', JointRead.TORQUE);
  }

  /** revolute: the angle of B relative to A minus the reference angle, after the last step */
  get angle(): number {
    this.#only('angle', ['revolute']);
    return this.#read('angle', JointRead.MEASURE);
  }

  /** prismatic, wheel: the translation of B's anchor along the axis from A's, after the last step */
  get translation(): number {
    this.#only('translation', ['prismatic', 'wheel']);
    return this.#read('translation', JointRead.MEASURE);
  }

  /** distance: the distance between the anchors after the last step */
  get currentLength(): number {
    this.#only('currentLength', ['distance']);
    return this.#read('currentLength', JointRead.MEASURE);
  }

  /** distance: the rest length, as the commands given so far leave it */
  get length(): number {
    this.#only('length', ['distance']);
    this.check();
    return this.#setting ?? this.#read('length', JointRead.SETTING);
  }

  /** revolute: the motor speed, as the commands given so far leave it */
  get motorSpeed(): number {
    this.#only('motorSpeed', ['revolute']);
    this.check();
    return this.#setting ?? this.#read('motorSpeed', JointRead.SETTING);
  }

  /** Checks a call of `method` as the joint of this type checks it, and queues it. */
  #call(method: JointCommand, args: unknown[]): void {
    this.world.checkJointCall(this.type, this.destroyed, method, args);
    // the arguments as checked: numbers, booleans and points (read as the check read them)
    const sent = args.map((a) =>
      typeof a === 'object' && a !== null ? { x: (a as Vec2).x, y: (a as Vec2).y } : a,
    );
    this.world.queue(['joint', this.id, method, sent]);
  }

  /** Moves a mouse joint's target and wakes its body, at the next step (see MouseJoint.setTarget). */
  setTarget(target: Vec2): void {
    this.#call('setTarget', [target]);
    this.#target = { x: target.x, y: target.y };
  }

  /** revolute, prismatic, wheel */
  enableMotor(enable: boolean): void {
    this.#call('enableMotor', [enable]);
  }

  /** revolute, prismatic, wheel: rad/s, or m/s for a prismatic joint */
  setMotorSpeed(speed: number): void {
    this.#call('setMotorSpeed', [speed]);
    if (this.type === 'revolute') this.#setting = speed;
  }

  /** revolute, wheel */
  setMaxMotorTorque(torque: number): void {
    this.#call('setMaxMotorTorque', [torque]);
  }

  /** prismatic */
  setMaxMotorForce(force: number): void {
    this.#call('setMaxMotorForce', [force]);
  }

  /** revolute, prismatic, wheel */
  enableLimit(enable: boolean): void {
    this.#call('enableLimit', [enable]);
  }

  /** revolute (angles), prismatic and wheel (translations) */
  setLimits(lower: number, upper: number): void {
    this.#call('setLimits', [lower, upper]);
  }

  /** distance, revolute, prismatic, wheel */
  enableSpring(enable: boolean): void {
    this.#call('enableSpring', [enable]);
  }

  /** distance, revolute, prismatic, wheel */
  setSpring(hertz: number, dampingRatio: number): void {
    this.#call('setSpring', [hertz, dampingRatio]);
  }

  /** distance */
  setLength(length: number): void {
    this.#call('setLength', [length]);
    this.#setting = length;
  }

  /** distance */
  setLengthRange(minLength: number, maxLength: number): void {
    this.#call('setLengthRange', [minLength, maxLength]);
  }

  /** weld: 0 makes that part rigid */
  setStiffness(linearHertz: number, angularHertz: number, dampingRatio: number): void {
    this.#call('setStiffness', [linearHertz, angularHertz, dampingRatio]);
  }

  /** motor: the wanted position of B's centre in A's frame */
  setLinearOffset(offset: Vec2): void {
    this.#call('setLinearOffset', [offset]);
  }

  /** motor */
  setAngularOffset(angle: number): void {
    this.#call('setAngularOffset', [angle]);
  }

  /** motor */
  setMaxForce(force: number): void {
    this.#call('setMaxForce', [force]);
  }

  /** motor */
  setMaxTorque(torque: number): void {
    this.#call('setMaxTorque', [torque]);
  }

  /** @internal */
  check(): void {
    if (this.destroyed) throw new FulcrumError('joint has been destroyed');
  }

  get isValid(): boolean {
    return !this.destroyed;
  }
}
