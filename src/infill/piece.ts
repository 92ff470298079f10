/**
 * A clipped piece of infill line: integer-µm points, and where each end meets the region boundary
 * (null when the end lies inside the region). The clippers produce pieces; the linker joins them.
 */
import { hypot, type Pt } from '../geometry/types.js';
import type { Anchor } from './region-index.js';

export interface Piece {
  pts: Pt[];
  a0: Anchor | null;
  a1: Anchor | null;
}

/** Length of a polyline, µm. */
export function polylineLengthUm(pts: readonly Pt[]): number {
  let l = 0;
  for (let i = 1; i < pts.length; i++) l += hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  return l;
}

/** Round a point to integer µm. */
export function rnd(x: number, y: number): Pt {
  return { x: Math.round(x), y: Math.round(y) };
}

/** Append a point unless it repeats the last one. */
export function pushPt(out: Pt[], p: Pt): void {
  const last = out[out.length - 1];
  if (!last || last.x !== p.x || last.y !== p.y) out.push(p);
}
