/** A bucket grid of points (µm) for "what is near here" questions; answers do not depend on insertion timing. */

const OFFSET = 1 << 20;

export class PointGrid {
  readonly #cell: number;
  readonly #buckets = new Map<number, number[]>();
  readonly xs: number[] = [];
  readonly ys: number[] = [];

  constructor(cellUm: number) {
    this.#cell = Math.max(1, cellUm);
  }

  #key(cx: number, cy: number): number {
    return (cx + OFFSET) * 2 * OFFSET + (cy + OFFSET);
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

  /** Ids of the points within `dist` of (x, y), ascending. */
  within(x: number, y: number, dist: number): number[] {
    const out: number[] = [];
    const c = this.#cell;
    const x0 = Math.floor((x - dist) / c), x1 = Math.floor((x + dist) / c);
    const y0 = Math.floor((y - dist) / c), y1 = Math.floor((y + dist) / c);
    const d2 = dist * dist;
    for (let cx = x0; cx <= x1; cx++) {
      for (let cy = y0; cy <= y1; cy++) {
        const b = this.#buckets.get(this.#key(cx, cy));
        if (!b) continue;
        for (const id of b) {
          const dx = this.xs[id] - x, dy = this.ys[id] - y;
          if (dx * dx + dy * dy <= d2) out.push(id);
        }
      }
    }
    return out.sort((a, b) => a - b);
  }

  /** The id of the point nearest (x, y) within `dist` (the lowest id on a tie), or -1. */
  nearest(x: number, y: number, dist: number): number {
    let best = -1, bestD = Infinity;
    for (const id of this.within(x, y, dist)) {
      const d = (this.xs[id] - x) ** 2 + (this.ys[id] - y) ** 2;
      if (d < bestD) {
        bestD = d;
        best = id;
      }
    }
    return best;
  }
}
