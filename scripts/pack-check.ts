// npm run pack:check: the package as a user gets it. Packs the tarball (prepack builds dist/), installs
// it into a scratch project in a temporary directory and runs a hello world there as ESM, as CommonJS,
// as strict TypeScript (node16 and bundler resolution, against the installed declarations; the
// README's examples too) and in Chromium from a plain HTML page with a <script> tag. Prints the
// tarball's size and files and the core's min+gzip size, and fails over the size budget.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import type { AddressInfo } from 'node:net';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { chromium } from 'playwright-core';

/** min+gzip budget of what `import 'fulcrum'` loads (1 kB = 1,000 bytes): issue 23's goal */
const CORE_BUDGET = 60_000;
/**
 * The size the core may not grow past while it is over the budget: over this the check fails,
 * between the two it warns. 69.4 kB when the check was written; 76.6 kB once issue 22's concave
 * decomposition, SVG paths and run-time shape editing and issue 24's layers were in; 78.9 kB with
 * issue 22's chains (the one-sided seam rule, its checks and casts) and svgShapes (features the core
 * carries for every user, not growth of the engine's own code); 79.5 kB with issue 21's engine
 * features for fulcrum/matter (Body.setMassData, the frictionMixing option); 80.6 kB with issue 28's
 * multi-core step (the World's `workers` option, workersReady and dispose, the step's team seam and
 * the contact passes' ranges: 0.64 kB; the team itself is loaded on demand and not counted); 80.8 kB
 * with issue 28's cold start (the step's long loops in functions that end with them, so that V8's
 * on-stack-replaced code is not thrown away at every step, and the contact columns reserved at once:
 * 0.17 kB) and issue 26's shared worker starter; 81.1 kB with issue 28's split by island (the
 * step's side: the team's integration and whole-solve passes, the heavy step's fallback, hit events in
 * the colouring's order: 0.35 kB; the split itself is in the team's chunk). Issue 23 holds the 60 kB
 * goal.
 */
const CORE_CEILING = 81_100;

const root = path.resolve(import.meta.dirname, '..');
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'fulcrum-pack-'));
const app = path.join(scratch, 'app');
const kB = (bytes: number) => `${(bytes / 1000).toFixed(1)} kB`;

function run(command: string, args: string[], cwd: string): string {
  return execFileSync(command, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] });
}

function step(name: string) {
  console.log(`\n== ${name}`);
}

/**
 * The hello world every runtime runs, given the package's exports: a ball of radius 0.5 m dropped from
 * 2.3 m onto the ground's top at y = 0, stepped for 1 s at 1/60 s. It falls freely until its bottom
 * meets the ground (at t = sqrt(2 * 1.8 / 10) = 0.6 s) and then rests there (restitution 0).
 * The solver's semi-implicit Euler at 1/240 s lags free fall by g t h / 2 (1 cm at 0.5 s).
 */
const helloWorld = `function helloWorld({ World, Shape }) {
  const world = new World({ gravity: { x: 0, y: -10 } });
  const ground = world.createBody({ position: { x: 0, y: -1 } });
  ground.createShape(Shape.box(20, 1));
  const ball = world.createBody({ type: 'dynamic', position: { x: 0, y: 2.3 } });
  ball.createShape(Shape.circle(0.5), { density: 1, restitution: 0 });
  const heights = [];
  for (let i = 1; i <= 60; i++) {
    world.step(1 / 60);
    if (i === 30) heights.push(ball.position.y);
  }
  heights.push(ball.position.y);
  const freeFall = 2.3 - 0.5 * 10 * 0.5 * 0.5;
  const problems = [];
  if (!(Math.abs(heights[0] - freeFall) < 0.02)) problems.push('at 0.5 s the ball is at ' + heights[0] + ' m, free fall says ' + freeFall);
  if (!(Math.abs(heights[1] - 0.5) < 0.01)) problems.push('at 1 s the ball is at ' + heights[1] + ' m, resting on the ground means 0.5');
  if (!(Math.abs(ball.linearVelocity.y) < 0.05)) problems.push('at 1 s the ball moves at ' + ball.linearVelocity.y + ' m/s');
  if (problems.length > 0) throw new Error('hello world: ' + problems.join('; '));
  return 'fell ' + (2.3 - heights[0]).toFixed(4) + ' m in 0.5 s (free fall ' + (2.3 - freeFall) + '), rests at ' + heights[1].toFixed(4) + ' m';
}`;

