/**
 * The part of matter-js 0.20 the benchmark adapter uses (the package ships no type declarations).
 * matter-js is a UMD bundle, so Node's ESM import sees only its default export.
 */
declare module 'matter-js' {
  interface Vector {
    x: number;
    y: number;
  }
  interface BodyOptions {
    isStatic?: boolean;
    density?: number;
    friction?: number;
    frictionAir?: number;
    restitution?: number;
    angle?: number;
    chamfer?: { radius: number };
    collisionFilter?: { group?: number; category?: number; mask?: number };
    parts?: MatterBody[];
    position?: Vector;
    vertices?: Vector[];
  }
  interface MatterBody {
    position: Vector;
    angle: number;
    mass: number;
    parts: MatterBody[];
    collisionFilter: { group: number; category: number; mask: number };
  }
  interface MatterConstraint {
    length: number;
  }
  interface MatterEngine {
    world: object;
    gravity: { x: number; y: number; scale: number };
    positionIterations: number;
    velocityIterations: number;
    constraintIterations: number;
    enableSleeping: boolean;
  }
  const Engine: {
    create(options?: {
      enableSleeping?: boolean;
      gravity?: { x: number; y: number; scale: number };
    }): MatterEngine;
    update(engine: MatterEngine, delta: number): void;
    clear(engine: MatterEngine): void;
  };
  const Composite: { add(composite: object, objects: Array<MatterBody | MatterConstraint>): void };
  const Bodies: {
    rectangle(x: number, y: number, width: number, height: number, options?: BodyOptions): MatterBody;
    circle(x: number, y: number, radius: number, options?: BodyOptions): MatterBody;
  };
  const Body: {
    create(options: BodyOptions): MatterBody;
    setStatic(body: MatterBody, isStatic: boolean): void;
    setPosition(body: MatterBody, position: Vector, updateVelocity?: boolean): void;
    setAngle(body: MatterBody, angle: number, updateVelocity?: boolean): void;
    setVelocity(body: MatterBody, velocity: Vector): void;
    setAngularVelocity(body: MatterBody, velocity: number): void;
  };
  const Constraint: {
    create(options: {
      bodyA?: MatterBody;
      bodyB?: MatterBody;
      pointA: Vector;
      pointB: Vector;
      length: number;
      stiffness: number;
      damping: number;
    }): MatterConstraint;
  };
  const Matter: {
    Bodies: typeof Bodies;
    Body: typeof Body;
    Composite: typeof Composite;
    Constraint: typeof Constraint;
    Engine: typeof Engine;
  };
  export default Matter;
  export type { MatterBody, MatterEngine, Vector };
}
