import { checkBoolean, checkKnownKeys, FulcrumError, fail } from '../core/errors';
import { checkRange, Limits } from '../core/limits';
import { arcTangent2 } from '../math/arc-tangent';
import { makeRotInto } from '../math/rot';
import type { Rot, Vec2 } from '../math/vec2';

/*
 * SVG path data to outlines. The parser follows the path grammar of SVG 1.1 and 2 (implicit repeated
 * commands, numbers that run together, arc flags without separators); curves and arcs are cut into
 * chords no farther than the tolerance from them. The points become shapes that feed the step, so they
 * are computed with the engine's deterministic sine, cosine and arc tangent: a path gives the same
 * bits on every JavaScript engine.
 */

/** Options of {@link parseSvgPath}. */
export interface SvgPathOptions {
  /**
   * The largest distance between a curve or arc and the chords that replace it, in the path's units
   * (before `scale`): a finite number > 0, default 0.01.
   */
  tolerance?: number;
  /** World units per path unit, in [1e-9, 1e9]; default 1. A drawing at 50 px to the metre: 1 / 50. */
  scale?: number;
  /**
   * Negate y (default false: the points keep the path's coordinates). SVG's y axis points down and the
   * world's up: `true` lands a drawing upright. Mirroring reverses the outlines' winding.
   */
  flipY?: boolean;
}

/** One subpath of an SVG path, flattened. */
export interface SvgSubpath {
  /** The outline's points in order, no two consecutive ones equal; a closed one does not repeat its start. */
  points: Vec2[];
  /** True when the subpath ends with `Z`: an outline for a concave shape or a chain loop. */
  closed: boolean;
}

const DEFAULT_TOLERANCE = 0.01;
/** No curve is cut into more chords than this: a finer tolerance is refused rather than filling memory. */
const MAX_CURVE_SEGMENTS = 100_000;
/**
 * Points closer than this fraction of the subpath's largest coordinate are one point: relative
 * commands that come back to where they started leave rounding errors of a few ulps.
 */
const WELD_FRACTION = 1e-12;
const TWO_PI = 2 * Math.PI;
const RADIANS_PER_DEGREE = Math.PI / 180;

const NO_CURVE = 0;
const CUBIC = 1;
const QUADRATIC = 2;

/** The command letters, absolute and relative, and how many arguments each takes. */
const ABSOLUTE = 'MLHVCSQTAZ';
const RELATIVE = 'mlhvcsqtaz';
const ARGUMENT_COUNTS: readonly number[] = [2, 2, 1, 1, 6, 4, 4, 2, 7, 0];

/**
 * Parses SVG path data (`M L H V C S Q T A Z`, absolute and relative, as in a `<path d="…">`) into one
 * outline per subpath: lines are kept, curves and arcs are flattened to `tolerance`. A subpath that
 * draws nothing (a lone moveto) gives no outline; an empty `d` gives none.
 *
 * The points are the path's coordinates times `scale`, y negated if `flipY`. A closed subpath
 * (ended by `Z`) suits a concave shape, an open one a chain such as a terrain.
 *
 * @throws FulcrumError naming the character index and what was found there, for data outside the
 * grammar (a path that does not start with a moveto, an unknown command, a missing number, a flag
 * other than 0 or 1, a number outside [-1e9, 1e9]); or for options out of range.
 */
export function parseSvgPath(d: string, options?: SvgPathOptions): SvgSubpath[] {
  if (typeof d !== 'string') fail('d', d, 'a string of SVG path data');
  let tolerance = DEFAULT_TOLERANCE;
  let scale = 1;
  let flipY = false;
  if (options !== undefined) {
    if (typeof options !== 'object' || options === null) fail('options', options, 'an object');
    checkKnownKeys('options', options, ['tolerance', 'scale', 'flipY']);
    if (options.tolerance !== undefined) {
      tolerance = options.tolerance;
      if (typeof tolerance !== 'number' || !(tolerance > 0 && tolerance <= Number.MAX_VALUE)) {
        fail('tolerance', tolerance, 'a finite number > 0');
      }
    }
    if (options.scale !== undefined) scale = checkRange('scale', options.scale, 1e-9, 1e9);
    if (options.flipY !== undefined) flipY = checkBoolean('flipY', options.flipY);
  }
  const path = new PathFlattener(tolerance);
  parseInto(d, path);
  path.endSubpath(false);
  const scaleY = flipY ? -scale : scale;
  // + 0 turns a -0 into 0
  return path.subpaths.map(({ points, closed }) => ({
    points: points.map((p) => ({ x: p.x * scale + 0, y: p.y * scaleY + 0 })),
    closed,
  }));
}

