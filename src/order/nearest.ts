/**
 * Nearest-first search: from where the nozzle is, take next the path whose nearest entry point is closest, and
 * go on from where that path is left. Entry points sit in a uniform grid searched in growing rings of cells, so
 * n paths cost about O(n) grid work instead of the O(n²) of a plain scan. The search is exact: what a tie
 * between equally near entry points gives is set by `Ties`.
 */
import { bucketByCell } from '../geometry/cell-buckets.js';
import type { Pt } from '../geometry/types.js';

/**
 * How a tie between equally near entry points is settled.
 *
 * - `'lowest'`: the lowest path's, and of its entry points the first: the order is the plain nearest-first order,
 *   whatever the grid. The grid has about one cell per entry point and is made again of the rest as they are used
 *   up; a few entry points are scanned without one.
 * - `'grid'`: the first the grid search comes to: ring by ring out from the nozzle's cell (clamped into the grid),
 *   row by row, and in a cell the entry points added last first, a used one taking the place of the cell's last.
 *   The grid has about one cell per path, at least GRID_TIES_CELL wide, and is never made again. Custom infill
 *   (shader and image) paths are ordered so, and their G-code depends on it.
 */
export type Ties = 'lowest' | 'grid';

/** A path visited: its index, and the index of the entry point it is entered at. */
export type Visit = [path: number, entry: number];

/**
 * The paths to order, by index. Path i is a line (`line(i)`: its entry points are its first and last point; it is
 * left at the end it was not entered at, and may be printed either way round) or a path left where it is entered
 * (a loop at one of its entry points, or a group of paths entered at one of its own).
 */
export interface PathSet {
  readonly count: number;
  /** Where path i may be entered: a line's two ends, first then last; at least one point. */
  entries(i: number): readonly Pt[];
  line(i: number): boolean;
  /**
   * Where the nozzle is after path i when it is not where `line` says: entered at entries(i)[entry], coming from
   * `at`. Only the nearest-first order reads it (shortening takes each path's ends as `line` says).
   */
  exit?(i: number, entry: number, at: Pt): Pt;
}

/** With `'lowest'` ties, up to this many entry points are scanned rather than put in a grid. */
const SCAN_BELOW = 24;
/**
 * With `'lowest'` ties, the grid is made again of the entry points still to be used when they are fewer than its
 * own over this.
 */
const REGRID_SHARE = 4;
/** With `'grid'` ties, the smallest grid cell, µm. */
const GRID_TIES_CELL = 100;

/**
 * Entry points bucketed by cell in flat arrays: cell c's live entries are items[start[c] … start[c] + live[c]),
 * added in entry order; as the search passes a used one, the cell's last takes its place.
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

/**
 * A grid of the entries `ids` (indices into `ends`, two coordinates each): √`across` cells (rounded up) across its
 * longer side, but none narrower than `minCell`.
 */
