/**
 * A window onto the global square lattice of cell size `cell`: lattice cell (i, j) spans [i·cell, (i+1)·cell) ×
 * [j·cell, (j+1)·cell) in mm. Every raster of one analysis shares the lattice, so rasters of different layers and
 * windows line up cell for cell. Bitmaps are row-major Uint8Arrays of cols × rows.
 */

export interface Grid {
  /** Cell size in mm. */
  cell: number;
  /** Lattice index of the first column and row. */
  i0: number;
  j0: number;
  cols: number;
  rows: number;
}

/**
 * The smallest window holding [xmin, xmax] × [ymin, ymax] grown by `margin` mm on every side, with a column count
 * that is a multiple of 4 so that bitmap rows can be read four cells at a time.
 */
export function gridAround(xmin: number, ymin: number, xmax: number, ymax: number, cell: number, margin: number): Grid {
  const i0 = Math.floor((xmin - margin) / cell);
  const j0 = Math.floor((ymin - margin) / cell);
  const i1 = Math.ceil((xmax + margin) / cell);
  const j1 = Math.ceil((ymax + margin) / cell);
  return { cell, i0, j0, cols: Math.ceil(Math.max(1, i1 - i0) / 4) * 4, rows: Math.max(1, j1 - j0) };
}

export function newBitmap(grid: Grid): Uint8Array {
  return new Uint8Array(grid.cols * grid.rows);
}

/** Number of set cells (bitmaps hold 0 or 1). */
export function countSet(bitmap: Uint8Array): number {
  return countRange(bitmap, 0, bitmap.length);
}

/** Number of set cells among bitmap[from, to) (bitmaps hold 0 or 1), summing four cells per word where aligned. */
export function countRange(bitmap: Uint8Array, from: number, to: number): number {
  let n = 0;
  let k = from;
  const aligned = bitmap.byteOffset % 4 === 0;
  while (k < to && (k & 3) !== 0) n += bitmap[k++]!;
  if (aligned) {
    const words = new Uint32Array(bitmap.buffer, bitmap.byteOffset, bitmap.length >>> 2);
    const last = to >>> 2;
    for (let w = k >>> 2; w < last; w++) {
      const v = words[w]!;
      if (v !== 0) n += Math.imul(v, 0x01010101) >>> 24;
    }
    k = Math.max(k, last << 2);
  }
  while (k < to) n += bitmap[k++]!;
  return n;
}

/** Whether the cell holding point (x, y) is set; false outside the window. */
export function bitmapAt(bitmap: Uint8Array, grid: Grid, x: number, y: number): boolean {
  const i = Math.floor(x / grid.cell) - grid.i0;
  const j = Math.floor(y / grid.cell) - grid.j0;
  if (i < 0 || j < 0 || i >= grid.cols || j >= grid.rows) return false;
  return bitmap[j * grid.cols + i] !== 0;
}

/** Column range [first, last] of cells whose centres lie in [a, b] (mm), clamped to the window. */
export function columnsOf(grid: Grid, a: number, b: number): [number, number] {
  const first = Math.max(0, Math.ceil(a / grid.cell - 0.5) - grid.i0);
  const last = Math.min(grid.cols - 1, Math.floor(b / grid.cell - 0.5) - grid.i0);
  return [first, last];
}
