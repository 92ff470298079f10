/**
 * Fast point queries against a fixed set of areas (µm): whether a point lies inside, the nearest point just
 * outside, and whether a segment crosses a boundary. The areas' edges are bucketed in a uniform grid, so a
 * query looks at the few edges near the point instead of every edge. Tree support asks these questions for
 * every branch on every layer.
 */
import { pointInArea } from './clip.js';
import { ringBounds, segmentsMeet } from './contain.js';
import { hypot, type Bounds, type ExPolygon } from './types.js';
import { LENGTH_EPS_UM } from './tolerances.js';

/** How far beyond the boundary a point pushed out of the areas lands, µm. */
export const OUTSIDE_MARGIN_UM = 5;
/** Smallest and largest grid cell, µm. */
const MIN_CELL_UM = 400;
const MAX_CELL_UM = 5000;

export interface Found {
  x: number;
  y: number;
}

/** Candidate points of AreaIndex.nearestClear: x, y, distance, and the order they are tried in. */
interface Candidates {
  x: Float64Array;
  y: Float64Array;
  d: Float64Array;
  order: Int32Array;
}
const makeCandidates = (n: number): Candidates => ({
  x: new Float64Array(n),
  y: new Float64Array(n),
  d: new Float64Array(n),
  order: new Int32Array(n),
});

function growCandidates(c: Candidates): Candidates {
  const g = makeCandidates(2 * c.d.length);
  g.x.set(c.x);
  g.y.set(c.y);
  g.d.set(c.d);
  return g;
}

/**
 * The index of one set of areas. It owns the working arrays of its queries (the candidate points, the edges
 * found), which each query fills afresh (every query is synchronous): made on first use, grown as needed.
 */
export class AreaIndex {
  /** Edges as x1, y1, x2, y2 (interior on the left: outer rings counter-clockwise, holes clockwise). */
  readonly #e: Float64Array;
  readonly #minX: number;
  readonly #minY: number;
  readonly #cell: number;
  readonly #nx: number;
  readonly #ny: number;
  /** Edges of cell c: #items[#start[c] .. #start[c+1]). */
  readonly #start: Int32Array;
  readonly #items: Int32Array;
  /** The first vertex of every ring, x, y. */
  readonly #firsts: number[] = [];
  readonly empty: boolean;
  /** Per edge, the query that last looked at it (nearestClear visits each edge once). */
  #seen: Int32Array | null = null;
  #query = 0;
  /** The candidates of the query in progress (nearestOutside, nearestClear), and how many it holds. */
  #cand: Candidates | null = null;
  #candCount = 0;
  /** Edge indices found by #edgesNear for the query in progress. */
  #near: Int32Array | null = null;
  /** Candidates nearest first, the earliest kept on a tie. */
  readonly #nearer = (a: number, b: number): number => this.#cand!.d[a] - this.#cand!.d[b] || a - b;

