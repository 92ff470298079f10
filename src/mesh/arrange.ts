/**
 * Arranging several models on the bed: their footprints (axis-aligned rectangles, mm) are packed
 * around the bed centre without overlapping, `gap` apart, and kept inside the bed.
 *
 * Greedy and deterministic: the largest footprint goes in the middle; each next one (by area, then
 * input order) tries the places touching a placed one on each side (centred on it or flush with
 * either of its edges) and takes the one that keeps the whole group smallest relative to the bed,
 * then nearest the centre. The group is centred on the bed at the end.
 */

export interface Footprint {
  /** Size in X and Y, mm. */
  width: number;
  length: number;
}

/** Centre of each footprint, mm, relative to the bed centre. */
export type Arrangement = Array<[number, number]>;

interface Placed {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/** Overlap tolerance, mm: rectangles that touch within this are not overlapping. */
const TOUCH_MM = 1e-6;

/**
 * Pack the footprints on a `bedWidth` × `bedLength` bed with `gap` mm between them. Returns each
 * footprint's centre relative to the bed centre, or null when they do not all fit.
 */
export function arrangeFootprints(items: readonly Footprint[], bedWidth: number, bedLength: number, gap: number): Arrangement | null {
  const order = items.map((_, i) => i).sort((a, b) => items[b].width * items[b].length - items[a].width * items[a].length || a - b);
  const placed: Placed[] = [];
  const centres: Arrangement = new Array(items.length);
  const hw = bedWidth / 2;
  const hl = bedLength / 2;
  // bounds of the group so far
  let gx0 = Infinity, gy0 = Infinity, gx1 = -Infinity, gy1 = -Infinity;
  for (const i of order) {
    const { width: w, length: l } = items[i];
    if (w > bedWidth + TOUCH_MM || l > bedLength + TOUCH_MM) return null;
    const candidates: Array<[number, number]> = placed.length === 0 ? [[0, 0]] : [];
    for (const p of placed) {
      const cx = (p.x0 + p.x1) / 2;
      const cy = (p.y0 + p.y1) / 2;
      const alongX = [cx, p.x0 + w / 2, p.x1 - w / 2];
      const alongY = [cy, p.y0 + l / 2, p.y1 - l / 2];
      for (const x of alongX) candidates.push([x, p.y1 + gap + l / 2], [x, p.y0 - gap - l / 2]);
      for (const y of alongY) candidates.push([p.x1 + gap + w / 2, y], [p.x0 - gap - w / 2, y]);
    }
    let best: [number, number] | null = null;
    let bestScore = [Infinity, Infinity, Infinity];
    for (const [x, y] of candidates) {
      const r = { x0: x - w / 2, y0: y - l / 2, x1: x + w / 2, y1: y + l / 2 };
      const nx0 = Math.min(gx0, r.x0), ny0 = Math.min(gy0, r.y0), nx1 = Math.max(gx1, r.x1), ny1 = Math.max(gy1, r.y1);
      // the group is centred at the end, so what must fit is its size
      if (nx1 - nx0 > bedWidth + TOUCH_MM || ny1 - ny0 > bedLength + TOUCH_MM) continue;
      if (placed.some((p) => overlaps(p, r, gap))) continue;
      const score = [Math.max((nx1 - nx0) / bedWidth, (ny1 - ny0) / bedLength), (nx1 - nx0) * (ny1 - ny0), Math.hypot(x, y)];
      if (lexLess(score, bestScore)) {
        best = [x, y];
        bestScore = score;
      }
    }
    if (best === null) return null;
    const [x, y] = best;
    const r = { x0: x - w / 2, y0: y - l / 2, x1: x + w / 2, y1: y + l / 2 };
    placed.push(r);
    centres[i] = best;
    gx0 = Math.min(gx0, r.x0);
    gy0 = Math.min(gy0, r.y0);
    gx1 = Math.max(gx1, r.x1);
    gy1 = Math.max(gy1, r.y1);
  }
  const sx = (gx0 + gx1) / 2;
  const sy = (gy0 + gy1) / 2;
  const out = centres.map(([x, y]) => [x - sx, y - sy] as [number, number]);
  // centring a group no larger than the bed keeps every footprint on it
  for (let i = 0; i < out.length; i++) {
    const { width: w, length: l } = items[i];
    if (Math.abs(out[i][0]) + w / 2 > hw + TOUCH_MM || Math.abs(out[i][1]) + l / 2 > hl + TOUCH_MM) return null;
  }
  return out;
}

/** Whether two rectangles come closer than `gap` (touching at exactly `gap` is fine). */
function overlaps(a: Placed, b: Placed, gap: number): boolean {
  const g = gap - TOUCH_MM;
  return a.x0 < b.x1 + g && b.x0 < a.x1 + g && a.y0 < b.y1 + g && b.y0 < a.y1 + g;
}

function lexLess(a: readonly number[], b: readonly number[]): boolean {
  const EPS = 1e-9;
  for (let k = 0; k < a.length; k++) {
    if (a[k] < b[k] - EPS) return true;
    if (a[k] > b[k] + EPS) return false;
  }
  return false;
}
