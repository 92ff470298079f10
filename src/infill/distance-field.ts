/**
 * Signed distance to the region boundary (positive inside), sampled on a grid. Each node keeps the id of
 * its nearest boundary edge: nodes near each edge are seeded exactly, then two raster sweeps pass edge ids
 * on to neighbours (vector propagation), each candidate's distance computed exactly from the segment. The
 * edge ids also let callers evaluate the exact distance at any point near a node (for refining contours).
 */
import type { RegionIndex } from './region-index.js';
import type { ScalarGrid } from './contour.js';
import { closestOnSegment } from './geom-util.js';
import { hypot } from '../geometry/types.js';
import { PARALLEL_SIN_EPS } from '../geometry/tolerances.js';

export interface DistanceField extends ScalarGrid {
  /** Nearest boundary edge of each node (−1 if none). */
  edge: Int32Array;
  /** Largest distance of any node (depth of the region), µm. */
  maxDepth: number;
}

/** Exact distance from (x, y) to edge e, with the nearest point. */
export function edgeDistance(ix: RegionIndex, e: number, x: number, y: number): { d: number; qx: number; qy: number } {
  const q = closestOnSegment(ix.ex0[e], ix.ey0[e], ix.ex1[e], ix.ey1[e], x, y);
  return { d: Math.sqrt(q.d2), qx: q.x, qy: q.y };
}