function syntaxError(d: string, index: number, expected: string, found?: string): never {
  const what = found ?? (index < d.length ? JSON.stringify(d[index]) : 'the end of the path');
  throw new FulcrumError(`d must be SVG path data: expected ${expected} at index ${index}, found ${what}`);
}

function isWhitespace(c: number): boolean {
  return c === 0x20 || c === 0x09 || c === 0x0a || c === 0x0d || c === 0x0c;
}

function isDigit(c: number): boolean {
  return c >= 0x30 && c <= 0x39;
}

function skipWhitespace(d: string, i: number): number {
  while (i < d.length && isWhitespace(d.charCodeAt(i))) i++;
  return i;
}

/** Whether a number may start at i: a digit, a point or a sign. */
function startsNumber(d: string, i: number): boolean {
  const c = d.charCodeAt(i);
  return isDigit(c) || c === 0x2e || c === 0x2b || c === 0x2d;
}

/**
 * The end of the number that starts at i, or -1 if none does. The grammar: a sign, then digits with
 * an optional fraction (`1`, `1.`, `1.5`) or a fraction alone (`.5`), then an optional exponent. The
 * number is the longest such text, so `.5.5` is two numbers and `-1-2` too.
 */
function scanNumber(d: string, i: number): number {
  let c = d.charCodeAt(i);
  if (c === 0x2b || c === 0x2d) c = d.charCodeAt(++i);
  let digits = false;
  while (isDigit(c)) {
    digits = true;
    c = d.charCodeAt(++i);
  }
  if (c === 0x2e) {
    c = d.charCodeAt(++i);
    while (isDigit(c)) {
      digits = true;
      c = d.charCodeAt(++i);
    }
  }
  if (!digits) return -1;
  if (c === 0x65 || c === 0x45) {
    // an exponent only if digits follow: in `1e` the number is 1 and `e` what comes after it
    let j = i + 1;
    let e = d.charCodeAt(j);
    if (e === 0x2b || e === 0x2d) e = d.charCodeAt(++j);
    if (isDigit(e)) {
      while (isDigit(d.charCodeAt(j))) j++;
      i = j;
    }
  }
  return i;
}

/**
 * Reads a command's arguments from i into `args`; returns the index after them. Between two arguments
 * a comma, whitespace or nothing; an arc's flags are one character each, `0` or `1`.
 */
function readArguments(d: string, i: number, letter: string, count: number, args: number[]): number {
  const isArc = letter === 'A' || letter === 'a';
  for (let k = 0; k < count; k++) {
    if (k > 0) {
      i = skipWhitespace(d, i);
      if (d.charCodeAt(i) === 0x2c) i = skipWhitespace(d, i + 1);
    }
    if (isArc && (k === 3 || k === 4)) {
      const c = d[i];
      if (c !== '0' && c !== '1') {
        syntaxError(d, i, `the ${k === 3 ? 'large-arc' : 'sweep'} flag (0 or 1) of "${letter}"`);
      }
      args[k] = c === '1' ? 1 : 0;
      i++;
      continue;
    }
    const end = scanNumber(d, i);
    if (end < 0) syntaxError(d, i, `a number (argument ${k + 1} of "${letter}")`);
    const text = d.slice(i, end);
    const value = Number(text);
    if (!(Math.abs(value) <= Limits.COORDINATE)) {
      syntaxError(d, i, `a number in [-${Limits.COORDINATE}, ${Limits.COORDINATE}]`, JSON.stringify(text));
    }
    args[k] = value;
    i = end;
  }
  return i;
}

