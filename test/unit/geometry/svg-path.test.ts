import { describe, expect, it } from 'vitest';
import { FulcrumError, parseSvgPath, type SvgSubpath, type Vec2 } from '../../../src/index';

/*
 * parseSvgPath against outlines computed by hand and against the curves themselves: arcs against
 * the circle or ellipse they lie on (centres and angles worked out here from the geometry, not from
 * the code's conversion), Béziers against their Bernstein form evaluated here.
 */

type P = [number, number];
const pts = (...xy: P[]): Vec2[] => xy.map(([x, y]) => ({ x, y }));

function only(d: string, options?: Parameters<typeof parseSvgPath>[1]): SvgSubpath {
  const subpaths = parseSvgPath(d, options);
  expect(subpaths.length).toBe(1);
  return subpaths[0];
}

function rejects(f: () => unknown, message: RegExp): void {
  let error: unknown;
  try {
    f();
  } catch (e) {
    error = e;
  }
  expect(error).toBeInstanceOf(FulcrumError);
  expect((error as Error).message).toMatch(message);
}

function distanceToSegment(p: Vec2, a: Vec2, b: Vec2): number {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const len2 = ex * ex + ey * ey;
  const t = len2 === 0 ? 0 : Math.max(0, Math.min(1, ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2));
  return Math.hypot(p.x - a.x - t * ex, p.y - a.y - t * ey);
}

/** Twice the signed area (shoelace). */
function doubleArea(points: Vec2[]): number {
  let sum = 0;
  for (let i = 0; i < points.length; i++) {
    const a = points[i];
    const b = points[(i + 1) % points.length];
    sum += a.x * b.y - a.y * b.x;
  }
  return sum;
}

type Curve = (t: number) => Vec2;

function cubic(...c: P[]): Curve {
  return (t) => {
    const s = 1 - t;
    const w = [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t];
    return { x: w.reduce((a, wi, i) => a + wi * c[i][0], 0), y: w.reduce((a, wi, i) => a + wi * c[i][1], 0) };
  };
}

function quadratic(...c: P[]): Curve {
  return (t) => {
    const s = 1 - t;
    const w = [s * s, 2 * s * t, t * t];
    return { x: w.reduce((a, wi, i) => a + wi * c[i][0], 0), y: w.reduce((a, wi, i) => a + wi * c[i][1], 0) };
  };
}

/** The parameter of the curve's point nearest p: a dense sampling, then a ternary search around the best sample. */
function nearest(curve: Curve, p: Vec2): { t: number; distance: number } {
  const dist = (t: number) => Math.hypot(curve(t).x - p.x, curve(t).y - p.y);
  const N = 4000;
  let best = 0;
  for (let i = 1; i <= N; i++) if (dist(i / N) < dist(best / N)) best = i;
  let lo = Math.max(0, (best - 1) / N);
  let hi = Math.min(1, (best + 1) / N);
  for (let k = 0; k < 200; k++) {
    const m1 = lo + (hi - lo) / 3;
    const m2 = hi - (hi - lo) / 3;
    if (dist(m1) < dist(m2)) hi = m2;
    else lo = m1;
  }
  const t = (lo + hi) / 2;
  return { t, distance: dist(t) };
}

/**
 * The flattened points lie on the curve, in order from its start to its end, and no stretch of the
 * curve between two of them strays more than `tolerance` from their chord. Returns the largest stray.
 */
function expectFlattened(points: Vec2[], curve: Curve, tolerance: number): number {
  const params = points.map((p) => {
    const { t, distance } = nearest(curve, p);
    expect(distance).toBeLessThanOrEqual(1e-9);
    return t;
  });
  expect(params[0]).toBeCloseTo(0, 9);
  expect(params[params.length - 1]).toBeCloseTo(1, 9);
  let worst = 0;
  for (let i = 0; i + 1 < points.length; i++) {
    expect(params[i + 1]).toBeGreaterThan(params[i]);
    for (let k = 1; k < 200; k++) {
      const q = curve(params[i] + ((params[i + 1] - params[i]) * k) / 200);
      worst = Math.max(worst, distanceToSegment(q, points[i], points[i + 1]));
    }
  }
  expect(worst).toBeLessThanOrEqual(tolerance);
  return worst;
}

