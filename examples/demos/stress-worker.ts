import solverUrl from '../../src/parallel/solver-worker.ts?worker&url';
import { WorkerWorld } from '../../src/worker/index';
import workerUrl from '../../src/worker/worker-entry.ts?worker&url';
import type { Demo } from '../demo';
import { buildStressScene, COUNT, stressDemo } from './stress';

/**
 * Threads that solve the world's contacts in the worker (`workers`): two where the page is isolated
 * and the machine has four cores or more, where the page, the world's worker and a solver worker each
 * have a core; `?threads=n` asks for n.
 */
function solverThreads(): number {
  const asked = Number(new URLSearchParams(location.search).get('threads'));
  if (Number.isInteger(asked) && asked >= 1 && asked <= 8) return asked;
  return globalThis.crossOriginIsolated === true && navigator.hardwareConcurrency >= 4 ? 2 : 1;
}

/** How often the readout changes, ms: the figures are averages, and text that flickers is unreadable. */
const READOUT_MS = 250;

/**
 * The 5,000-body scene of the stress demo, stepped in a Web Worker by fulcrum/worker. The page's
 * Runner sends each fixed step to the worker and draws every frame at once from the last state the
 * worker published (a SharedArrayBuffer, the gallery being cross-origin isolated), blended between
 * its last two steps: the page draws at the display's rate whatever the step costs.
 */
export const stressWorkerDemo: Demo = {
  id: 'stress-worker',
  title: '5,000 bodies in a worker',
  description:
    "The 5,000-body scene stepped in a Web Worker (fulcrum/worker): the page only draws, at the display's rate, the latest state the worker published, while physics runs at its own pace. Compare the page's frame time with the worker's step time; drag a body with the mouse (a mouse joint moved by commands).",
  view: stressDemo.view,
  maxStepsPerFrame: 2,
  create: async (ctx) => {
    const world = await WorkerWorld.create({
      workers: solverThreads(),
      // the world in the worker starts its solver workers: an address that does not depend on where it runs
      workerUrl: new URL(solverUrl, location.href).href,
      worker: { url: workerUrl },
    });
    buildStressScene(world);
    // the e2e tests and the curious: frames drawn, the last step drawn (see waitForDrawnStep), timings
    const state = {
      frames: 0,
      drawnStep: -1,
      /** frames drawn while steps were still out in the worker: the page did not wait for them */
      framesWithStepsOut: 0,
      /** ms the page's last frame took to send its steps and draw (its work, not the time between frames) */
      frameMs: 0,
      bufferMode: world.bufferMode,
      crossOriginIsolated: globalThis.crossOriginIsolated === true,
    };
    let frameStart = 0;
    let frameMsSum = 0;
    let frameMsCount = 0;
    ctx.track(
      ctx.runner.on('beforeFrame', () => {
        frameStart = performance.now();
      }),
    );
    ctx.track(
      ctx.runner.on('afterFrame', ({ runner }) => {
        state.frameMs = performance.now() - frameStart;
        frameMsSum += state.frameMs;
        frameMsCount++;
        state.frames++;
        if (runner.stepsInFlight > 0) state.framesWithStepsOut++;
        // the frame drew the runner's latest step only when none was still out
        state.drawnStep = runner.stepsInFlight === 0 ? runner.stepCount : -1;
      }),
    );
    const readout = document.createElement('div');
    readout.className = 'timings';
    readout.dataset.role = 'timings';
    ctx.ui.append(readout);
    const timer = setInterval(() => {
      const frame = frameMsCount > 0 ? frameMsSum / frameMsCount : 0;
      frameMsSum = 0;
      frameMsCount = 0;
      const threads = world.workers === 1 ? '' : ` on ${world.workers} threads`;
      readout.textContent = `page frame ${frame.toFixed(2)} ms (${ctx.runner.fps.toFixed(0)} fps) · worker step ${ctx.runner.stepMs.toFixed(2)} ms${threads} · ${ctx.runner.stepCount} steps`;
    }, READOUT_MS);
    ctx.track(() => clearInterval(timer));
    ctx.setStatus(`${COUNT.toLocaleString('en')} dynamic bodies in a worker, ${world.bufferMode} buffers`);
    return { world, state, dispose: () => world.terminate() };
  },
};