function buildGrid(ends: Float64Array, ids: Int32Array, across: number, minCell: number): Grid {
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
  const cell = Math.max(span / Math.max(1, Math.ceil(Math.sqrt(across))), minCell);
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

/** A search for the nearest live entry: from where, how ties go, the nearest found so far (squared distance, entry). */
interface Search {
  x: number;
  y: number;
  lowest: boolean;
  d: number;
  entry: number;
}

/**
 * Look at the live entries of cell c, the last added first, dropping used ones (the cell's last takes a used one's
 * place), and keep the nearest: on a tie the one found first, or with `lowest` the lowest entry.
 */
function visit(grid: Grid, c: number, ends: Float64Array, owner: Int32Array, used: Uint8Array, s: Search): void {
  const from = grid.start[c];
  let n = grid.live[c];
  if (n === 0) return;
  const items = grid.items;
  for (let k = from + n - 1; k >= from; k--) {
    const e = items[k];
    if (used[owner[e]]) {
      // dead entry: the cell's last (looked at already) takes its place
      items[k] = items[from + n - 1];
      n--;
      continue;
    }
    const dx = ends[2 * e] - s.x,
      dy = ends[2 * e + 1] - s.y;
    const d = dx * dx + dy * dy;
    if (d < s.d || (s.lowest && d === s.d && e < s.entry)) {
      s.d = d;
      s.entry = e;
    }
  }
  grid.live[c] = n;
}

/** The paths in nearest-first order from `from`, each with the entry point it is entered at. */
export function nearestFirst(paths: PathSet, from: Pt, ties: Ties): Visit[] {
  const count = paths.count;
  if (count === 0) return [];
  const lowest = ties === 'lowest';
  if (count === 1 && lowest) {
    // one path (a tree branch's loop, its one line): its nearest entry, the first on a tie, as the scan below finds it
    const c = paths.entries(0);
    let best = 0;
    let bestD = Infinity;
    for (let k = 0; k < c.length; k++) {
      const dx = c[k].x - from.x,
        dy = c[k].y - from.y;
      const d = dx * dx + dy * dy;
      if (d < bestD) {
        bestD = d;
        best = k;
      }
    }
    return [[0, best]];
  }
  // every path's entry points, one after another: entry e is path owner[e]'s entry which[e]
  const owner: number[] = [];
  const which: number[] = [];
  const points: Pt[] = [];
  for (let i = 0; i < count; i++) {
    const c = paths.entries(i);
    for (let k = 0; k < c.length; k++) {
      owner.push(i);
      which.push(k);
      points.push(c[k]);
    }
  }
  const n = points.length;
  const used = new Uint8Array(count);
  const out: Visit[] = [];
  /** Where the nozzle is after entering path `item` at entry e from `at`. */
  const leave = (item: number, e: number, at: Pt): Pt => {
    if (paths.exit) return paths.exit(item, which[e], at);
    return paths.line(item) ? points[which[e] === 0 ? e + 1 : e - 1] : points[e];
  };
  let at = from;
  if (lowest && n <= SCAN_BELOW) {
    // a few entry points (a support branch's loop and line, an island's walls): a plain scan finds the same
    // nearest (first in path, then entry order on a tie) without making a grid
    for (let done = 0; done < count; done++) {
      let best = -1;
      let bestD = Infinity;
      for (let e = 0; e < n; e++) {
        if (used[owner[e]]) continue;
        const dx = points[e].x - at.x,
          dy = points[e].y - at.y;
        const d = dx * dx + dy * dy;
        if (d < bestD) {
          bestD = d;
          best = e;
        }
      }
      const item = owner[best];
      used[item] = 1;
      out.push([item, which[best]]);
      at = leave(item, best, at);
    }
    return out;
  }
  const ends = new Float64Array(2 * n);
  for (let e = 0; e < n; e++) {
    ends[2 * e] = points[e].x;
    ends[2 * e + 1] = points[e].y;
  }
  const owners = Int32Array.from(owner);
  const all = new Int32Array(n);
  for (let e = 0; e < n; e++) all[e] = e;
  const across = lowest ? n : count;
  const minCell = lowest ? 1 : GRID_TIES_CELL;
  let grid = buildGrid(ends, all, across, minCell);
  // entries per path, and entries whose path is still to be printed: when most of the grid's entries are used,
  // its rings are mostly empty cells, and (with 'lowest' ties) a grid of the rest is made
  const per = new Int32Array(count);
  for (let e = 0; e < n; e++) per[owner[e]]++;
  let liveEntries = n,
    gridEntries = n;
  const s: Search = { x: 0, y: 0, lowest, d: Infinity, entry: -1 };
  for (let done = 0; done < count; done++) {
    if (lowest && liveEntries * REGRID_SHARE < gridEntries && liveEntries >= SCAN_BELOW) {
      const rest = new Int32Array(liveEntries);
      let k = 0;
      for (let e = 0; e < n; e++) if (!used[owner[e]]) rest[k++] = e;
      grid = buildGrid(ends, rest, liveEntries, minCell);
      gridEntries = liveEntries;
    }
    const { cols, rows, cell } = grid;
    let cx = Math.floor((at.x - grid.minX) / cell);
    let cy = Math.floor((at.y - grid.minY) / cell);
    if (!lowest) {
      cx = Math.min(cols - 1, Math.max(0, cx));
      cy = Math.min(rows - 1, Math.max(0, cy));
    }
    s.x = at.x;
    s.y = at.y;
    s.d = Infinity;
    s.entry = -1;
    // rings of cells around (cx, cy), from the first ring that touches the grid
    const dxOut = cx < 0 ? -cx : cx >= cols ? cx - cols + 1 : 0;
    const dyOut = cy < 0 ? -cy : cy >= rows ? cy - rows + 1 : 0;
    const r0 = Math.max(dxOut, dyOut);
    const rMax = Math.max(Math.abs(cx), Math.abs(cx - cols + 1), Math.abs(cy), Math.abs(cy - rows + 1));
    for (let r = r0; r <= rMax; r++) {
      // every point in ring r is at least r - 1 cells away
      if (s.entry >= 0) {
        const ring = (r - 1) * cell;
        if (lowest ? ring > Math.sqrt(s.d) : ring > 0 && ring * ring > s.d) break;
      }
      const y0 = Math.max(0, cy - r),
        y1 = Math.min(rows - 1, cy + r);
      const x0 = Math.max(0, cx - r),
        x1 = Math.min(cols - 1, cx + r);
      for (let gy = y0; gy <= y1; gy++) {
        if (gy === cy - r || gy === cy + r) {
          for (let gx = x0; gx <= x1; gx++) visit(grid, gy * cols + gx, ends, owners, used, s);
        } else {
          if (cx - r >= 0 && cx - r < cols) visit(grid, gy * cols + cx - r, ends, owners, used, s);
          if (r > 0 && cx + r >= 0 && cx + r < cols) visit(grid, gy * cols + cx + r, ends, owners, used, s);
        }
      }
    }
    const best = s.entry;
    const item = owner[best];
    used[item] = 1;
    liveEntries -= per[item];
    out.push([item, which[best]]);
    at = leave(item, best, at);
  }
  return out;
}
