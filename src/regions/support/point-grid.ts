/** A bucket grid of points (µm) for "what is near here" questions; answers do not depend on insertion timing. */

/** Cell coordinates are taken modulo this in a bucket's key, which then stays a small integer. */
const WRAP = 1 << 15;

export class PointGrid {
  readonly #cell: number;
  readonly #buckets = new Map<number, number[]>();
  readonly xs: number[] = [];
  readonly ys: number[] = [];

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

  /** Ids of the points within `dist` of (x, y), in no particular order (but always the same one). */
  near(x: number, y: number, dist: number, out: number[] = []): number[] {
    out.length = 0;
    const c = this.#cell;
    const x0 = Math.floor((x - dist) / c), x1 = Math.floor((x + dist) / c);
    const y0 = Math.floor((y - dist) / c), y1 = Math.floor((y + dist) / c);
    const d2 = dist * dist;
    const xs = this.xs, ys = this.ys;
    if (x1 - x0 >= WRAP - 1 || y1 - y0 >= WRAP - 1 || (x1 - x0 + 1) * (y1 - y0 + 1) > xs.length) {
      // more cells than points: look at every point
      for (let id = 0; id < xs.length; id++) {
        const dx = xs[id] - x, dy = ys[id] - y;
        if (dx * dx + dy * dy <= d2) out.push(id);
      }
      return out;
    }
    for (let cx = x0; cx <= x1; cx++) {
      for (let cy = y0; cy <= y1; cy++) {
        const b = this.#buckets.get(this.#key(cx, cy));
        if (!b) continue;
        for (let k = 0; k < b.length; k++) {
          const id = b[k];
          const dx = xs[id] - x, dy = ys[id] - y;
          if (dx * dx + dy * dy <= d2) out.push(id);
        }
      }
    }
    return out;
  }

  /** The id of the point nearest (x, y) within `dist` (the lowest id on a tie), or -1. */
  nearest(x: number, y: number, dist: number): number {
    let best = -1, bestD = Infinity;
    const found = this.near(x, y, dist);
    for (let k = 0; k < found.length; k++) {
      const id = found[k];
      const d = (this.xs[id] - x) ** 2 + (this.ys[id] - y) ** 2;
      if (d < bestD || (d === bestD && id < best)) {
        bestD = d;
        best = id;
      }
    }
    return best;
  }
}
