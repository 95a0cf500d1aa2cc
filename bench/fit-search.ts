/**
 * The largest count of rooms that keeps 60 Hz, for the rooms benchmarks: first `guess` rooms, then up
 * by a fifth while they fit, then bisection between the largest count seen to fit and the smallest
 * seen not to. `trial(count)` measures that many rooms.
 */
export async function largestThatFits<T extends { keeps60Hz: boolean }>(
  trial: (count: number) => Promise<T>,
  guess: number,
): Promise<{ rooms: number; trials: (T & { rooms: number })[] }> {
  const trials: (T & { rooms: number })[] = [];
  let fits = 0;
  let fails = Number.POSITIVE_INFINITY;
  let count = Math.max(1, Math.round(guess));
  for (;;) {
    const t = { ...(await trial(count)), rooms: count };
    trials.push(t);
    if (t.keeps60Hz) fits = count;
    else fails = count;
    if (fails - fits <= 1) return { rooms: fits, trials };
    count = fails === Number.POSITIVE_INFINITY ? Math.ceil(fits * 1.2) + 1 : Math.floor((fits + fails) / 2);
  }
}
