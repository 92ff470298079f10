/**
 * Regions as horizontal spans: for each lattice row j (centre y = (j + 0.5)·cell) a sorted list of disjoint
 * x-intervals in mm. Exact in x, sampled in y; booleans, growing and shrinking are cheap row-wise operations.
 */
import type { Grid } from './grid.js';
import { columnsOf, countRange } from './grid.js';

export interface Spans {
  cell: number;
  /** Lattice index of the first row. */
  j0: number;
  rows: number;
  /** Interval offsets per row: row r holds intervals start[r] .. start[r+1]-1. */
  start: Uint32Array;
  /** Interval k is [xs[2k], xs[2k+1]]. */
  xs: Float64Array;
}

export function emptySpans(cell: number): Spans {
  return { cell, j0: 0, rows: 0, start: new Uint32Array(1), xs: new Float64Array(0) };
}

/** Builds spans row by row, in increasing row order. */
export class SpansBuilder {
  private xs: Float64Array;
  private n = 0;
  private readonly start: Uint32Array;
  private row = 0;
  constructor(
    private readonly cell: number,
    private readonly j0: number,
    private readonly rows: number,
  ) {
    this.start = new Uint32Array(Math.max(0, rows) + 1);
    this.xs = new Float64Array(64);
  }
  /** Appends [a, b] to row `r` (0-based, never decreasing between calls). */
  add(r: number, a: number, b: number): void {
    while (this.row < r) this.start[++this.row] = this.n;
    if (2 * this.n + 2 > this.xs.length) {
      const bigger = new Float64Array(this.xs.length * 2);
      bigger.set(this.xs);
      this.xs = bigger;
    }
    this.xs[2 * this.n] = a;
    this.xs[2 * this.n + 1] = b;
    this.n++;
  }
  finish(): Spans {
    while (this.row < this.rows) this.start[++this.row] = this.n;
    return { cell: this.cell, j0: this.j0, rows: this.rows, start: this.start, xs: this.xs.slice(0, 2 * this.n) };
  }
}

/** Total area in mm². */
export function spansArea(s: Spans): number {
  let sum = 0;
  for (let k = 0; k < s.xs.length; k += 2) sum += s.xs[k + 1]! - s.xs[k]!;
  return sum * s.cell;
}

export function isEmptySpans(s: Spans): boolean {
  return s.xs.length === 0;
}

/** Whether (x, y) lies in the region (using the row whose band holds y). */
export function spansContain(s: Spans, x: number, y: number): boolean {
  const r = Math.floor(y / s.cell) - s.j0;
  if (r < 0 || r >= s.rows) return false;
  for (let k = s.start[r]!; k < s.start[r + 1]!; k++) {
    if (x < s.xs[2 * k]!) return false;
    if (x <= s.xs[2 * k + 1]!) return true;
  }
  return false;
}

/** Bounding box [xmin, ymin, xmax, ymax] in mm, or null when empty. */
export function spansBounds(s: Spans): [number, number, number, number] | null {
  let xmin = Infinity;
  let xmax = -Infinity;
  let rmin = -1;
  let rmax = -1;
  for (let r = 0; r < s.rows; r++) {
    const a = s.start[r]!;
    const b = s.start[r + 1]!;
    if (a === b) continue;
    if (rmin < 0) rmin = r;
    rmax = r;
    if (s.xs[2 * a]! < xmin) xmin = s.xs[2 * a]!;
    if (s.xs[2 * b - 1]! > xmax) xmax = s.xs[2 * b - 1]!;
  }
  if (rmin < 0) return null;
  return [xmin, (s.j0 + rmin) * s.cell, xmax, (s.j0 + rmax + 1) * s.cell];
}

type RowOp = 'union' | 'intersect' | 'subtract';

