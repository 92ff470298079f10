/**
 * Nearest-neighbour ordering, shared by the planner and the infill engine: from the current position,
 * take next the item whose nearest candidate entry point is closest (ties: lower item, then lower
 * candidate). Entry points sit in a uniform grid searched in growing rings, so n items cost about O(n)
 * grid work instead of the O(n²) of a plain scan.
 */
import { bucketByCell } from './cell-buckets.js';
import type { Polyline, Pt } from './types.js';

/** Up to this many entry points are scanned rather than put in a grid. */
const SCAN_BELOW = 24;
/** The grid is made again of the entries still to be printed when they are fewer than its own over this. */
const REGRID_SHARE = 4;

/**
 * Entry points bucketed by cell in flat arrays: cell c's entries are items[start[c] … start[c] + live[c]),
 * the used ones dropped as the search passes them.
 */
interface Grid {
  cell: number;
  minX: number;
  minY: number;
  cols: number;
  rows: number;
  start: Int32Array;
  live: Int32Array;
  items: Int32Array;
}

/** A grid of the entries `ids` (indices into `ends`, two coordinates each). */
function buildGrid(ends: Float64Array, ids: Int32Array): Grid {
  const count = ids.length;
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (let k = 0; k < count; k++) {
    const x = ends[2 * ids[k]],
      y = ends[2 * ids[k] + 1];
    if (x < minX) minX = x;
    if (y < minY) minY = y;
    if (x > maxX) maxX = x;
    if (y > maxY) maxY = y;
  }
  const span = Math.max(maxX - minX, maxY - minY, 1);
  const cols0 = Math.max(1, Math.ceil(Math.sqrt(count)));
  const cell = Math.max(span / cols0, 1);
  const cols = Math.floor((maxX - minX) / cell) + 1;
  const rows = Math.floor((maxY - minY) / cell) + 1;
  const cellOf = new Int32Array(count);
  for (let k = 0; k < count; k++)
    cellOf[k] = Math.floor((ends[2 * ids[k] + 1] - minY) / cell) * cols + Math.floor((ends[2 * ids[k]] - minX) / cell);
  const { start, items } = bucketByCell(cellOf, cols * rows);
  // bucketed by position in `ids`: back to entry numbers, still ascending within a cell
  for (let k = 0; k < count; k++) items[k] = ids[items[k]];
  // every entry live at first
  const live = new Int32Array(cols * rows);
  for (let c = 0; c < cols * rows; c++) live[c] = start[c + 1] - start[c];
  return { cell, minX, minY, cols, rows, start, live, items };
}

/** The nearest live entry found so far by `visit` (squared distance, entry), reset before each search; one per call of orderNearest. */
interface Nearest {
  d: number;
  entry: number;
}

/** Look at the live entries of cell (gx, gy) from (x, y), dropping used ones, and keep the nearest (the lowest entry on a tie). */
function visit(
  grid: Grid,
  gx: number,
  gy: number,
  x: number,
  y: number,
  ends: Float64Array,
  owner: readonly number[],
  used: Uint8Array,
  near: Nearest,
): void {
  const c = gy * grid.cols + gx;
  const from = grid.start[c],
    n = grid.live[c];
  if (n === 0) return;
  const items = grid.items;
  let kept = from;
  for (let k = from; k < from + n; k++) {
    const e = items[k];
    if (used[owner[e]]) continue; // dead entry: dropped from the cell
    items[kept++] = e;
    const ddx = ends[2 * e] - x,
      ddy = ends[2 * e + 1] - y;
    const d = ddx * ddx + ddy * ddy;
    if (d < near.d || (d === near.d && e < near.entry)) {
      near.d = d;
      near.entry = e;
    }
  }
  grid.live[c] = kept - from;
}

/**
 * Order items by nearest end. Each item offers candidate start points (`starts(i)`), and ends where
 * `endOf(i, startIdx)` says. Returns [item, startIdx] pairs in print order.
 */
