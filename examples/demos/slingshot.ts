/**
 * The slingshot game's page: the pointer pulls the bird, the band and the flight trail are drawn over
 * the world, and a small heads-up display shows the level, the score and the birds left. The rules
 * are in slingshot-game.ts.
 */
import type { Vec2 } from '../../src/index';
import type { Demo } from '../demo';
import { drawnPosition } from '../lib';
import { ANCHOR, BIRD_RADIUS, MAX_PULL, materials, SlingshotGame } from './slingshot-game';

/** the world's left edge the camera shows at the start of a level; the right edge follows the level */
const VIEW_LEFT = -14;
/** the two tips of the sling's fork, where the band is tied */
const FORK: Vec2[] = [
  { x: ANCHOR.x - 0.45, y: ANCHOR.y + 0.25 },
  { x: ANCHOR.x + 0.45, y: ANCHOR.y + 0.25 },
];
const COLORS = {
  bird: 0xd9695f,
  target: 0x7ccf5a,
  ground: 0x4d5a3c,
  sling: 0x7a5230,
  band: '#4a2f1c',
};

function element<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  className: string,
  parent: HTMLElement,
): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  el.className = className;
  parent.append(el);
  return el;
}

export const slingshotDemo: Demo = {
  id: 'slingshot',
  title: 'Slingshot game',
  description:
    'Drag the bird back on its spring (a distance joint) and let go: the spring lets go of the bird as it passes the sling. Towers of wood, stone and ice (different density and friction) guard the green targets; a target hit faster than 2.5 m/s (a contactHit event) is destroyed, and ice breaks above 6 m/s. Clear every target to win the level: three levels, four birds each.',
  view: { center: { x: 2.5, y: 6 }, halfHeight: 8 },
  flags: { sleeping: false },
  create: (ctx) => {
    const game = new SlingshotGame();
    const render = ctx.render;
    let scoreAtLevelStart = 0;
    let aiming = false;

    // the heads-up display: plain DOM over the canvas, also read by the end-to-end tests
    const hud = element('div', 'sling-hud', ctx.stage);
    hud.id = 'sling-hud';
    const levelText = element('div', 'sling-level', hud);
    levelText.id = 'sling-level';
    const scoreText = element('div', 'sling-score', hud);
    scoreText.id = 'sling-score';
    const birdsText = element('div', 'sling-birds', hud);
    birdsText.id = 'sling-birds';
    const message = element('div', 'sling-message', ctx.stage);
    message.id = 'sling-message';
    const style = document.createElement('style');
    style.textContent = `
      .sling-hud { position: absolute; top: 8px; left: 10px; pointer-events: none;
        font-variant-numeric: tabular-nums; text-shadow: 0 1px 2px #000; line-height: 1.5; }
      .sling-level { font-weight: 600; }
      .sling-score { font-size: 20px; color: var(--accent); font-weight: 600; }
      .sling-birds { letter-spacing: 2px; }
      .sling-message { position: absolute; left: 50%; top: 28%; transform: translate(-50%, -50%);
        padding: 12px 22px; border-radius: 8px; background: rgba(15, 17, 21, 0.85);
        border: 1px solid var(--accent); font-size: 22px; font-weight: 600; text-align: center;
        pointer-events: none; }
      .sling-message:empty { display: none; }
      .sling-message small { display: block; font-size: 14px; font-weight: 400; color: var(--muted); }
    `;
    document.head.append(style);
    ctx.track(() => {
      hud.remove();
      message.remove();
      style.remove();
    });

    const restartButton = ctx.button('Restart level', () => startLevel(game.level));
    const nextButton = ctx.button('Next level ▸', () => startLevel(game.level + 1));
    ctx.button('New game', () => {
      game.score = 0;
      scoreAtLevelStart = 0;
      game.level = 1;
      startLevel(1);
    });
    restartButton.id = 'sling-restart';
    nextButton.id = 'sling-next';

    const update = () => {
      levelText.textContent = `Level ${game.level}/${game.levelCount}: ${game.levelName}`;
      scoreText.textContent = `Score ${game.score}`;
      const birds = game.birdsUnused;
      birdsText.textContent = `Birds ${'●'.repeat(birds)}${'○'.repeat(Math.max(0, 4 - birds))}  ·  targets left ${game.targets.size}`;
      const won = game.state === 'won';
      const lost = game.state === 'lost' && game.bird === null && game.targets.size > 0;
      message.dataset.state = won ? 'won' : lost ? 'lost' : 'playing';
      if (won && game.level === game.levelCount) {
        message.innerHTML = `You won the game!<small>final score ${game.score} · New game to play again</small>`;
      } else if (won) {
        message.innerHTML = `Level cleared!<small>score ${game.score} · on to the next level</small>`;
      } else if (lost) {
        message.innerHTML = 'Out of birds<small>Restart the level and try another angle</small>';
      } else {
        message.textContent = '';
      }
      nextButton.disabled = !(won && game.level < game.levelCount);
      ctx.setStatus(`level ${game.level} · score ${game.score} · ${game.state}`);
    };
    game.onChange = update;

    /** shows the sling and everything of the level, the ground near the bottom */
    const fitCamera = () => {
      const camera = render.camera;
      let right = 12;
      for (const body of [...game.blocks.keys(), ...game.targets])
        right = Math.max(right, body.position.x + 2);
      const halfWidth = (right - VIEW_LEFT) / 2;
      const halfHeight = Math.max(6, (halfWidth * camera.height) / Math.max(1, camera.width));
      camera.setView({ center: { x: (VIEW_LEFT + right) / 2, y: halfHeight - 1 }, halfHeight });
    };

    const styleBodies = () => {
      render.setBodyStyle(game.ground, { color: COLORS.ground });
      render.setBodyStyle(game.sling, { color: COLORS.sling });
      for (const [body, material] of game.blocks)
        render.setBodyStyle(body, { color: materials[material].color });
      for (const target of game.targets) render.setBodyStyle(target, { color: COLORS.target });
      if (game.bird) render.setBodyStyle(game.bird, { color: COLORS.bird });
    };

    const startLevel = (n: number) => {
      aiming = false;
      // a restart takes back the points of the attempt; a new level keeps them
      if (n === game.level) game.score = scoreAtLevelStart;
      else scoreAtLevelStart = game.score;
      game.start(n);
      ctx.runner.interpolator.reset();
      styleBodies();
      fitCamera();
      update();
    };

    // a new bird appears after each shot: colour it
    ctx.track(
      game.world.on('postStep', () => {
        if (game.bird && render.getBodyStyle(game.bird) === undefined)
          render.setBodyStyle(game.bird, { color: COLORS.bird });
      }),
    );

    // a sky behind the world
    ctx.track(
      render.on('beforeDraw', ({ context }) => {
        const camera = render.camera;
        const sky = context.createLinearGradient(0, 0, 0, camera.height);
        sky.addColorStop(0, '#1d2a40');
        sky.addColorStop(1, '#15171d');
        context.fillStyle = sky;
        context.fillRect(0, 0, camera.width, camera.height);
      }),
    );

    // the pointer: only the bird can be grabbed (dragging elsewhere pans, the wheel zooms)
    ctx.pointer.filter = () => false;
    ctx.track(
      ctx.pointer.on('down', (e) => {
        if (!game.canGrab(e.point)) return;
        e.handled = true;
        aiming = game.grab(e.point);
        try {
          render.canvas.setPointerCapture(e.event.pointerId);
        } catch {
          // synthetic events have no pointer to capture
        }
      }),
    );
    ctx.track(
      ctx.pointer.on('move', (e) => {
        if (aiming) game.pull(e.point);
      }),
    );
    ctx.track(
      ctx.pointer.on('up', () => {
        if (!aiming) return;
        aiming = false;
        game.release();
      }),
    );

    ctx.track(
      render.on('afterDraw', ({ context, pixel }) => {
        // the trail of the last bird
        context.fillStyle = 'rgba(230, 235, 245, 0.6)';
        for (const p of game.trail) {
          context.beginPath();
          context.arc(p.x, p.y, 2.5 * pixel, 0, 2 * Math.PI);
          context.fill();
        }
        // the band, from the fork's tips to the back of the bird while it sits in the sling
        const bird = game.bird;
        if (bird && (game.state === 'ready' || game.state === 'aiming')) {
          const p = drawnPosition(ctx.runner, bird);
          let dx = p.x - ANCHOR.x;
          let dy = p.y - ANCHOR.y;
          const d = Math.hypot(dx, dy);
          if (d > 1e-6) {
            dx /= d;
            dy /= d;
          } else {
            dx = -1;
            dy = 0;
          }
          const back = { x: p.x + dx * BIRD_RADIUS * 0.8, y: p.y + dy * BIRD_RADIUS * 0.8 };
          context.strokeStyle = COLORS.band;
          context.lineCap = 'round';
          context.lineWidth =
            (game.state === 'aiming' ? 3 + 3 * Math.min(1, 1.2 / Math.max(d, 0.4)) : 5) * pixel;
          context.beginPath();
          for (const tip of FORK) {
            context.moveTo(tip.x, tip.y);
            context.lineTo(back.x, back.y);
          }
          context.stroke();
          context.lineCap = 'butt';
        }
        // cracks on the ice, so it reads as ice
        context.strokeStyle = 'rgba(255, 255, 255, 0.5)';
        context.lineWidth = pixel;
        for (const [body, material] of game.blocks) {
          if (material !== 'ice') continue;
          const a = body.getWorldPoint({ x: -0.08, y: 0.1 });
          const b = body.getWorldPoint({ x: 0.05, y: -0.02 });
          const c = body.getWorldPoint({ x: 0.12, y: 0.12 });
          context.beginPath();
          context.moveTo(a.x, a.y);
          context.lineTo(b.x, b.y);
          context.lineTo(c.x, c.y);
          context.stroke();
        }
      }),
    );

    startLevel(1);
    return {
      world: game.world,
      game,
      anchor: ANCHOR,
      maxPull: MAX_PULL,
      /** for tests: the bird's position, or null */
      birdPosition: () => (game.bird ? game.bird.position : null),
    };
  },
};
