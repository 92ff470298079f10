/**
 * Bucket grids of points (µm) for "what is near here" questions, the tree-support planner's most frequent
 * ones: `PointGrid` takes points as they come, `FixedPointGrid` holds a set known at once in flat arrays
 * (no map lookup per cell). A query writes the ids it finds into the caller's array and returns how many,
 * so one array serves every query without being given up and grown again (an array's `length = 0` drops
 * its storage). Which ids are found never depends on how the points are bucketed, only their order does.
 */

import { bucketByCell } from './cell-buckets.js';

/** Cell coordinates are taken modulo this in a bucket's key, which then stays a small integer. */
const WRAP = 1 << 15;

export class PointGrid {
  readonly #cell: number;
  readonly #buckets = new Map<number, number[]>();
  readonly xs: number[] = [];
  readonly ys: number[] = [];
  /** Scratch for `nearest`. */
  readonly #found: number[] = [];

  constructor(cellUm: number) {
    this.#cell = Math.max(1, cellUm);
  }

  /** Cells WRAP apart share a bucket (the distance test sorts them out); a query spans fewer cells than that. */
  #key(cx: number, cy: number): number {
    return (cx & (WRAP - 1)) * WRAP + (cy & (WRAP - 1));
  }

  /** Add a point; returns its id (0, 1, 2 … in the order added). */
  add(x: number, y: number): number {
    const id = this.xs.length;
    this.xs.push(x);
    this.ys.push(y);
    const k = this.#key(Math.floor(x / this.#cell), Math.floor(y / this.#cell));
    const b = this.#buckets.get(k);
    if (b) b.push(id);
    else this.#buckets.set(k, [id]);
    return id;
  }

  /** Writes the ids of the points within `dist` of (x, y) to out[0 …) and returns how many (the rest of `out` is stale). */
  near(x: number, y: number, dist: number, out: number[]): number {
    const c = this.#cell;
    const x0 = Math.floor((x - dist) / c),
      x1 = Math.floor((x + dist) / c);
    const y0 = Math.floor((y - dist) / c),
      y1 = Math.floor((y + dist) / c);
    const d2 = dist * dist;
    const xs = this.xs,
      ys = this.ys;
    let n = 0;
    if (x1 - x0 >= WRAP - 1 || y1 - y0 >= WRAP - 1 || (x1 - x0 + 1) * (y1 - y0 + 1) > xs.length) {
      // more cells than points: look at every point
      for (let id = 0; id < xs.length; id++) {
        const dx = xs[id] - x,
          dy = ys[id] - y;
        if (dx * dx + dy * dy <= d2) out[n++] = id;
      }
      return n;
    }
    for (let cx = x0; cx <= x1; cx++) {
      for (let cy = y0; cy <= y1; cy++) {
        const b = this.#buckets.get(this.#key(cx, cy));
        if (!b) continue;
        for (let k = 0; k < b.length; k++) {
          const id = b[k];
          const dx = xs[id] - x,
            dy = ys[id] - y;
          if (dx * dx + dy * dy <= d2) out[n++] = id;
        }
      }
    }
    return n;
  }

  /** The id of the point nearest (x, y) within `dist` (the lowest id on a tie), or -1. */
  nearest(x: number, y: number, dist: number): number {
    const found = this.#found;
    const n = this.near(x, y, dist, found);
    let best = -1,
      bestD = Infinity;
    for (let k = 0; k < n; k++) {
      const id = found[k];
      const dx = this.xs[id] - x,
        dy = this.ys[id] - y;
      const d = dx * dx + dy * dy;
      if (d < bestD || (d === bestD && id < best)) {
        bestD = d;
        best = id;
      }
    }
    return best;
  }
}

/** A FixedPointGrid has at most about this many cells per point (a coarser cell otherwise). */
const CELLS_PER_POINT = 4;

/** The points (xs[i], ys[i]), ids 0 … n-1, bucketed once: each cell's ids lie together in one array. */
export class FixedPointGrid {
  readonly xs: Float64Array;
  readonly ys: Float64Array;
  readonly #cell: number;
  readonly #minX: number;
  readonly #minY: number;
  readonly #nx: number;
  readonly #ny: number;
  /** The ids of cell c are items[start[c] … start[c + 1]). */
  readonly #start: Int32Array;
  readonly #items: Int32Array;

  constructor(xs: Float64Array, ys: Float64Array, cellUm: number) {
    this.xs = xs;
    this.ys = ys;
    const n = xs.length;
    let minX = Infinity,
      minY = Infinity,
      maxX = -Infinity,
      maxY = -Infinity;
    for (let i = 0; i < n; i++) {
      if (xs[i] < minX) minX = xs[i];
      if (xs[i] > maxX) maxX = xs[i];
      if (ys[i] < minY) minY = ys[i];
      if (ys[i] > maxY) maxY = ys[i];
    }
    if (n === 0) minX = minY = maxX = maxY = 0;
    let cell = Math.max(1, cellUm);
    while ((Math.floor((maxX - minX) / cell) + 1) * (Math.floor((maxY - minY) / cell) + 1) > CELLS_PER_POINT * n + 1)
      cell *= 2;
    const nx = Math.floor((maxX - minX) / cell) + 1,
      ny = Math.floor((maxY - minY) / cell) + 1;
    const cellOf = new Int32Array(n);
    for (let i = 0; i < n; i++) cellOf[i] = Math.floor((ys[i] - minY) / cell) * nx + Math.floor((xs[i] - minX) / cell);
    const { start, items } = bucketByCell(cellOf, nx * ny);
    this.#cell = cell;
    this.#minX = minX;
    this.#minY = minY;
    this.#nx = nx;
    this.#ny = ny;
    this.#start = start;
    this.#items = items;
  }

  /** Writes the ids of the points within `dist` of (x, y) to out[0 …) and returns how many (the rest of `out` is stale). */
  near(x: number, y: number, dist: number, out: number[]): number {
    const c = this.#cell,
      nx = this.#nx;
    const x0 = Math.max(0, Math.floor((x - dist - this.#minX) / c)),
      x1 = Math.min(nx - 1, Math.floor((x + dist - this.#minX) / c));
    const y0 = Math.max(0, Math.floor((y - dist - this.#minY) / c)),
      y1 = Math.min(this.#ny - 1, Math.floor((y + dist - this.#minY) / c));
    if (x0 > x1 || y0 > y1) return 0;
    const d2 = dist * dist;
    const xs = this.xs,
      ys = this.ys,
      start = this.#start,
      items = this.#items;
    let n = 0;
    for (let cy = y0; cy <= y1; cy++) {
      for (let k = start[cy * nx + x0], end = start[cy * nx + x1 + 1]; k < end; k++) {
        const id = items[k];
        const dx = xs[id] - x,
          dy = ys[id] - y;
        if (dx * dx + dy * dy <= d2) out[n++] = id;
      }
    }
    return n;
  }
}
