/**
 * The slingshot game's page in the gallery: wires the game (game.ts) to the pointer, the camera, the
 * pictures, the sound and the heads-up display.
 */
import type { Demo } from '../../demo';
import { Painter } from './art';
import { Sounds } from './audio';
import { GameCamera } from './camera';
import { Effects } from './effects';
import { ANCHOR, type SlingshotGame as Game, MAX_PULL, SlingshotGame, STEP } from './game';
import { Hud } from './hud';
import { TrajectoryPreview } from './preview';

const STORAGE_KEY = 'fulcrum-slingshot-stars';
/**
 * The most device pixels the canvas gets: beyond it (a 4K screen, a big window at a high pixel
 * ratio) the canvas is drawn at a lower ratio and scaled up, so a frame costs no more than at 2560 ×
 * 1560. The art is soft shapes: it shows little.
 */
const MAX_PIXELS = 4e6;
/** the level's hint shows this long, steps */
const HINT_STEPS = 300;

function loadStars(game: Game): void {
  try {
    const saved = JSON.parse(localStorage.getItem(STORAGE_KEY) ?? '[]');
    if (Array.isArray(saved))
      saved.forEach((s, i) => {
        if (i < game.best.length && Number.isInteger(s)) game.best[i] = Math.min(3, Math.max(0, s));
      });
  } catch {
    // no storage (private mode): the stars last as long as the page
  }
}

function saveStars(game: Game): void {
  try {
    localStorage.setItem(STORAGE_KEY, JSON.stringify(game.best));
  } catch {
    // as above
  }
}