/** An ellipse: centre, radii, rotation of its x axis (radians). */
interface Ellipse {
  cx: number;
  cy: number;
  rx: number;
  ry: number;
  phi: number;
}

function ellipsePoint(e: Ellipse, theta: number): Vec2 {
  const ex = e.rx * Math.cos(theta);
  const ey = e.ry * Math.sin(theta);
  const c = Math.cos(e.phi);
  const s = Math.sin(e.phi);
  return { x: e.cx + c * ex - s * ey, y: e.cy + s * ex + c * ey };
}

/** The point in the ellipse's unit-circle frame. */
function ellipseFrame(e: Ellipse, p: Vec2): Vec2 {
  const dx = p.x - e.cx;
  const dy = p.y - e.cy;
  const c = Math.cos(e.phi);
  const s = Math.sin(e.phi);
  return { x: (c * dx + s * dy) / e.rx, y: (-s * dx + c * dy) / e.ry };
}

/**
 * Every point on the ellipse (its equation within 1e-9), the angles going monotonically from
 * `start` by `sweep`, and the chords within `tolerance` of the arc.
 */
function expectOnArc(points: Vec2[], e: Ellipse, start: number, sweep: number, tolerance: number): void {
  const angles: number[] = [];
  for (const p of points) {
    const u = ellipseFrame(e, p);
    expect(Math.abs(u.x * u.x + u.y * u.y - 1)).toBeLessThanOrEqual(1e-9);
    let a = Math.atan2(u.y, u.x);
    if (angles.length === 0) {
      // the start angle up to whole turns
      a += 2 * Math.PI * Math.round((start - a) / (2 * Math.PI));
    } else {
      const prev = angles[angles.length - 1];
      a += 2 * Math.PI * Math.round((prev - a) / (2 * Math.PI)); // unwrapped next to the previous one
      expect(Math.sign(a - prev)).toBe(Math.sign(sweep));
    }
    angles.push(a);
  }
  expect(angles[0]).toBeCloseTo(start, 9);
  expect(angles[angles.length - 1] - angles[0]).toBeCloseTo(sweep, 9);
  let worst = 0;
  for (let i = 0; i + 1 < points.length; i++) {
    for (let k = 1; k < 200; k++) {
      const q = ellipsePoint(e, angles[i] + ((angles[i + 1] - angles[i]) * k) / 200);
      worst = Math.max(worst, distanceToSegment(q, points[i], points[i + 1]));
    }
  }
  expect(worst).toBeLessThanOrEqual(tolerance);
}

