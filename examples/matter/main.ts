/**
 * The matter.js page of the gallery: one matter.js program at a time, run on Fulcrum through
 * `fulcrum/matter`, and on request on matter.js itself beside it, the same code given each `Matter`.
 */
import RealMatter from 'matter-js';
import FulcrumMatter from '../../src/matter/index';
import { programs } from './programs/index';
import type { MatterNamespace, MatterProgram, RunningProgram } from './programs/program';

/** every program is written for a world of 800 by 600 px; the canvas is scaled to its pane by CSS */
const WIDTH = 800;
const HEIGHT = 600;

type PaneName = 'fulcrum' | 'matter';

interface Pane {
  Matter: MatterNamespace;
  figure: HTMLElement;
  view: HTMLElement;
  running: RunningProgram | null;
}

function element<T extends HTMLElement>(id: string): T {
  const found = document.getElementById(id);
  if (!found) throw new Error(`matter.html has no #${id}`);
  return found as T;
}

function paneOf(Matter: MatterNamespace, id: string): Pane {
  const figure = element(id);
  return { Matter, figure, view: figure.querySelector('.view') as HTMLElement, running: null };
}

const panes: Record<PaneName, Pane> = {
  fulcrum: paneOf(FulcrumMatter as unknown as MatterNamespace, 'pane-fulcrum'),
  matter: paneOf(RealMatter as unknown as MatterNamespace, 'pane-matter'),
};

const list = element('program-list');
const title = element('program-title');
const description = element('program-description');
const pauseButton = element<HTMLButtonElement>('btn-pause');
const compareBox = element<HTMLInputElement>('compare');

let program: MatterProgram = programs[0];
let paused = false;
let comparing = new URLSearchParams(location.search).has('compare');

for (const p of programs) {
  const link = document.createElement('a');
  link.href = `#${p.id}`;
  link.textContent = p.title;
  link.dataset.program = p.id;
  list.append(link);
}

/** Stops a pane's program and lets go of it: its frames, its events, its world, its canvas. */
function stop(pane: Pane): void {
  const running = pane.running;
  if (!running) return;
  const { Render, Runner, Engine, Events, Composite } = pane.Matter;
  Render.stop(running.render);
  Runner.stop(running.runner);
  Events.off(running.engine);
  Events.off(running.render);
  Events.off(running.runner);
  if (running.mouseConstraint) Events.off(running.mouseConstraint);
  Composite.clear(running.engine.world, false);
  Engine.clear(running.engine);
  running.render.canvas.remove();
  pane.running = null;
}

function start(pane: Pane): void {
  stop(pane);
  pane.running = program.run(pane.Matter, { element: pane.view, width: WIDTH, height: HEIGHT });
  if (paused) pane.Matter.Runner.stop(pane.running.runner);
}

function activePanes(): Pane[] {
  return comparing ? [panes.fulcrum, panes.matter] : [panes.fulcrum];
}

/** Runs the current program from its start in every pane shown. */
function restart(): void {
  panes.matter.figure.hidden = !comparing;
  element('panes').classList.toggle('comparing', comparing);
  if (!comparing) stop(panes.matter);
  for (const pane of activePanes()) start(pane);
}

function open(id: string): void {
  program = programs.find((p) => p.id === id) ?? programs[0];
  title.textContent = program.title;
  description.textContent = program.description;
  document.title = `${program.title} — matter.js programs on Fulcrum`;
  for (const link of Array.from(list.querySelectorAll<HTMLAnchorElement>('a'))) {
    link.classList.toggle('active', link.dataset.program === program.id);
  }
  restart();
}

function setPaused(value: boolean): void {
  paused = value;
  pauseButton.textContent = paused ? 'Play' : 'Pause';
  for (const pane of activePanes()) {
    const running = pane.running;
    if (!running) continue;
    if (paused) pane.Matter.Runner.stop(running.runner);
    else pane.Matter.Runner.run(running.runner, running.engine);
  }
}

function setComparing(value: boolean): void {
  comparing = value;
  compareBox.checked = value;
  const url = new URL(location.href);
  if (value) url.searchParams.set('compare', '1');
  else url.searchParams.delete('compare');
  history.replaceState(null, '', url);
  restart();
}

/** Updates each pane's engine `n` times by 1000/60 ms, as the runner would, and draws the result. */
function step(n: number): void {
  for (const pane of activePanes()) {
    const running = pane.running;
    if (!running) continue;
    for (let i = 0; i < n; i++) pane.Matter.Engine.update(running.engine, 1000 / 60);
    pane.Matter.Render.world(running.render);
  }
}

pauseButton.addEventListener('click', () => setPaused(!paused));
element('btn-reset').addEventListener('click', restart);
compareBox.checked = comparing;
compareBox.addEventListener('change', () => setComparing(compareBox.checked));
window.addEventListener('keydown', (event) => {
  if (event.target instanceof HTMLInputElement) return;
  if (event.key === ' ') {
    event.preventDefault();
    setPaused(!paused);
  } else if (event.key === 'r') {
    restart();
  }
});

const programFromUrl = () => decodeURIComponent(location.hash.replace(/^#\/?/, ''));
window.addEventListener('hashchange', () => open(programFromUrl()));

function hookOf(pane: Pane) {
  const running = pane.running;
  return running && { Matter: pane.Matter, ...running };
}

// for the end-to-end tests and the curious: window.matterGallery in the browser console
Object.assign(window, {
  matterGallery: {
    get program() {
      return program.id;
    },
    get paused() {
      return paused;
    },
    get comparing() {
      return comparing;
    },
    /** each pane's Matter, engine, render, runner (and the program's extras); null when not shown */
    get panes() {
      return { fulcrum: hookOf(panes.fulcrum), matter: comparing ? hookOf(panes.matter) : null };
    },
    pause: () => setPaused(true),
    play: () => setPaused(false),
    step,
    reset: restart,
    open,
    setComparing,
  },
});

open(programFromUrl());
