/**
 * Marking the parts of a path that lie over nothing: each edge is split where it crosses the boundary of the
 * area over air, and every piece is flagged by whether its middle lies inside that area. The planner prints
 * flagged runs their own way (bridge skin, slowed overhang walls).
 */
import { boundsOf, pointInArea } from '../geometry/clip.js';
import { ringBounds } from '../geometry/contain.js';
import { hypot, type Bounds, type ExPolygon, type Pt } from '../geometry/types.js';

/** Pieces shorter than this (µm) keep their neighbour's flag: no run is shorter than a few micrometres. */
const MIN_PIECE_UM = 5;

interface AreaIndex {
  areas: readonly ExPolygon[];
  bounds: Bounds[];
  box: Bounds;
}

export function indexArea(areas: readonly ExPolygon[]): AreaIndex {
  const bounds = areas.map((a) => boundsOf([a]));
  return { areas, bounds, box: boundsOf(areas) };
}

function overlaps(a: Bounds, minX: number, minY: number, maxX: number, maxY: number): boolean {
  return a.minX <= maxX && a.maxX >= minX && a.minY <= maxY && a.maxY >= minY;
}

function inside(p: Pt, idx: AreaIndex): boolean {
  for (let k = 0; k < idx.areas.length; k++) {
    const b = idx.bounds[k];
    if (p.x < b.minX || p.x > b.maxX || p.y < b.minY || p.y > b.maxY) continue;
    if (pointInArea(p, idx.areas[k])) return true;
  }
  return false;
}

/** Parameters t in (0, 1) where segment a→b crosses a ring edge of the area. */
function crossings(a: Pt, b: Pt, idx: AreaIndex, out: number[]): void {
  const minX = Math.min(a.x, b.x), maxX = Math.max(a.x, b.x), minY = Math.min(a.y, b.y), maxY = Math.max(a.y, b.y);
  const dx = b.x - a.x, dy = b.y - a.y;
  for (let k = 0; k < idx.areas.length; k++) {
    if (!overlaps(idx.bounds[k], minX, minY, maxX, maxY)) continue;
    const area = idx.areas[k];
    for (let r = -1; r < area.holes.length; r++) {
      const ring = r < 0 ? area.outer : area.holes[r];
      for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
        const c = ring[j], d = ring[i];
        if (Math.max(c.x, d.x) < minX || Math.min(c.x, d.x) > maxX || Math.max(c.y, d.y) < minY || Math.min(c.y, d.y) > maxY) continue;
        const ex = d.x - c.x, ey = d.y - c.y;
        const den = dx * ey - dy * ex;
        if (den === 0) continue;
        const t = ((c.x - a.x) * ey - (c.y - a.y) * ex) / den;
        const u = ((c.x - a.x) * dy - (c.y - a.y) * dx) / den;
        if (t > 0 && t < 1 && u >= 0 && u <= 1) out.push(t);
      }
    }
  }
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
export function flagOverAir(path: readonly Pt[], closed: boolean, idx: AreaIndex, widths: Float64Array | null = null): FlaggedPath | null {
  const n = path.length;
  if (n < 2 || idx.areas.length === 0) return null;
  // quick rejection: the path's bounds miss the area
  const { minX, minY, maxX, maxY } = ringBounds(path);
  if (!overlaps(idx.box, minX, minY, maxX, maxY)) return null;
  const points: Pt[] = [];
  const flags: number[] = [];
  const ts: number[] = [];
  const ws: number[] | null = widths ? [] : null;
  const edges = closed ? n : n - 1;
  let any = false;
  for (let e = 0; e < edges; e++) {
    const a = path[e], b = path[(e + 1) % n];
    points.push(a);
    const wa = widths ? widths[e] : 0, wb = widths ? widths[(e + 1) % n] : 0;
    if (ws) ws.push(wa);
    ts.length = 0;
    crossings(a, b, idx, ts);
    ts.sort((p, q) => p - q);
    const len = hypot(b.x - a.x, b.y - a.y);
    let prevT = 0;
    let prev = a;
    const cuts = ts.filter((t, i) => (i === 0 || t - ts[i - 1] > 1e-9) && t * len > MIN_PIECE_UM && (1 - t) * len > MIN_PIECE_UM);
    cuts.push(1);
    for (let c = 0; c < cuts.length; c++) {
      const t = cuts[c];
      const mid = { x: a.x + ((prevT + t) / 2) * (b.x - a.x), y: a.y + ((prevT + t) / 2) * (b.y - a.y) };
      const f = inside(mid, idx) ? 1 : 0;
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