describe('parseSvgPath: lines, moves and closes', () => {
  it('M L H V Z, absolute and relative, give the outline drawn by hand', () => {
    const square = { points: pts([10, 20], [30, 40], [50, 40], [50, 60]), closed: true };
    expect(parseSvgPath('M10 20 L30 40 H50 V60 Z')).toEqual([square]);
    expect(parseSvgPath('m10 20 l20 20 h20 v20 z')).toEqual([square]);
    expect(parseSvgPath('M1 2 h3 v4 l-1 1 L0 0 z')).toEqual([
      { points: pts([1, 2], [4, 2], [4, 6], [3, 7], [0, 0]), closed: true },
    ]);
    expect(parseSvgPath('M0 0 L4 0 L4 3')).toEqual([{ points: pts([0, 0], [4, 0], [4, 3]), closed: false }]);
  });

  it('repeats a command while numbers follow; after a moveto the repeats are linetos', () => {
    expect(only('M0 0 1 0 1 1').points).toEqual(pts([0, 0], [1, 0], [1, 1]));
    expect(only('m1 1 2 0 0 2').points).toEqual(pts([1, 1], [3, 1], [3, 3])); // relative l after m
    expect(only('M0 0 L1 0 2 0 2 1').points).toEqual(pts([0, 0], [1, 0], [2, 0], [2, 1]));
    expect(only('M0 0 h1 2 3').points).toEqual(pts([0, 0], [1, 0], [3, 0], [6, 0]));
    expect(only('M0 0 V1 2 3').points).toEqual(pts([0, 0], [0, 1], [0, 2], [0, 3]));
    expect(only('M0 0 v1 2 3').points).toEqual(pts([0, 0], [0, 1], [0, 3], [0, 6]));
    expect(only('M0 0,1 1,2 0').points).toEqual(pts([0, 0], [1, 1], [2, 0])); // commas between groups
  });

  it('Z returns to the subpath start, which the next command starts from', () => {
    // a drawing command after Z starts a new subpath at the closed one's start
    expect(parseSvgPath('M10 10 L20 10 L20 20 Z L0 0')).toEqual([
      { points: pts([10, 10], [20, 10], [20, 20]), closed: true },
      { points: pts([10, 10], [0, 0]), closed: false },
    ]);
    // a relative moveto after Z is relative to that start
    expect(parseSvgPath('M10 10 l5 0 l0 5 z m1 1 l1 0')).toEqual([
      { points: pts([10, 10], [15, 10], [15, 15]), closed: true },
      { points: pts([11, 11], [12, 11]), closed: false },
    ]);
    // a relative lineto after z too
    expect(parseSvgPath('m10 10 h5 v5 z l-3 -4')[1].points).toEqual(pts([10, 10], [7, 6]));
  });

  it('one outline per subpath; a lone moveto or an empty path gives none', () => {
    expect(parseSvgPath('M0 0 L1 0 M5 5 L6 5 Z')).toEqual([
      { points: pts([0, 0], [1, 0]), closed: false },
      { points: pts([5, 5], [6, 5]), closed: true },
    ]);
    expect(parseSvgPath('M0 0 M1 1 L2 2')).toEqual([{ points: pts([1, 1], [2, 2]), closed: false }]);
    expect(parseSvgPath('M1 1')).toEqual([]);
    expect(parseSvgPath('M1 1 Z')).toEqual([]);
    expect(parseSvgPath('')).toEqual([]);
    expect(parseSvgPath(' \t\n\r\f')).toEqual([]);
  });

  it('drops a closing point equal to the start and consecutive duplicates', () => {
    expect(only('M0 0 L1 0 L1 1 L0 0 Z')).toEqual({ points: pts([0, 0], [1, 0], [1, 1]), closed: true });
    expect(only('M0 0 L0 0 L1 0 L1 0 L1 1 H1').points).toEqual(pts([0, 0], [1, 0], [1, 1]));
    // an open subpath that ends where it began keeps both ends: only Z closes
    expect(only('M0 0 L1 0 L1 1 L0 0')).toEqual({
      points: pts([0, 0], [1, 0], [1, 1], [0, 0]),
      closed: false,
    });
    // relative steps that come back to the start up to rounding (0.1 + 0.2 - 0.2 is not 0.1 in doubles)
    expect(0.1 + 0.2 - 0.2).not.toBe(0.1);
    const back = only('M0.1 0 l0.2 0 l0 1 l-0.2 0 l0 -1 z');
    expect(back).toEqual({
      points: pts([0.1, 0], [0.1 + 0.2, 0], [0.1 + 0.2, 1], [0.1 + 0.2 - 0.2, 1]),
      closed: true,
    });
  });
});

