/**
 * A region (islands with holes, integer µm) flattened into rings with arc-length tables, plus a lazily
 * built spatial index over its edges: a uniform grid for segment/edge intersection and nearest-boundary
 * queries, and horizontal bands for point-in-region tests. Built once per layer call, plain arrays only.
 */
import { hypot, type ExPolygon, type Polygon } from '../geometry/types.js';
import { closestOnSegment } from './geom-util.js';

/** One closed ring: vertex coordinates and cumulative arc length (cum[i] = length up to vertex i, cum[n] = total). */
export interface Ring {
  n: number;
  xs: Float64Array;
  ys: Float64Array;
  cum: Float64Array;
  length: number;
}

/** A point on the boundary: ring index and arc-length position along it (µm from vertex 0). */
export interface Anchor {
  ring: number;
  pos: number;
}

export interface RegionGeom {
  rings: Ring[];
  /** First global edge id of each ring (edge e of ring r is vertex i → i+1 with e = edgeStart[r] + i). */
  edgeStart: number[];
  edgeCount: number;
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  /** Area, µm² (outer minus holes). */
  area: number;
  /** Total boundary length, µm. */
  perimeter: number;
}

export interface RegionIndex extends RegionGeom {
  /** Edge endpoints by global edge id. */
  ex0: Float64Array;
  ey0: Float64Array;
  ex1: Float64Array;
  ey1: Float64Array;
  edgeRing: Int32Array;
  edgeLocal: Int32Array;
  /** Grid: cell size (µm), columns, rows, CSR lists of edges per cell. */
  cell: number;
  nx: number;
  ny: number;
  cellStart: Int32Array;
  cellEdges: Int32Array;
  /** Bands (one per grid row): CSR lists of non-horizontal edges overlapping the row in Y. */
  bandStart: Int32Array;
  bandEdges: Int32Array;
  /** Scratch for de-duplicating edges during one query. */
  stamp: Int32Array;
  stampNow: { v: number };
}

function ringOf(poly: Polygon): Ring | null {
  const n = poly.length;
  if (n < 3) return null;
  const xs = new Float64Array(n),
    ys = new Float64Array(n),
    cum = new Float64Array(n + 1);
  for (let i = 0; i < n; i++) {
    xs[i] = poly[i].x;
    ys[i] = poly[i].y;
  }
  for (let i = 0; i < n; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    cum[i + 1] = cum[i] + hypot(xs[j] - xs[i], ys[j] - ys[i]);
  }
  return { n, xs, ys, cum, length: cum[n] };
}

function signedArea(r: Ring): number {
  let a = 0;
  for (let i = 0, j = r.n - 1; i < r.n; j = i++) a += (r.xs[j] + r.xs[i]) * (r.ys[j] - r.ys[i]);
  return -a / 2;
}

/** Flatten a region into rings with arc-length tables (cheap; enough for the scanline clipper and linking). */
export function regionGeom(region: readonly ExPolygon[]): RegionGeom {
  const rings: Ring[] = [];
  const edgeStart: number[] = [];
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  let area = 0,
    perimeter = 0,
    edgeCount = 0;
  const add = (poly: Polygon, hole: boolean) => {
    const r = ringOf(poly);
    if (!r) return;
    edgeStart.push(edgeCount);
    edgeCount += r.n;
    rings.push(r);
    perimeter += r.length;
    const a = Math.abs(signedArea(r));
    area += hole ? -a : a;
    for (let i = 0; i < r.n; i++) {
      const x = r.xs[i],
        y = r.ys[i];
      if (x < minX) minX = x;
      if (x > maxX) maxX = x;
      if (y < minY) minY = y;
      if (y > maxY) maxY = y;
    }
  };
  for (const e of region) {
    add(e.outer, false);
    for (const h of e.holes) add(h, true);
  }
  return { rings, edgeStart, edgeCount, minX, minY, maxX, maxY, area: Math.max(0, area), perimeter };
}

