/**
 * Exact, conservative containment test for integer-µm rings: lets a boolean whose result is known
 * (a subject island inside the clip area) be skipped. Orientation tests on integer coordinates are
 * exact in doubles for coordinates below 2^25 µm (33 m).
 */
import type { Bounds, ExPolygon, Polygon, Pt } from './types.js';

/**
 * Whether the area enclosed by `ring` lies strictly inside `areas` (non-zero islands: outer rings
 * with their holes): no edge of the ring meets or touches an edge of the areas, one of its points
 * is inside the areas, and no ring of the areas lies inside it. False when unsure.
 */
export function ringInside(ring: Polygon, areas: readonly ExPolygon[]): boolean {
  if (ring.length < 3) return false;
  const box = ringBounds(ring);
  // the first point must be inside exactly one island, and in none of its holes
  let host: ExPolygon | null = null;
  for (const a of areas) {
    if (pointInRing(ring[0], a.outer)) {
      host = a;
      break;
    }
  }
  if (!host) return false;
  for (const h of host.holes) if (pointInRing(ring[0], h)) return false;
  // no crossings or contacts with any ring near it, and none of them inside it
  for (const a of areas) {
    if (!checkRing(ring, box, a.outer)) return false;
    for (const h of a.holes) if (!checkRing(ring, box, h)) return false;
  }
  return true;
}

/** False when `other` meets `ring` or lies inside it. */
function checkRing(ring: Polygon, box: Bounds, other: Polygon): boolean {
  const ob = ringBounds(other);
  if (ob.minX > box.maxX || ob.maxX < box.minX || ob.minY > box.maxY || ob.maxY < box.minY) return true;
  if (ringsTouch(ring, other, ob)) return false;
  // no contact: `other` is wholly inside or wholly outside `ring`
  return !pointInRing(other[0], ring);
}

/** Twice the signed area of a ring, µm² (positive = counter-clockwise). */
export function twiceArea(r: readonly Pt[]): number {
  let a = 0;
  for (let i = 0, j = r.length - 1; i < r.length; j = i++) a += (r[j].x - r[i].x) * (r[j].y + r[i].y);
  return a;
}

/** Bounding box of a ring. */
export function ringBounds(r: readonly Pt[]): Bounds {
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (const p of r) {
    if (p.x < minX) minX = p.x;
    if (p.x > maxX) maxX = p.x;
    if (p.y < minY) minY = p.y;
    if (p.y > maxY) maxY = p.y;
  }
  return { minX, minY, maxX, maxY };
}

/** Whether any edge of `a` meets any edge of `b` (crossing, touching or overlapping). */
function ringsTouch(a: Polygon, b: Polygon, bb: Bounds): boolean {
  const na = a.length,
    nb = b.length;
  for (let i = 0, pi = na - 1; i < na; pi = i++) {
    const p = a[pi],
      q = a[i];
    const minX = p.x < q.x ? p.x : q.x,
      maxX = p.x < q.x ? q.x : p.x;
    const minY = p.y < q.y ? p.y : q.y,
      maxY = p.y < q.y ? q.y : p.y;
    if (minX > bb.maxX || maxX < bb.minX || minY > bb.maxY || maxY < bb.minY) continue;
    for (let j = 0, pj = nb - 1; j < nb; pj = j++) {
      const r = b[pj],
        s = b[j];
      if (
        (r.x < minX && s.x < minX) ||
        (r.x > maxX && s.x > maxX) ||
        (r.y < minY && s.y < minY) ||
        (r.y > maxY && s.y > maxY)
      )
        continue;
      if (segmentsMeet(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y)) return true;
    }
  }
  return false;
}

function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  const v = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  return v > 0 ? 1 : v < 0 ? -1 : 0;
}

/** Closed segments pq and rs share a point (crossing, touching or overlapping). */
export function segmentsMeet(
  px: number,
  py: number,
  qx: number,
  qy: number,
  rx: number,
  ry: number,
  sx: number,
  sy: number,
): boolean {
  if (Math.max(px, qx) < Math.min(rx, sx) || Math.max(rx, sx) < Math.min(px, qx)) return false;
  if (Math.max(py, qy) < Math.min(ry, sy) || Math.max(ry, sy) < Math.min(py, qy)) return false;
  const o1 = orient(px, py, qx, qy, rx, ry),
    o2 = orient(px, py, qx, qy, sx, sy);
  if (o1 !== 0 && o1 === o2) return false;
  const o3 = orient(rx, ry, sx, sy, px, py),
    o4 = orient(rx, ry, sx, sy, qx, qy);
  if (o3 !== 0 && o3 === o4) return false;
  // proper crossing, or a collinear / touching case; with overlapping boxes, collinear means overlap
  return true;
}

/** Even-odd point-in-ring test (the answer for points on an edge is either: callers rule those out). */
export function pointInRing(p: Pt, ring: readonly Pt[]): boolean {
  let inside = false;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const a = ring[i],
      b = ring[j];
    if (a.y > p.y !== b.y > p.y && p.x < a.x + ((p.y - a.y) * (b.x - a.x)) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}
