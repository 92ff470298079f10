/**
 * Travel ordering of infill paths: nearest-neighbour chaining (geometry/nearest-order.ts) of loops,
 * each rotated to its nearest vertex, then of polylines, each reversed if entered from its far end.
 */
import { orderLoops, orderPolylines } from '../geometry/nearest-order.js';
import { hypot, type Pt } from '../geometry/types.js';

/** Order loops (first) and then lines by nearest-neighbour chaining from `start`. */
export function orderPaths(
  lines: readonly Pt[][],
  loops: readonly Pt[][],
  start: Pt,
): { lines: Pt[][]; loops: Pt[][] } {
  const L = orderLoops(loops, start);
  return { loops: L.loops, lines: orderPolylines(lines, L.end) };
}

/** Total travel distance of an ordering (start → first path, path end → next start), µm. */
export function travelLength(lines: readonly Pt[][], start: Pt): number {
  let cur = start;
  let t = 0;
  for (const l of lines) {
    t += hypot(l[0].x - cur.x, l[0].y - cur.y);
    cur = l[l.length - 1];
  }
  return t;
}