/** Row-wise boolean of two regions on the same lattice. */
export function spansBoolean(a: Spans, b: Spans, op: RowOp): Spans {
  const cell = a.cell;
  let jStart: number;
  let jEnd: number;
  if (op === 'union') {
    if (a.rows === 0) return b;
    if (b.rows === 0) return a;
    jStart = Math.min(a.j0, b.j0);
    jEnd = Math.max(a.j0 + a.rows, b.j0 + b.rows);
  } else if (op === 'intersect') {
    jStart = Math.max(a.j0, b.j0);
    jEnd = Math.min(a.j0 + a.rows, b.j0 + b.rows);
  } else {
    jStart = a.j0;
    jEnd = a.j0 + a.rows;
  }
  if (jEnd <= jStart) return emptySpans(cell);
  const out = new SpansBuilder(cell, jStart, jEnd - jStart);
  const scratch = new RowScratch();
  for (let j = jStart; j < jEnd; j++) {
    const [a0, a1] = rowRange(a, j);
    const [b0, b1] = rowRange(b, j);
    scratch.clear();
    if (op === 'union') unionRows(a.xs, a0, a1, b.xs, b0, b1, scratch);
    else if (op === 'intersect') intersectRows(a.xs, a0, a1, b.xs, b0, b1, scratch);
    else subtractRows(a.xs, a0, a1, b.xs, b0, b1, scratch);
    for (let k = 0; k < scratch.n; k++) out.add(j - jStart, scratch.a[k]!, scratch.b[k]!);
  }
  return out.finish();
}

/** Minkowski sum with a disc of radius r (mm), sampled at row centres. */
export function dilateSpans(s: Spans, r: number): Spans {
  if (s.rows === 0 || r <= 0) return s;
  const c = s.cell;
  const K = Math.floor(r / c + 1e-9);
  const half = new Float64Array(K + 1);
  for (let k = 0; k <= K; k++) half[k] = Math.sqrt(Math.max(0, r * r - k * c * k * c));
  const rows = s.rows + 2 * K;
  const out = new SpansBuilder(c, s.j0 - K, rows);
  const scratch = new RowScratch();
  for (let ro = 0; ro < rows; ro++) {
    scratch.clear();
    for (let k = -K; k <= K; k++) {
      const rs = ro - K + k;
      if (rs < 0 || rs >= s.rows) continue;
      const h = half[Math.abs(k)]!;
      for (let q = s.start[rs]!; q < s.start[rs + 1]!; q++) scratch.push(s.xs[2 * q]! - h, s.xs[2 * q + 1]! + h);
    }
    scratch.sortAndMerge();
    for (let k = 0; k < scratch.n; k++) out.add(ro, scratch.a[k]!, scratch.b[k]!);
  }
  return out.finish();
}

/** Points whose disc of radius r (mm) lies in the region, sampled at row centres. */
export function erodeSpans(s: Spans, r: number): Spans {
  if (s.rows === 0 || r <= 0) return s;
  const c = s.cell;
  const K = Math.floor(r / c + 1e-9);
  const rows = s.rows - 2 * K;
  if (rows <= 0) return emptySpans(c);
  const half = new Float64Array(K + 1);
  for (let k = 0; k <= K; k++) half[k] = Math.sqrt(Math.max(0, r * r - k * c * k * c));
  const out = new SpansBuilder(c, s.j0 + K, rows);
  let cur = new RowScratch();
  let next = new RowScratch();
  const shrunk = new RowScratch();
  for (let ro = 0; ro < rows; ro++) {
    const centre = ro + K;
    cur.clear();
    shrinkRow(s, centre, half[0]!, cur);
    for (let k = 1; k <= K && cur.n > 0; k++) {
      for (let side = -1; side <= 1; side += 2) {
        shrunk.clear();
        shrinkRow(s, centre + side * k, half[k]!, shrunk);
        next.clear();
        intersectRows2(cur, shrunk, next);
        const t = cur;
        cur = next;
        next = t;
      }
    }
    for (let k = 0; k < cur.n; k++) out.add(ro, cur.a[k]!, cur.b[k]!);
  }
  return out.finish();
}

