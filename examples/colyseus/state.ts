/**
 * What a physics room shows its clients, as Colyseus schema: Colyseus sends only what changed since
 * the last patch. A body's shapes are written once, when it joins the room; its pose each step.
 */
import { type SchemaType, schema, t } from '@colyseus/schema';

/** One shape in its body's frame: a circle's centre, a capsule's or segment's two centres, a polygon's vertices. */
export const ShapeView = schema({
  kind: t.string(),
  radius: t.float32(),
  points: t.array('float32'),
});
export type ShapeView = SchemaType<typeof ShapeView>;

/** A body's pose (its origin and angle, float32 on the wire) and shapes. */
export const BodyView = schema({
  x: t.float32(),
  y: t.float32(),
  angle: t.float32(),
  isStatic: t.boolean(),
  shapes: t.array(ShapeView),
});
export type BodyView = SchemaType<typeof BodyView>;

/** The room: its bodies in command order (the scene's, then the spawned ones), the steps taken, the last step's time. */
export const PhysicsState = schema({
  step: t.uint32(),
  stepMs: t.float32(),
  bodies: t.array(BodyView),
});
export type PhysicsState = SchemaType<typeof PhysicsState>;
