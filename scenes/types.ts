/**
 * Engine-neutral scene descriptions, shared by tests, examples and benchmarks.
 * Units: metres, kilograms, seconds, radians; y up. A scene is plain data, so the benchmark
 * adapters can build the same scene in every engine.
 */
export interface V {
  x: number;
  y: number;
}

export interface ShapeMaterial {
  density?: number; // kg/m^2, default 1
  friction?: number; // default 0.6
  restitution?: number; // default 0
  /**
   * Collision filter, Box2D's: two shapes collide when each one's category has a bit in the other's
   * mask. Default: category 1, mask all bits.
   */
  filter?: { categoryBits: number; maskBits: number };
}

export type SceneShape = ShapeMaterial &
  (
    | { kind: 'circle'; radius: number; center?: V }
    | { kind: 'box'; halfWidth: number; halfHeight: number; center?: V; angle?: number }
    | { kind: 'polygon'; points: V[]; radius?: number }
    | { kind: 'capsule'; p1: V; p2: V; radius: number }
    | { kind: 'segment'; p1: V; p2: V }
  );

export interface SceneBody {
  type: 'static' | 'kinematic' | 'dynamic';
  position: V;
  angle?: number;
  linearVelocity?: V;
  angularVelocity?: number;
  bullet?: boolean;
  shapes: SceneShape[];
  /** free-form tag a scene uses to find bodies again (e.g. 'ball', 'link') */
  tag?: string;
}

/** Joints refer to bodies by their index in `bodies`. Anchors are world points. */
export type SceneJoint =
  | {
      type: 'revolute';
      bodyA: number;
      bodyB: number;
      anchor: V;
      collideConnected?: boolean;
      /** angle limits relative to the starting pose, radians */
      limit?: { lower: number; upper: number };
    }
  | {
      type: 'distance';
      bodyA: number;
      bodyB: number;
      anchorA: V;
      anchorB: V;
      length?: number;
      collideConnected?: boolean;
      /** a damped spring instead of a rigid rod */
      spring?: { hertz: number; dampingRatio: number };
    }
  | {
      type: 'wheel';
      bodyA: number;
      bodyB: number;
      anchor: V;
      axis: V;
      spring: { hertz: number; dampingRatio: number };
      motor?: { speed: number; maxTorque: number };
    };

export interface Scene {
  name: string;
  gravity: V;
  bodies: SceneBody[];
  joints: SceneJoint[];
  /** suggested camera for viewers: centre and half-height of the view, metres */
  view?: { center: V; halfHeight: number };
  /** dynamic bodies whose origin leaves this box count as escaped (container and tumbler scenes) */
  containment?: { lower: V; upper: V };
}