/** Padding of the grid registration, µm: a point within this of a cell border is listed on both sides. */
const GRID_PAD_UM = 1;

/** Column range [c0, c1] of cells an x-interval touches, clamped. */
function cols(ix: RegionIndex, xa: number, xb: number): [number, number] {
  const c0 = Math.max(0, Math.floor((Math.min(xa, xb) - GRID_PAD_UM - ix.minX) / ix.cell));
  const c1 = Math.min(ix.nx - 1, Math.floor((Math.max(xa, xb) + GRID_PAD_UM - ix.minX) / ix.cell));
  return [c0, c1];
}

/**
 * Visit every grid cell a segment may touch (row by row, the segment's x-range within each row, padded).
 * `visit(cellIndex)` is called once per cell.
 */
function forCells(ix: RegionIndex, x0: number, y0: number, x1: number, y1: number, visit: (c: number) => void): void {
  const yLo = Math.min(y0, y1),
    yHi = Math.max(y0, y1);
  const r0 = Math.max(0, Math.floor((yLo - GRID_PAD_UM - ix.minY) / ix.cell));
  const r1 = Math.min(ix.ny - 1, Math.floor((yHi + GRID_PAD_UM - ix.minY) / ix.cell));
  const dy = y1 - y0;
  for (let r = r0; r <= r1; r++) {
    let xa: number, xb: number;
    if (dy === 0) {
      xa = x0;
      xb = x1;
    } else {
      const bandLo = ix.minY + r * ix.cell - GRID_PAD_UM,
        bandHi = ix.minY + (r + 1) * ix.cell + GRID_PAD_UM;
      const ya = Math.max(yLo, bandLo),
        yb = Math.min(yHi, bandHi);
      xa = x0 + ((ya - y0) / dy) * (x1 - x0);
      xb = x0 + ((yb - y0) / dy) * (x1 - x0);
    }
    const [c0, c1] = cols(ix, xa, xb);
    for (let c = c0; c <= c1; c++) visit(r * ix.nx + c);
  }
}

/** Build the spatial index over a region's edges. */
export function indexRegion(geom: RegionGeom): RegionIndex {
  const E = geom.edgeCount;
  const ex0 = new Float64Array(E),
    ey0 = new Float64Array(E),
    ex1 = new Float64Array(E),
    ey1 = new Float64Array(E);
  const edgeRing = new Int32Array(E),
    edgeLocal = new Int32Array(E);
  for (let r = 0; r < geom.rings.length; r++) {
    const ring = geom.rings[r];
    const base = geom.edgeStart[r];
    for (let i = 0; i < ring.n; i++) {
      const j = i + 1 === ring.n ? 0 : i + 1;
      const e = base + i;
      ex0[e] = ring.xs[i];
      ey0[e] = ring.ys[i];
      ex1[e] = ring.xs[j];
      ey1[e] = ring.ys[j];
      edgeRing[e] = r;
      edgeLocal[e] = i;
    }
  }
  const w = Math.max(1, geom.maxX - geom.minX),
    h = Math.max(1, geom.maxY - geom.minY);
  const targetCells = Math.min(1 << 16, Math.max(64, 2 * E));
  const cell = Math.max(50, Math.sqrt((w * h) / targetCells), Math.max(w, h) / 1024);
  const nx = Math.max(1, Math.ceil(w / cell) + 1),
    ny = Math.max(1, Math.ceil(h / cell) + 1);
  const ix: RegionIndex = {
    ...geom,
    ex0,
    ey0,
    ex1,
    ey1,
    edgeRing,
    edgeLocal,
    cell,
    nx,
    ny,
    cellStart: new Int32Array(nx * ny + 1),
    cellEdges: new Int32Array(0),
    bandStart: new Int32Array(ny + 1),
    bandEdges: new Int32Array(0),
    stamp: new Int32Array(E),
    stampNow: { v: 0 },
  };
  // grid: count, then fill (CSR)
  const counts = new Int32Array(nx * ny);
  for (let e = 0; e < E; e++) forCells(ix, ex0[e], ey0[e], ex1[e], ey1[e], (c) => counts[c]++);
  let total = 0;
  for (let c = 0; c < nx * ny; c++) {
    ix.cellStart[c] = total;
    total += counts[c];
  }
  ix.cellStart[nx * ny] = total;
  const cellEdges = new Int32Array(total);
  const fill = ix.cellStart.slice(0, nx * ny);
  for (let e = 0; e < E; e++) forCells(ix, ex0[e], ey0[e], ex1[e], ey1[e], (c) => (cellEdges[fill[c]++] = e));
  ix.cellEdges = cellEdges;
  // bands
  const bc = new Int32Array(ny);
  const bandRange = (e: number): [number, number] => {
    const lo = Math.min(ey0[e], ey1[e]),
      hi = Math.max(ey0[e], ey1[e]);
    return [Math.max(0, Math.floor((lo - ix.minY) / cell)), Math.min(ny - 1, Math.floor((hi - ix.minY) / cell))];
  };
  for (let e = 0; e < E; e++) {
    if (ey0[e] === ey1[e]) continue;
    const [b0, b1] = bandRange(e);
    for (let b = b0; b <= b1; b++) bc[b]++;
  }
  let bt = 0;
  for (let b = 0; b < ny; b++) {
    ix.bandStart[b] = bt;
    bt += bc[b];
  }
  ix.bandStart[ny] = bt;
  const bandEdges = new Int32Array(bt);
  const bf = ix.bandStart.slice(0, ny);
  for (let e = 0; e < E; e++) {
    if (ey0[e] === ey1[e]) continue;
    const [b0, b1] = bandRange(e);
    for (let b = b0; b <= b1; b++) bandEdges[bf[b]++] = e;
  }
  ix.bandEdges = bandEdges;
  return ix;
}

