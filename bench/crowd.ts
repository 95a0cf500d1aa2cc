/**
 * A crowd created on one spot (a spawn bug): `count` dynamic 0.5 m boxes or circles created at the
 * same point 1 m above a wide static ground, stepped at 60 Hz. Prints the time of the first step and
 * of the first 60, the peak RSS and heap (sampled after every step), the contacts, and how far the
 * crowd has come apart after 1, 2, 5, 10 and 20 s: the deepest overlap of a contact point, the bodies
 * that overlap another by more than 5 cm, the shapes still waiting for contacts, where the bodies are.
 *
 *   npm run bench:crowd -- [count=10000] [box|circle] [seconds=10] [--spread] [--limit n]
 *
 * --spread creates the bodies within 1 cm of the point (a golden-angle spiral) instead of exactly on
 * it: exactly coincident boxes push each other straight up and down, into a column. --limit sets
 * world.maxContactsPerShape (16777215: no limit but the world's).
 */
import { Shape, stateHash, type WarningEvent, World } from '../src/index';

const args = process.argv.slice(2);
const flag = (name: string) => args.indexOf(name);
const limitAt = flag('--limit');
const limit = limitAt >= 0 ? Number(args[limitAt + 1]) : undefined;
const spread = flag('--spread') >= 0;
const positional = args.filter((a, i) => !a.startsWith('--') && (limitAt < 0 || i !== limitAt + 1));
const count = Number(positional[0] ?? 10000);
const kind = positional[1] ?? 'box';
const seconds = Number(positional[2] ?? 10);
const mb = (n: number) => `${(n / 1048576).toFixed(0)} MB`;

const world = new World();
if (limit !== undefined) world.maxContactsPerShape = limit;
const ground = world.createBody({ position: { x: 0, y: -0.5 } });
ground.createShape(Shape.box(500, 0.5));
const geometry = kind === 'circle' ? Shape.circle(0.25) : Shape.box(0.25, 0.25);
const created = performance.now();
for (let i = 0; i < count; i++) {
  const r = spread ? 0.01 * Math.sqrt(i / count) : 0;
  const angle = i * 2.399963;
  const body = world.createBody({
    type: 'dynamic',
    position: { x: r * Math.cos(angle), y: 1 + r * Math.sin(angle) },
  });
  body.createShape(geometry);
}
const warnings: WarningEvent[] = [];
world.on('warning', (w) => warnings.push(w));

/** the deepest overlap of a contact point, and the bodies overlapping another by more than 5 cm */
function overlaps(): { deepest: number; over5cm: number } {
  const contacts = world.core.contacts;
  const deep = new Uint8Array(world.core.bodies.slotCount);
  let deepest = 0;
  for (let c = 0; c < contacts.slotCount; c++) {
    if (contacts.alive[c] === 0) continue;
    for (let j = 0; j < contacts.pointCount[c]; j++) {
      const depth = -contacts.separation[c * 2 + j];
      deepest = Math.max(deepest, depth);
      if (depth > 0.05) {
        if (world.core.bodies.kind[contacts.bodyA[c]] !== 0) deep[contacts.bodyA[c]] = 1;
        if (world.core.bodies.kind[contacts.bodyB[c]] !== 0) deep[contacts.bodyB[c]] = 1;
      }
    }
  }
  return { deepest, over5cm: deep.reduce((a, b) => a + b, 0) };
}

/** the box the crowd's bodies span */
function extent(): string {
  let minX = Number.POSITIVE_INFINITY;
  let maxX = Number.NEGATIVE_INFINITY;
  let minY = Number.POSITIVE_INFINITY;
  let maxY = Number.NEGATIVE_INFINITY;
  for (const body of world.bodies) {
    if (body.type !== 'dynamic') continue;
    const p = body.position;
    minX = Math.min(minX, p.x);
    maxX = Math.max(maxX, p.x);
    minY = Math.min(minY, p.y);
    maxY = Math.max(maxY, p.y);
  }
  return `x ${minX.toFixed(1)}..${maxX.toFixed(1)}, y ${minY.toFixed(1)}..${maxY.toFixed(1)}`;
}

let peakRss = 0;
let peakHeap = 0;
let peakContacts = 0;
const sample = () => {
  const m = process.memoryUsage();
  peakRss = Math.max(peakRss, m.rss);
  peakHeap = Math.max(peakHeap, m.heapUsed + m.arrayBuffers);
  peakContacts = Math.max(peakContacts, world.contactCount);
};
sample();
console.log(
  `${count} ${kind}es ${spread ? 'within 1 cm of' : 'on'} one spot, limit ${world.maxContactsPerShape}: ` +
    `created in ${(performance.now() - created).toFixed(0)} ms, RSS ${mb(peakRss)}`,
);
let stepTime = 0;
const marks = new Set([1, 2, 5, 10, 20, 30, 60].map((s) => 60 * s));
for (let i = 1; i <= seconds * 60; i++) {
  const t = performance.now();
  world.step(1 / 60);
  const dt = performance.now() - t;
  stepTime += dt;
  sample();
  if (i === 1) {
    console.log(
      `first step ${dt.toFixed(0)} ms: ${world.contactCount} contacts, RSS ${mb(peakRss)}, heap+buffers ${mb(peakHeap)}`,
    );
  }
  if (i === 60) console.log(`first 60 steps ${(stepTime / 1000).toFixed(1)} s`);
  if (marks.has(i)) {
    const o = overlaps();
    console.log(
      `t = ${i / 60} s: steps took ${(stepTime / 1000).toFixed(1)} s; ${world.contactCount} contacts ` +
        `(peak ${peakContacts}), ${world.crowdedShapeCount} shapes waiting, deepest overlap ${o.deepest.toFixed(3)} m, ` +
        `${o.over5cm} bodies overlapping > 5 cm; peak RSS ${mb(peakRss)}, heap+buffers ${mb(peakHeap)}; ${extent()}`,
    );
  }
}
for (const w of warnings) console.log(`warning: ${w.message}`);
console.log(`state hash ${stateHash(world)}`);
