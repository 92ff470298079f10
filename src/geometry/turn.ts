/**
 * Turning integer-µm geometry about the origin (coordinates rounded back to integers, so a turn and its inverse
 * move a point by at most a micrometre). The scanline booleans are cheapest when long edges run along x: a
 * family of parallel diagonal lines keeps every edge active on every scanbeam, turned flat it keeps almost none.
 */
import type { ExPolygon, Pt } from './types.js';

/** A turn by an angle, as its cosine and sine. */
export interface Turn {
  cos: number;
  sin: number;
}

/** Below this |sin| of the angle to the x axis, lines count as flat already (no turn). */
const FLAT_SIN = 1e-3;

/**
 * The turn that lays the longest segment of `lines` along the x axis, or null when it already runs along it
 * (or there are no segments).
 */
export function flatteningTurn(lines: readonly (readonly Pt[])[]): Turn | null {
  let best = 0,
    bx = 1,
    by = 0;
  for (const l of lines) {
    for (let i = 1; i < l.length; i++) {
      const dx = l[i].x - l[i - 1].x,
        dy = l[i].y - l[i - 1].y;
      const d = dx * dx + dy * dy;
      if (d > best) {
        best = d;
        bx = dx;
        by = dy;
      }
    }
  }
  if (best === 0) return null;
  const len = Math.sqrt(best);
  // turning by minus the segment's angle: cos = bx/len, sin = -by/len
  const t = { cos: bx / len, sin: -by / len };
  return Math.abs(t.sin) < FLAT_SIN && t.cos > 0 ? null : t;
}

/** The inverse turn. */
export function inverse(t: Turn): Turn {
  return { cos: t.cos, sin: -t.sin };
}

/** Points turned (new array, integer coordinates). */
export function turnPts(pts: readonly Pt[], t: Turn): Pt[] {
  const out: Pt[] = new Array<Pt>(pts.length);
  const c = t.cos,
    s = t.sin;
  for (let i = 0; i < pts.length; i++) {
    const p = pts[i];
    // + 0 turns -0 into 0
    out[i] = { x: Math.round(p.x * c - p.y * s) + 0, y: Math.round(p.x * s + p.y * c) + 0 };
  }
  return out;
}

/** Islands turned. */
export function turnAreas(areas: readonly ExPolygon[], t: Turn): ExPolygon[] {
  return areas.map((a) => ({ outer: turnPts(a.outer, t), holes: a.holes.map((h) => turnPts(h, t)) }));
}
