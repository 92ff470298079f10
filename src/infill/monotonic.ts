/**
 * Monotonic solid fill: one family of parallel lines, printed so that every line is laid beside lines
 * already printed on one side only, never into the gap between two of them, so the surface has no seam
 * where two fronts of lines meet (PrusaSlicer's `monotonic` pattern; it irons this way too).
 *
 * The scanline clipper cuts the family into pieces, one row per line of the family. A piece is adjacent to
 * the pieces of the next row whose extent along the lines overlaps its own. Where a piece has exactly one
 * such neighbour and that neighbour has only it, the two belong to one run (a monotonic region); runs
 * split where a hole or a notch divides the rows. A run may print once every run it rests on (the runs of
 * its first piece's neighbours in the row before) is printed; among the runs that may print, the one whose
 * first piece is nearest the nozzle goes next. Inside a run the pieces print row after row, back and forth,
 * each joined to the next along the boundary when their ends are neighbours there and close, as the
 * zig-zag of rectilinear fill is. Rows always advance one way, so within a run and across runs a line has
 * at most its predecessors printed beside it.
 */
import type { ExPolygon, Polyline, Pt } from '../geometry/types.js';
import { type Anchor, type RegionGeom, boundaryPath, regionGeom } from './region-index.js';
import { clipSweep } from './sweep.js';
import { type Piece, pushPt, rnd } from './piece.js';
import { LINK_REACH } from './generate.js';

/**
 * The pieces of one family and their neighbours in the rows before and after: the neighbours of a piece in
 * one row are consecutive in the sweep, so each piece keeps a count and its first neighbour after it, and a
 * count and where its neighbours before it start in one list of them.
 */
interface Rows {
  pieces: Piece[];
  nextCount: Int32Array;
  nextFirst: Int32Array;
  prevCount: Int32Array;
  prevStart: Int32Array;
  /** The neighbours before of every piece, each piece's together. */
  prevList: Int32Array;
}

function rowsOf(geom: RegionGeom, angleDeg: number, spacingUm: number, origin: Pt): Rows {
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: angleDeg, spacingUm, offsetUm: 0 }, origin, pieces);
  const a = (angleDeg * Math.PI) / 180;
  const c = Math.cos(a),
    s = Math.sin(a);
  const P = pieces.length;
  const v0 = -origin.x * s + origin.y * c;
  const row = new Int32Array(P),
    lo = new Float64Array(P),
    hi = new Float64Array(P);
  for (let i = 0; i < P; i++) {
    const [p, q] = pieces[i].pts;
    row[i] = Math.round((-p.x * s + p.y * c - v0) / spacingUm);
    lo[i] = p.x * c + p.y * s;
    hi[i] = q.x * c + q.y * s;
  }
  const nextCount = new Int32Array(P),
    nextFirst = new Int32Array(P),
    prevCount = new Int32Array(P),
    prevStart = new Int32Array(P);
  // two rows of n and m intervals overlap in at most n + m − 1 pairs
  const prevList = new Int32Array(2 * P);
  let edges = 0;
  // the clipper emits rows in order and each row's pieces along the lines: sweep pairs of adjacent rows
  let start = 0;
  while (start < P) {
    let end = start;
    while (end < P && row[end] === row[start]) end++;
    let nEnd = end;
    while (nEnd < P && row[nEnd] === row[end]) nEnd++;
    if (end < P && row[end] === row[start] + 1) {
      for (let i = start, j = end; i < end && j < nEnd; ) {
        if (Math.min(hi[i], hi[j]) > Math.max(lo[i], lo[j])) {
          if (nextCount[i]++ === 0) nextFirst[i] = j;
          if (prevCount[j]++ === 0) prevStart[j] = edges;
          prevList[edges++] = i;
        }
        if (hi[i] < hi[j]) i++;
        else j++;
      }
    }
    start = end;
  }
  return { pieces, nextCount, nextFirst, prevCount, prevStart, prevList };
}

/** Runs of pieces, each a piece per row that has exactly one neighbour on either side between them. */
function runsOf(r: Rows): number[][] {
  const P = r.pieces.length;
  const runOf = new Int32Array(P).fill(-1);
  const runs: number[][] = [];
  for (let i = 0; i < P; i++) {
    if (runOf[i] >= 0) continue;
    const run = [i];
    runOf[i] = runs.length;
    let cur = i;
    while (r.nextCount[cur] === 1 && r.prevCount[r.nextFirst[cur]] === 1) {
      cur = r.nextFirst[cur];
      run.push(cur);
      runOf[cur] = runs.length;
    }
    runs.push(run);
  }
  return runs;
}

/** Ends of pieces along each boundary ring, to tell whether two ends are neighbours there. */
class RingEnds {
  readonly #rank: Int32Array;
  readonly #lists: number[][];
  constructor(geom: RegionGeom, pieces: readonly Piece[]) {
    this.#rank = new Int32Array(2 * pieces.length).fill(-1);
    const per: Array<Array<{ node: number; pos: number }>> = geom.rings.map(() => []);
    pieces.forEach((p, i) => {
      if (p.a0) per[p.a0.ring].push({ node: 2 * i, pos: p.a0.pos });
      if (p.a1) per[p.a1.ring].push({ node: 2 * i + 1, pos: p.a1.pos });
    });
    this.#lists = per.map((list) => {
      list.sort((a, b) => a.pos - b.pos || a.node - b.node);
      list.forEach((e, k) => (this.#rank[e.node] = k));
      return list.map((e) => e.node);
    });
  }
  /** +1 when `y` follows `x` along their ring, −1 when it precedes it, 0 when they are not neighbours. */
  side(x: number, ring: number, y: number): number {
    const list = this.#lists[ring];
    const m = list.length,
      k = this.#rank[x];
    if (m < 2 || k < 0) return 0;
    if (list[(k + 1) % m] === y) return 1;
    if (list[(k - 1 + m) % m] === y) return -1;
    return 0;
  }
}

