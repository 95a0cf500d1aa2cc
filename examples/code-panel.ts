/**
 * The "Show code" panel: the running demo's TypeScript source, as it is in examples/demos/. Vite bundles
 * each file's text as a chunk of its own, loaded when the panel first shows it.
 */
import { cardOf } from './cards';
import type { Demo } from './demo';

const sources = import.meta.glob<string>('./demos/**/*.ts', { query: '?raw', import: 'default' });

/** The demo's source files (keys of `sources`): its file, or its folder's files with demo.ts first. */
export function sourceFiles(demo: Demo): string[] {
  const name = cardOf(demo).source ?? demo.id;
  const single = `./demos/${name}.ts`;
  if (single in sources) return [single];
  const folder = `./demos/${name}/`;
  const main = `${folder}demo.ts`;
  return Object.keys(sources)
    .filter((path) => path.startsWith(folder))
    .sort((a, b) => (a === main ? -1 : b === main ? 1 : a.localeCompare(b)));
}

export class CodePanel {
  private demo: Demo | null = null;
  private file: string | null = null;
  /** the load whose text may still show: a later one makes an earlier one's text stale */
  private ticket = 0;
  private readonly tabs: HTMLElement;
  private readonly text: HTMLElement;
  private readonly pre: HTMLElement;

  constructor(
    private readonly panel: HTMLElement,
    private readonly toggle: HTMLButtonElement,
  ) {
    const header = document.createElement('div');
    header.className = 'code-header';
    this.tabs = document.createElement('div');
    this.tabs.className = 'code-tabs';
    this.tabs.setAttribute('role', 'tablist');
    const close = document.createElement('button');
    close.type = 'button';
    close.className = 'code-close';
    close.id = 'code-close';
    close.textContent = '×';
    close.title = 'Close the code';
    close.setAttribute('aria-label', 'Close the code');
    close.addEventListener('click', () => this.setOpen(false));
    header.append(this.tabs, close);
    this.pre = document.createElement('pre');
    this.pre.tabIndex = 0;
    this.text = document.createElement('code');
    this.text.id = 'code-text';
    this.pre.append(this.text);
    panel.replaceChildren(header, this.pre);
    toggle.setAttribute('aria-controls', panel.id);
    toggle.addEventListener('click', () => this.setOpen(!this.open));
    this.setOpen(false);
  }

  get open(): boolean {
    return !this.panel.hidden;
  }

  setOpen(open: boolean): void {
    this.panel.hidden = !open;
    // the stage and the panel share their parent's grid while it is open
    this.panel.parentElement?.classList.toggle('with-code', open);
    this.toggle.textContent = open ? 'Hide code' : 'Show code';
    this.toggle.setAttribute('aria-expanded', String(open));
    if (open && this.demo && this.file === null) this.show(this.demo, sourceFiles(this.demo)[0]);
    // under the stage on a phone: brought into view
    if (open) this.panel.scrollIntoView({ block: 'nearest' });
  }

  /** The demo whose code the panel shows (loaded now if the panel is open, else when it opens). */
  setDemo(demo: Demo | null): void {
    // the same demo started again (Reset) keeps the file and the place in it
    if (demo === this.demo) return;
    this.demo = demo;
    this.file = null;
    this.ticket++;
    this.tabs.replaceChildren();
    this.text.textContent = '';
    if (demo && this.open) this.show(demo, sourceFiles(demo)[0]);
  }

  private show(demo: Demo, file: string | undefined): void {
    const files = sourceFiles(demo);
    // the folder once, then a tab per file named by its own name: a folder of eleven files takes two lines
    const folder = document.createElement('span');
    folder.className = 'code-path';
    folder.textContent = `examples${(file ?? './demos/').replace(/[^/]*$/, '').slice(1)}`;
    this.tabs.replaceChildren(
      folder,
      ...files.map((path) => {
        const tab = document.createElement('button');
        tab.type = 'button';
        tab.className = 'code-tab';
        tab.setAttribute('role', 'tab');
        tab.setAttribute('aria-selected', String(path === file));
        tab.title = `examples${path.slice(1)}`;
        tab.textContent = path.slice(path.lastIndexOf('/') + 1);
        if (files.length > 1) tab.addEventListener('click', () => this.show(demo, path));
        return tab;
      }),
    );
    this.file = file ?? '';
    const ticket = ++this.ticket;
    if (file === undefined) {
      this.text.textContent = `No source file found for ${demo.id}.`;
      return;
    }
    this.text.textContent = 'Loading…';
    sources[file]().then(
      (text) => {
        if (ticket !== this.ticket) return;
        this.text.textContent = text;
        this.pre.scrollTo(0, 0);
      },
      (error: unknown) => {
        if (ticket === this.ticket) this.text.textContent = `Could not load ${file}: ${String(error)}`;
      },
    );
  }
}