describe('parseSvgPath: the grammar', () => {
  it('reads numbers as SVG does: exponents, leading and trailing points, signs that separate', () => {
    expect(only('M1e-3 2E+2L1.e1 .5e1').points).toEqual(pts([0.001, 200], [10, 5]));
    expect(only('M.5.5 1.5.25').points).toEqual(pts([0.5, 0.5], [1.5, 0.25])); // .5.5 is two numbers
    expect(only('M-1-2-3-4').points).toEqual(pts([-1, -2], [-3, -4]));
    expect(only('M+1+2L-.5-.5').points).toEqual(pts([1, 2], [-0.5, -0.5]));
    expect(only('M0 0L1e1-1e1').points).toEqual(pts([0, 0], [10, -10]));
  });

  it('takes whitespace and commas between numbers, in any mix, and none where the grammar allows', () => {
    const expected = pts([1, 2], [3, 4], [5, 6]);
    expect(only('\t\nM\r\n1\f,2  L 3 , 4\n5,6 \n').points).toEqual(expected);
    expect(only('M1,2L3,4,5,6').points).toEqual(expected);
    expect(only('M1 2L3 4L5 6').points).toEqual(expected);
    expect(only('M1,2 L3,4 5,6').points).toEqual(expected);
  });

  it('reads arc flags written without separators', () => {
    const spaced = parseSvgPath('M0 0 a1 1 0 0 0 1 1');
    expect(parseSvgPath('M0 0 a1 1 0 00 1 1')).toEqual(spaced);
    expect(parseSvgPath('M0 0 a1,1,0,0,0,1,1')).toEqual(spaced);
    expect(parseSvgPath('M0 0 a1 1 0 001 1')).toEqual(spaced);
    expect(parseSvgPath('M0 0 a1 1 0 0,0 1,1')).toEqual(spaced);
    // "10" after the rotation is two flags: large arc 1, sweep 0
    expect(parseSvgPath('M0 0 a1 1 0 10 1 1')).toEqual(parseSvgPath('M0 0 a1 1 0 1 0 1 1'));
    expect(parseSvgPath('M0 0 a1 1 0 10 1 1')).not.toEqual(spaced);
  });
});

describe('parseSvgPath: bad input', () => {
  it('names the character index and what was found there', () => {
    rejects(
      () => parseSvgPath('L0 0'),
      /^d must be SVG path data: expected "M" or "m" at index 0, found "L"$/,
    );
    rejects(() => parseSvgPath('  l0 0'), /expected "M" or "m" at index 2, found "l"/);
    rejects(() => parseSvgPath('5 5'), /expected "M" or "m" at index 0, found "5"/);
    rejects(() => parseSvgPath('M0 0 X1 1'), /expected a command letter at index 5, found "X"/);
    // a letter whose upper case is S is not S
    rejects(() => parseSvgPath('M0 0 \u017f1 1 2 2'), /expected a command letter at index 5, found "\u017f"/);
    rejects(
      () => parseSvgPath('M0 0 L1'),
      /expected a number \(argument 2 of "L"\) at index 7, found the end/,
    );
    rejects(() => parseSvgPath('M0 0 C1 1 2 2'), /argument 5 of "C"\) at index 13, found the end/);
    rejects(() => parseSvgPath('M0 0 L1,,2'), /at index 8, found ","/);
    rejects(() => parseSvgPath('M,0 0'), /at index 1, found ","/);
    rejects(() => parseSvgPath('M0 0 L1 1,'), /at index 10, found the end/);
    rejects(() => parseSvgPath('M0 0,L1 1'), /at index 5, found "L"/);
    rejects(() => parseSvgPath('M0 0 L1 -'), /expected a number \(argument 2 of "L"\) at index 8, found "-"/);
    rejects(() => parseSvgPath('M1e 2'), /expected a number \(argument 2 of "M"\) at index 2, found "e"/);
    rejects(
      () => parseSvgPath('M0 0 A1 1 0 2 0 1 1'),
      /large-arc flag \(0 or 1\) of "A" at index 12, found "2"/,
    );
    rejects(() => parseSvgPath('M0 0 a1 1 0 0 7 1 1'), /sweep flag \(0 or 1\) of "a" at index 14, found "7"/);
    rejects(() => parseSvgPath('M0 0 L1 1 Z 1 1'), /expected a command letter at index 12, found "1"/);
    rejects(() => parseSvgPath('M1e999 0'), /at index 1, found "1e999"/);
    rejects(
      () => parseSvgPath('M0 0 L2e9 0'),
      /a number in \[-1000000000, 1000000000\] at index 6, found "2e9"/,
    );
  });

  it('refuses a d that is not a string and options out of range', () => {
    rejects(() => parseSvgPath(42 as unknown as string), /^d must be a string of SVG path data, got 42$/);
    rejects(() => parseSvgPath(null as unknown as string), /^d must be .*, got null$/);
    const d = 'M0 0 L1 1';
    rejects(() => parseSvgPath(d, null as never), /^options must be an object, got null$/);
    rejects(() => parseSvgPath(d, 0.1 as never), /^options must be an object, got 0.1$/);
    rejects(() => parseSvgPath(d, { tolerence: 0.1 } as never), /unknown option "tolerence"/);
    for (const bad of [0, -1, Number.NaN, Number.POSITIVE_INFINITY, '0.1', null]) {
      rejects(
        () => parseSvgPath(d, { tolerance: bad as number }),
        /^tolerance must be a finite number > 0, got /,
      );
    }
    for (const bad of [0, -1, 1e10, Number.NaN, '2']) {
      rejects(
        () => parseSvgPath(d, { scale: bad as number }),
        /^scale must be a number in \[1e-9, 1000000000\]/,
      );
    }
    rejects(() => parseSvgPath(d, { flipY: 1 as unknown as boolean }), /^flipY must be a boolean, got 1$/);
  });

  it('refuses a tolerance so fine that a curve would take more than 100000 segments', () => {
    rejects(
      () => parseSvgPath('M0 0 L1 1 A1 1 0 0 1 1000 0', { tolerance: 1e-12 }),
      /^tolerance 1e-12 is too fine for the curve at index 11 of d: it would take more than 100000 segments$/,
    );
    rejects(() => parseSvgPath('M0 0 C0 1e6 1e6 1e6 1e6 0', { tolerance: 1e-6 }), /curve at index 6 of d/);
    // a coarser tolerance draws it
    expect(only('M0 0 C0 1e6 1e6 1e6 1e6 0', { tolerance: 1 }).points.length).toBeGreaterThan(100);
  });
});