/** Reads the path data command by command and hands each argument group to `path`. */
function parseInto(d: string, path: PathFlattener): void {
  const args = [0, 0, 0, 0, 0, 0, 0];
  let i = skipWhitespace(d, 0);
  if (i < d.length && d[i] !== 'M' && d[i] !== 'm') syntaxError(d, i, '"M" or "m"');
  while (i < d.length) {
    let letter = d[i];
    const relative = RELATIVE.indexOf(letter) >= 0;
    let command = relative ? RELATIVE.indexOf(letter) : ABSOLUTE.indexOf(letter);
    if (command < 0) syntaxError(d, i, 'a command letter');
    const count = ARGUMENT_COUNTS[command];
    i = skipWhitespace(d, i + 1);
    if (count === 0) {
      path.close();
      continue;
    }
    // the command repeats while numbers follow; after a moveto the repeats are linetos
    for (;;) {
      const at = i;
      i = readArguments(d, i, letter, count, args);
      path.command(ABSOLUTE[command], relative, args, at);
      if (command === 0) {
        command = 1;
        letter = relative ? 'l' : 'L';
      }
      i = skipWhitespace(d, i);
      const comma = d.charCodeAt(i) === 0x2c;
      if (comma) i = skipWhitespace(d, i + 1);
      if (i < d.length && startsNumber(d, i)) continue;
      if (comma) syntaxError(d, i, `a number (argument 1 of "${letter}")`);
      break;
    }
  }
}

/** The state of the path as it is drawn: the current point, the subpath, the last control point. */
class PathFlattener {
  readonly subpaths: SvgSubpath[] = [];
  private points: Vec2[] | null = null;
  private x = 0;
  private y = 0;
  private startX = 0;
  private startY = 0;
  /** The last curve's last control point, which S reflects after a cubic and T after a quadratic. */
  private controlX = 0;
  private controlY = 0;
  private lastCurve = NO_CURVE;
  private readonly rot: Rot = { c: 1, s: 0 };

  constructor(private readonly tolerance: number) {}

  /** One command with its arguments; `at` is their index in the data, for errors. */
  command(command: string, relative: boolean, a: readonly number[], at: number): void {
    const ox = relative ? this.x : 0;
    const oy = relative ? this.y : 0;
    const x = this.x;
    const y = this.y;
    let curve = NO_CURVE;
    switch (command) {
      case 'M':
        this.endSubpath(false);
        this.x = this.startX = ox + a[0];
        this.y = this.startY = oy + a[1];
        this.points = [{ x: this.x, y: this.y }];
        break;
      case 'L':
        this.lineTo(ox + a[0], oy + a[1]);
        break;
      case 'H':
        this.lineTo(ox + a[0], y);
        break;
      case 'V':
        this.lineTo(x, oy + a[0]);
        break;
      case 'C':
        this.cubicTo(ox + a[0], oy + a[1], ox + a[2], oy + a[3], ox + a[4], oy + a[5], at);
        curve = CUBIC;
        break;
      case 'S': {
        const reflect = this.lastCurve === CUBIC;
        const x1 = reflect ? 2 * x - this.controlX : x;
        const y1 = reflect ? 2 * y - this.controlY : y;
        this.cubicTo(x1, y1, ox + a[0], oy + a[1], ox + a[2], oy + a[3], at);
        curve = CUBIC;
        break;
      }
      case 'Q':
        this.quadraticTo(ox + a[0], oy + a[1], ox + a[2], oy + a[3], at);
        curve = QUADRATIC;
        break;
      case 'T': {
        const reflect = this.lastCurve === QUADRATIC;
        const x1 = reflect ? 2 * x - this.controlX : x;
        const y1 = reflect ? 2 * y - this.controlY : y;
        this.quadraticTo(x1, y1, ox + a[0], oy + a[1], at);
        curve = QUADRATIC;
        break;
      }
      default:
        this.arcTo(a[0], a[1], a[2], a[3] === 1, a[4] === 1, ox + a[5], oy + a[6], at);
    }
    this.lastCurve = curve;
  }