/** Even-odd point-in-region test (points exactly on the boundary may go either way). */
export function pointInside(ix: RegionIndex, x: number, y: number): boolean {
  if (x < ix.minX || x > ix.maxX || y < ix.minY || y > ix.maxY) return false;
  const b = Math.min(ix.ny - 1, Math.max(0, Math.floor((y - ix.minY) / ix.cell)));
  let inside = false;
  for (let k = ix.bandStart[b], end = ix.bandStart[b + 1]; k < end; k++) {
    const e = ix.bandEdges[k];
    const ay = ix.ey0[e],
      by = ix.ey1[e];
    if (ay > y !== by > y) {
      const xi = ix.ex0[e] + ((y - ay) / (by - ay)) * (ix.ex1[e] - ix.ex0[e]);
      if (x < xi) inside = !inside;
    }
  }
  return inside;
}

/** One intersection of a query segment with a region edge: parameters along the segment (t) and the edge (u). */
export interface Hit {
  t: number;
  edge: number;
  u: number;
}

function hitEdge(ix: RegionIndex, e: number, x0: number, y0: number, dx: number, dy: number, out: Hit[]): void {
  const ax = ix.ex0[e],
    ay = ix.ey0[e];
  const ux = ix.ex1[e] - ax,
    uy = ix.ey1[e] - ay;
  const den = dx * uy - dy * ux;
  if (den === 0) return;
  const wx = ax - x0,
    wy = ay - y0;
  const t = (wx * uy - wy * ux) / den;
  if (t < 0 || t > 1) return;
  const u = (wx * dy - wy * dx) / den;
  if (u < 0 || u > 1) return;
  out.push({ t, edge: e, u });
}

