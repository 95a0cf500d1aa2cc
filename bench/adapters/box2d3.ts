/**
 * Box2D v3 compiled to WebAssembly (box2d3-wasm). The package ships two Emscripten builds in
 * build/dist/es/: `compat` (plain WASM) and `deluxe` (WASM SIMD, built with pthreads). Its entry point
 * picks one by feature detection, so each build is imported here by file path to measure both.
 * Both run single-threaded: worlds are made with b2CreateWorld and the default workerCount 0.
 *
 * Settings: b2DefaultWorldDef() (contact hertz 30, damping ratio 10, restitution threshold 1 m/s,
 * continuous on), b2World_Step with 4 substeps (the count Box2D v3 recommends), enableSleep false.
 * Units: metres, kilograms, seconds, radians, y up, like the scenes: nothing to map.
 * Mixing (Box2D's own): friction sqrt(a * b), restitution max(a, b).
 * Collision filters: the scene's category and mask bits as the shape def's filter.
 */

import type {
  b2BodyId,
  b2ShapeDef,
  b2WorldId,
  MainModule,
} from '../../node_modules/box2d3-wasm/build/dist/es/compat/Box2D.compat';
import type { Scene, SceneShape, V } from '../../scenes/types';
import { type EngineAdapter, unsupportedJoint } from '../adapter';

export type Box2dFlavour = 'compat' | 'deluxe';

const SUBSTEPS = 4;
const distDir = new URL('../../node_modules/box2d3-wasm/build/dist/es/', import.meta.url);

export class Box2dAdapter implements EngineAdapter {
  readonly settings: string;
  private b2!: MainModule;
  private world: b2WorldId | null = null;
  private bodies: b2BodyId[] = [];

  constructor(private readonly flavour: Box2dFlavour) {
    this.settings = `${flavour} build, single thread, b2DefaultWorldDef, ${SUBSTEPS} substeps, enableSleep false`;
  }

  async init(): Promise<void> {
    const url = new URL(`${this.flavour}/Box2D.${this.flavour}.mjs`, distDir);
    const factory = (await import(url.href)).default as () => Promise<MainModule>;
    this.b2 = await factory();
  }

  private vec(v: V) {
    return new this.b2.b2Vec2(v.x, v.y);
  }

  build(scene: Scene): void {
    this.dispose();
    const b2 = this.b2;
    const worldDef = b2.b2DefaultWorldDef();
    worldDef.gravity = this.vec(scene.gravity);
    worldDef.enableSleep = false;
    const world = b2.b2CreateWorld(worldDef);
    this.world = world;
    const types = {
      static: b2.b2BodyType.b2_staticBody,
      kinematic: b2.b2BodyType.b2_kinematicBody,
      dynamic: b2.b2BodyType.b2_dynamicBody,
    };
    this.bodies = scene.bodies.map((b) => {
      const def = b2.b2DefaultBodyDef();
      def.type = types[b.type];
      def.position = this.vec(b.position);
      def.rotation = b2.b2MakeRot(b.angle ?? 0);
      def.linearVelocity = this.vec(b.linearVelocity ?? { x: 0, y: 0 });
      def.angularVelocity = b.angularVelocity ?? 0;
      def.isBullet = b.bullet ?? false;
      def.enableSleep = false;
      const id = b2.b2CreateBody(world, def);
      for (const shape of b.shapes) this.createShape(id, shape);
      return id;
    });
    for (const j of scene.joints) {
      if (j.type !== 'revolute') unsupportedJoint('box2d3', j.type);
      const def = b2.b2DefaultRevoluteJointDef();
      const base = def.base;
      base.bodyIdA = this.bodies[j.bodyA];
      base.bodyIdB = this.bodies[j.bodyB];
      base.localFrameA = this.frame(this.bodies[j.bodyA], j.anchor);
      base.localFrameB = this.frame(this.bodies[j.bodyB], j.anchor);
      base.collideConnected = j.collideConnected ?? false;
      def.base = base;
      b2.b2CreateRevoluteJoint(world, def);
    }
  }

  /** a joint frame at world point `anchor`, in the body's frame */
  private frame(body: b2BodyId, anchor: V) {
    const frame = new this.b2.b2Transform();
    frame.p = this.b2.b2Body_GetLocalPoint(body, this.vec(anchor));
    frame.q = this.b2.b2Rot_identity;
    return frame;
  }

  private shapeDef(shape: SceneShape): b2ShapeDef {
    const def = this.b2.b2DefaultShapeDef();
    def.density = shape.density ?? 1;
    const material = def.material;
    material.friction = shape.friction ?? 0.6;
    material.restitution = shape.restitution ?? 0;
    def.material = material;
    if (shape.filter) {
      const filter = def.filter;
      filter.categoryBits = shape.filter.categoryBits;
      filter.maskBits = shape.filter.maskBits;
      def.filter = filter;
    }
    return def;
  }

  private createShape(body: b2BodyId, shape: SceneShape): void {
    const b2 = this.b2;
    const def = this.shapeDef(shape);
    switch (shape.kind) {
      case 'circle': {
        const circle = new b2.b2Circle();
        circle.center = this.vec(shape.center ?? { x: 0, y: 0 });
        circle.radius = shape.radius;
        b2.b2CreateCircleShape(body, def, circle);
        return;
      }
      case 'box': {
        const center = this.vec(shape.center ?? { x: 0, y: 0 });
        const box = b2.b2MakeOffsetBox(
          shape.halfWidth,
          shape.halfHeight,
          center,
          b2.b2MakeRot(shape.angle ?? 0),
        );
        b2.b2CreatePolygonShape(body, def, box);
        return;
      }
      case 'polygon': {
        const hull = b2.b2ComputeHull(shape.points.map((p) => this.vec(p)));
        b2.b2CreatePolygonShape(body, def, b2.b2MakePolygon(hull, shape.radius ?? 0));
        return;
      }
      case 'capsule': {
        const capsule = new b2.b2Capsule();
        capsule.center1 = this.vec(shape.p1);
        capsule.center2 = this.vec(shape.p2);
        capsule.radius = shape.radius;
        b2.b2CreateCapsuleShape(body, def, capsule);
        return;
      }
      case 'segment': {
        const segment = new b2.b2Segment();
        segment.point1 = this.vec(shape.p1);
        segment.point2 = this.vec(shape.p2);
        b2.b2CreateSegmentShape(body, def, segment);
        return;
      }
    }
  }

  step(dt: number): void {
    this.b2.b2World_Step(this.world!, dt, SUBSTEPS);
  }

  readTransforms(out: Float64Array): void {
    for (let i = 0; i < this.bodies.length; i++) {
      const p = this.b2.b2Body_GetPosition(this.bodies[i]);
      const q = this.b2.b2Body_GetRotation(this.bodies[i]);
      out[3 * i] = p.x;
      out[3 * i + 1] = p.y;
      out[3 * i + 2] = Math.atan2(q.s, q.c);
      p.delete();
      q.delete();
    }
  }

  dispose(): void {
    if (this.world) this.b2.b2DestroyWorld(this.world);
    this.world = null;
    this.bodies = [];
  }
}