  /** Z: back to the subpath's start, which a following command other than M starts from. */
  close(): void {
    this.open();
    this.endSubpath(true);
    this.x = this.startX;
    this.y = this.startY;
    this.lastCurve = NO_CURVE;
  }

  /** Keeps the subpath being drawn if it draws anything, without duplicate points. */
  endSubpath(closed: boolean): void {
    const points = this.points;
    this.points = null;
    if (points === null) return;
    let largest = 0;
    for (const p of points) largest = Math.max(largest, Math.abs(p.x), Math.abs(p.y));
    const weld = Math.min(this.tolerance, WELD_FRACTION * largest);
    const same = (p: Vec2, q: Vec2) => Math.abs(p.x - q.x) <= weld && Math.abs(p.y - q.y) <= weld;
    const kept = [points[0]];
    for (let i = 1; i < points.length; i++) {
      if (!same(points[i], kept[kept.length - 1])) kept.push(points[i]);
    }
    if (closed && kept.length > 1 && same(kept[kept.length - 1], kept[0])) kept.pop();
    if (kept.length > 1) this.subpaths.push({ points: kept, closed });
  }

  /** After Z, a drawing command starts a new subpath at the current point (the closed one's start). */
  private open(): Vec2[] {
    if (this.points === null) {
      this.points = [{ x: this.x, y: this.y }];
      this.startX = this.x;
      this.startY = this.y;
    }
    return this.points;
  }

  private lineTo(x: number, y: number): void {
    this.open().push({ x, y });
    this.x = x;
    this.y = y;
  }

  /**
   * How many chords a curve needs, from `exact`, the real-valued count its error bound asks for
   * (floor + 1 keeps each chord's error strictly under the tolerance).
   */
  private segments(exact: number, at: number): number {
    if (!(exact < MAX_CURVE_SEGMENTS)) {
      throw new FulcrumError(
        `tolerance ${this.tolerance} is too fine for the curve at index ${at} of d: it would take more than ${MAX_CURVE_SEGMENTS} segments`,
      );
    }
    return Math.floor(exact) + 1;
  }

  /**
   * Uniform steps in t. A chord over a step h of a polynomial curve B strays at most h² max|B''| / 8
   * from it, and |B''| <= 6 max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|) on a cubic.
   */
  private cubicTo(x1: number, y1: number, x2: number, y2: number, x3: number, y3: number, at: number): void {
    const x0 = this.x;
    const y0 = this.y;
    const bend = Math.max(
      Math.sqrt((x0 - 2 * x1 + x2) ** 2 + (y0 - 2 * y1 + y2) ** 2),
      Math.sqrt((x1 - 2 * x2 + x3) ** 2 + (y1 - 2 * y2 + y3) ** 2),
    );
    const n = this.segments(Math.sqrt((0.75 * bend) / this.tolerance), at);
    const points = this.open();
    for (let i = 1; i < n; i++) {
      const t = i / n;
      const s = 1 - t;
      const b0 = s * s * s;
      const b1 = 3 * s * s * t;
      const b2 = 3 * s * t * t;
      const b3 = t * t * t;
      points.push({ x: b0 * x0 + b1 * x1 + b2 * x2 + b3 * x3, y: b0 * y0 + b1 * y1 + b2 * y2 + b3 * y3 });
    }
    points.push({ x: x3, y: y3 });
    this.x = x3;
    this.y = y3;
    this.controlX = x2;
    this.controlY = y2;
  }