/** All intersections of segment (x0,y0)→(x1,y1) with region edges, sorted by t. Parallel overlaps are ignored. */
export function segmentHits(ix: RegionIndex, x0: number, y0: number, x1: number, y1: number, out: Hit[]): void {
  if (out.length) out.length = 0;
  // fast path: a short segment well inside one cell that holds no edge cannot cross anything
  const fx0 = (x0 - ix.minX) / ix.cell,
    fy0 = (y0 - ix.minY) / ix.cell;
  const fx1 = (x1 - ix.minX) / ix.cell,
    fy1 = (y1 - ix.minY) / ix.cell;
  const cx = Math.floor(fx0),
    cy = Math.floor(fy0);
  const dx = x1 - x0,
    dy = y1 - y0;
  if (cx === Math.floor(fx1) && cy === Math.floor(fy1) && cx >= 0 && cy >= 0 && cx < ix.nx && cy < ix.ny) {
    const pad = GRID_PAD_UM / ix.cell;
    const inner = (f: number) => f - Math.floor(f) > pad && Math.ceil(f) - f > pad;
    if (inner(fx0) && inner(fy0) && inner(fx1) && inner(fy1)) {
      // a short segment well inside one cell meets only that cell's edges
      const c = cy * ix.nx + cx;
      for (let k = ix.cellStart[c], end = ix.cellStart[c + 1]; k < end; k++)
        hitEdge(ix, ix.cellEdges[k], x0, y0, dx, dy, out);
      if (out.length > 1) out.sort((a, b) => a.t - b.t || a.edge - b.edge);
      return;
    }
  }
  // general case: the cells of each row the segment passes (as in forCells, inlined: this is hot)
  const stamp = ++ix.stampNow.v;
  const yLo = Math.min(y0, y1),
    yHi = Math.max(y0, y1);
  const r0 = Math.max(0, Math.floor((yLo - GRID_PAD_UM - ix.minY) / ix.cell));
  const r1 = Math.min(ix.ny - 1, Math.floor((yHi + GRID_PAD_UM - ix.minY) / ix.cell));
  for (let r = r0; r <= r1; r++) {
    let xa: number, xb: number;
    if (dy === 0) {
      xa = x0;
      xb = x1;
    } else {
      const ya = Math.max(yLo, ix.minY + r * ix.cell - GRID_PAD_UM),
        yb = Math.min(yHi, ix.minY + (r + 1) * ix.cell + GRID_PAD_UM);
      xa = x0 + ((ya - y0) / dy) * dx;
      xb = x0 + ((yb - y0) / dy) * dx;
    }
    const c0 = Math.max(0, Math.floor((Math.min(xa, xb) - GRID_PAD_UM - ix.minX) / ix.cell));
    const c1 = Math.min(ix.nx - 1, Math.floor((Math.max(xa, xb) + GRID_PAD_UM - ix.minX) / ix.cell));
    for (let c = r * ix.nx + c0, cEnd = r * ix.nx + c1; c <= cEnd; c++) {
      for (let k = ix.cellStart[c], end = ix.cellStart[c + 1]; k < end; k++) {
        const e = ix.cellEdges[k];
        if (ix.stamp[e] === stamp) continue;
        ix.stamp[e] = stamp;
        hitEdge(ix, e, x0, y0, dx, dy, out);
      }
    }
  }
  if (out.length > 1) out.sort((a, b) => a.t - b.t || a.edge - b.edge);
}

/** Whether the open segment crosses the boundary anywhere except within `endSlackUm` of its ends. */
export function segmentCrosses(
  ix: RegionIndex,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  endSlackUm: number,
  scratch: Hit[],
): boolean {
  segmentHits(ix, x0, y0, x1, y1, scratch);
  if (scratch.length === 0) return false;
  const len = hypot(x1 - x0, y1 - y0);
  const slack = len > 0 ? endSlackUm / len : 1;
  for (const h of scratch) if (h.t > slack && h.t < 1 - slack) return true;
  return false;
}

/** Anchor (ring, arc position) of the point at parameter u on global edge e. */
export function anchorOnEdge(
  ix: RegionGeom & { edgeRing?: Int32Array; edgeLocal?: Int32Array },
  e: number,
  u: number,
): Anchor {
  let r = 0;
  let i = 0;
  if (ix.edgeRing && ix.edgeLocal) {
    r = ix.edgeRing[e];
    i = ix.edgeLocal[e];
  } else {
    while (r + 1 < ix.edgeStart.length && ix.edgeStart[r + 1] <= e) r++;
    i = e - ix.edgeStart[r];
  }
  const ring = ix.rings[r];
  return { ring: r, pos: ring.cum[i] + u * (ring.cum[i + 1] - ring.cum[i]) };
}