export const slingshotDemo: Demo = {
  id: 'slingshot',
  title: 'Slingshot game',
  description:
    'Pull the bird back with the mouse or a finger and let go to fling it at the towers; the dotted line shows where it will fly. Knock out every green blob to clear a level. Wood breaks, ice shatters, stone needs a heavy blow. The blue bird splits in three and the yellow one dashes ahead when you tap while it flies; the big grey one is simply heavy. Birds you do not need earn stars. Six levels; sound and a view of the physics behind the pictures are switches above the game.',
  view: { center: { x: 8, y: 5 }, halfHeight: 7 },
  flags: { shapes: false, joints: false, sleeping: false },
  drawSwitches: false,
  create: (ctx) => {
    const game = new SlingshotGame();
    loadStars(game);
    const render = ctx.render;
    const runner = ctx.runner;
    const effects = new Effects();
    const preview = new TrajectoryPreview(game.world.gravity);
    const sounds = new Sounds();
    const camera = new GameCamera(render.camera, game);
    const painter = new Painter(render, runner.interpolator, game, preview, effects);
    let hintSteps = 0;
    let aimingPointer: number | null = null;

    const hud = new Hud(ctx, game, {
      play: (n) => startLevel(n),
      toggleSound: () => {
        sounds.setOn(!sounds.on);
        return sounds.on;
      },
      toggleDebug: () => {
        const on = !render.flags.shapes;
        render.flags = { ...render.flags, shapes: on, wireframe: on, joints: on, contacts: on };
        if (runner.paused) render.draw(runner.interpolator);
        return on;
      },
    });
    ctx.track(() => {
      hud.dispose();
      sounds.dispose();
    });

    const startLevel = (n: number) => {
      aimingPointer = null;
      game.start(n);
      effects.clear();
      preview.clear();
      runner.interpolator.reset();
      camera.reset();
      hintSteps = HINT_STEPS;
      hud.setHint(game.levelDef.hint);
      hud.showLevels(false);
      hud.update();
      if (runner.paused) render.draw(runner.interpolator);
    };

    game.onEvent = (e) => {
      switch (e.type) {
        case 'launch':
          effects.dust(ANCHOR.x, ANCHOR.y, 0.3);
          sounds.launch(e.strength);
          break;
        case 'trick':
          effects.dust(e.x, e.y, 0.4, 8, 5);
          sounds.trick();
          break;
        case 'hit':
          if (e.strength > 3) sounds.hit(e.material, e.strength);
          break;
        case 'break':
          effects.breakBlock(e.block, e.x, e.y, e.angle, e.vx, e.vy);
          effects.popup(e.x, e.y, e.points);
          sounds.crash(e.block.material);
          break;
        case 'pop':
          effects.pop(e.x, e.y, e.target.radius);
          effects.popup(e.x, e.y + e.target.radius, e.points);
          sounds.pop();
          break;
        case 'gone':
          effects.feathers(e.x, e.y);
          sounds.gone();
          break;
        case 'state':
          if (e.state === 'won') {
            saveStars(game);
            sounds.win();
          } else if (e.state === 'lost') {
            sounds.lose();
          }
          break;
      }
      hud.update();
    };

    ctx.track(
      game.world.on('postStep', () => {
        effects.step(STEP);
        camera.step();
        painter.cloudDrift += 0.01;
        if (hintSteps > 0) hintSteps--;
        // while a bird with a trick flies, how to use it; else the level's hint for a while
        const bird = game.flying[game.flying.length - 1];
        const trick = game.state === 'flying' && bird && !bird.spent ? bird.type.ability : 'none';
        const playing = game.state !== 'won' && game.state !== 'lost';
        hud.setHint(
          trick === 'split'
            ? 'Tap to split the bird in three!'
            : trick === 'dash'
              ? 'Tap to dash!'
              : hintSteps > 0 && playing
                ? game.levelDef.hint
                : '',
        );
      }),
    );

    let viewWidth = 0;
    let viewHeight = 0;
    ctx.track(() => {
      render.pixelRatio = null;
    });
    ctx.track(
      render.on('beforeDraw', ({ context }) => {
        if (render.camera.width !== viewWidth || render.camera.height !== viewHeight) {
          viewWidth = render.camera.width;
          viewHeight = render.camera.height;
          camera.resized();
          // takes effect from the next frame
          const ratio = window.devicePixelRatio || 1;
          const cap = Math.sqrt(MAX_PIXELS / (viewWidth * viewHeight));
          render.pixelRatio = ratio > cap ? cap : null;
        }
        painter.draw(context);
      }),
    );

    // the pointer aims (the camera is the game's: no panning, no zooming, no dragging of blocks)
    const pointer = ctx.pointer;
    pointer.filter = () => false;
    const { pan, zoom } = pointer;
    pointer.pan = false;
    pointer.zoom = false;
    ctx.track(() => {
      pointer.pan = pan;
      pointer.zoom = zoom;
    });
    ctx.track(
      pointer.on('down', (e) => {
        e.handled = true;
        if (game.canGrab(e.point) && game.grab(e.point)) {
          aimingPointer = e.event.pointerId;
          game.pull(e.point);
          const bird = game.loaded;
          if (bird) preview.update(bird.type, bird.body.position, game.world);
          sounds.stretch();
          try {
            render.canvas.setPointerCapture(e.event.pointerId);
          } catch {
            // a synthetic event has no pointer to capture
          }
        } else {
          game.tap();
        }
        if (runner.paused) render.draw(runner.interpolator);
      }),
    );
    ctx.track(
      pointer.on('move', (e) => {
        if (aimingPointer !== e.event.pointerId || game.state !== 'aiming') return;
        game.pull(e.point);
        const bird = game.loaded;
        if (bird) preview.update(bird.type, bird.body.position, game.world);
        if (runner.paused) render.draw(runner.interpolator);
      }),
    );
    ctx.track(
      pointer.on('up', (e) => {
        if (aimingPointer !== e.event.pointerId) return;
        aimingPointer = null;
        game.release();
        preview.clear();
        if (runner.paused) render.draw(runner.interpolator);
      }),
    );

    startLevel(1);
    return {
      world: game.world,
      game,
      camera,
      preview,
      anchor: ANCHOR,
      maxPull: MAX_PULL,
      step: STEP,
      /**
       * The step hook for tests: takes steps by hand (as the Step button does, each one drawn) until
       * `until(game)` is true or `limit` steps were taken; returns the steps taken.
       */
      advance: (limit: number, until?: (g: Game) => boolean): number => {
        let n = 0;
        while (n < limit && !(until?.(game) ?? false)) {
          runner.step();
          n++;
        }
        return n;
      },
    };
  },
};