describe('parseSvgPath: arcs', () => {
  it('a half circle by each sweep: on the circle, through the side the sweep flag says', () => {
    const circle = { cx: 0, cy: 0, rx: 1, ry: 1, phi: 0 };
    // sweep 1: the angle increases, from 0 through pi/2 (the point (0, 1)) to pi
    const up = only('M1 0 A1 1 0 0 1 -1 0', { tolerance: 1e-3 }).points;
    expectOnArc(up, circle, 0, Math.PI, 1e-3);
    for (const p of up) expect(p.y).toBeGreaterThanOrEqual(0);
    // sweep 0: it decreases, through (0, -1)
    const down = only('M1 0 A1 1 0 0 0 -1 0', { tolerance: 1e-3 }).points;
    expectOnArc(down, circle, 0, -Math.PI, 1e-3);
    // no more chords than the least count that keeps within the tolerance, plus one
    const least = Math.ceil(Math.PI / (2 * Math.acos(1 - 1e-3)));
    expect(up.length - 1).toBeGreaterThanOrEqual(least);
    expect(up.length - 1).toBeLessThanOrEqual(least + 1);
  });

  it('the four flag combinations pick the arc the spec defines', () => {
    // unit circles through (0, 0) and (1, 1) are centred at (1, 0) or (0, 1)
    const at10 = { cx: 1, cy: 0, rx: 1, ry: 1, phi: 0 };
    const at01 = { cx: 0, cy: 1, rx: 1, ry: 1, phi: 0 };
    const cases: [string, Ellipse, number, number][] = [
      // flags: large-arc, sweep; centre; start angle; signed sweep
      ['0 0', at10, Math.PI, -Math.PI / 2], // small arc, angle decreasing: round (1, 0) from pi to pi/2
      ['1 0', at01, -Math.PI / 2, (-3 * Math.PI) / 2], // large arc, decreasing: round (0, 1)
      ['0 1', at01, -Math.PI / 2, Math.PI / 2], // small arc, increasing: round (0, 1)
      ['1 1', at10, Math.PI, (3 * Math.PI) / 2], // large arc, increasing: round (1, 0)
    ];
    for (const [flags, circle, start, sweep] of cases) {
      for (const tolerance of [0.1, 1e-3]) {
        const { points } = only(`M0 0 A1 1 0 ${flags} 1 1`, { tolerance });
        expect(points[0]).toEqual({ x: 0, y: 0 });
        expect(points[points.length - 1]).toEqual({ x: 1, y: 1 });
        expectOnArc(points, circle, start, sweep, tolerance);
        // relative: the same arc drawn from (3, -2)
        const moved = only(`M3 -2 a1 1 0 ${flags} 1 1`, { tolerance }).points;
        expectOnArc(moved, { ...circle, cx: circle.cx + 3, cy: circle.cy - 2 }, start, sweep, tolerance);
      }
    }
  });

  it('rotated ellipse arcs lie on the ellipse, for every flag combination', () => {
    // an ellipse at (2, -1) with radii 3 and 1.5, its x axis turned 30 degrees; the arc from angle
    // 0.3 to 2.1 (a sweep of 1.8 < pi) and the other arcs between the same two points
    const e: Ellipse = { cx: 2, cy: -1, rx: 3, ry: 1.5, phi: Math.PI / 6 };
    const a = ellipsePoint(e, 0.3);
    const b = ellipsePoint(e, 2.1);
    // the other ellipse of these radii through a and b: e turned half a turn about the chord's middle
    const twin: Ellipse = { ...e, cx: a.x + b.x - e.cx, cy: a.y + b.y - e.cy };
    const cases: [string, Ellipse, number, number][] = [
      ['0 1', e, 0.3, 1.8],
      ['1 0', e, 0.3, 1.8 - 2 * Math.PI],
      // on the twin, a sits at angle 2.1 + pi and b at 0.3 + pi
      ['1 1', twin, 2.1 + Math.PI, 2 * Math.PI - 1.8],
      ['0 0', twin, 2.1 + Math.PI, -1.8],
    ];
    for (const [flags, ellipse, start, sweep] of cases) {
      for (const rotation of ['30', '390', '-330']) {
        const tolerance = 2e-3;
        const { points } = only(`M${a.x} ${a.y} A3 1.5 ${rotation} ${flags} ${b.x} ${b.y}`, { tolerance });
        expectOnArc(points, ellipse, start, sweep, tolerance);
      }
    }
  });

  it('radii too small to reach the end point grow in proportion until they just do (F.6.6)', () => {
    // radii 1 and 2 across a chord of 10 along x: scaled by 5 to 5 and 10, centred mid-chord
    const { points } = only('M0 0 A1 2 0 0 1 10 0', { tolerance: 0.01 });
    expectOnArc(points, { cx: 5, cy: 0, rx: 5, ry: 10, phi: 0 }, Math.PI, Math.PI, 0.01);
    for (const p of points) expect(p.y).toBeLessThanOrEqual(0); // angles from pi to 2 pi
    // a circle of radius 1 rotated 45 degrees across a chord of 4: radius 2, about (2, 0)
    const { points: small } = only('M0 0 A1 1 45 1 0 4 0', { tolerance: 0.01 });
    expectOnArc(small, { cx: 2, cy: 0, rx: 2, ry: 2, phi: 0 }, Math.PI, -Math.PI, 0.01);
    // negative radii count as their magnitudes
    expect(parseSvgPath('M0 0 A-1 -2 0 0 1 10 0', { tolerance: 0.01 })).toEqual(
      parseSvgPath('M0 0 A1 2 0 0 1 10 0', { tolerance: 0.01 }),
    );
  });

  it('an arc with a zero radius is a line; an arc to its own start draws nothing', () => {
    expect(only('M0 0 A0 5 0 0 1 3 4').points).toEqual(pts([0, 0], [3, 4]));
    expect(only('M0 0 a5 0 0 1 1 3 4').points).toEqual(pts([0, 0], [3, 4]));
    expect(only('M1 1 A2 2 0 1 1 1 1 L2 2').points).toEqual(pts([1, 1], [2, 2]));
  });

  it('a full circle of two arcs has the area of a circle, less at most perimeter x tolerance', () => {
    const r = 2;
    for (const tolerance of [0.1, 0.01, 1e-3]) {
      const circle = only('M1 3 A2 2 0 0 1 5 3 A2 2 0 0 1 1 3 Z', { tolerance });
      expect(circle.closed).toBe(true);
      expect(circle.points[0]).toEqual({ x: 1, y: 3 });
      expect(circle.points[circle.points.length - 1]).not.toEqual({ x: 1, y: 3 }); // closing point dropped
      for (const p of circle.points)
        expect(Math.abs(Math.hypot(p.x - 3, p.y - 3) - r)).toBeLessThanOrEqual(1e-9);
      // each chord cuts off a circular segment of area at most chord x sagitta <= chord x tolerance,
      // and the chords are shorter than the circumference
      const area = doubleArea(circle.points) / 2;
      expect(area).toBeLessThanOrEqual(Math.PI * r * r);
      expect(area).toBeGreaterThanOrEqual(Math.PI * r * r - 2 * Math.PI * r * tolerance);
      // flipped, the same circle turns the other way
      const flipped = only('M1 3 A2 2 0 0 1 5 3 A2 2 0 0 1 1 3 Z', { tolerance, flipY: true });
      expect(doubleArea(flipped.points) / 2).toBeCloseTo(-area, 12);
    }
  });
});