/** Node has no DOM: fulcrum/render loads, and new Render() says it needs a browser. */
const renderInNode = `function renderInNode(fulcrum, render) {
  try {
    new render.Render();
  } catch (e) {
    if (e instanceof fulcrum.FulcrumError && /needs a browser/.test(e.message)) return 'new Render() in Node: ' + e.message;
    throw e;
  }
  throw new Error('new Render() in Node did not throw');
}`;

/** fulcrum/matter: a matter.js program (pixels, y down, milliseconds) falls and lands as on matter.js. */
const helloMatter = `function helloMatter(Matter) {
  const engine = Matter.Engine.create();
  const ground = Matter.Bodies.rectangle(400, 610, 810, 60, { isStatic: true });
  const box = Matter.Bodies.rectangle(400, 200, 40, 40, { frictionAir: 0 });
  Matter.Composite.add(engine.world, [ground, box]);
  for (let i = 0; i < 30; i++) Matter.Engine.update(engine, 1000 / 60);
  const fallen = box.position.y - 200;
  for (let i = 0; i < 150; i++) Matter.Engine.update(engine, 1000 / 60);
  const problems = [];
  // gravity 0.001 px/ms^2: 1000 px/s^2, 125 px in 0.5 s
  if (!(Math.abs(fallen - 125) < 4)) problems.push('in 0.5 s the box fell ' + fallen + ' px, free fall says 125');
  if (!(Math.abs(box.position.y - 560) < 1)) problems.push('after 3 s the box is at y = ' + box.position.y + ', resting on the ground means 560');
  if (typeof Matter.use !== 'function' || typeof Matter.Render.create !== 'function') problems.push('Matter.use or Matter.Render is missing');
  if (problems.length > 0) throw new Error('hello matter: ' + problems.join('; '));
  return 'fulcrum/matter: fell ' + fallen.toFixed(1) + ' px in 0.5 s (free fall 125), rests at y = ' + box.position.y.toFixed(2);
}`;

/** fulcrum/worker: a world stepped in a worker gives the same state, bit for bit, as the same calls on a World. */
const helloWorker = `async function helloWorker(fulcrum, WorkerWorld) {
  const build = (world) => {
    const ground = world.createBody();
    ground.createShape(fulcrum.Shape.box(5, 0.5), {});
    const ball = world.createBody({ type: 'dynamic', position: { x: 0.3, y: 3 } });
    ball.createShape(fulcrum.Shape.circle(0.5), { restitution: 0.5 });
    return ball;
  };
  const local = new fulcrum.World();
  const remote = await WorkerWorld.create();
  try {
    const ball = build(remote);
    build(local);
    for (let i = 0; i < 90; i++) {
      local.step(1 / 60);
      await remote.step(1 / 60);
    }
    const hash = await remote.stateHash();
    if (hash !== fulcrum.stateHash(local)) throw new Error('hello worker: the worker world hash ' + hash + ' differs from the World on this thread, ' + fulcrum.stateHash(local));
    return 'fulcrum/worker (' + remote.bufferMode + ' buffers): 90 steps in a worker, the same state hash as on this thread; the ball at y = ' + ball.position.y.toFixed(4) + ' m';
  } finally {
    remote.terminate();
  }
}`;

/**
 * new World({ workers: 2 }): the package's solver-worker.js is found and started, and a 600-box pile
 * steps to the same state hash as on one thread.
 */
const helloThreads = `async function helloThreads(fulcrum) {
  const build = (world) => {
    world.createBody().createShape(fulcrum.Shape.box(30, 0.5));
    for (let i = 0; i < 600; i++) {
      const box = world.createBody({ type: 'dynamic', position: { x: -25 + (i % 50), y: 1 + Math.floor(i / 50) } });
      box.createShape(fulcrum.Shape.box(0.45, 0.45));
    }
  };
  const two = new fulcrum.World({ workers: 2 });
  const one = new fulcrum.World();
  const threads = await two.workersReady;
  if (threads !== 2) throw new Error('hello threads: ' + threads + ' threads started, not 2');
  build(two);
  build(one);
  for (let i = 0; i < 120; i++) {
    two.step(1 / 60);
    one.step(1 / 60);
  }
  two.dispose();
  if (fulcrum.stateHash(two) !== fulcrum.stateHash(one)) throw new Error('hello threads: two threads and one differ');
  return 'new World({ workers: 2 }): 120 steps of 600 boxes on two threads, the same state hash as on one';
}`;