  /** As cubicTo, with B'' = 2 (P0 - 2 P1 + P2). */
  private quadraticTo(x1: number, y1: number, x2: number, y2: number, at: number): void {
    const x0 = this.x;
    const y0 = this.y;
    const bend = Math.sqrt((x0 - 2 * x1 + x2) ** 2 + (y0 - 2 * y1 + y2) ** 2);
    const n = this.segments(Math.sqrt(bend / (4 * this.tolerance)), at);
    const points = this.open();
    for (let i = 1; i < n; i++) {
      const t = i / n;
      const s = 1 - t;
      const b0 = s * s;
      const b1 = 2 * s * t;
      const b2 = t * t;
      points.push({ x: b0 * x0 + b1 * x1 + b2 * x2, y: b0 * y0 + b1 * y1 + b2 * y2 });
    }
    points.push({ x: x2, y: y2 });
    this.x = x2;
    this.y = y2;
    this.controlX = x1;
    this.controlY = y1;
  }

  /**
   * An elliptical arc from the current point to (x2, y2), per the SVG implementation notes:
   * out-of-range radii corrected (F.6.6), endpoints converted to centre and angles (F.6.5).
   */
  private arcTo(
    radiusX: number,
    radiusY: number,
    degrees: number,
    largeArc: boolean,
    sweep: boolean,
    x2: number,
    y2: number,
    at: number,
  ): void {
    const x1 = this.x;
    const y1 = this.y;
    if (x1 === x2 && y1 === y2) return; // an arc to its own start draws nothing
    let rx = Math.abs(radiusX);
    let ry = Math.abs(radiusY);
    if (rx === 0 || ry === 0) {
      this.lineTo(x2, y2);
      return;
    }
    const q = makeRotInto((degrees - 360 * Math.floor(degrees / 360)) * RADIANS_PER_DEGREE, this.rot);
    const c = q.c;
    const s = q.s;
    // the half chord in the ellipse's axes
    const hx = (x1 - x2) / 2;
    const hy = (y1 - y2) / 2;
    const px = c * hx + s * hy;
    const py = -s * hx + c * hy;
    // radii too small to reach the end point grow, keeping their ratio, until the ellipse just does
    const lambda = (px * px) / (rx * rx) + (py * py) / (ry * ry);
    if (lambda > 1) {
      const grow = Math.sqrt(lambda);
      rx *= grow;
      ry *= grow;
    }
    const rx2 = rx * rx;
    const ry2 = ry * ry;
    const below = rx2 * py * py + ry2 * px * px;
    const above = rx2 * ry2 - below;
    // of the two centres, the one on the side the flags choose
    let k = above > 0 ? Math.sqrt(above / below) : 0;
    if (largeArc === sweep) k = -k;
    const ccx = (k * rx * py) / ry;
    const ccy = (-k * ry * px) / rx;
    const cx = c * ccx - s * ccy + (x1 + x2) / 2;
    const cy = s * ccx + c * ccy + (y1 + y2) / 2;
    const ux = (px - ccx) / rx;
    const uy = (py - ccy) / ry;
    const vx = (-px - ccx) / rx;
    const vy = (-py - ccy) / ry;
    const start = arcTangent2(uy, ux);
    let sweepAngle = arcTangent2(ux * vy - uy * vx, ux * vx + uy * vy);
    if (!sweep && sweepAngle > 0) sweepAngle -= TWO_PI;
    else if (sweep && sweepAngle < 0) sweepAngle += TWO_PI;
    // a chord over an angle step h strays at most r (1 - cos(h / 2)) <= r h² / 8 from the ellipse,
    // r its larger radius (the ellipse is the image of a circle stretched by at most r)
    const n = this.segments(Math.abs(sweepAngle) * Math.sqrt(Math.max(rx, ry) / (8 * this.tolerance)), at);
    const points = this.open();
    const e = this.rot;
    for (let i = 1; i < n; i++) {
      makeRotInto(start + (sweepAngle * i) / n, e);
      const ex = rx * e.c;
      const ey = ry * e.s;
      points.push({ x: c * ex - s * ey + cx, y: s * ex + c * ey + cy });
    }
    points.push({ x: x2, y: y2 });
    this.x = x2;
    this.y = y2;
  }
}
