/**
 * Marking the parts of a path that lie over nothing: each edge is split where it crosses the boundary of the
 * area over air, and every piece is flagged by whether its middle lies inside that area. The planner prints
 * flagged runs their own way (bridge skin, slowed overhang walls).
 */
import { AreaIndex as EdgeGrid } from '../geometry/area-index.js';
import { boundsOf, pointInArea } from '../geometry/clip.js';
import { ringBounds } from '../geometry/contain.js';
import { hypot, type Bounds, type ExPolygon, type Pt } from '../geometry/types.js';
import { SEGMENT_T_EPS } from '../geometry/tolerances.js';

/** Pieces shorter than this (µm) keep their neighbour's flag: no run is shorter than a few micrometres. */
const MIN_PIECE_UM = 5;

export interface AreaIndex {
  areas: readonly ExPolygon[];
  bounds: Bounds[];
  box: Bounds;
  /** The areas' edges in a grid, for large areas tested against many paths (the levels of overhanging walls). */
  grid?: EdgeGrid;
}

/** @param grid bucket the areas' edges in a grid (point and crossing tests then look at the edges nearby only) */
export function indexArea(areas: readonly ExPolygon[], grid = false): AreaIndex {
  const bounds = areas.map((a) => boundsOf([a]));
  const idx: AreaIndex = { areas, bounds, box: boundsOf(areas) };
  if (grid && areas.length) idx.grid = new EdgeGrid(areas);
  return idx;
}

function overlaps(a: Bounds, minX: number, minY: number, maxX: number, maxY: number): boolean {
  return a.minX <= maxX && a.maxX >= minX && a.minY <= maxY && a.maxY >= minY;
}

function inside(p: Pt, idx: AreaIndex): boolean {
  if (idx.grid)
    return (
      p.x >= idx.box.minX &&
      p.x <= idx.box.maxX &&
      p.y >= idx.box.minY &&
      p.y <= idx.box.maxY &&
      idx.grid.contains(p.x, p.y)
    );
  for (let k = 0; k < idx.areas.length; k++) {
    const b = idx.bounds[k];
    if (p.x < b.minX || p.x > b.maxX || p.y < b.minY || p.y > b.maxY) continue;
    if (pointInArea(p, idx.areas[k])) return true;
  }
  return false;
}

/**
 * Parameters t in (0, 1) where segment a→b crosses a ring edge of the area; with a grid, whether an edge also
 * touches it at an end or runs along it (without, false).
 */
function crossings(a: Pt, b: Pt, idx: AreaIndex, out: number[]): boolean {
  if (idx.grid) return idx.grid.crossingsAlong(a.x, a.y, b.x, b.y, out);
  const minX = Math.min(a.x, b.x),
    maxX = Math.max(a.x, b.x),
    minY = Math.min(a.y, b.y),
    maxY = Math.max(a.y, b.y);
  const dx = b.x - a.x,
    dy = b.y - a.y;
  for (let k = 0; k < idx.areas.length; k++) {
    if (!overlaps(idx.bounds[k], minX, minY, maxX, maxY)) continue;
    const area = idx.areas[k];
    for (let r = -1; r < area.holes.length; r++) {
      const ring = r < 0 ? area.outer : area.holes[r];
      for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
        const c = ring[j],
          d = ring[i];
        if (
          Math.max(c.x, d.x) < minX ||
          Math.min(c.x, d.x) > maxX ||
          Math.max(c.y, d.y) < minY ||
          Math.min(c.y, d.y) > maxY
        )
          continue;
        const ex = d.x - c.x,
          ey = d.y - c.y;
        const den = dx * ey - dy * ex;
        if (den === 0) continue;
        const t = ((c.x - a.x) * ey - (c.y - a.y) * ex) / den;
        const u = ((c.x - a.x) * dy - (c.y - a.y) * dx) / den;
        if (t > 0 && t < 1 && u >= 0 && u <= 1) out.push(t);
      }
    }
  }
  return false;
}

export interface FlaggedPath {
  points: Pt[];
  /** One per edge (closed paths: the last edge returns to the first point). */
  flags: Uint8Array;
  /** The path's per-point widths at the new points (interpolated where an edge was split), when it had them. */
  widths: Float64Array | null;
}

/**
 * Split a path where it crosses into and out of `idx`'s area and flag each edge; null when no part of it
 * lies over air (the common case: the path is returned unchanged by the caller).
 */
export function flagOverAir(
  path: readonly Pt[],
  closed: boolean,
  idx: AreaIndex,
  widths: Float64Array | null = null,
): FlaggedPath | null {
  return flagPath(path, closed, [idx], widths);
}

/**
 * Split a path where it crosses the boundary of any of `levels`' areas and flag each edge with its level: the
 * highest k whose area (`levels[k - 1]`) holds the edge, 0 for none (levels of overhang: from level 2 on each
 * level's area lies within the one before). Pieces of one edge that end up on one level are one edge again.
 * Null when no part of the path lies in any level's area.
 */
