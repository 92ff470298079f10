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
 * The two crossed cell sides (0 bottom, 1 right, 2 top, 3 left) for each corner sign pattern
 * (bit 0: (0,0), bit 1: (1,0), bit 2: (1,1), bit 3: (0,1) at or above the level); saddles 5 and 10 apart.
 */
const CASE_EDGES: ReadonlyArray<readonly [number, number]> = [
  [0, 0],
  [0, 3],
  [0, 1],
  [1, 3],
  [1, 2],
  [0, 0],
  [0, 2],
  [2, 3],
  [2, 3],
  [0, 2],
  [0, 0],
  [1, 2],
  [1, 3],
  [0, 1],
  [0, 3],
  [0, 0],
];

/** Reusable per-grid work arrays for traceContours (sized for the grid; cleaned after every call). */
export interface ContourScratch {
  nb: Int32Array;
  seen: Uint8Array;
}

export function contourScratch(g: ScalarGrid): ContourScratch {
  const nE = g.nx * (g.ny + 1) + (g.nx + 1) * g.ny;
  return { nb: new Int32Array(2 * nE).fill(-1), seen: new Uint8Array(nE) };
}

/**
 * Trace the level set `level`. `centre(i, j)` gives the field at the centre of cell (i, j) for saddle
 * cells; `refine` (optional) moves each linearly interpolated crossing onto the true level set. `cells`
 * (optional) limits the work to the listed cells (j·nx + i), which must include every cell the level
 * crosses; `scratch` avoids allocating the work arrays on every call.
 */
export function traceContours(
  g: ScalarGrid,
  level: number,
  centre: (i: number, j: number) => number,
  refine?: Refine,
  cells?: ArrayLike<number>,
  scratch?: ContourScratch,
): Contour[] {
  const { nx, ny, x0, y0, h, v } = g;
  const W = nx + 1;
  const nH = nx * (ny + 1);
  const { nb, seen } = scratch ?? contourScratch(g);
  const touched: number[] = [];
  const link = (e1: number, e2: number) => {
    if (nb[2 * e1] === -1) {
      nb[2 * e1] = e2;
      touched.push(e1);
    } else nb[2 * e1 + 1] = e2;
    if (nb[2 * e2] === -1) {
      nb[2 * e2] = e1;
      touched.push(e2);
    } else nb[2 * e2 + 1] = e1;
  };
  const cell = (i: number, j: number) => {
    const n = j * W + i;
    const a = v[n] >= level,
      b = v[n + 1] >= level,
      c = v[n + W + 1] >= level,
      d = v[n + W] >= level;
    const code = (a ? 1 : 0) | (b ? 2 : 0) | (c ? 4 : 0) | (d ? 8 : 0);
    if (code === 0 || code === 15) return;
    const bottom = j * nx + i,
      top = (j + 1) * nx + i,
      left = nH + n,
      right = nH + n + 1;
    if (code === 5 || code === 10) {
      if (centre(i, j) >= level === a) {
        link(bottom, right);
        link(top, left);
      } else {
        link(bottom, left);
        link(right, top);
      }
      return;
    }
    const pair = CASE_EDGES[code];
    const e0 = pair[0] === 0 ? bottom : pair[0] === 1 ? right : pair[0] === 2 ? top : left;
    const e1 = pair[1] === 0 ? bottom : pair[1] === 1 ? right : pair[1] === 2 ? top : left;
    link(e0, e1);
  };
  if (cells) {
    for (let k = 0; k < cells.length; k++) {
      const c = cells[k],
        j = Math.floor(c / nx);
      cell(c - j * nx, j);
    }
  } else {
    for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) cell(i, j);
  }
  const pointOf = (e: number) => {
    let na: number, nbN: number, xa: number, ya: number, xb: number, yb: number;
    if (e < nH) {
      const j = Math.floor(e / nx),
        i = e - j * nx;
      na = j * W + i;
      nbN = na + 1;
      xa = x0 + i * h;
      ya = y0 + j * h;
      xb = xa + h;
      yb = ya;
    } else {
      const q = e - nH,
        j = Math.floor(q / W),
        i = q - j * W;
      na = j * W + i;
      nbN = na + W;
      xa = x0 + i * h;
      ya = y0 + j * h;
      xb = xa;
      yb = ya + h;
    }
    const fa = v[na] - level,
      fb = v[nbN] - level;
    const t = fa === fb ? 0.5 : fa / (fa - fb);
    const x = xa + t * (xb - xa),
      y = ya + t * (yb - ya);
    return refine ? refine(x, y, na, nbN) : { x, y };
  };
  const out: Contour[] = [];
  const walk = (start: number, closed: boolean) => {
    const pts: ContourPt[] = [];
    let prev = -1,
      cur = start;
    while (cur !== -1 && !seen[cur]) {
      seen[cur] = 1;
      pts.push(pointOf(cur));
      const n0 = nb[2 * cur],
        n1 = nb[2 * cur + 1];
      const next = n0 !== -1 && n0 !== prev && !seen[n0] ? n0 : n1 !== -1 && n1 !== prev && !seen[n1] ? n1 : -1;
      prev = cur;
      cur = next;
    }
    if (pts.length >= 2) out.push({ pts, closed: closed && pts.length > 2 });
  };
  // open contours from their ends first (they leave the grid), then the closed ones; edges in id order
  touched.sort((p, q) => p - q);
  for (const e of touched) if (!seen[e] && nb[2 * e + 1] === -1) walk(e, false);
  for (const e of touched) if (!seen[e]) walk(e, true);
  for (const e of touched) {
    nb[2 * e] = -1;
    nb[2 * e + 1] = -1;
    seen[e] = 0;
  }
  return out;
}