/** Sets (to `value`) every cell of the window whose centre lies in the region. */
export function spansToBitmap(s: Spans, grid: Grid, bitmap: Uint8Array, value = 1): void {
  for (let r = 0; r < grid.rows; r++) {
    const rs = grid.j0 + r - s.j0;
    if (rs < 0 || rs >= s.rows) continue;
    const base = r * grid.cols;
    for (let q = s.start[rs]!; q < s.start[rs + 1]!; q++) {
      const [first, last] = columnsOf(grid, s.xs[2 * q]!, s.xs[2 * q + 1]!);
      if (last >= first) bitmap.fill(value, base + first, base + last + 1);
    }
  }
}

/** The set cells of a bitmap as spans (each run of cells becomes the interval between its cell edges). */
export function bitmapToSpans(bitmap: Uint8Array, grid: Grid): Spans {
  const c = grid.cell;
  const out = new SpansBuilder(c, grid.j0, grid.rows);
  const wordsPerRow = grid.cols % 4 === 0 && bitmap.byteOffset % 4 === 0 ? grid.cols >>> 2 : 0;
  const words = wordsPerRow > 0 ? new Uint32Array(bitmap.buffer, bitmap.byteOffset, bitmap.length >>> 2) : null;
  for (let r = 0; r < grid.rows; r++) {
    const base = r * grid.cols;
    let i = 0;
    while (i < grid.cols) {
      // Skip empty cells four at a time where the row is word-aligned.
      if (words && (i & 3) === 0 && words[(base + i) >>> 2] === 0) {
        i += 4;
        continue;
      }
      if (bitmap[base + i] === 0) {
        i++;
        continue;
      }
      const runStart = i;
      while (i < grid.cols && bitmap[base + i] !== 0) i++;
      out.add(r, (grid.i0 + runStart) * c, (grid.i0 + i) * c);
    }
  }
  return out.finish();
}

/** Cells of the window whose centres lie in the region: [cells in region, of those set in `bitmap`]. */
export function countInSpans(s: Spans, grid: Grid, bitmap: Uint8Array): [number, number] {
  let total = 0;
  let set = 0;
  for (let r = 0; r < grid.rows; r++) {
    const rs = grid.j0 + r - s.j0;
    if (rs < 0 || rs >= s.rows) continue;
    const base = r * grid.cols;
    for (let q = s.start[rs]!; q < s.start[rs + 1]!; q++) {
      const [first, last] = columnsOf(grid, s.xs[2 * q]!, s.xs[2 * q + 1]!);
      if (last < first) continue;
      total += last - first + 1;
      set += countRange(bitmap, base + first, base + last + 1);
    }
  }
  return [total, set];
}

// ---- row helpers -------------------------------------------------------------------------------------------

/** Growable pair of interval-end arrays for one row. */
class RowScratch {
  a = new Float64Array(32);
  b = new Float64Array(32);
  n = 0;
  clear(): void {
    this.n = 0;
  }
  push(a: number, b: number): void {
    if (this.n === this.a.length) {
      const na = new Float64Array(this.n * 2);
      const nb = new Float64Array(this.n * 2);
      na.set(this.a);
      nb.set(this.b);
      this.a = na;
      this.b = nb;
    }
    this.a[this.n] = a;
    this.b[this.n] = b;
    this.n++;
  }
  /** Sorts by start and merges overlapping intervals. */
  sortAndMerge(): void {
    const n = this.n;
    if (n < 2) return;
    sortIntervals(this.a, this.b, n);
    let w = 0;
    for (let k = 1; k < n; k++) {
      if (this.a[k]! <= this.b[w]!) {
        if (this.b[k]! > this.b[w]!) this.b[w] = this.b[k]!;
      } else {
        w++;
        this.a[w] = this.a[k]!;
        this.b[w] = this.b[k]!;
      }
    }
    this.n = w + 1;
  }
}

/** Sorts parallel arrays a[0..n), b[0..n) by `a`. */
function sortIntervals(a: Float64Array, b: Float64Array, n: number): void {
  sortByKey(a, b, 0, n - 1);
}

/**
 * Sorts a[lo..hi] ascending, moving b's entries along: quicksort on ranges, insertion sort below 16 elements.
 */