export function flagLevels(
  path: readonly Pt[],
  closed: boolean,
  levels: readonly AreaIndex[],
  widths: Float64Array | null = null,
): FlaggedPath | null {
  const f = flagPath(path, closed, levels, widths);
  return f && joinLevelRuns(f, path);
}

/**
 * The level of a point: one area at a time from the first, stopping at the first it is not in after the first
 * two (level 1's area need not hold the ones above it near the outline's edge; from level 2 on each lies within
 * the one before), levels with no area passed over.
 */
function levelAt(p: Pt, levels: readonly AreaIndex[]): number {
  let level = 0;
  for (let k = 0; k < levels.length; k++) {
    if (levels[k].areas.length === 0) continue;
    if (inside(p, levels[k])) level = k + 1;
    else if (k > 0) break;
  }
  return level;
}

function flagPath(
  path: readonly Pt[],
  closed: boolean,
  levels: readonly AreaIndex[],
  widths: Float64Array | null,
): FlaggedPath | null {
  const n = path.length;
  if (n < 2 || levels.every((idx) => idx.areas.length === 0)) return null;
  // quick rejection: the path's bounds miss the area
  const { minX, minY, maxX, maxY } = ringBounds(path);
  if (!levels.some((idx) => idx.areas.length > 0 && overlaps(idx.box, minX, minY, maxX, maxY))) return null;
  const points: Pt[] = [];
  const flags: number[] = [];
  const ts: number[] = [];
  const ws: number[] | null = widths ? [] : null;
  const edges = closed ? n : n - 1;
  let any = false;
  // With every area in a grid, an edge that no boundary crosses or touches, after one the same, keeps the
  // level the path had (it cannot change without crossing a boundary): no point test.
  const carry = levels.every((idx) => idx.grid || idx.areas.length === 0);
  let clear = false;
  for (let e = 0; e < edges; e++) {
    const a = path[e],
      b = path[(e + 1) % n];
    points.push(a);
    const wa = widths ? widths[e] : 0,
      wb = widths ? widths[(e + 1) % n] : 0;
    if (ws) ws.push(wa);
    ts.length = 0;
    let touch = false;
    for (const idx of levels) if (crossings(a, b, idx, ts)) touch = true;
    if (carry && clear && !touch && ts.length === 0) {
      // the whole edge on the level of the piece before
      const f = flags[flags.length - 1];
      flags.push(f);
      continue;
    }
    clear = !touch && ts.length === 0;
    ts.sort((p, q) => p - q);
    const len = hypot(b.x - a.x, b.y - a.y);
    let prevT = 0;
    let prev = a;
    const cuts = ts.filter(
      (t, i) => (i === 0 || t - ts[i - 1] > SEGMENT_T_EPS) && t * len > MIN_PIECE_UM && (1 - t) * len > MIN_PIECE_UM,
    );
    cuts.push(1);
    for (let c = 0; c < cuts.length; c++) {
      const t = cuts[c];
      const mid = { x: a.x + ((prevT + t) / 2) * (b.x - a.x), y: a.y + ((prevT + t) / 2) * (b.y - a.y) };
      const f = levelAt(mid, levels);
      if (f) any = true;
      flags.push(f);
      if (t < 1) {
        const p = { x: Math.round(a.x + t * (b.x - a.x)), y: Math.round(a.y + t * (b.y - a.y)) };
        if (p.x !== prev.x || p.y !== prev.y) {
          points.push(p);
          if (ws) ws.push(wa + t * (wb - wa));
          prev = p;
        } else flags.pop();
      }
      prevT = t;
    }
  }
  if (!closed) {
    points.push(path[n - 1]);
    if (ws) ws.push(widths![n - 1]);
  }
  if (!any) return null;
  return { points, flags: Uint8Array.from(flags), widths: ws ? Float64Array.from(ws) : null };
}

/** Drop the points a split added between two pieces of one edge that took the same level. */
function joinLevelRuns(f: FlaggedPath, path: readonly Pt[]): FlaggedPath {
  const { points, flags, widths } = f;
  if (points.length === path.length) return f;
  const keep: number[] = [];
  let original = 0; // the next of the path's own points
  for (let k = 0; k < points.length; k++) {
    const own = original < path.length && points[k] === path[original];
    if (own) original++;
    // point k ends edge k - 1 and starts edge k (a loop's point 0 is the path's own)
    if (own || k === 0 || flags[k - 1] !== flags[k]) keep.push(k);
  }
  if (keep.length === points.length) return f;
  const edges = flags.length;
  const outFlags = keep.filter((k) => k < edges).map((k) => flags[k]);
  return {
    points: keep.map((k) => points[k]),
    flags: Uint8Array.from(outFlags),
    widths: widths ? Float64Array.from(keep.map((k) => widths[k])) : null,
  };
}
