/**
 * Path ordering, the one way the product orders paths for short travel (the planner's blocks and islands, infill
 * and skin lines and loops, custom infill): nearest-first chaining from a start point (nearest.ts), lines entered
 * at either end, loops at one of their entry points; optionally the tour then shortened on to an end point
 * (shorten.ts).
 */
import type { Polyline, Pt } from '../geometry/types.js';
import { nearestFirst, type PathSet, type Ties, type Visit } from './nearest.js';
import { shortenTour, type TourStop } from './shorten.js';

export type { PathSet, Ties, Visit } from './nearest.js';

export interface OrderOptions {
  /** Where the nozzle is before the first path. */
  from: Pt;
  /** Shorten the nearest-first tour (2-opt and or-opt; see shorten.ts). */
  shorten?: boolean;
  /** With `shorten`, where the nozzle goes after the last path, so that the tour also ends near it. */
  to?: Pt | null;
  /** How a tie between equally near entry points is settled (default `'lowest'`). */
  ties?: Ties;
}

/** The paths in print order from `options.from`, each with the entry point it is entered at. */
export function orderPaths(paths: PathSet, options: OrderOptions): Visit[] {
  const visits = nearestFirst(paths, options.from, options.ties ?? 'lowest');
  return options.shorten ? shortenOrder(paths, visits, options.from, options.to ?? null) : visits;
}

/**
 * A shorter tour of the same paths than `visits` (in print order from `from`, then on to `to` when given): paths
 * moved, and stretches of the tour printed the other way round (a line turned round is entered at its other end).
 */
export function shortenOrder(paths: PathSet, visits: readonly Visit[], from: Pt, to: Pt | null): Visit[] {
  const stops: TourStop[] = visits.map((v) => ({ in: entryPoint(paths, v), out: exitPoint(paths, v) }));
  const t = shortenTour(stops, from, to);
  const out: Visit[] = new Array(visits.length);
  for (let q = 0; q < visits.length; q++) {
    const [i, c] = visits[t.order[q]];
    // a line turned round is entered at its other end; a loop is left where it was entered either way
    out[q] = [i, t.reversed[q] && paths.line(i) ? 1 - c : c];
  }
  return out;
}

/** Where a visit enters its path. */
export function entryPoint(paths: PathSet, [i, c]: Visit): Pt {
  return paths.entries(i)[c];
}

/** Where a visit leaves its path as `line` says: a line at its other end, another path where it was entered. */
export function exitPoint(paths: PathSet, [i, c]: Visit): Pt {
  const e = paths.entries(i);
  return paths.line(i) ? e[1 - c] : e[c];
}

/** Open polylines nearest-first from `from`, each turned round when entered at its last point. */
export function orderLines(lines: readonly Polyline[], from: Pt): Polyline[] {
  const order = orderPaths(
    { count: lines.length, entries: (i) => [lines[i][0], lines[i][lines[i].length - 1]], line: () => true },
    { from },
  );
  return order.map(([i, c]) => (c === 0 ? lines[i] : lines[i].slice().reverse()));
}

/**
 * Closed loops (their first point not repeated) nearest-first from `from`, each entered at its nearest vertex and
 * started there; and where the last one ends.
 */
export function orderLoops(loops: readonly Polyline[], from: Pt): { loops: Polyline[]; end: Pt } {
  const order = orderPaths({ count: loops.length, entries: (i) => loops[i], line: () => false }, { from });
  const out = order.map(([i, k]) => (k === 0 ? loops[i] : loops[i].slice(k).concat(loops[i].slice(0, k))));
  return { loops: out, end: out.length ? out[out.length - 1][0] : from };
}
