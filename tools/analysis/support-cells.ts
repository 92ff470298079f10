/**
 * Cell helpers of the support checks on the support grid (see support-raster.ts): windows of the grid, reading
 * four cells to a word, and walking cells along spans.
 */
import type { Grid } from './grid.js';
import { columnsOf, gridAround, newBitmap } from './grid.js';
import type { Spans } from './spans.js';
import type { LayerRasters } from './support-raster.js';

/**
 * 1 in every byte of a word: masks four cells' flags at once (Cell bits: Any 0, Part 1, Support 2, Interface 3,
 * Raft 4).
 */
export const LOW_BYTES = 0x01010101;

/** A raster's cells four to a word (grid columns are a multiple of 4). */
export function words(bits: Uint8Array): Uint32Array {
  return new Uint32Array(bits.buffer, bits.byteOffset, bits.length >>> 2);
}

/** A window of grid `g` around [xmin, ymin, xmax, ymax] (mm) grown by `margin`, clamped to the grid. */
export function windowIn(g: Grid, b: [number, number, number, number], margin: number): Grid {
  const w = gridAround(b[0], b[1], b[2], b[3], g.cell, margin);
  const i0 = Math.max(g.i0, w.i0);
  const j0 = Math.max(g.j0, w.j0);
  const i1 = Math.min(g.i0 + g.cols, w.i0 + w.cols);
  const j1 = Math.min(g.j0 + g.rows, w.j0 + w.rows);
  return { cell: g.cell, i0, j0, cols: Math.max(1, i1 - i0), rows: Math.max(1, j1 - j0) };
}

/** Bounds [xmin, ymin, xmax, ymax] (mm) of a window and of cells of grid `g` (full-grid indices). */
export function cellBounds(g: Grid, win: Grid | null, cells: number[]): [number, number, number, number] {
  let i0 = Infinity,
    j0 = Infinity,
    i1 = -Infinity,
    j1 = -Infinity;
  if (win) {
    i0 = win.i0;
    j0 = win.j0;
    i1 = win.i0 + win.cols;
    j1 = win.j0 + win.rows;
  }
  for (const q of cells) {
    const i = (q % g.cols) + g.i0;
    const j = Math.floor(q / g.cols) + g.j0;
    if (i < i0) i0 = i;
    if (i + 1 > i1) i1 = i + 1;
    if (j < j0) j0 = j;
    if (j + 1 > j1) j1 = j + 1;
  }
  const c = g.cell;
  return [i0 * c, j0 * c, i1 * c, j1 * c];
}

/** The cells of window `win` (of the rasters' grid) where any of the layers `below` has one of `mask`'s bits. */
export function windowOf(rasters: LayerRasters, win: Grid, below: number[], mask: number): Uint8Array {
  const any = newBitmap(win);
  const g = rasters.grid;
  for (const k of below) {
    const r = rasters.get(k).bits;
    for (let j = 0; j < win.rows; j++) {
      const src = (j + win.j0 - g.j0) * g.cols + (win.i0 - g.i0);
      const dst = j * win.cols;
      for (let i = 0; i < win.cols; i++) if ((r[src + i]! & mask) !== 0) any[dst + i] = 1;
    }
  }
  return any;
}

/** Index in window `win` of the full-grid cell q of grid `g`. */
export function inWindow(g: Grid, win: Grid, q: number): number {
  const i = (q % g.cols) + g.i0;
  const j = Math.floor(q / g.cols) + g.j0;
  return (j - win.j0) * win.cols + (i - win.i0);
}

/** Cells of the grid whose centres lie in the region and that have any of `mask`'s bits. */
export function countMaskedInSpans(s: Spans, grid: Grid, bitmap: Uint8Array, mask: number): number {
  let n = 0;
  for (let r = 0; r < grid.rows; r++) {
    const rs = grid.j0 + r - s.j0;
    if (rs < 0 || rs >= s.rows) continue;
    const base = r * grid.cols;
    for (let q = s.start[rs]!; q < s.start[rs + 1]!; q++) {
      const [first, last] = columnsOf(grid, s.xs[2 * q]!, s.xs[2 * q + 1]!);
      for (let k = base + first; k <= base + last; k++) if ((bitmap[k]! & mask) !== 0) n++;
    }
  }
  return n;
}

/**
 * The cells of `cells` (full-grid indices in increasing order) whose centres lie outside the region, walking each
 * row's intervals along with the cells.
 */
export function outsideSpans(cells: number[], g: Grid, s: Spans): number[] {
  const out: number[] = [];
  let row = -1;
  let q = 0;
  let end = 0;
  for (const k of cells) {
    const i = k % g.cols;
    const j = (k - i) / g.cols;
    if (j !== row) {
      row = j;
      const r = j + g.j0 - s.j0;
      q = r >= 0 && r < s.rows ? s.start[r]! : 0;
      end = r >= 0 && r < s.rows ? s.start[r + 1]! : 0;
    }
    const x = (i + g.i0 + 0.5) * g.cell;
    while (q < end && s.xs[2 * q + 1]! < x) q++;
    if (q < end && s.xs[2 * q]! <= x) continue;
    out.push(k);
  }
  return out;
}

/** Full-grid indices (grid `g`) of every set cell of a window bitmap, in increasing order. */
export function setCells(g: Grid, bitmap: Uint8Array, win: Grid): number[] {
  const out: number[] = [];
  for (let j = 0; j < win.rows; j++) {
    const base = j * win.cols;
    const dst = (j + win.j0 - g.j0) * g.cols + (win.i0 - g.i0);
    for (let i = 0; i < win.cols; i++) if (bitmap[base + i] !== 0) out.push(dst + i);
  }
  return out;
}