export function sortByKey(a: Float64Array, b: Float64Array | Int8Array, lo: number, hi: number): void {
  while (hi - lo >= 16) {
    const pivot = a[(lo + hi) >>> 1]!;
    let i = lo;
    let j = hi;
    while (i <= j) {
      while (a[i]! < pivot) i++;
      while (a[j]! > pivot) j--;
      if (i <= j) {
        const ta = a[i]!;
        a[i] = a[j]!;
        a[j] = ta;
        const tb = b[i]!;
        b[i] = b[j]!;
        b[j] = tb;
        i++;
        j--;
      }
    }
    // Recurse into the smaller part, loop on the larger.
    if (j - lo < hi - i) {
      sortByKey(a, b, lo, j);
      lo = i;
    } else {
      sortByKey(a, b, i, hi);
      hi = j;
    }
  }
  for (let i = lo + 1; i <= hi; i++) {
    const ka = a[i]!;
    const kb = b[i]!;
    let j = i - 1;
    while (j >= lo && a[j]! > ka) {
      a[j + 1] = a[j]!;
      b[j + 1] = b[j]!;
      j--;
    }
    a[j + 1] = ka;
    b[j + 1] = kb;
  }
}

function rowRange(s: Spans, j: number): [number, number] {
  const r = j - s.j0;
  if (r < 0 || r >= s.rows) return [0, 0];
  return [s.start[r]!, s.start[r + 1]!];
}

function shrinkRow(s: Spans, r: number, h: number, out: RowScratch): void {
  if (r < 0 || r >= s.rows) return;
  for (let q = s.start[r]!; q < s.start[r + 1]!; q++) {
    const a = s.xs[2 * q]! + h;
    const b = s.xs[2 * q + 1]! - h;
    if (b >= a) out.push(a, b);
  }
}

function unionRows(
  xa: Float64Array,
  a0: number,
  a1: number,
  xb: Float64Array,
  b0: number,
  b1: number,
  out: RowScratch,
): void {
  for (let q = a0; q < a1; q++) out.push(xa[2 * q]!, xa[2 * q + 1]!);
  for (let q = b0; q < b1; q++) out.push(xb[2 * q]!, xb[2 * q + 1]!);
  out.sortAndMerge();
}

function intersectRows(
  xa: Float64Array,
  a0: number,
  a1: number,
  xb: Float64Array,
  b0: number,
  b1: number,
  out: RowScratch,
): void {
  let p = a0;
  let q = b0;
  while (p < a1 && q < b1) {
    const lo = Math.max(xa[2 * p]!, xb[2 * q]!);
    const hi = Math.min(xa[2 * p + 1]!, xb[2 * q + 1]!);
    if (hi > lo) out.push(lo, hi);
    if (xa[2 * p + 1]! < xb[2 * q + 1]!) p++;
    else q++;
  }
}

function intersectRows2(x: RowScratch, y: RowScratch, out: RowScratch): void {
  let p = 0;
  let q = 0;
  while (p < x.n && q < y.n) {
    const lo = Math.max(x.a[p]!, y.a[q]!);
    const hi = Math.min(x.b[p]!, y.b[q]!);
    if (hi >= lo) out.push(lo, hi);
    if (x.b[p]! < y.b[q]!) p++;
    else q++;
  }
}

function subtractRows(
  xa: Float64Array,
  a0: number,
  a1: number,
  xb: Float64Array,
  b0: number,
  b1: number,
  out: RowScratch,
): void {
  let q = b0;
  for (let p = a0; p < a1; p++) {
    let lo = xa[2 * p]!;
    const hi = xa[2 * p + 1]!;
    while (q < b1 && xb[2 * q + 1]! <= lo) q++;
    let k = q;
    while (k < b1 && xb[2 * k]! < hi) {
      if (xb[2 * k]! > lo) out.push(lo, xb[2 * k]!);
      lo = Math.max(lo, xb[2 * k + 1]!);
      k++;
    }
    if (hi > lo) out.push(lo, hi);
  }
}