/** Signed distance field of the region on a grid of cell size h (µm), one cell of margin outside. */
export function distanceField(ix: RegionIndex, h: number): DistanceField {
  const x0 = ix.minX - h,
    y0 = ix.minY - h;
  const nx = Math.ceil((ix.maxX - ix.minX) / h) + 2,
    ny = Math.ceil((ix.maxY - ix.minY) / h) + 2;
  const W = nx + 1,
    N = W * (ny + 1);
  const best = new Float64Array(N).fill(Infinity);
  const edge = new Int32Array(N).fill(-1);
  const E = ix.edgeCount;
  // seed: nodes within about one cell of each edge
  for (let e = 0; e < E; e++) {
    const ax = ix.ex0[e],
      ay = ix.ey0[e],
      bx = ix.ex1[e],
      by = ix.ey1[e];
    const j0 = Math.max(0, Math.floor((Math.min(ay, by) - y0) / h) - 1),
      j1 = Math.min(ny, Math.ceil((Math.max(ay, by) - y0) / h) + 1);
    for (let j = j0; j <= j1; j++) {
      const y = y0 + j * h;
      let xa: number, xb: number;
      if (ay === by) {
        xa = Math.min(ax, bx);
        xb = Math.max(ax, bx);
      } else {
        const lo = Math.max(Math.min(ay, by), y - h),
          hi = Math.min(Math.max(ay, by), y + h);
        const xl = ax + ((lo - ay) / (by - ay)) * (bx - ax),
          xh = ax + ((hi - ay) / (by - ay)) * (bx - ax);
        xa = Math.min(xl, xh);
        xb = Math.max(xl, xh);
      }
      const i0 = Math.max(0, Math.floor((xa - x0) / h) - 1),
        i1 = Math.min(nx, Math.ceil((xb - x0) / h) + 1);
      for (let i = i0; i <= i1; i++) {
        const n = j * W + i;
        const d2 = closestOnSegment(ix.ex0[e], ix.ey0[e], ix.ex1[e], ix.ey1[e], x0 + i * h, y).d2;
        if (d2 < best[n] || (d2 === best[n] && e < edge[n])) {
          best[n] = d2;
          edge[n] = e;
        }
      }
    }
  }
  // one forward and one backward sweep pass nearest-edge ids on (the exact seeding makes one pair enough)
  const { ex0, ey0, ex1, ey1 } = ix;
  const relax = (n: number, m: number, x: number, y: number) => {
    const e = edge[m];
    if (e < 0 || e === edge[n]) return;
    const ax = ex0[e],
      ay = ey0[e],
      ux = ex1[e] - ax,
      uy = ey1[e] - ay;
    const l2 = ux * ux + uy * uy;
    let t = l2 > 0 ? ((x - ax) * ux + (y - ay) * uy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const dx = x - ax - t * ux,
      dy = y - ay - t * uy;
    const d2 = dx * dx + dy * dy;
    if (d2 < best[n]) {
      best[n] = d2;
      edge[n] = e;
    }
  };
  for (let j = 0; j <= ny; j++) {
    const y = y0 + j * h;
    for (let i = 0; i <= nx; i++) {
      const n = j * W + i,
        x = x0 + i * h;
      if (i > 0) relax(n, n - 1, x, y);
      if (j > 0) {
        relax(n, n - W, x, y);
        if (i > 0) relax(n, n - W - 1, x, y);
        if (i < nx) relax(n, n - W + 1, x, y);
      }
    }
  }
  for (let j = ny; j >= 0; j--) {
    const y = y0 + j * h;
    for (let i = nx; i >= 0; i--) {
      const n = j * W + i,
        x = x0 + i * h;
      if (i < nx) relax(n, n + 1, x, y);
      if (j < ny) {
        relax(n, n + W, x, y);
        if (i < nx) relax(n, n + W + 1, x, y);
        if (i > 0) relax(n, n + W - 1, x, y);
      }
    }
  }
  // sign: even-odd along each node row
  const v = new Float64Array(N);
  const xs: number[] = [];
  let maxDepth = 0;
  for (let j = 0; j <= ny; j++) {
    const y = y0 + j * h;
    xs.length = 0;
    const b = Math.min(ix.ny - 1, Math.max(0, Math.floor((y - ix.minY) / ix.cell)));
    for (let k = ix.bandStart[b], end = ix.bandStart[b + 1]; k < end; k++) {
      const e = ix.bandEdges[k];
      const ay = ix.ey0[e],
        by = ix.ey1[e];
      if (ay > y !== by > y) xs.push(ix.ex0[e] + ((y - ay) / (by - ay)) * (ix.ex1[e] - ix.ex0[e]));
    }
    xs.sort((p, q) => p - q);
    let k = 0;
    let inside = false;
    for (let i = 0; i <= nx; i++) {
      const x = x0 + i * h;
      while (k < xs.length && xs[k] <= x) {
        inside = !inside;
        k++;
      }
      const n = j * W + i;
      const d = Math.sqrt(best[n]);
      v[n] = inside ? d : -d;
      if (inside && d > maxDepth) maxDepth = d;
    }
  }
  return { nx, ny, x0, y0, h, v, edge, maxDepth };
}

/**
 * Move a point near the level set {distance = t} onto it, using the nearest edges of two grid nodes.
 * `tag` is the edge the point ends up nearest to when that nearest point lies inside the edge (not at a
 * vertex), else −1: the contour there runs parallel to that edge.
 */
export function refineToDepth(
  ix: RegionIndex,
  f: DistanceField,
  x: number,
  y: number,
  na: number,
  nb: number,
  t: number,
): { x: number; y: number; tag: number } {
  let px = x,
    py = y,
    tag = -1;
  for (let it = 0; it < 2; it++) {
    let bestD = Infinity,
      qx = 0,
      qy = 0,
      be = -1;
    for (const e of [f.edge[na], f.edge[nb]]) {
      if (e < 0) continue;
      const r = edgeDistance(ix, e, px, py);
      if (r.d < bestD) {
        bestD = r.d;
        qx = r.qx;
        qy = r.qy;
        be = e;
      }
    }
    if (!(bestD > 0) || !isFinite(bestD)) break;
    // never move farther than a cell: a wrong edge candidate must not throw the point away
    if (Math.abs(t - bestD) > f.h) break;
    const k = (t - bestD) / bestD;
    px += (px - qx) * k;
    py += (py - qy) * k;
    const atVertex = (qx === ix.ex0[be] && qy === ix.ey0[be]) || (qx === ix.ex1[be] && qy === ix.ey1[be]);
    tag = atVertex ? -1 : be;
  }
  return { x: px, y: py, tag };
}

/**
 * Restore the sharp corners the sampling cut off: where two consecutive contour points run parallel to
 * different boundary edges, the contour turns where the two parallels meet (a convex corner of the inset);
 * that point is inserted when it lies within `reach` of both.
 */
export function restoreCorners(ix: RegionIndex, pts: ContourPtIn[], closed: boolean, reach: number): ContourPtIn[] {
  const out: ContourPtIn[] = [];
  const n = pts.length;
  const dir = (e: number) => {
    const ux = ix.ex1[e] - ix.ex0[e],
      uy = ix.ey1[e] - ix.ey0[e];
    const l = hypot(ux, uy);
    return { x: ux / l, y: uy / l };
  };
  for (let k = 0; k < n; k++) {
    const a = pts[k];
    out.push(a);
    if (!closed && k === n - 1) break;
    const b = pts[(k + 1) % n];
    const ea = a.tag ?? -1,
      eb = b.tag ?? -1;
    if (ea < 0 || eb < 0 || ea === eb) continue;
    const da = dir(ea),
      db = dir(eb);
    const den = da.x * db.y - da.y * db.x;
    if (Math.abs(den) < PARALLEL_SIN_EPS) continue;
    // a + s·da = b + r·db
    const wx = b.x - a.x,
      wy = b.y - a.y;
    const sA = (wx * db.y - wy * db.x) / den;
    const cx = a.x + sA * da.x,
      cy = a.y + sA * da.y;
    if (hypot(cx - a.x, cy - a.y) > reach || hypot(cx - b.x, cy - b.y) > reach) continue;
    out.push({ x: cx, y: cy, tag: -1 });
  }
  return out;
}

interface ContourPtIn {
  x: number;
  y: number;
  tag?: number;
}