describe('parseSvgPath: Bézier curves', () => {
  it('cubic curves: every point on the curve, every chord within the tolerance', () => {
    for (const tolerance of [0.1, 0.01, 1e-4]) {
      expectFlattened(
        only('M0 0 C1 2 3 2 4 0', { tolerance }).points,
        cubic([0, 0], [1, 2], [3, 2], [4, 0]),
        tolerance,
      );
      // an S bend
      expectFlattened(
        only('M0 0 C0 3 4 -3 4 0', { tolerance }).points,
        cubic([0, 0], [0, 3], [4, -3], [4, 0]),
        tolerance,
      );
      // relative control points: c from (10, 10)
      expectFlattened(
        only('M10 10 c1 2 3 2 4 0', { tolerance }).points,
        cubic([10, 10], [11, 12], [13, 12], [14, 10]),
        tolerance,
      );
    }
    // the chords are not needlessly many: a quarter of the tolerance, about twice the points
    const coarse = only('M0 0 C1 2 3 2 4 0', { tolerance: 0.04 }).points.length - 1;
    const fine = only('M0 0 C1 2 3 2 4 0', { tolerance: 0.01 }).points.length - 1;
    expect(fine / coarse).toBeGreaterThan(1.5);
    expect(fine / coarse).toBeLessThan(2.5);
  });

  it('quadratic curves: every point on the curve, every chord within the tolerance', () => {
    for (const tolerance of [0.1, 0.01, 1e-4]) {
      expectFlattened(
        only('M0 0 Q2 4 4 0', { tolerance }).points,
        quadratic([0, 0], [2, 4], [4, 0]),
        tolerance,
      );
      expectFlattened(
        only('M-1 1 q3 -5 6 -2', { tolerance }).points,
        quadratic([-1, 1], [2, -4], [5, -1]),
        tolerance,
      );
    }
  });

  it('a straight curve with evenly spaced control points is its chord', () => {
    expect(only('M0 0 C1 1 2 2 3 3').points).toEqual(pts([0, 0], [3, 3]));
    expect(only('M0 0 Q1 1 2 2').points).toEqual(pts([0, 0], [2, 2]));
  });

  it('S reflects the last cubic control point about the current point, else starts at it', () => {
    // (3, 2) reflected about (4, 0) is (5, -2)
    const smooth = only('M0 0 C1 2 3 2 4 0 S7 -2 8 0').points;
    expect(smooth).toEqual(only('M0 0 C1 2 3 2 4 0 C5 -2 7 -2 8 0').points);
    expect(only('M0 0 c1 2 3 2 4 0 s3 -2 4 0').points).toEqual(smooth);
    const second = smooth.slice(smooth.findIndex((p) => p.x === 4 && p.y === 0));
    expectFlattened(second, cubic([4, 0], [5, -2], [7, -2], [8, 0]), 0.01);
    // S after S reflects the S's own second control point: (7, -2) about (8, 0) is (9, 2)
    expect(only('M0 0 C1 2 3 2 4 0 S7 -2 8 0 S11 2 12 0').points).toEqual(
      only('M0 0 C1 2 3 2 4 0 C5 -2 7 -2 8 0 C9 2 11 2 12 0').points,
    );
    // after a line, a quadratic or a close, no reflection: the first control point is the current point
    expect(only('M0 0 L1 0 S3 2 4 0').points).toEqual(only('M0 0 L1 0 C1 0 3 2 4 0').points);
    expect(only('M0 0 Q1 1 2 0 S3 1 4 0').points).toEqual(only('M0 0 Q1 1 2 0 C2 0 3 1 4 0').points);
    expect(parseSvgPath('M0 0 C1 1 2 1 3 0 Z S1 -1 2 0')[1].points).toEqual(
      only('M0 0 C0 0 1 -1 2 0').points,
    );
  });

  it('T reflects the last quadratic control point about the current point, else starts at it', () => {
    // (1, 1) about (2, 0) is (3, -1); then (3, -1) about (4, 0) is (5, 1)
    const smooth = only('M0 0 Q1 1 2 0 T4 0 T6 0').points;
    expect(smooth).toEqual(only('M0 0 Q1 1 2 0 Q3 -1 4 0 Q5 1 6 0').points);
    expect(only('M0 0 q1 1 2 0 t2 0 t2 0').points).toEqual(smooth);
    const last = smooth.slice(smooth.findIndex((p) => p.x === 4 && p.y === 0));
    expectFlattened(last, quadratic([4, 0], [5, 1], [6, 0]), 0.01);
    // after a cubic, no reflection: T from (3, 0) with its control at (3, 0), a straight run to (5, 0)
    const afterCubic = only('M0 0 C1 1 2 1 3 0 T5 0').points;
    expect(afterCubic).toEqual(only('M0 0 C1 1 2 1 3 0 Q3 0 5 0').points);
    const run = afterCubic.slice(afterCubic.findIndex((p) => p.x === 3 && p.y === 0));
    for (let i = 1; i < run.length; i++) {
      expect(run[i].y).toBe(0);
      expect(run[i].x).toBeGreaterThan(run[i - 1].x);
    }
    expect(run[run.length - 1]).toEqual({ x: 5, y: 0 });
  });
});

