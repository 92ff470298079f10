/**
 * Level-set tracing on a sampled scalar field (marching squares): the crossings of the level on grid edges
 * are joined cell by cell into polylines, open where they leave the grid and closed otherwise. Saddle cells
 * are resolved by a value at the cell centre supplied by the caller; every crossing point may be refined
 * onto the true level set by a caller's function (Newton steps on the exact field).
 * Shared by the gyroid (implicit surface sections) and concentric (distance-field insets) patterns.
 */

export interface ScalarGrid {
  /** Number of cells in X and Y (nodes are (nx+1)·(ny+1)). */
  nx: number;
  ny: number;
  /** Position of node (0, 0) and the cell size. */
  x0: number;
  y0: number;
  h: number;
  /** Node values, row-major: node (i, j) at j·(nx+1) + i. */
  v: Float64Array;
}

/** A contour point; `tag` is free for the refine function (concentric stores the nearest boundary edge). */
export interface ContourPt {
  x: number;
  y: number;
  tag?: number;
}

export interface Contour {
  pts: ContourPt[];
  closed: boolean;
}

export type Refine = (x: number, y: number, nodeA: number, nodeB: number) => ContourPt;

/**
 * Trace the level set `level`. `centre(i, j)` gives the field at the centre of cell (i, j) for saddle
 * cells; `refine` (optional) moves each linearly interpolated crossing onto the true level set.
 */
export function traceContours(g: ScalarGrid, level: number, centre: (i: number, j: number) => number, refine?: Refine): Contour[] {
  const { nx, ny, x0, y0, h, v } = g;
  const W = nx + 1;
  const nH = nx * (ny + 1);
  const nE = nH + W * ny;
  const nb = new Int32Array(2 * nE).fill(-1);
  const link = (e1: number, e2: number) => {
    nb[2 * e1 + (nb[2 * e1] === -1 ? 0 : 1)] = e2;
    nb[2 * e2 + (nb[2 * e2] === -1 ? 0 : 1)] = e1;
  };
  const es: number[] = [];
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const a = v[j * W + i] >= level, b = v[j * W + i + 1] >= level;
      const c = v[(j + 1) * W + i + 1] >= level, d = v[(j + 1) * W + i] >= level;
      if (a === b && b === c && c === d) continue;
      const bottom = j * nx + i, top = (j + 1) * nx + i, left = nH + j * W + i, right = nH + j * W + i + 1;
      const cb = a !== b, cr = b !== c, ct = c !== d, cl = d !== a;
      if (cb && cr && ct && cl) {
        if (centre(i, j) >= level === a) {
          link(bottom, right);
          link(top, left);
        } else {
          link(bottom, left);
          link(right, top);
        }
        continue;
      }
      es.length = 0;
      if (cb) es.push(bottom);
      if (cr) es.push(right);
      if (ct) es.push(top);
      if (cl) es.push(left);
      if (es.length === 2) link(es[0], es[1]);
    }
  }
  const pointOf = (e: number) => {
    let na: number, nbN: number, xa: number, ya: number, xb: number, yb: number;
    if (e < nH) {
      const j = Math.floor(e / nx), i = e - j * nx;
      na = j * W + i;
      nbN = na + 1;
      xa = x0 + i * h; ya = y0 + j * h; xb = xa + h; yb = ya;
    } else {
      const q = e - nH, j = Math.floor(q / W), i = q - j * W;
      na = j * W + i;
      nbN = na + W;
      xa = x0 + i * h; ya = y0 + j * h; xb = xa; yb = ya + h;
    }
    const fa = v[na] - level, fb = v[nbN] - level;
    const t = fa === fb ? 0.5 : fa / (fa - fb);
    const x = xa + t * (xb - xa), y = ya + t * (yb - ya);
    return refine ? refine(x, y, na, nbN) : { x, y };
  };
  const seen = new Uint8Array(nE);
  const out: Contour[] = [];
  const walk = (start: number, closed: boolean) => {
    const pts: ContourPt[] = [];
    let prev = -1, cur = start;
    while (cur !== -1 && !seen[cur]) {
      seen[cur] = 1;
      pts.push(pointOf(cur));
      const n0 = nb[2 * cur], n1 = nb[2 * cur + 1];
      const next = n0 !== -1 && n0 !== prev && !seen[n0] ? n0 : n1 !== -1 && n1 !== prev && !seen[n1] ? n1 : -1;
      prev = cur;
      cur = next;
    }
    if (pts.length >= 2) out.push({ pts, closed: closed && pts.length > 2 });
  };
  for (let e = 0; e < nE; e++) if (!seen[e] && nb[2 * e] !== -1 && nb[2 * e + 1] === -1) walk(e, false);
  for (let e = 0; e < nE; e++) if (!seen[e] && nb[2 * e] !== -1) walk(e, true);
  return out;
}

/**
 * Total length of the level set `level`, by linear interpolation only (no chaining, no refinement);
 * `weight(i, j)` scales each cell's contribution. A quick measure for choosing parameters.
 */
export function contourLength(g: ScalarGrid, level: number, weight?: (i: number, j: number) => number): number {
  const { nx, ny, h, v } = g;
  const W = nx + 1;
  let total = 0;
  const px: number[] = [], py: number[] = [];
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const a = v[j * W + i] - level, b = v[j * W + i + 1] - level;
      const c = v[(j + 1) * W + i + 1] - level, d = v[(j + 1) * W + i] - level;
      const sa = a >= 0, sb = b >= 0, sc = c >= 0, sd = d >= 0;
      if (sa === sb && sb === sc && sc === sd) continue;
      px.length = 0;
      py.length = 0;
      if (sa !== sb) { px.push(a / (a - b)); py.push(0); }
      if (sb !== sc) { px.push(1); py.push(b / (b - c)); }
      if (sc !== sd) { px.push(1 - c / (c - d)); py.push(1); }
      if (sd !== sa) { px.push(0); py.push(1 - d / (d - a)); }
      let l = Math.hypot(px[1] - px[0], py[1] - py[0]);
      if (px.length === 4) l += Math.hypot(px[3] - px[2], py[3] - py[2]);
      total += (weight ? weight(i, j) : 1) * l * h;
    }
  }
  return total;
}
