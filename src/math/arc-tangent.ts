const HALF_PI = Math.PI / 2;
const PI = Math.PI;

/** atan(t) for 0 <= t <= 1: three half-angle reductions, then the odd Taylor series. */
function atanUnit(t: number): number {
  // tan(x/2) = tan(x) / (1 + sqrt(1 + tan(x)^2)); after three halvings t <= tan(pi/32) < 0.0985
  t = t / (1 + Math.sqrt(1 + t * t));
  t = t / (1 + Math.sqrt(1 + t * t));
  t = t / (1 + Math.sqrt(1 + t * t));
  const t2 = t * t;
  // terms up to t^17/17; the first omitted term is below 1e-20
  const series =
    t *
    (1 +
      t2 *
        (-1 / 3 +
          t2 *
            (1 / 5 +
              t2 * (-1 / 7 + t2 * (1 / 9 + t2 * (-1 / 11 + t2 * (1 / 13 + t2 * (-1 / 15 + t2 / 17))))))));
  return 8 * series;
}

/**
 * Deterministic atan2 built only from + - * / and sqrt, for values that feed the simulation
 * (Math.atan2 is not specified to the last bit). Returns an angle in [-pi, pi]; atan2(0, 0) = 0.
 */
export function arcTangent2(y: number, x: number): number {
  const ax = Math.abs(x);
  const ay = Math.abs(y);
  if (ax === 0 && ay === 0) return 0;
  let angle = ax >= ay ? atanUnit(ay / ax) : HALF_PI - atanUnit(ax / ay);
  if (x < 0) angle = PI - angle;
  return y < 0 ? -angle : angle;
}