/** Nearest boundary point to (x, y) within maxDist µm, or null. */
export interface Nearest {
  x: number;
  y: number;
  dist: number;
  edge: number;
  u: number;
}

export function nearestBoundary(ix: RegionIndex, x: number, y: number, maxDist: number): Nearest | null {
  let best: Nearest | null = null;
  let bestD2 = maxDist * maxDist;
  const cx = Math.floor((x - ix.minX) / ix.cell),
    cy = Math.floor((y - ix.minY) / ix.cell);
  const maxRing = Math.ceil(maxDist / ix.cell) + 1;
  const stamp = ++ix.stampNow.v;
  for (let rr = 0; rr <= maxRing; rr++) {
    // cells at Chebyshev distance rr from (cx, cy)
    if (best) {
      const ringMin = (rr - 1) * ix.cell;
      if (ringMin > 0 && ringMin * ringMin > bestD2) break;
    }
    const y0 = cy - rr,
      y1 = cy + rr;
    for (let gy = y0; gy <= y1; gy++) {
      if (gy < 0 || gy >= ix.ny) continue;
      const edgeRow = gy === y0 || gy === y1;
      for (let gx = cx - rr; gx <= cx + rr; gx += edgeRow ? 1 : 2 * rr || 1) {
        if (gx < 0 || gx >= ix.nx) continue;
        const c = gy * ix.nx + gx;
        for (let k = ix.cellStart[c], end = ix.cellStart[c + 1]; k < end; k++) {
          const e = ix.cellEdges[k];
          if (ix.stamp[e] === stamp) continue;
          ix.stamp[e] = stamp;
          const q = closestOnSegment(ix.ex0[e], ix.ey0[e], ix.ex1[e], ix.ey1[e], x, y);
          if (q.d2 < bestD2 || (q.d2 === bestD2 && best && e < best.edge)) {
            bestD2 = q.d2;
            best = { x: q.x, y: q.y, dist: Math.sqrt(q.d2), edge: e, u: q.t };
          }
        }
      }
    }
  }
  return best;
}

/** Boundary path from anchor a forward (increasing arc position) to anchor b on the same ring, both ends included. */
export function boundaryPath(geom: RegionGeom, a: Anchor, b: Anchor): Array<{ x: number; y: number }> {
  const ring = geom.rings[a.ring];
  const L = ring.length;
  const at = (pos: number) => {
    let p = pos % L;
    if (p < 0) p += L;
    // binary search the edge containing p
    let lo = 0,
      hi = ring.n - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (ring.cum[mid] <= p) lo = mid;
      else hi = mid - 1;
    }
    const i = lo,
      j = i + 1 === ring.n ? 0 : i + 1;
    const el = ring.cum[i + 1] - ring.cum[i];
    const u = el > 0 ? (p - ring.cum[i]) / el : 0;
    return { i, x: ring.xs[i] + u * (ring.xs[j] - ring.xs[i]), y: ring.ys[i] + u * (ring.ys[j] - ring.ys[i]) };
  };
  let gap = b.pos - a.pos;
  if (gap < 0) gap += L;
  const pa = at(a.pos);
  const out = [{ x: pa.x, y: pa.y }];
  // vertices strictly after a.pos up to b.pos (walk forward)
  let i = pa.i;
  let travelled = ring.cum[i + 1] - (a.pos % L < 0 ? (a.pos % L) + L : a.pos % L);
  while (travelled < gap) {
    i = i + 1 === ring.n ? 0 : i + 1;
    out.push({ x: ring.xs[i], y: ring.ys[i] });
    travelled += ring.cum[i + 1] - ring.cum[i];
  }
  const pb = at(b.pos);
  out.push({ x: pb.x, y: pb.y });
  return out;
}