  constructor(areas: readonly ExPolygon[]) {
    let n = 0;
    for (let i = 0; i < areas.length; i++) {
      const a = areas[i];
      n += a.outer.length;
      for (let h = 0; h < a.holes.length; h++) n += a.holes[h].length;
    }
    const e = new Float64Array(4 * n);
    let minX = Infinity,
      minY = Infinity,
      maxX = -Infinity,
      maxY = -Infinity;
    let k = 0;
    for (let i = 0; i < areas.length; i++) {
      const a = areas[i];
      for (let r = -1; r < a.holes.length; r++) {
        const ring = r < 0 ? a.outer : a.holes[r];
        const len = ring.length;
        if (len) this.#firsts.push(ring[0].x, ring[0].y);
        for (let i = 0; i < len; i++) {
          const p = ring[i],
            q = ring[i + 1 < len ? i + 1 : 0];
          e[k++] = p.x;
          e[k++] = p.y;
          e[k++] = q.x;
          e[k++] = q.y;
          if (p.x < minX) minX = p.x;
          if (p.x > maxX) maxX = p.x;
          if (p.y < minY) minY = p.y;
          if (p.y > maxY) maxY = p.y;
        }
      }
    }
    this.#e = e;
    this.empty = n === 0;
    if (this.empty) {
      this.#minX = this.#minY = 0;
      this.#cell = MIN_CELL_UM;
      this.#nx = this.#ny = 1;
      this.#start = new Int32Array(2);
      this.#items = new Int32Array(0);
      return;
    }
    const w = maxX - minX,
      h = maxY - minY;
    const cell = Math.min(MAX_CELL_UM, Math.max(MIN_CELL_UM, 2 * Math.sqrt((w * h) / n)));
    this.#minX = minX;
    this.#minY = minY;
    this.#cell = cell;
    const nx = (this.#nx = Math.floor(w / cell) + 1);
    this.#ny = Math.floor(h / cell) + 1;
    // each edge goes into every cell its bounds cover: count per cell, then fill
    const cells = nx * this.#ny;
    const ranges = new Int32Array(4 * n);
    const start = new Int32Array(cells + 1);
    for (let i = 0; i < n; i++) {
      const x1 = e[4 * i],
        y1 = e[4 * i + 1],
        x2 = e[4 * i + 2],
        y2 = e[4 * i + 3];
      const c0 = Math.floor(((x1 < x2 ? x1 : x2) - minX) / cell),
        c1 = Math.floor(((x1 < x2 ? x2 : x1) - minX) / cell);
      const r0 = Math.floor(((y1 < y2 ? y1 : y2) - minY) / cell),
        r1 = Math.floor(((y1 < y2 ? y2 : y1) - minY) / cell);
      ranges[4 * i] = c0;
      ranges[4 * i + 1] = c1;
      ranges[4 * i + 2] = r0;
      ranges[4 * i + 3] = r1;
      for (let r = r0; r <= r1; r++) for (let c = c0; c <= c1; c++) start[r * nx + c + 1]++;
    }
    for (let c = 0; c < cells; c++) start[c + 1] += start[c];
    const fill = start.slice(0, cells);
    const items = new Int32Array(start[cells]);
    for (let i = 0; i < n; i++) {
      for (let r = ranges[4 * i + 2]; r <= ranges[4 * i + 3]; r++) {
        for (let c = ranges[4 * i]; c <= ranges[4 * i + 1]; c++) items[fill[r * nx + c]++] = i;
      }
    }
    this.#start = start;
    this.#items = items;
  }

  #col(x: number): number {
    return Math.min(this.#nx - 1, Math.max(0, Math.floor((x - this.#minX) / this.#cell)));
  }

  #row(y: number): number {
    return Math.min(this.#ny - 1, Math.max(0, Math.floor((y - this.#minY) / this.#cell)));
  }

  /**
   * Whether (x, y) lies inside the areas (even-odd over every ring; a point on an edge may go either way): the
   * parity of the crossings of a ray to the nearest side of the grid, so a query walks few cells.
   */
  contains(x: number, y: number): boolean {
    if (this.empty) return false;
    const minX = this.#minX,
      minY = this.#minY;
    if (x < minX || y < minY || x > minX + this.#nx * this.#cell || y > minY + this.#ny * this.#cell) return false;
    const c = this.#col(x),
      r = this.#row(y);
    const right = this.#nx - 1 - c,
      up = this.#ny - 1 - r;
    const m = Math.min(right, c, up, r);
    if (m === right) return this.#ray(x, y, c, r, 0, 1);
    if (m === c) return this.#ray(x, y, c, r, 0, -1);
    if (m === up) return this.#ray(x, y, c, r, 1, 1);
    return this.#ray(x, y, c, r, 1, -1);
  }

  /**
   * The parity of the crossings of the ray from (x, y) along x (axis 0) or y (axis 1), towards + (dir 1) or -
   * (-1), each crossing counted in the one cell that holds it.
   */
  #ray(x: number, y: number, c0: number, r0: number, axis: 0 | 1, dir: 1 | -1): boolean {
    const e = this.#e;
    // p along the ray, q across it; edges read in the same order
    const p = axis === 0 ? x : y,
      q = axis === 0 ? y : x;
    let inside = false;
    for (let c = c0, r = r0; c >= 0 && c < this.#nx && r >= 0 && r < this.#ny; axis === 0 ? (c += dir) : (r += dir)) {
      const cell = r * this.#nx + c;
      for (let s = this.#start[cell], t = this.#start[cell + 1]; s < t; s++) {
        const k = 4 * this.#items[s];
        const p1 = e[k + axis],
          q1 = e[k + 1 - axis],
          p2 = e[k + 2 + axis],
          q2 = e[k + 3 - axis];
        if (q1 > q === q2 > q) continue;
        let cp = p1 + ((q - q1) * (p2 - p1)) / (q2 - q1);
        cp = Math.min(Math.max(cp, Math.min(p1, p2)), Math.max(p1, p2));
        if ((dir > 0 ? cp <= p : cp >= p) || (axis === 0 ? this.#col(cp) !== c : this.#row(cp) !== r)) continue;
        inside = !inside;
      }
    }
    return inside;
  }

  /**
   * The point nearest to (x, y) that lies just outside the areas (OUTSIDE_MARGIN_UM beyond the boundary, in
   * whole µm), looking no further than `maxUm`; (x, y) itself when it is outside; null when nothing is found.
   */
  nearestOutside(x: number, y: number, maxUm: number): Found | null {
    if (!this.contains(x, y)) return { x, y };
    const e = this.#e;
    const cell = this.#cell;
    const reach = maxUm + OUTSIDE_MARGIN_UM;
    const c0 = this.#col(x - reach),
      c1 = this.#col(x + reach),
      r0 = this.#row(y - reach),
      r1 = this.#row(y + reach);
    let best = Infinity,
      bx = 0,
      by = 0,
      bi = -1;
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        // skip cells wholly further than the best so far
        const cx0 = this.#minX + c * cell,
          cy0 = this.#minY + r * cell;
        const dx = Math.max(cx0 - x, 0, x - cx0 - cell),
          dy = Math.max(cy0 - y, 0, y - cy0 - cell);
        if (dx * dx + dy * dy > Math.min(best, reach * reach)) continue;
        const id = r * this.#nx + c;
        for (let s = this.#start[id], t = this.#start[id + 1]; s < t; s++) {
          const i = this.#items[s];
          const x1 = e[4 * i],
            y1 = e[4 * i + 1],
            ex = e[4 * i + 2] - x1,
            ey = e[4 * i + 3] - y1;
          const len2 = ex * ex + ey * ey;
          const u = len2 > 0 ? Math.min(1, Math.max(0, ((x - x1) * ex + (y - y1) * ey) / len2)) : 0;
          const px = x1 + u * ex,
            py = y1 + u * ey;
          const d = (px - x) * (px - x) + (py - y) * (py - y);
          if (d < best) {
            best = d;
            bx = px;
            by = py;
            bi = i;
          }
        }
      }
    }
    if (bi < 0 || best > reach * reach) return null;
    // out through the nearest edge: along the way from the point to it, or along the edge's outward normal
    const d = Math.sqrt(best);
    const ex = e[4 * bi + 2] - e[4 * bi],
      ey = e[4 * bi + 3] - e[4 * bi + 1];
    const el = hypot(ex, ey) || 1;
    for (let way = d > LENGTH_EPS_UM ? 0 : 1; way < 2; way++) {
      const ux = way === 0 ? (bx - x) / d : ey / el,
        uy = way === 0 ? (by - y) / d : -ex / el;
      for (let k = 0; k < 2; k++) {
        const m = k === 0 ? OUTSIDE_MARGIN_UM : 4 * OUTSIDE_MARGIN_UM;
        const qx = Math.round(bx + ux * m),
          qy = Math.round(by + uy * m);
        if (hypot(qx - x, qy - y) <= reach && !this.contains(qx, qy)) return { x: qx, y: qy };
      }
    }
    // the nearest edge leads into more of the areas (a sliver between two of them, a small hole): the points
    // just off every edge within reach, nearest first
    this.#edgeCandidates(x, y, OUTSIDE_MARGIN_UM, maxUm);
    return this.#firstClear(0);
  }

  /** Whether some edge of the areas comes within `dist` of (x, y). */
  edgeWithin(x: number, y: number, dist: number): boolean {
    if (this.empty) return false;
    const e = this.#e;
    const d2 = dist * dist;
    const c0 = this.#col(x - dist),
      c1 = this.#col(x + dist),
      r0 = this.#row(y - dist),
      r1 = this.#row(y + dist);
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        const id = r * this.#nx + c;
        for (let s = this.#start[id], t = this.#start[id + 1]; s < t; s++) {
          const i = this.#items[s];
          const x1 = e[4 * i],
            y1 = e[4 * i + 1],
            ex = e[4 * i + 2] - x1,
            ey = e[4 * i + 3] - y1;
          const len2 = ex * ex + ey * ey;
          const u = len2 > 0 ? Math.min(1, Math.max(0, ((x - x1) * ex + (y - y1) * ey) / len2)) : 0;
          const px = x1 + u * ex - x,
            py = y1 + u * ey - y;
          if (px * px + py * py <= d2) return true;
        }
      }
    }
    return false;
  }

  /** Whether the disc of radius r round (x, y) meets the areas. */
  meetsDisc(x: number, y: number, r: number): boolean {
    return this.contains(x, y) || this.edgeWithin(x, y, r);
  }

  /**
   * The point nearest (x, y), within `maxUm` of it, that lies more than `d` outside the areas (by
   * OUTSIDE_MARGIN_UM; a found point is in whole µm); (x, y) itself when it does; null when none is found. Tried in turn: off each edge
   * near the point by d (along its outward normal, and along the way from the edge to the point), then
   * points round (x, y) in 16 directions (unless `rings` is off).
   */
  nearestClear(x: number, y: number, d: number, maxUm: number, rings = true): Found | null {
    if (d <= 0) return this.nearestOutside(x, y, maxUm);
    if (!this.meetsDisc(x, y, d)) return { x, y };
    this.#edgeCandidates(x, y, d + OUTSIDE_MARGIN_UM, maxUm);
    const best = this.#firstClear(d);
    if (best || !rings) return best;
    for (let k = 1; k <= 4; k++) {
      this.#candCount = 0;
      for (let a = 0; a < 16; a++) {
        const ang = (a * Math.PI) / 8;
        this.#addCandidate(x + ((maxUm * k) / 4) * Math.cos(ang), y + ((maxUm * k) / 4) * Math.sin(ang), x, y, maxUm);
      }
      const q = this.#firstClear(d);
      if (q) return q;
    }
    return null;
  }

  /**
   * The candidates (in #cand) `want` off every edge within reach of (x, y): off the edge's nearest point along
   * its outward normal, and away from (x, y); only those within maxUm of (x, y).
   */
  #edgeCandidates(x: number, y: number, want: number, maxUm: number): void {
    const e = this.#e;
    const reach = maxUm + want;
    const c0 = this.#col(x - reach),
      c1 = this.#col(x + reach),
      r0 = this.#row(y - reach),
      r1 = this.#row(y + reach);
    // candidates within maxUm, then tested nearest first (the earliest found on a tie): the first clear one wins
    this.#candCount = 0;
    const seen = (this.#seen ??= new Int32Array(e.length / 4));
    const query = ++this.#query;
    for (let r = r0; r <= r1; r++) {
      for (let c = c0; c <= c1; c++) {
        const id = r * this.#nx + c;
        for (let s = this.#start[id], t = this.#start[id + 1]; s < t; s++) {
          const i = this.#items[s];
          if (seen[i] === query) continue;
          seen[i] = query;
          const x1 = e[4 * i],
            y1 = e[4 * i + 1],
            ex = e[4 * i + 2] - x1,
            ey = e[4 * i + 3] - y1;
          const len2 = ex * ex + ey * ey;
          if (len2 === 0) continue;
          const u = Math.min(1, Math.max(0, ((x - x1) * ex + (y - y1) * ey) / len2));
          const bx = x1 + u * ex,
            by = y1 + u * ey;
          const db = hypot(x - bx, y - by);
          if (db > reach) continue;
          const el = Math.sqrt(len2);
          this.#addCandidate(bx + (ey / el) * want, by - (ex / el) * want, x, y, maxUm);
          if (db > LENGTH_EPS_UM)
            this.#addCandidate(bx + ((x - bx) / db) * want, by + ((y - by) / db) * want, x, y, maxUm);
        }
      }
    }
  }

  /** Keep (qx, qy), in whole µm (as the areas' own points are, and as the point queries are compiled for), when it lies within maxUm of (x, y). */
  #addCandidate(qx: number, qy: number, x: number, y: number, maxUm: number): void {
    qx = Math.round(qx);
    qy = Math.round(qy);
    const dq = hypot(qx - x, qy - y);
    if (!(dq <= maxUm)) return;
    let cand = (this.#cand ??= makeCandidates(64));
    const n = this.#candCount;
    if (n === cand.d.length) cand = this.#cand = growCandidates(cand);
    cand.x[n] = qx;
    cand.y[n] = qy;
    cand.d[n] = dq;
    this.#candCount = n + 1;
  }

  /** The nearest of the candidates that lies more than d from the areas (d = 0: outside them), or null. */
  #firstClear(d: number): Found | null {
    const n = this.#candCount;
    if (n === 0) return null;
    const { x: cx, y: cy, order } = this.#cand!;
    for (let i = 0; i < n; i++) order[i] = i;
    const ids = order.subarray(0, n).sort(this.#nearer);
    for (let k = 0; k < n; k++) {
      const i = ids[k];
      if (d > 0 ? !this.meetsDisc(cx[i], cy[i], d) : !this.contains(cx[i], cy[i])) return { x: cx[i], y: cy[i] };
    }
    return null;
  }

  /**
   * Whether an area meets the areas: a vertex of either lies inside the other, or their edges cross. Only
   * the areas' edges whose bounds meet the area's can cross it; when there are none, the area lies wholly
   * inside or wholly outside (one vertex tells) and holds no ring of the areas. Along a ring whose edges
   * cross none of the areas' edges every vertex lies on the same side, so one vertex of each ring is tested
   * for containment and the rest only for crossings.
   */
  meets(a: ExPolygon): boolean {
    if (this.empty || a.outer.length === 0) return false;
    const bounds = ringBounds(a.outer);
    const found = this.#edgesNear(bounds);
    if (found === 0) return this.contains(a.outer[0].x, a.outer[0].y);
    const e = this.#e,
      near = this.#near!;
    for (let r = -1; r < a.holes.length; r++) {
      const ring = r < 0 ? a.outer : a.holes[r];
      if (ring.length && this.contains(ring[0].x, ring[0].y)) return true;
      for (let i = 0; i < ring.length; i++) {
        const p = ring[i],
          q = ring[i + 1 < ring.length ? i + 1 : 0];
        for (let k = 0; k < found; k++) {
          const t = 4 * near[k];
          if (segmentsMeet(p.x, p.y, q.x, q.y, e[t], e[t + 1], e[t + 2], e[t + 3])) return true;
        }
      }
    }
    // a ring of the areas inside `a` has its first vertex within a's bounds
    const { minX, minY, maxX, maxY } = bounds;
    const f = this.#firsts;
    for (let k = 0; k < f.length; k += 2) {
      const x = f[k],
        y = f[k + 1];
      if (x >= minX && x <= maxX && y >= minY && y <= maxY && pointInArea({ x, y }, a)) return true;
    }
    return false;
  }

  /** The areas' edges (in #near, possibly repeated) whose bounds meet `bounds`; returns how many. */
  #edgesNear(bounds: Bounds): number {
    const { minX, minY, maxX, maxY } = bounds;
    const gx = this.#minX + this.#nx * this.#cell,
      gy = this.#minY + this.#ny * this.#cell;
    if (maxX < this.#minX || maxY < this.#minY || minX > gx || minY > gy) return 0;
    const e = this.#e;
    const c0 = this.#col(minX),
      c1 = this.#col(maxX),
      r0 = this.#row(minY),
      r1 = this.#row(maxY);
    let near = (this.#near ??= new Int32Array(256));
    let n = 0;
    for (let r = r0; r <= r1; r++) {
      const row = r * this.#nx;
      for (let s = this.#start[row + c0], t = this.#start[row + c1 + 1]; s < t; s++) {
        const i = this.#items[s],
          k = 4 * i;
        const x1 = e[k],
          y1 = e[k + 1],
          x2 = e[k + 2],
          y2 = e[k + 3];
        if (
          (x1 < x2 ? x2 : x1) < minX ||
          (x1 < x2 ? x1 : x2) > maxX ||
          (y1 < y2 ? y2 : y1) < minY ||
          (y1 < y2 ? y1 : y2) > maxY
        )
          continue;
        if (n === near.length) {
          const grown = new Int32Array(2 * n);
          grown.set(near);
          near = this.#near = grown;
        }
        near[n++] = i;
      }
    }
    return n;
  }

  /** Whether the segment from (ax, ay) to (bx, by) crosses an edge of the areas. */
  crosses(ax: number, ay: number, bx: number, by: number): boolean {
    if (this.empty) return false;
    const e = this.#e;
    const cell = this.#cell;
    // walk the cells the segment passes through (grid traversal), testing their edges
    let c = this.#col(ax),
      r = this.#row(ay);
    const cEnd = this.#col(bx),
      rEnd = this.#row(by);
    const dx = bx - ax,
      dy = by - ay;
    const stepC = dx > 0 ? 1 : -1,
      stepR = dy > 0 ? 1 : -1;
    // where the segment leaves its first cell across x and across y
    let tMaxX = dx !== 0 ? (this.#minX + (c + (stepC > 0 ? 1 : 0)) * cell - ax) / dx : Infinity;
    let tMaxY = dy !== 0 ? (this.#minY + (r + (stepR > 0 ? 1 : 0)) * cell - ay) / dy : Infinity;
    const tDX = dx !== 0 ? Math.abs(cell / dx) : Infinity;
    const tDY = dy !== 0 ? Math.abs(cell / dy) : Infinity;
    for (let guard = 0; guard < this.#nx + this.#ny + 2; guard++) {
      const id = r * this.#nx + c;
      for (let s = this.#start[id], t = this.#start[id + 1]; s < t; s++) {
        const i = this.#items[s];
        if (segmentsMeet(ax, ay, bx, by, e[4 * i], e[4 * i + 1], e[4 * i + 2], e[4 * i + 3])) return true;
      }
      if (c === cEnd && r === rEnd) break;
      if (tMaxX < tMaxY) {
        if (c === cEnd) break;
        c += stepC;
        tMaxX += tDX;
      } else {
        if (r === rEnd) break;
        r += stepR;
        tMaxY += tDY;
      }
      if (c < 0 || r < 0 || c >= this.#nx || r >= this.#ny) break;
    }
    return false;
  }

  /**
   * Where the segment from a to b crosses the areas' edges: the parameters t in (0, 1) along it (a + t·(b − a)),
   * pushed to `out` unsorted, an edge that meets it at an end of the edge counted (it may come twice). Returns
   * whether an edge touches it at a or b, or runs along its line (the segment may start or end on the boundary).
   */
  crossingsAlong(ax: number, ay: number, bx: number, by: number, out: number[]): boolean {
    if (this.empty) return false;
    const n = this.#edgesNear({
      minX: Math.min(ax, bx),
      minY: Math.min(ay, by),
      maxX: Math.max(ax, bx),
      maxY: Math.max(ay, by),
    });
    const e = this.#e,
      near = this.#near!;
    const dx = bx - ax,
      dy = by - ay;
    let touch = false;
    for (let j = 0; j < n; j++) {
      const k = 4 * near[j];
      const cx = e[k],
        cy = e[k + 1];
      const ex = e[k + 2] - cx,
        ey = e[k + 3] - cy;
      const den = dx * ey - dy * ex;
      if (den === 0) {
        if ((cx - ax) * dy - (cy - ay) * dx === 0) touch = true;
        continue;
      }
      const t = ((cx - ax) * ey - (cy - ay) * ex) / den;
      const u = ((cx - ax) * dy - (cy - ay) * dx) / den;
      if (u < 0 || u > 1) continue;
      if (t > 0 && t < 1) out.push(t);
      else if (t === 0 || t === 1) touch = true;
    }
    return touch;
  }
}
