import { buildFulcrumWorld } from '../../scenes/build-fulcrum';
import { softBlobs } from '../../scenes/index';
import type { Body } from '../../src/index';
import type { Demo } from '../demo';
import { drawnPosition } from '../lib';

const COUNT = 4;
const SEGMENTS = 20;
const palette = ['#8fcf7a', '#e3cf6a', '#c792ea', '#f08a6c'];

export const softBodyDemo: Demo = {
  id: 'soft-body',
  title: 'Soft bodies',
  description:
    'Each blob is a ring of 20 circles on springs to a centre disc and to each other (soft distance joints, scenes/soft-bodies.ts): it squashes when it lands and wobbles back into shape. Drag one by its rim or its centre.',
  view: { center: { x: 0, y: 5 }, halfHeight: 6.5 },
  flags: { joints: false },
  create: (ctx) => {
    const scene = softBlobs({ count: COUNT, segments: SEGMENTS });
    const { world, bodies } = buildFulcrumWorld(scene);
    // a blob is its centre followed by its rim, in the scene's order
    const blobs: { centre: Body; rim: Body[] }[] = [];
    bodies.forEach((body, i) => {
      const tag = scene.bodies[i].tag;
      if (tag === 'blob-centre') blobs.push({ centre: body, rim: [] });
      else if (tag === 'blob-rim') blobs[blobs.length - 1].rim.push(body);
    });
    blobs.forEach((blob, i) => {
      for (const body of [blob.centre, ...blob.rim]) ctx.render.setBodyStyle(body, { color: palette[i % 4] });
    });
    ctx.track(
      ctx.render.on('afterDraw', ({ context, pixel }) => {
        // fill each blob's skin through its rim, and draw its spokes faintly
        blobs.forEach((blob, i) => {
          const rim = blob.rim.map((b) => drawnPosition(ctx.runner, b));
          const c = drawnPosition(ctx.runner, blob.centre);
          context.globalAlpha = 0.3;
          context.fillStyle = palette[i % 4];
          context.beginPath();
          for (const [k, p] of rim.entries()) {
            if (k === 0) context.moveTo(p.x, p.y);
            else context.lineTo(p.x, p.y);
          }
          context.closePath();
          context.fill();
          context.globalAlpha = 0.25;
          context.strokeStyle = palette[i % 4];
          context.lineWidth = pixel;
          context.beginPath();
          for (const p of rim) {
            context.moveTo(c.x, c.y);
            context.lineTo(p.x, p.y);
          }
          context.stroke();
          context.globalAlpha = 1;
        });
      }),
    );
    return { world, blobs };
  },
};