export interface MonotonicOptions {
  /** Where the nozzle is before the fill (default: the region's lower-left corner). */
  start?: Pt;
  /** Join the pieces of a run along the boundary (default true). */
  connect?: boolean;
}

/**
 * Monotonic solid fill of `region`: lines `spacingUm` apart at `angleDeg`, phase anchored at `origin`, in
 * print order, each to be printed from its first point.
 */
export function monotonicFill(
  region: readonly ExPolygon[],
  angleDeg: number,
  spacingUm: number,
  origin: Pt,
  options: MonotonicOptions = {},
): Polyline[] {
  if (region.length === 0 || !(spacingUm > 0)) return [];
  const geom = regionGeom(region);
  const rows = rowsOf(geom, angleDeg, spacingUm, origin);
  const { pieces } = rows;
  if (pieces.length === 0) return [];
  const runs = runsOf(rows);
  const runOf = new Int32Array(pieces.length);
  runs.forEach((run, k) => run.forEach((i) => (runOf[i] = k)));
  // what each run waits for
  const waiting = new Int32Array(runs.length);
  const after: number[][] = runs.map(() => []);
  runs.forEach((run, k) => {
    const first = run[0];
    const deps = new Set<number>();
    for (let e = rows.prevStart[first], end = e + rows.prevCount[first]; e < end; e++)
      deps.add(runOf[rows.prevList[e]]);
    waiting[k] = deps.size;
    for (const d of deps) after[d].push(k);
  });
  const ends = options.connect === false ? null : new RingEnds(geom, pieces);
  const maxGap = LINK_REACH * spacingUm;
  const out: Polyline[] = [];
  let at = options.start ?? { x: geom.minX, y: geom.minY };
  const ready: number[] = [];
  for (let k = 0; k < runs.length; k++) if (waiting[k] === 0) ready.push(k);
  const d2 = (p: Pt) => (p.x - at.x) ** 2 + (p.y - at.y) ** 2;
  while (ready.length) {
    // the nearest run that may print, entered at the nearer end of its first piece
    let best = 0,
      bestD = Infinity,
      bestForward = true;
    for (let r = 0; r < ready.length; r++) {
      const pts = pieces[runs[ready[r]][0]].pts;
      const da = d2(pts[0]),
        db = d2(pts[1]);
      const d = Math.min(da, db);
      if (d < bestD || (d === bestD && ready[r] < ready[best])) {
        best = r;
        bestD = d;
        bestForward = da <= db;
      }
    }
    const k = ready[best];
    ready.splice(best, 1);
    at = emitRun(geom, pieces, runs[k], bestForward, ends, maxGap, out);
    for (const n of after[k]) if (--waiting[n] === 0) ready.push(n);
  }
  return out;
}

/** Print one run back and forth from its first piece (entered at its start when `forward`); returns where it ends. */
function emitRun(
  geom: RegionGeom,
  pieces: readonly Piece[],
  run: readonly number[],
  forward: boolean,
  ends: RingEnds | null,
  maxGap: number,
  out: Polyline[],
): Pt {
  let line: Pt[] = [];
  let exit: { node: number; anchor: Anchor | null } | null = null;
  for (const i of run) {
    const p = pieces[i];
    const inNode = forward ? 2 * i : 2 * i + 1;
    const inAnchor = forward ? p.a0 : p.a1;
    const from = forward ? p.pts[0] : p.pts[1],
      to = forward ? p.pts[1] : p.pts[0];
    if (exit) {
      const link =
        ends && exit.anchor && inAnchor
          ? connector(geom, ends, exit.node, exit.anchor, inNode, inAnchor, maxGap)
          : null;
      if (link) for (const q of link) pushPt(line, q);
      else {
        if (line.length >= 2) out.push(line);
        line = [];
      }
    }
    pushPt(line, from);
    pushPt(line, to);
    exit = { node: forward ? 2 * i + 1 : 2 * i, anchor: forward ? p.a1 : p.a0 };
    forward = !forward;
  }
  if (line.length >= 2) out.push(line);
  return line[line.length - 1] ?? pieces[run[run.length - 1]].pts[0];
}

/** The boundary path from one piece end to the next when they are neighbours on one ring and close enough. */
function connector(
  geom: RegionGeom,
  ends: RingEnds,
  x: number,
  ax: Anchor,
  y: number,
  ay: Anchor,
  maxGap: number,
): Pt[] | null {
  if (ax.ring !== ay.ring) return null;
  const side = ends.side(x, ax.ring, y);
  if (side === 0) return null;
  const L = geom.rings[ax.ring].length;
  let gap = side > 0 ? ay.pos - ax.pos : ax.pos - ay.pos;
  if (gap < 0) gap += L;
  if (gap > maxGap) return null;
  const raw = side > 0 ? boundaryPath(geom, ax, ay) : boundaryPath(geom, ay, ax).reverse();
  return raw.map((q) => rnd(q.x, q.y));
}
