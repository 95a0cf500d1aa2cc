// In-place quicksorts over Int32Array ranges: no allocation, recursion only on the smaller part
// (depth O(log n)), insertion sort for short ranges. Deterministic: only comparisons and swaps.

const SHORT = 12;

/** Sorts `a[lo, hi)` ascending. */
export function sortInts(a: Int32Array, lo: number, hi: number): void {
  while (hi - lo > SHORT) {
    const pivot = medianOfThree(a[lo], a[(lo + hi) >> 1], a[hi - 1]);
    let i = lo;
    let j = hi - 1;
    while (i <= j) {
      while (a[i] < pivot) i++;
      while (a[j] > pivot) j--;
      if (i <= j) {
        const t = a[i];
        a[i++] = a[j];
        a[j--] = t;
      }
    }
    if (j - lo < hi - i) {
      sortInts(a, lo, j + 1);
      lo = i;
    } else {
      sortInts(a, i, hi);
      hi = j + 1;
    }
  }
  for (let i = lo + 1; i < hi; i++) {
    const v = a[i];
    let j = i - 1;
    while (j >= lo && a[j] > v) {
      a[j + 1] = a[j];
      j--;
    }
    a[j + 1] = v;
  }
}

/**
 * Sorts the pairs (a[2k], a[2k + 1]) for k in [lo, hi) lexicographically, moving both ints together.
 * `lo` and `hi` count pairs, not ints.
 */
export function sortIntPairs(a: Int32Array, lo: number, hi: number): void {
  while (hi - lo > SHORT) {
    // Median of the first, middle and last pair, by (first, second).
    let m = lo;
    const mid = (lo + hi) >> 1;
    const last = hi - 1;
    if (pairLess(a, mid, lo) !== pairLess(a, mid, last)) m = mid;
    else if (pairLess(a, last, lo) !== pairLess(a, last, mid)) m = last;
    const pa = a[2 * m];
    const pb = a[2 * m + 1];
    let i = lo;
    let j = last;
    while (i <= j) {
      while (a[2 * i] < pa || (a[2 * i] === pa && a[2 * i + 1] < pb)) i++;
      while (a[2 * j] > pa || (a[2 * j] === pa && a[2 * j + 1] > pb)) j--;
      if (i <= j) {
        swapPairs(a, i++, j--);
      }
    }
    if (j - lo < hi - i) {
      sortIntPairs(a, lo, j + 1);
      lo = i;
    } else {
      sortIntPairs(a, i, hi);
      hi = j + 1;
    }
  }
  for (let i = lo + 1; i < hi; i++) {
    const va = a[2 * i];
    const vb = a[2 * i + 1];
    let j = i - 1;
    while (j >= lo && (a[2 * j] > va || (a[2 * j] === va && a[2 * j + 1] > vb))) {
      a[2 * j + 2] = a[2 * j];
      a[2 * j + 3] = a[2 * j + 1];
      j--;
    }
    a[2 * j + 2] = va;
    a[2 * j + 3] = vb;
  }
}

function medianOfThree(x: number, y: number, z: number): number {
  if (x < y) return y < z ? y : Math.max(x, z);
  return x < z ? x : Math.max(y, z);
}

function pairLess(a: Int32Array, i: number, j: number): boolean {
  const x = a[2 * i];
  const y = a[2 * j];
  return x < y || (x === y && a[2 * i + 1] < a[2 * j + 1]);
}

function swapPairs(a: Int32Array, i: number, j: number): void {
  const x = a[2 * i];
  const y = a[2 * i + 1];
  a[2 * i] = a[2 * j];
  a[2 * i + 1] = a[2 * j + 1];
  a[2 * j] = x;
  a[2 * j + 1] = y;
}