export function orderNearest(
  count: number,
  candidates: (i: number) => readonly Pt[],
  endOf: (i: number, startIdx: number) => Pt,
  from: Pt,
): Array<[number, number]> {
  if (count === 0) return [];
  if (count === 1) {
    // one item (a tree branch's loop, its one line): its nearest start, the first on a tie, as the scan below finds it
    const c = candidates(0);
    let best = 0;
    let bestD = Infinity;
    for (let k = 0; k < c.length; k++) {
      const ddx = c[k].x - from.x,
        ddy = c[k].y - from.y;
      const d = ddx * ddx + ddy * ddy;
      if (d < bestD) {
        bestD = d;
        best = k;
      }
    }
    return [[0, best]];
  }
  // flatten candidate start points
  const owner: number[] = [];
  const which: number[] = [];
  const pts: number[] = [];
  for (let i = 0; i < count; i++) {
    const c = candidates(i);
    for (let k = 0; k < c.length; k++) {
      owner.push(i);
      which.push(k);
      pts.push(c[k].x, c[k].y);
    }
  }
  const n = owner.length;
  const used = new Uint8Array(count);
  const out: Array<[number, number]> = [];
  let at = from;
  if (n <= SCAN_BELOW) {
    // a few entry points (a support branch's loop and line, an island's walls): a plain scan finds the
    // same nearest (first in item, then candidate order on a tie) without building a grid
    for (let done = 0; done < count; done++) {
      let best = -1;
      let bestD = Infinity;
      for (let e = 0; e < n; e++) {
        if (used[owner[e]]) continue;
        const ddx = pts[2 * e] - at.x,
          ddy = pts[2 * e + 1] - at.y;
        const d = ddx * ddx + ddy * ddy;
        if (d < bestD) {
          bestD = d;
          best = e;
        }
      }
      const item = owner[best];
      used[item] = 1;
      out.push([item, which[best]]);
      at = endOf(item, which[best]);
    }
    return out;
  }
  const ends = Float64Array.from(pts);
  const all = new Int32Array(n);
  for (let e = 0; e < n; e++) all[e] = e;
  let grid = buildGrid(ends, all);
  // entries per item, and entries whose item is still to be printed: when most of the grid's entries are
  // used, its rings are mostly empty cells, and a grid of the rest is made (the search is exact either way)
  const per = new Int32Array(count);
  for (let e = 0; e < n; e++) per[owner[e]]++;
  let liveEntries = n,
    gridEntries = n;
  const near: Nearest = { d: Infinity, entry: -1 };
  for (let done = 0; done < count; done++) {
    if (liveEntries * REGRID_SHARE < gridEntries && liveEntries >= SCAN_BELOW) {
      const rest = new Int32Array(liveEntries);
      let k = 0;
      for (let e = 0; e < n; e++) if (!used[owner[e]]) rest[k++] = e;
      grid = buildGrid(ends, rest);
      gridEntries = liveEntries;
    }
    const cx = Math.floor((at.x - grid.minX) / grid.cell);
    const cy = Math.floor((at.y - grid.minY) / grid.cell);
    near.entry = -1;
    near.d = Infinity;
    const x = at.x,
      y = at.y;
    // rings of cells around (cx, cy), starting at the first ring that touches the grid
    const dxOut = cx < 0 ? -cx : cx >= grid.cols ? cx - grid.cols + 1 : 0;
    const dyOut = cy < 0 ? -cy : cy >= grid.rows ? cy - grid.rows + 1 : 0;
    const r0 = Math.max(dxOut, dyOut);
    const rMax = Math.max(Math.abs(cx), Math.abs(cx - grid.cols + 1), Math.abs(cy), Math.abs(cy - grid.rows + 1));
    for (let r = r0; r <= rMax; r++) {
      // every point in ring r is at least (r - 1) cells away
      if (near.entry >= 0 && (r - 1) * grid.cell > Math.sqrt(near.d)) break;
      const y0 = Math.max(0, cy - r),
        y1 = Math.min(grid.rows - 1, cy + r);
      const x0 = Math.max(0, cx - r),
        x1 = Math.min(grid.cols - 1, cx + r);
      for (let gy = y0; gy <= y1; gy++) {
        if (gy === cy - r || gy === cy + r) {
          for (let gx = x0; gx <= x1; gx++) visit(grid, gx, gy, x, y, ends, owner, used, near);
        } else {
          if (cx - r >= 0 && cx - r < grid.cols) visit(grid, cx - r, gy, x, y, ends, owner, used, near);
          if (r > 0 && cx + r >= 0 && cx + r < grid.cols) visit(grid, cx + r, gy, x, y, ends, owner, used, near);
        }
      }
    }
    const best = near.entry;
    const item = owner[best];
    used[item] = 1;
    liveEntries -= per[item];
    out.push([item, which[best]]);
    at = endOf(item, which[best]);
  }
  return out;
}

/** Order closed loops nearest-first, each rotated to start at its nearest vertex; also returns where the last ends. */
export function orderLoops(loops: readonly Polyline[], from: Pt): { loops: Polyline[]; end: Pt } {
  const order = orderNearest(
    loops.length,
    (i) => loops[i],
    (i, k) => loops[i][k],
    from,
  );
  const out = order.map(([i, k]) => (k === 0 ? loops[i] : loops[i].slice(k).concat(loops[i].slice(0, k))));
  return { loops: out, end: out.length ? out[out.length - 1][0] : from };
}

/** Order open polylines nearest-first, reversing those entered from their far end. */
export function orderPolylines(lines: readonly Polyline[], from: Pt): Polyline[] {
  const order = orderNearest(
    lines.length,
    (i) => [lines[i][0], lines[i][lines[i].length - 1]],
    (i, s) => (s === 0 ? lines[i][lines[i].length - 1] : lines[i][0]),
    from,
  );
  return order.map(([i, s]) => (s === 0 ? lines[i] : lines[i].slice().reverse()));
}
