/**
 * Distances between convex polygons in mm as [x, y] pairs (object footprints: pipeline/objects.ts
 * `footprintHull`), for the clearance checks and the support of sequential printing.
 */

/** A point, mm. */
export type P = readonly [number, number];

/** Distance from `p` to the segment from `a` to `b`. */
export function segmentPointDistance(p: P, a: P, b: P): number {
  const dx = b[0] - a[0],
    dy = b[1] - a[1];
  const len2 = dx * dx + dy * dy;
  let t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return Math.hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

/** Whether `p` lies inside or on the convex counter-clockwise polygon (3 vertices or more). */
export function insideConvex(p: P, poly: readonly P[]): boolean {
  if (poly.length < 3) return false;
  for (let i = 0; i < poly.length; i++) {
    const a = poly[i],
      b = poly[(i + 1) % poly.length];
    if ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) < 0) return false;
  }
  return true;
}

function segmentsCross(a: P, b: P, c: P, d: P): boolean {
  const side = (p: P, q: P, r: P) => Math.sign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

/** The distance between two convex polygons (counter-clockwise, mm), 0 when they touch or overlap. */
export function hullDistance(a: readonly P[], b: readonly P[]): number {
  if (a.length === 0 || b.length === 0) return Infinity;
  if (insideConvex(a[0], b) || insideConvex(b[0], a)) return 0;
  let best = Infinity;
  for (let i = 0; i < a.length; i++) {
    const a0 = a[i],
      a1 = a[(i + 1) % a.length];
    for (let j = 0; j < b.length; j++) {
      const b0 = b[j],
        b1 = b[(j + 1) % b.length];
      if (segmentsCross(a0, a1, b0, b1)) return 0;
      best = Math.min(best, segmentPointDistance(a0, b0, b1), segmentPointDistance(b0, a0, a1));
    }
  }
  return best;
}

/** The distance from a point to a convex counter-clockwise polygon, 0 inside or on it. */
export function pointHullDistance(p: P, hull: readonly P[]): number {
  if (hull.length === 0) return Infinity;
  if (insideConvex(p, hull)) return 0;
  let best = Infinity;
  for (let i = 0; i < hull.length; i++)
    best = Math.min(best, segmentPointDistance(p, hull[i], hull[(i + 1) % hull.length]));
  return best;
}
