/**
 * Small geometric helpers shared by the infill engine and patterns: closest point on a segment, a
 * scanline's crossings with plain rings, and a region's bounds in a rotated frame.
 */
import type { ExPolygon, Pt } from '../geometry/types.js';

/** Closest point to (x, y) on segment a→b: parameter t ∈ [0, 1], the point, squared distance. */
export function closestOnSegment(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  x: number,
  y: number,
): { t: number; x: number; y: number; d2: number } {
  const ux = bx - ax,
    uy = by - ay;
  const l2 = ux * ux + uy * uy;
  let t = l2 > 0 ? ((x - ax) * ux + (y - ay) * uy) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const px = ax + t * ux,
    py = ay + t * uy;
  return { t, x: px, y: py, d2: (px - x) * (px - x) + (py - y) * (py - y) };
}

/** X positions where the horizontal line at y crosses the rings (half-open rule), sorted: pairs bound the inside. */
export function rowCrossings(rings: readonly (readonly Pt[])[], y: number, out: number[]): number[] {
  out.length = 0;
  for (const ring of rings) {
    for (let i = 0, k = ring.length - 1; i < ring.length; k = i++) {
      const a = ring[k],
        b = ring[i];
      if (a.y > y !== b.y > y) out.push(a.x + ((y - a.y) / (b.y - a.y)) * (b.x - a.x));
    }
  }
  return out.sort((p, q) => p - q);
}

/** Every ring of a region (outers and holes). */
export function ringsOf(region: readonly ExPolygon[]): Pt[][] {
  const rings: Pt[][] = [];
  for (const e of region) rings.push(e.outer, ...e.holes);
  return rings;
}

/** Bounds of the region's outer rings in the frame rotated by `angleRad` about `origin` (u along, v across). */
export function frameBounds(
  region: readonly ExPolygon[],
  origin: Pt,
  angleRad: number,
): { uMin: number; uMax: number; vMin: number; vMax: number } {
  const c = Math.cos(angleRad),
    s = Math.sin(angleRad);
  let uMin = Infinity,
    uMax = -Infinity,
    vMin = Infinity,
    vMax = -Infinity;
  for (const e of region)
    for (const p of e.outer) {
      const dx = p.x - origin.x,
        dy = p.y - origin.y;
      const u = dx * c + dy * s,
        v = -dx * s + dy * c;
      if (u < uMin) uMin = u;
      if (u > uMax) uMax = u;
      if (v < vMin) vMin = v;
      if (v > vMax) vMax = v;
    }
  return { uMin, uMax, vMin, vMax };
}
