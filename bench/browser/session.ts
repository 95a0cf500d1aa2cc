/**
 * A headless browser for the benchmark: Chromium through playwright-core, Firefox through
 * puppeteer-core (WebDriver BiDi; playwright-core drives only Playwright's own patched Firefox). Every
 * call opens a fresh browser context (its own renderer process in Chromium: no compiled code, no
 * cache kept from another run, like a fresh Node process) and page, calls the page's `fulcrumBench`
 * (page.ts) and closes both.
 */
import { existsSync } from 'node:fs';
import { chromium } from 'playwright-core';
import type { BrowserName } from '../options';
import type { BenchPage } from './page';

export const CHROMIUM = process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';
export const FIREFOX = process.env.FIREFOX_PATH ?? '/usr/bin/firefox';

type Method = keyof BenchPage;
type Result<M extends Method> = Awaited<ReturnType<BenchPage[M]>>;

export interface BrowserSession {
  name: BrowserName;
  /** the browser's own name for its version, e.g. 150.0.7871.100 */
  version: string;
  /** fulcrumBench[method](...args) in a fresh context and page at `url`; rejects after timeoutMs */
  call<M extends Method>(
    url: string,
    method: M,
    args: Parameters<BenchPage[M]>,
    timeoutMs: number,
  ): Promise<Result<M>>;
  close(): Promise<void>;
}

/** the minimal page both drivers give */
interface DriverPage {
  goto(url: string): Promise<unknown>;
  evaluate(expression: string): Promise<unknown>;
}

interface Driver {
  version: string;
  /** a fresh context with one page in it, uncaught errors of the page to `onError`, and how to close it */
  open(onError: (message: string) => void): Promise<{ page: DriverPage; close(): Promise<void> }>;
  close(): Promise<void>;
}

/**
 * The call goes to the page as an expression, not a function: functions are sent as their source,
 * and tsx's compiled source of one refers to helpers (`__name`) the page does not have.
 */
function expression(method: Method, args: readonly unknown[]): string {
  return `globalThis.fulcrumBench.${method}(...${JSON.stringify(args)})`;
}

function session(name: BrowserName, driver: Driver): BrowserSession {
  async function call<M extends Method>(
    url: string,
    method: M,
    args: Parameters<BenchPage[M]>,
    timeoutMs: number,
  ): Promise<Result<M>> {
    const errors: string[] = [];
    const { page, close } = await driver.open((message) => errors.push(message));
    let timer: ReturnType<typeof setTimeout> | undefined;
    try {
      await page.goto(url);
      const timeout = new Promise<never>((_, reject) => {
        timer = setTimeout(() => reject(new Error(`timed out after ${timeoutMs / 1000} s`)), timeoutMs);
      });
      return (await Promise.race([page.evaluate(expression(method, args)), timeout])) as Result<M>;
    } catch (error) {
      const message = error instanceof Error ? error.message : String(error);
      throw new Error(errors.length > 0 ? `${message} (page errors: ${errors.join(' | ')})` : message);
    } finally {
      clearTimeout(timer);
      await close();
    }
  }
  return { name, version: driver.version, call, close: () => driver.close() };
}

const JS_FLAGS = process.env.JS_FLAGS;

async function launchChromium(): Promise<Driver> {
  const browser = await chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    // JS_FLAGS: V8 flags for the page (--js-flags), to see how the JIT's tiers shape the cold start
    args: ['--no-sandbox', '--disable-gpu', ...(JS_FLAGS ? [`--js-flags=${JS_FLAGS}`] : [])],
  });
  return {
    version: browser.version(),
    async open(onError) {
      const context = await browser.newContext();
      const page = await context.newPage();
      page.on('pageerror', (error) => onError(error.message));
      return { page, close: () => context.close() };
    },
    close: () => browser.close(),
  };
}

async function launchFirefox(): Promise<Driver> {
  const puppeteer = await import('puppeteer-core');
  const browser = await puppeteer.launch({
    browser: 'firefox',
    executablePath: FIREFOX,
    headless: true,
  });
  const version = (await browser.version()).replace(/^firefox\//i, '');
  return {
    version,
    async open(onError) {
      const context = await browser.createBrowserContext();
      const page = await context.newPage();
      page.on('pageerror', (error) => onError(error instanceof Error ? error.message : String(error)));
      return { page, close: () => context.close() };
    },
    close: () => browser.close(),
  };
}

export async function launch(name: BrowserName): Promise<BrowserSession> {
  const path = name === 'chromium' ? CHROMIUM : FIREFOX;
  if (!existsSync(path)) {
    const env = name === 'chromium' ? 'CHROMIUM_PATH' : 'FIREFOX_PATH';
    const pkg = name === 'chromium' ? 'chromium' : 'firefox-esr';
    throw new Error(`no ${name} at ${path}: install it (apt-get install -y ${pkg}) or set ${env}`);
  }
  return session(name, name === 'chromium' ? await launchChromium() : await launchFirefox());
}
