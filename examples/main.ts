/**
 * The gallery shell: the landing view of cards (no demo in the URL's hash), or a demo with the list,
 * the controls, the readout and its code.
 */
import {
  type AnyWorld,
  type DebugDrawFlags,
  defaultDebugDrawFlags,
  isWorkerWorld,
  Pointer,
  Render,
  Runner,
} from '../src/render/index';
import { CodePanel } from './code-panel';
import type { Demo, DemoContext, DemoInstance } from './demo';
import { Landing } from './landing';
import { demos, findDemo } from './registry';

function $(id: string): HTMLElement {
  const el = document.getElementById(id);
  if (!el) throw new Error(`gallery: #${id} is missing`);
  return el;
}

const canvas = $('view') as HTMLCanvasElement;
const stage = $('stage');
const ui = $('demo-ui');
const render = new Render<AnyWorld>({ canvas });
const runner = new Runner<AnyWorld>({ render });
const pointer = new Pointer<AnyWorld>({ render });

const flagLabels: [keyof DebugDrawFlags, string][] = [
  ['shapes', 'shapes'],
  ['wireframe', 'wireframe'],
  ['joints', 'joints'],
  ['aabbs', 'AABBs'],
  ['contacts', 'contact points'],
  ['contactNormals', 'contact normals'],
  ['velocities', 'velocities'],
  ['centersOfMass', 'centres of mass'],
  ['sleeping', 'sleep tint'],
];
const flagInputs = new Map<keyof DebugDrawFlags, HTMLInputElement>();
for (const [key, label] of flagLabels) {
  const wrap = document.createElement('label');
  const input = document.createElement('input');
  input.type = 'checkbox';
  input.id = `flag-${key}`;
  input.addEventListener('change', () => {
    render.flags[key] = input.checked;
    if (runner.paused) render.draw(runner.interpolator);
  });
  wrap.append(input, ` ${label}`);
  $('flags').append(wrap);
  flagInputs.set(key, input);
}

const list = $('demo-list');
for (const demo of demos) {
  const a = document.createElement('a');
  a.href = `#${demo.id}`;
  a.textContent = demo.title;
  a.dataset.demo = demo.id;
  list.append(a);
}

const landing = new Landing($('cards'), demos);
const codePanel = new CodePanel($('code-panel'), $('btn-code') as HTMLButtonElement);

let current: Demo | null = null;
let instance: DemoInstance | null = null;
const cleanups: (() => void)[] = [];
/** demos started so far: a demo whose world runs in a worker starts once its worker runs */
let started = 0;
/** tells a demo still being made (a worker world's) that it has been left meanwhile */
let starting = 0;

function stopDemo(): void {
  starting++;
  for (const cleanup of cleanups.splice(0).reverse()) {
    try {
      cleanup();
    } catch (error) {
      console.error(error);
    }
  }
  // before dispose: a worker world ended by it takes no more commands
  pointer.endDrag();
  instance?.dispose?.();
  instance = null;
  runner.setWorld(null);
  ui.replaceChildren();
  $('demo-status').textContent = '';
  // undo what a demo may have changed
  canvas.style.display = '';
  runner.render = render;
  pointer.enabled = true;
  pointer.filter = (body) => body.type === 'dynamic';
}

/**
 * The demo's zoom for the canvas as it is: zoomed out from its view where the canvas is too narrow to
 * show its fitWidth (a phone held upright). Called whenever the canvas changes size, which is also
 * when it is first laid out.
 */
function fitDemoWidth(demo: Demo): void {
  if (demo.fitWidth === undefined) return;
  render.resize();
  const camera = render.camera;
  const view = demo.view;
  const halfHeight = Math.max(view.halfHeight, (demo.fitWidth * camera.height) / camera.width);
  const lift = demo.fitAnchor === 'center' ? 0 : halfHeight - view.halfHeight;
  camera.setView({ center: { x: view.center.x, y: view.center.y + lift }, halfHeight });
}

new ResizeObserver(() => {
  if (current !== null) fitDemoWidth(current);
}).observe(canvas);

