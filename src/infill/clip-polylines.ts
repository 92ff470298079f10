/**
 * The general clipper for curved and arbitrary polylines (gyroid, spiral, hexagon chains, trees, linked
 * loops). Each polyline is cut at every crossing with a region edge (found through the region's edge
 * grid), and each piece between cuts is kept if a point in its middle is inside the region. Cut points are
 * exact intersections, so pieces end on the boundary, and carry their boundary anchors for linking.
 * It gives the same result as the facade's `clipLines` (tests compare them) but avoids building a
 * general sweep for every call, which matters for patterns with thousands of short segments.
 */
import type { Polyline, Pt } from '../geometry/types.js';
import { type Hit, type RegionIndex, anchorOnEdge, pointInside, segmentHits } from './region-index.js';
import { type Piece, pushPt, rnd } from './piece.js';

/** Cuts closer than this along the polyline are merged (a crossing through a region vertex), µm. */
const CUT_MERGE_UM = 0.01;

interface Cut {
  /** Position along the polyline: segment index + parameter. */
  s: number;
  edge: number;
  u: number;
  /** The cut point. */
  x: number;
  y: number;
}

function pointAt(pl: Polyline, s: number): { x: number; y: number } {
  const i = Math.min(Math.floor(s), pl.length - 2);
  const t = s - i;
  const a = pl[i],
    b = pl[i + 1];
  return { x: a.x + t * (b.x - a.x), y: a.y + t * (b.y - a.y) };
}

/** Clip polylines (any coordinates; output rounded to µm) to the region, appending inside pieces to `out`. */
export function clipPolylines(ix: RegionIndex, lines: readonly Polyline[], out: Piece[]): void {
  const hits: Hit[] = [];
  const cuts: Cut[] = [];
  for (const pl of lines) {
    const n = pl.length;
    if (n < 2) continue;
    cuts.length = 0;
    for (let i = 0; i + 1 < n; i++) {
      const a = pl[i],
        b = pl[i + 1];
      if (a.x === b.x && a.y === b.y) continue;
      segmentHits(ix, a.x, a.y, b.x, b.y, hits);
      for (const h of hits) {
        const qx = a.x + h.t * (b.x - a.x),
          qy = a.y + h.t * (b.y - a.y);
        const last = cuts[cuts.length - 1];
        // merge with the previous cut when it is the same point (a crossing through a region vertex)
        if (last && Math.abs(last.x - qx) + Math.abs(last.y - qy) <= CUT_MERGE_UM) continue;
        cuts.push({ s: i + h.t, edge: h.edge, u: h.u, x: qx, y: qy });
      }
    }
    const sEnd = n - 1;
    let cur: Piece | null = null;
    let prevS = 0;
    let prevCut: Cut | null = null;
    const finish = (endCut: Cut | null) => {
      if (!cur) return;
      cur.a1 = endCut ? anchorOnEdge(ix, endCut.edge, endCut.u) : null;
      if (cur.pts.length >= 2) out.push(cur);
      cur = null;
    };
    for (let k = 0; k <= cuts.length; k++) {
      const cut = k < cuts.length ? cuts[k] : null;
      const sB = cut ? cut.s : sEnd;
      if (sB - prevS <= 0) {
        if (cut) prevCut = cut;
        continue;
      }
      const mid = pointAt(pl, (prevS + sB) / 2);
      const inside = pointInside(ix, mid.x, mid.y);
      if (inside) {
        if (!cur) {
          const p = pointAt(pl, prevS);
          cur = { pts: [rnd(p.x, p.y)], a0: prevCut ? anchorOnEdge(ix, prevCut.edge, prevCut.u) : null, a1: null };
        }
        const piece: Piece = cur;
        for (let v = Math.floor(prevS) + 1; v < sB; v++) pushPt(piece.pts, rnd(pl[v].x, pl[v].y));
        const q = pointAt(pl, sB);
        pushPt(piece.pts, rnd(q.x, q.y));
        // a cut followed by another inside stretch is a touch: keep going in the same piece
        if (!cut) finish(null);
      } else if (cur) {
        finish(prevCut);
      }
      prevS = sB;
      prevCut = cut;
    }
    if (cur) finish(prevCut);
  }
}

/** Convenience: clip and return plain polylines. */
export function clipToRegion(ix: RegionIndex, lines: readonly Polyline[]): Pt[][] {
  const out: Piece[] = [];
  clipPolylines(ix, lines, out);
  return out.map((p) => p.pts);
}
