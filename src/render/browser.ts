import { FulcrumError } from '../core/errors';

/**
 * Throws a FulcrumError when the global `feature` (`document`, `Path2D`, `requestAnimationFrame`) is
 * missing, as in Node or a worker: `fulcrum/render` draws on an HTML canvas and runs from animation
 * frames. Without this check the first use of the global failed with a bare ReferenceError that said
 * nothing of why.
 */
export function requireBrowser(what: string, feature: string): void {
  if ((globalThis as Record<string, unknown>)[feature] === undefined) {
    throw new FulcrumError(
      `${what} needs a browser: ${feature} is not defined here (fulcrum/render draws on an HTML canvas; the engine, 'fulcrum', runs anywhere)`,
    );
  }
}