describe('parseSvgPath: units and the y axis', () => {
  it('scale and flipY map the drawing into the world; by default the points are the path’s', () => {
    const d = 'M0 0 L100 0 L100 50 Z';
    expect(only(d).points).toEqual(pts([0, 0], [100, 0], [100, 50]));
    const world = only(d, { scale: 1 / 50, flipY: true }).points;
    expect(world).toEqual(pts([0, 0], [2, 0], [2, -1]));
    expect(Object.is(world[0].y, 0)).toBe(true); // no -0
    expect(only(d, { flipY: true }).points).toEqual(pts([0, 0], [100, 0], [100, -50]));
  });

  it('the tolerance is in the path’s units: scaled, the error scales with it', () => {
    const scale = 1 / 50;
    const tolerance = 0.5;
    const { points } = only('M0 0 A100 100 0 0 1 200 0', { tolerance, scale });
    const circle = { cx: 100 * scale, cy: 0, rx: 100 * scale, ry: 100 * scale, phi: 0 };
    expectOnArc(points, circle, Math.PI, Math.PI, tolerance * scale);
  });

  it('the default tolerance is 0.01', () => {
    const d = 'M1 0 A1 1 0 0 1 -1 0 Q0 -2 1 0';
    expect(parseSvgPath(d)).toEqual(parseSvgPath(d, { tolerance: 0.01 }));
    expect(parseSvgPath(d)).not.toEqual(parseSvgPath(d, { tolerance: 0.02 }));
  });
});