const typedMatter = `import Matter, { Bodies, Composite, Engine } from 'fulcrum/matter';
const engine = Engine.create();
const box = Bodies.rectangle(0, 0, 40, 40);
Composite.add(engine.world, box);
Matter.Engine.update(engine, 1000 / 60);
export const y: number = box.position.y;
`;

const typedHello = `import { type Body, FulcrumError, Shape, World, type WorldDef } from 'fulcrum';
import { Camera, type CameraView, Render, type RenderOptions, Runner } from 'fulcrum/render';

const def: WorldDef = { gravity: { x: 0, y: -10 } };
const world = new World(def);
const ball: Body = world.createBody({ type: 'dynamic', position: { x: 0, y: 2.3 } });
ball.createShape(Shape.circle(0.5), { density: 1, restitution: 0 });
world.on('contactBegin', (e) => console.log(e.normal.x, e.bodyA.position.y));
const view: Partial<CameraView> = { center: { x: 0, y: 1 }, halfHeight: 3 };
const options: RenderOptions = { world, view };
const camera = new Camera(view);
const runner = new Runner({ world, dt: 1 / 60 });
runner.step();
export function show(canvas: HTMLCanvasElement): Render | FulcrumError {
  try {
    return new Render({ ...options, canvas });
  } catch (e) {
    if (e instanceof FulcrumError) return e;
    throw e;
  }
}
export const scale: number = camera.scale;
`;

const typedCjsHello = `import fulcrum = require('fulcrum');
import render = require('fulcrum/render');

const world = new fulcrum.World({ gravity: { x: 0, y: -10 } });
world.createBody({ type: 'dynamic' }).createShape(fulcrum.Shape.box(0.5, 0.5));
world.step(1 / 60);
export const camera: render.Camera = new render.Camera({ halfHeight: 2 });
`;

/** The README's TypeScript blocks that import the package, one file each. */
function readmeExamples(): string[] {
  const readme = fs.readFileSync(path.join(root, 'README.md'), 'utf8');
  const blocks = [...readme.matchAll(/```ts\n([\s\S]*?)```/g)].map((m) => m[1]);
  return blocks.filter((b) => /from 'fulcrum(\/render)?'/.test(b));
}

async function inChromium(dir: string): Promise<string> {
  const page = `<!doctype html>
<html><head><link rel="icon" href="data:,"></head><body>
<canvas id="view" width="320" height="240"></canvas>
<script src="node_modules/fulcrum/dist/fulcrum.global.js"></script>
<script>
${helloWorld}
try {
  const message = helloWorld(Fulcrum);
  const world = new Fulcrum.World();
  world.createBody().createShape(Fulcrum.Shape.box(5, 0.5));
  const render = new Fulcrum.render.Render({ canvas: document.getElementById('view'), world, view: { center: { x: 0, y: 0 }, halfHeight: 3 } });
  render.draw();
  // the canvas's centre is the world's origin, inside the ground box: not the background (#15171d)
  const pixel = Array.from(render.context.getImageData(160, 120, 1, 1).data);
  if (pixel[0] === 0x15 && pixel[1] === 0x17 && pixel[2] === 0x1d) throw new Error('Fulcrum.render drew no ground at the canvas centre');
  window.result = { ok: true, message: message + '; Fulcrum.render drew the ground (pixel ' + pixel.join(',') + ')' };
} catch (e) {
  window.result = { ok: false, message: String(e && e.stack || e) };
}
</script>
</body></html>`;
  fs.writeFileSync(path.join(dir, 'index.html'), page);
  // the docs' script-tag example as a user copies it, with the CDN's file replaced by the installed one
  const example = fs
    .readFileSync(path.join(root, 'docs', 'examples', 'script-tag.html'), 'utf8')
    .replace(
      'https://unpkg.com/fulcrum/dist/fulcrum.global.js',
      'node_modules/fulcrum/dist/fulcrum.global.js',
    );
  fs.writeFileSync(path.join(dir, 'script-tag.html'), example);
  const server = http.createServer((req, res) => {
    // browsers ask for one; the pages are not about it
    if (req.url === '/favicon.ico') {
      res.statusCode = 204;
      return res.end();
    }
    const file = path.join(dir, decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname));
    if (!file.startsWith(dir) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      const index = path.join(dir, 'index.html');
      if (req.url === '/') return res.end(fs.readFileSync(index));
      res.statusCode = 404;
      return res.end();
    }
    res.setHeader('content-type', file.endsWith('.js') ? 'text/javascript' : 'text/html');
    res.end(fs.readFileSync(file));
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu'],
  });
  try {
    const tab = await browser.newPage();
    const errors: string[] = [];
    tab.on('pageerror', (e) => errors.push(e.message));
    tab.on('console', (m) => {
      if (m.type() === 'error') errors.push(m.text());
    });
    await tab.goto(`http://127.0.0.1:${port}/`);
    await tab.waitForFunction(() => (window as unknown as { result?: unknown }).result !== undefined);
    const result = (await tab.evaluate(() => (window as unknown as { result: unknown }).result)) as {
      ok: boolean;
      message: string;
    };
    if (!result.ok) throw new Error(`in Chromium: ${result.message}`);
    if (errors.length > 0) throw new Error(`in Chromium, page errors: ${errors.join('; ')}`);
    // the docs' example runs and draws: some pixel of its canvas is not the background (#15171d)
    await tab.goto(`http://127.0.0.1:${port}/script-tag.html`);
    await tab.waitForFunction(() => {
      const canvas = document.querySelector('canvas');
      const context = canvas?.getContext('2d');
      if (!canvas || !context || canvas.width === 0) return false;
      const data = context.getImageData(0, 0, canvas.width, canvas.height).data;
      for (let i = 0; i < data.length; i += 4) {
        if (data[i] !== 0x15 || data[i + 1] !== 0x17 || data[i + 2] !== 0x1d) return true;
      }
      return false;
    });
    if (errors.length > 0)
      throw new Error(`in Chromium, docs/examples/script-tag.html: ${errors.join('; ')}`);
    return `${result.message}; docs/examples/script-tag.html runs and draws`;
  } finally {
    await browser.close();
    server.close();
  }
}

