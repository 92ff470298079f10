/**
 * Travel ordering: nearest-neighbour chaining. From the current position, print next the path whose
 * nearest entry point (either end of a polyline, reversing it if needed; any vertex of a loop, rotating it)
 * is closest. Entry points sit in a uniform grid searched in growing rings, so a layer with n paths costs
 * about O(n) grid work instead of the O(n²) of a plain scan.
 */
import type { Pt } from '../geometry/types.js';

interface Entry {
  x: number;
  y: number;
  item: number;
  /** For polylines: 0 = start, 1 = end. For loops: the vertex index. */
  at: number;
}

class EntryGrid {
  private readonly cells: Entry[][];
  private readonly nx: number;
  private readonly ny: number;
  private readonly minX: number;
  private readonly minY: number;
  private readonly cell: number;
  constructor(entries: Entry[]) {
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (const e of entries) {
      if (e.x < minX) minX = e.x;
      if (e.y < minY) minY = e.y;
      if (e.x > maxX) maxX = e.x;
      if (e.y > maxY) maxY = e.y;
    }
    const w = Math.max(1, maxX - minX), h = Math.max(1, maxY - minY);
    const cell = Math.max(1, Math.sqrt((w * h) / Math.max(1, entries.length)), Math.max(w, h) / 2048);
    this.nx = Math.ceil(w / cell) + 1;
    this.ny = Math.ceil(h / cell) + 1;
    this.minX = minX;
    this.minY = minY;
    this.cell = cell;
    this.cells = Array.from({ length: this.nx * this.ny }, () => []);
    for (const e of entries) this.cells[this.cy(e.y) * this.nx + this.cx(e.x)].push(e);
  }
  private cx(x: number): number {
    return Math.min(this.nx - 1, Math.max(0, Math.floor((x - this.minX) / this.cell)));
  }
  private cy(y: number): number {
    return Math.min(this.ny - 1, Math.max(0, Math.floor((y - this.minY) / this.cell)));
  }
  /** Nearest entry whose item is not used; removes dead entries it meets. Ties go to the lower item/at. */
  nearest(x: number, y: number, used: Uint8Array): Entry | null {
    const cx = this.cx(x), cy = this.cy(y);
    // distance from the query to the grid box, so rings can be skipped for far-away queries
    const maxR = Math.max(cx, this.nx - 1 - cx, cy, this.ny - 1 - cy);
    let best: Entry | null = null;
    let bestD = Infinity;
    const outX = Math.max(0, this.minX - x, x - (this.minX + this.nx * this.cell));
    const outY = Math.max(0, this.minY - y, y - (this.minY + this.ny * this.cell));
    const outside = Math.hypot(outX, outY);
    for (let r = 0; r <= maxR; r++) {
      if (best && (r - 1) * this.cell + outside > Math.sqrt(bestD)) break;
      for (let gy = cy - r; gy <= cy + r; gy++) {
        if (gy < 0 || gy >= this.ny) continue;
        const rowEdge = gy === cy - r || gy === cy + r;
        const step = rowEdge ? 1 : Math.max(1, 2 * r);
        for (let gx = cx - r; gx <= cx + r; gx += step) {
          if (gx < 0 || gx >= this.nx) continue;
          const list = this.cells[gy * this.nx + gx];
          let w = 0;
          for (let k = 0; k < list.length; k++) {
            const e = list[k];
            if (used[e.item]) continue;
            list[w++] = e;
            const d = (e.x - x) * (e.x - x) + (e.y - y) * (e.y - y);
            if (d < bestD || (d === bestD && best && (e.item < best.item || (e.item === best.item && e.at < best.at)))) {
              bestD = d;
              best = e;
            }
          }
          list.length = w;
        }
      }
    }
    return best;
  }
}

function orderLoops(loops: readonly Pt[][], at: Pt): { loops: Pt[][]; end: Pt } {
  if (loops.length === 0) return { loops: [], end: at };
  const entries: Entry[] = [];
  loops.forEach((l, i) => l.forEach((p, k) => entries.push({ x: p.x, y: p.y, item: i, at: k })));
  const grid = new EntryGrid(entries);
  const used = new Uint8Array(loops.length);
  const out: Pt[][] = [];
  let cur = at;
  for (let n = 0; n < loops.length; n++) {
    const e = grid.nearest(cur.x, cur.y, used);
    if (!e) break;
    used[e.item] = 1;
    const l = loops[e.item];
    const rot = l.slice(e.at).concat(l.slice(0, e.at));
    out.push(rot);
    cur = rot[0];
  }
  return { loops: out, end: cur };
}

function orderLines(lines: readonly Pt[][], at: Pt): Pt[][] {
  if (lines.length === 0) return [];
  const entries: Entry[] = [];
  lines.forEach((l, i) => {
    entries.push({ x: l[0].x, y: l[0].y, item: i, at: 0 });
    entries.push({ x: l[l.length - 1].x, y: l[l.length - 1].y, item: i, at: 1 });
  });
  const grid = new EntryGrid(entries);
  const used = new Uint8Array(lines.length);
  const out: Pt[][] = [];
  let cur = at;
  for (let n = 0; n < lines.length; n++) {
    const e = grid.nearest(cur.x, cur.y, used);
    if (!e) break;
    used[e.item] = 1;
    const l = e.at === 0 ? lines[e.item] : lines[e.item].slice().reverse();
    out.push(l);
    cur = l[l.length - 1];
  }
  return out;
}

/** Order loops (first) and then lines by nearest-neighbour chaining from `start`. */
export function orderPaths(lines: readonly Pt[][], loops: readonly Pt[][], start: Pt): { lines: Pt[][]; loops: Pt[][] } {
  const L = orderLoops(loops, start);
  return { loops: L.loops, lines: orderLines(lines, L.end) };
}

/** Total travel distance of an ordering (start → first path, path end → next start), µm. */
export function travelLength(lines: readonly Pt[][], start: Pt): number {
  let cur = start;
  let t = 0;
  for (const l of lines) {
    t += Math.hypot(l[0].x - cur.x, l[0].y - cur.y);
    cur = l[l.length - 1];
  }
  return t;
}