function startDemo(demo: Demo): void {
  stopDemo();
  current = demo;
  render.flags = { ...defaultDebugDrawFlags, ...demo.flags };
  for (const [key, input] of flagInputs) input.checked = render.flags[key];
  $('flags').style.display = demo.drawSwitches === false ? 'none' : '';
  render.resize();
  render.camera.setView(demo.view);
  fitDemoWidth(demo);
  runner.maxStepsPerFrame = demo.maxStepsPerFrame ?? 4;
  const ctx: DemoContext = {
    render,
    runner,
    pointer,
    stage,
    ui,
    preview: false,
    track: (cleanup) => cleanups.push(cleanup),
    setStatus: (text) => {
      $('demo-status').textContent = text;
    },
    button: (label, onClick) => {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = label;
      b.addEventListener('click', onClick);
      ui.append(b);
      return b;
    },
    useExternalRenderer: () => {
      canvas.style.display = 'none';
      runner.render = null;
    },
  };
  $('demo-title').textContent = demo.title;
  $('demo-description').textContent = demo.description;
  document.title = `${demo.title} — Fulcrum`;
  markActive(demo.id);
  codePanel.setDemo(demo);
  const made = demo.create(ctx);
  if (!(made instanceof Promise)) {
    show(made);
    return;
  }
  const ticket = starting;
  made.then(
    (ready) => {
      if (ticket === starting) show(ready);
      else ready.dispose?.();
    },
    (error: unknown) => {
      if (ticket === starting) ctx.setStatus(`could not start: ${String(error)}`);
      console.error(error);
    },
  );
}

function show(made: DemoInstance): void {
  instance = made;
  runner.setWorld(made.world);
  render.world = made.world;
  started++;
  exposeState();
}

function markActive(id: string | null): void {
  list.querySelectorAll('a').forEach((a) => {
    a.classList.toggle('active', a.dataset.demo === id || (id === null && a.id === 'home-link'));
  });
}

function exposeState(): void {
  // for the end-to-end tests and the curious: window.gallery in the browser console
  (window as unknown as { gallery: unknown }).gallery = {
    view: current ? 'demo' : 'landing',
    landing,
    runner,
    render,
    pointer,
    demo: current?.id,
    instance,
    world: instance?.world,
    started,
  };
}

/** The landing view: the demo that ran is let go, the cards' thumbnails start. */
function showLanding(): void {
  stopDemo();
  runner.stop();
  current = null;
  codePanel.setDemo(null);
  document.body.classList.add('landing');
  document.title = 'Fulcrum — demo gallery';
  markActive(null);
  landing.show();
  exposeState();
}

/** Opens the demo the URL's hash names (#pyramid), or the landing view when it names none (no hash, #gallery). */
function route(): void {
  const id = decodeURIComponent(location.hash.replace(/^#\/?/, ''));
  const demo = findDemo(id);
  if (!demo) {
    showLanding();
    return;
  }
  // the thumbnails' worlds go before the demo's is made
  landing.hide();
  document.body.classList.remove('landing');
  startDemo(demo);
  runner.start();
}

window.addEventListener('hashchange', route);

const pauseButton = $('btn-pause');
function setPaused(paused: boolean): void {
  runner.paused = paused;
  pauseButton.textContent = paused ? 'Play' : 'Pause';
}
pauseButton.addEventListener('click', () => setPaused(!runner.paused));
$('btn-step').addEventListener('click', () => {
  setPaused(true);
  runner.step();
});
$('btn-reset').addEventListener('click', () => {
  if (current) startDemo(current);
});
const speed = $('speed') as HTMLSelectElement;
speed.addEventListener('change', () => {
  runner.timeScale = Number(speed.value);
});
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
  // the controls' keys act on a demo; the landing view leaves them to the page (space scrolls)
  if (!current) return;
  if (e.key === ' ') {
    e.preventDefault();
    setPaused(!runner.paused);
  } else if (e.key === 's') {
    setPaused(true);
    runner.step();
  } else if (e.key === 'r' && current) {
    startDemo(current);
  }
});

// the readout: a few times a second is plenty
const stats = {
  bodies: $('stat-bodies'),
  awake: $('stat-awake'),
  contacts: $('stat-contacts'),
  step: $('stat-step'),
  fps: $('stat-fps'),
};
setInterval(() => {
  const world = runner.world;
  if (!world) return;
  stats.bodies.textContent = String(world.bodyCount);
  // counted in the worker, for a worker world: not on this thread
  stats.awake.textContent = isWorkerWorld(world) ? '–' : String(world.awakeBodyCount);
  stats.contacts.textContent = isWorkerWorld(world) ? '–' : String(world.contactCount);
  stats.step.textContent = runner.stepMs.toFixed(2);
  stats.fps.textContent = runner.fps.toFixed(0);
}, 250);

route();