/** What `import 'fulcrum'` loads: dist/index.js and the chunks it imports. */
function coreFiles(dist: string): string[] {
  const files = ['index.js'];
  for (let i = 0; i < files.length; i++) {
    const code = fs.readFileSync(path.join(dist, files[i]), 'utf8');
    for (const m of code.matchAll(/from\s*['"]\.\/([^'"]+\.js)['"]/g))
      if (!files.includes(m[1])) files.push(m[1]);
  }
  return files;
}

async function main() {
  step('npm pack (prepack builds dist/)');
  const packed = run('npm', ['pack', '--json', '--pack-destination', scratch], root);
  const info = JSON.parse(packed.slice(packed.indexOf('[\n'))) as {
    filename: string;
    size: number;
    unpackedSize: number;
    files: { path: string; size: number }[];
  }[];
  const tarball = info[0];
  console.log(`${tarball.filename}: ${kB(tarball.size)} packed, ${kB(tarball.unpackedSize)} unpacked`);
  for (const f of tarball.files) console.log(`  ${kB(f.size).padStart(9)}  ${f.path}`);
  const maps = tarball.files.filter((f) => f.path.endsWith('.map'));
  if (maps.length > 0) throw new Error(`source maps in the tarball: ${maps.map((f) => f.path).join(', ')}`);

  step('install the tarball into a scratch project');
  fs.mkdirSync(app);
  fs.writeFileSync(
    path.join(app, 'package.json'),
    JSON.stringify({ name: 'app', private: true, type: 'module' }),
  );
  run(
    'npm',
    ['install', '--no-audit', '--no-fund', '--ignore-scripts', path.join(scratch, tarball.filename)],
    app,
  );

  step('size of the core');
  const dist = path.join(app, 'node_modules', 'fulcrum', 'dist');
  const core = coreFiles(dist);
  const code = Buffer.concat(core.map((f) => fs.readFileSync(path.join(dist, f))));
  const gzipped = zlib.gzipSync(code, { level: 9 }).length;
  console.log(
    `min+gzip of ${core.join(' + ')}: ${kB(gzipped)} (budget ${kB(CORE_BUDGET)}; minified ${kB(code.length)})`,
  );
  const matter = fs.readFileSync(path.join(dist, 'matter.js'));
  console.log(`min+gzip of fulcrum/matter over the core: ${kB(zlib.gzipSync(matter, { level: 9 }).length)}`);
  const global = fs.readFileSync(path.join(dist, 'fulcrum.global.js'));
  console.log(
    `min+gzip of fulcrum.global.js (engine and render): ${kB(zlib.gzipSync(global, { level: 9 }).length)}`,
  );

  step('ESM (hello.mjs)');
  fs.writeFileSync(
    path.join(app, 'hello.mjs'),
    `import * as fulcrum from 'fulcrum';\nimport * as render from 'fulcrum/render';\nimport Matter from 'fulcrum/matter';\nimport { WorkerWorld } from 'fulcrum/worker';\n${helloWorld}\n${renderInNode}\n${helloMatter}\n${helloWorker}\n${helloThreads}\nconsole.log(helloWorld(fulcrum));\nconsole.log(renderInNode(fulcrum, render));\nconsole.log(helloMatter(Matter));\nconsole.log(await helloWorker(fulcrum, WorkerWorld));\nconsole.log(await helloThreads(fulcrum));\n`,
  );
  console.log(run('node', ['hello.mjs'], app).trim());

  step('CommonJS (hello.cjs)');
  fs.writeFileSync(
    path.join(app, 'hello.cjs'),
    `const fulcrum = require('fulcrum');\nconst render = require('fulcrum/render');\nconst Matter = require('fulcrum/matter');\nconst { WorkerWorld } = require('fulcrum/worker');\n${helloWorld}\n${renderInNode}\n${helloMatter}\n${helloWorker}\n${helloThreads}\nconsole.log(helloWorld(fulcrum));\nconsole.log(renderInNode(fulcrum, render));\nconsole.log(helloMatter(Matter));\nhelloWorker(fulcrum, WorkerWorld)\n  .then(console.log)\n  .then(() => helloThreads(fulcrum))\n  .then(console.log, (e) => { console.error(e); process.exitCode = 1; });\n`,
  );
  console.log(run('node', ['hello.cjs'], app).trim());

  step('strict TypeScript against the installed declarations');
  const tsc = path.join(root, 'node_modules', 'typescript', 'bin', 'tsc');
  fs.writeFileSync(path.join(app, 'hello.ts'), typedHello);
  fs.writeFileSync(path.join(app, 'hello-cjs.cts'), typedCjsHello);
  fs.writeFileSync(path.join(app, 'hello-matter.ts'), typedMatter);
  const examples = readmeExamples();
  const readme = examples.map((block, i) => {
    fs.writeFileSync(path.join(app, `readme-${i + 1}.ts`), block);
    return `readme-${i + 1}.ts`;
  });
  const common = [
    '--strict',
    '--noEmit',
    '--skipLibCheck',
    'false',
    '--target',
    'es2022',
    '--lib',
    'es2022,dom',
  ];
  const sets: [string, string[]][] = [
    [
      'node16',
      [
        '--module',
        'node16',
        '--moduleResolution',
        'node16',
        'hello.ts',
        'hello-cjs.cts',
        'hello-matter.ts',
        ...readme,
      ],
    ],
    [
      'bundler',
      ['--module', 'esnext', '--moduleResolution', 'bundler', 'hello.ts', 'hello-matter.ts', ...readme],
    ],
  ];
  for (const [name, args] of sets) {
    run('node', [tsc, ...common, ...args], app);
    console.log(
      `tsc --strict (${name}): hello.ts${name === 'node16' ? ', hello-cjs.cts' : ''}, hello-matter.ts and ${readme.length} README example(s) typecheck`,
    );
  }

  step('Chromium: a plain HTML page with <script src=".../fulcrum.global.js">');
  console.log(await inChromium(app));

  if (gzipped > CORE_CEILING) {
    throw new Error(
      `the core is ${kB(gzipped)} min+gzip, over the ceiling of ${kB(CORE_CEILING)} (budget ${kB(CORE_BUDGET)})`,
    );
  }
  if (gzipped > CORE_BUDGET) {
    console.warn(
      `warning: the core is ${kB(gzipped)} min+gzip, over the budget of ${kB(CORE_BUDGET)} (and under the ceiling of ${kB(CORE_CEILING)} that it may not pass)`,
    );
  }
  fs.rmSync(scratch, { recursive: true, force: true });
  console.log('\npack:check passed');
}

main().catch((e) => {
  console.error(
    `\npack:check FAILED: ${e instanceof Error ? e.message : e}\n(scratch project kept in ${scratch})`,
  );
  process.exit(1);
});
