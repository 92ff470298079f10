/**
 * Islands from the flat rings of a clipping result: rings that do not cross (they may touch at points),
 * outer rings counter-clockwise and holes clockwise. Each hole goes to the smallest outer ring around it,
 * which is the tree a boolean would have built.
 */
import { ringBounds, twiceArea } from './contain.js';
import type { ExPolygon, Polygon, Pt } from './types.js';

/** The islands the rings make, in the order of their outer rings; holes keep their order too. */
export function nestRings(rings: readonly Polygon[]): ExPolygon[] {
  const outers: number[] = [];
  const holes: number[] = [];
  const areas = new Float64Array(rings.length);
  for (let i = 0; i < rings.length; i++) {
    const a = twiceArea(rings[i]);
    areas[i] = a;
    if (a > 0) outers.push(i);
    else if (a < 0) holes.push(i);
  }
  const islands: ExPolygon[] = outers.map((i) => ({ outer: rings[i], holes: [] }));
  if (holes.length === 0) return islands;
  const boxes = new Float64Array(4 * rings.length);
  for (let i = 0; i < rings.length; i++) ringBox(rings[i], boxes, 4 * i);
  for (const h of holes) {
    let best = -1;
    let bestArea = Infinity;
    let candidates = 0;
    for (let k = 0; k < outers.length; k++) if (boxHolds(boxes, 4 * outers[k], 4 * h)) candidates++;
    for (let k = 0; k < outers.length; k++) {
      const o = outers[k];
      if (areas[o] >= bestArea || !boxHolds(boxes, 4 * o, 4 * h)) continue;
      if (candidates === 1 || ringWithin(rings[h], rings[o])) {
        best = k;
        bestArea = areas[o];
      }
    }
    if (best >= 0) islands[best].holes.push(rings[h]);
  }
  return islands;
}

function ringBox(r: readonly Pt[], out: Float64Array, at: number): void {
  const b = ringBounds(r);
  out[at] = b.minX;
  out[at + 1] = b.minY;
  out[at + 2] = b.maxX;
  out[at + 3] = b.maxY;
}

/** Whether box `o` holds box `h` (borders may coincide). */
function boxHolds(b: Float64Array, o: number, h: number): boolean {
  return b[o] <= b[h] && b[o + 1] <= b[h + 1] && b[o + 2] >= b[h + 2] && b[o + 3] >= b[h + 3];
}

/**
 * Whether `inner` lies within `outer`, for rings that do not cross: decided by the first point of
 * `inner` off `outer`'s boundary, else by the first edge midpoint off it; inside when none is.
 */
function ringWithin(inner: readonly Pt[], outer: readonly Pt[]): boolean {
  for (const p of inner) {
    const s = pointSide(p.x, p.y, outer);
    if (s !== 0) return s > 0;
  }
  for (let i = 0, j = inner.length - 1; i < inner.length; j = i++) {
    const s = pointSide((inner[i].x + inner[j].x) / 2, (inner[i].y + inner[j].y) / 2, outer);
    if (s !== 0) return s > 0;
  }
  return true;
}

/** 1 inside the ring, -1 outside, 0 on its boundary (exact for integer coordinates below 2^25 and their midpoints). */
function pointSide(px: number, py: number, ring: readonly Pt[]): number {
  let inside = false;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const a = ring[j],
      b = ring[i];
    if (a.y === py && b.y === py) {
      if ((a.x <= px && px <= b.x) || (b.x <= px && px <= a.x)) return 0;
      continue;
    }
    if (a.y > py !== b.y > py) {
      // where the edge crosses the horizontal line through p, compared with p.x without division
      const cross = (b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y);
      if (cross === 0) return 0;
      if (cross > 0 === b.y > a.y) inside = !inside;
    } else if ((a.y === py && a.x === px) || (b.y === py && b.x === px)) {
      return 0;
    }
  }
  return inside ? 1 : -1;
}
