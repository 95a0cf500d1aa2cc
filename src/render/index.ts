/**
 * `fulcrum/render`: draw a world on a canvas, run it in the browser, drag bodies with the pointer.
 * @module fulcrum/render
 */

export { Emitter } from '../core/emitter';
export { Camera, type CameraView } from './camera';
export { CanvasDebugDraw, type Sprite } from './canvas-draw';
export { cssColor, toCss } from './color';
export {
  type Color,
  colors,
  type DebugDraw,
  type DebugDrawFlags,
  type DrawWorldOptions,
  defaultBodyColor,
  defaultDebugDrawFlags,
  drawWorld,
  dynamicPalette,
  mixColor,
  type ShapeStyle,
  scaleColor,
} from './debug-draw';
export type {
  AnyBody,
  AnyShape,
  AnyWorld,
  BodyRecord,
  ContactPointRecord,
  DrawSource,
  JointRecord,
  MotionRecord,
  ShapeRecord,
} from './draw-source';
export { Interpolator } from './interpolation';
export {
  type BodyOf,
  type DragEvent,
  Pointer,
  type PointerEventInfo,
  type PointerEvents,
  type PointerOptions,
} from './pointer';
export {
  type BodyStyle,
  clientToCanvas,
  type DrawEvent,
  Render,
  type RenderEvents,
  type RenderOptions,
} from './render';
export { type FrameEvent, Runner, type RunnerEvents, type RunnerOptions, type StepEvent } from './runner';
export { drawSourceOf, isWorkerWorld } from './source-of';
