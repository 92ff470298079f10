/**
 * The width of a thin strip (a gap between walls, a sliver of skin), from its area and perimeter alone: the
 * width of the rectangle with the same area and perimeter. Exact for a rectangle, where 2·area / perimeter
 * (the mean width) falls short by the ends' share of the perimeter; for a wedge it is about half its widest.
 */
import { area } from '../geometry/clip.js';
import { hypot, type ExPolygon } from '../geometry/types.js';

/** Perimeter of an island's rings, µm. */
export function perimeter(a: ExPolygon): number {
  let p = 0;
  for (const r of [a.outer, ...a.holes]) {
    for (let i = 0, j = r.length - 1; i < r.length; j = i++) p += hypot(r[i].x - r[j].x, r[i].y - r[j].y);
  }
  return p;
}

/** Width W of the W × L rectangle with the island's area and perimeter (L ≥ W), µm. */
export function stripWidthUm(a: ExPolygon): number {
  const A = area([a]);
  const halfP = perimeter(a) / 2;
  if (!(A > 0) || !(halfP > 0)) return 0;
  // W + L = P/2 and W·L = A; a shape rounder than a square has no such rectangle: take the square's side
  return (halfP - Math.sqrt(Math.max(0, halfP * halfP - 4 * A))) / 2;
}
