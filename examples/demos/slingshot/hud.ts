/**
 * The heads-up display: plain DOM over the canvas. A bar across the top holds the level, the score
 * and the birds left on the left, the buttons on the right; it wraps to two lines on a narrow screen,
 * so the two never overlap. A panel in the middle tells a won or lost level (with its stars), a
 * level select lists the levels with the best stars of each, and a line at the bottom gives hints.
 * The end-to-end tests read it by its ids.
 */
import type { DemoContext } from '../../demo';
import { birdTypes } from './birds';
import type { SlingshotGame } from './game';
import { levels } from './levels';

export interface HudActions {
  play(level: number): void;
  toggleSound(): boolean;
  toggleDebug(): boolean;
}

function element<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  parent: HTMLElement,
  className = '',
  id = '',
): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  if (className) el.className = className;
  if (id) el.id = id;
  parent.append(el);
  return el;
}

function button(parent: HTMLElement, label: string, id: string, onClick: () => void): HTMLButtonElement {
  const b = element('button', parent, 'sling-button', id);
  b.type = 'button';
  b.textContent = label;
  b.addEventListener('click', onClick);
  return b;
}

function starText(stars: number): string {
  return '★'.repeat(stars) + '☆'.repeat(3 - stars);
}

export class Hud {
  private readonly level: HTMLElement;
  private readonly score: HTMLElement;
  private readonly birds: HTMLElement;
  private readonly message: HTMLElement;
  private readonly select: HTMLElement;
  private readonly hint: HTMLElement;
  private readonly hintText: HTMLElement;
  private readonly removers: (() => void)[] = [];
  private shownScore = -1;
  private shownBirds = '';

  constructor(
    ctx: DemoContext,
    private readonly game: SlingshotGame,
    private readonly actions: HudActions,
  ) {
    const ui = ctx.ui;
    ui.classList.add('sling-ui');
    this.removers.push(() => ui.classList.remove('sling-ui'));
    const info = element('div', ui, 'sling-info', 'sling-hud');
    this.level = element('div', info, 'sling-level', 'sling-level');
    const line = element('div', info, 'sling-line');
    this.score = element('span', line, 'sling-score', 'sling-score');
    this.birds = element('span', line, 'sling-birds', 'sling-birds');
    const controls = element('div', ui, 'sling-controls');
    button(controls, 'Levels', 'sling-levels', () => this.showLevels(this.select.hidden));
    button(controls, '↻ Restart', 'sling-restart', () => actions.play(game.level));
    const sound = button(controls, 'Sound: off', 'sling-sound', () => {
      const on = actions.toggleSound();
      sound.textContent = on ? 'Sound: on' : 'Sound: off';
      sound.setAttribute('aria-pressed', String(on));
    });
    sound.setAttribute('aria-pressed', 'false');
    const debug = button(controls, 'Physics view', 'sling-debug', () => {
      debug.setAttribute('aria-pressed', String(actions.toggleDebug()));
    });
    debug.setAttribute('aria-pressed', 'false');
    debug.title = 'Shows the shapes, joints and contacts the engine works with';

    this.message = element('div', ctx.stage, 'sling-panel', 'sling-message');
    this.message.hidden = true;
    this.select = element('div', ctx.stage, 'sling-panel sling-select', 'sling-select');
    this.select.hidden = true;
    // the hint takes a line of its own under the bar
    this.hint = element('div', ui, 'sling-hint');
    this.hintText = element('span', this.hint, '', 'sling-hint');
    this.hint.hidden = true;
    this.removers.push(() => {
      this.message.remove();
      this.select.remove();
    });
  }

  dispose(): void {
    for (const remove of this.removers) remove();
  }

  /** Shows or hides the level select. */
  showLevels(open: boolean): void {
    this.select.hidden = !open;
    if (!open) return;
    this.select.replaceChildren();
    element('h3', this.select).textContent = 'Choose a level';
    const grid = element('div', this.select, 'sling-grid');
    levels.forEach((make, i) => {
      const b = button(grid, '', `sling-level-${i + 1}`, () => {
        this.select.hidden = true;
        this.actions.play(i + 1);
      });
      b.dataset.level = String(i + 1);
      element('span', b, 'sling-number').textContent = String(i + 1);
      element('span', b).textContent = make().name;
      element('span', b, 'sling-stars-small').textContent = starText(this.game.best[i]);
    });
    button(this.select, 'Close', 'sling-close', () => this.showLevels(false));
  }

  /** A line at the bottom, for a while (steps are counted by the caller). */
  setHint(text: string): void {
    if (this.hintText.textContent === text) return;
    this.hintText.textContent = text;
    this.hint.hidden = text === '';
  }

  /** Brings the texts up to date (cheap when nothing changed). */
  update(): void {
    const game = this.game;
    const levelText = `Level ${game.level}/${game.levelCount} · ${game.levelDef.name}`;
    if (this.level.textContent !== levelText) this.level.textContent = levelText;
    if (this.shownScore !== game.score) {
      this.shownScore = game.score;
      this.score.textContent = `Score ${game.score.toLocaleString('en-US')}`;
    }
    const kinds = (game.loaded ? [game.loaded.type.kind] : []).concat(game.queue);
    const birdsKey = kinds.join(',');
    if (birdsKey !== this.shownBirds) {
      this.shownBirds = birdsKey;
      this.birds.replaceChildren();
      this.birds.dataset.count = String(kinds.length);
      for (const kind of kinds) {
        const dot = element('i', this.birds, 'sling-bird');
        dot.style.background = birdTypes[kind].body;
        dot.title = birdTypes[kind].name;
      }
    }
    this.updateMessage();
  }

  private updateMessage(): void {
    const game = this.game;
    const state = game.state === 'won' ? 'won' : game.state === 'lost' ? 'lost' : 'playing';
    if (this.message.dataset.state === state) return;
    this.message.dataset.state = state;
    this.message.hidden = state === 'playing';
    this.message.replaceChildren();
    if (state === 'playing') return;
    const last = game.level === game.levelCount;
    if (state === 'won') {
      element('h3', this.message).textContent = last ? 'You cleared every level!' : 'Level cleared!';
      const stars = element('div', this.message, 'sling-stars', 'sling-stars');
      stars.dataset.stars = String(game.stars);
      stars.textContent = starText(game.stars);
      stars.setAttribute('aria-label', `${game.stars} of 3 stars`);
      element('p', this.message).textContent = `Score ${game.score.toLocaleString('en-US')}`;
    } else {
      element('h3', this.message).textContent = 'Out of birds';
      element('p', this.message).textContent = 'Try another angle, or another target first.';
    }
    const row = element('div', this.message, 'sling-row');
    button(row, state === 'won' ? 'Replay' : 'Try again', 'sling-replay', () =>
      this.actions.play(game.level),
    );
    button(row, 'Levels', 'sling-panel-levels', () => this.showLevels(true));
    if (state === 'won' && !last) {
      const next = button(row, 'Next level ▸', 'sling-next', () => this.actions.play(game.level + 1));
      next.classList.add('sling-primary');
    }
  }
}
