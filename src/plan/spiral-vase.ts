/**
 * Spiral vase turns. Above a vase's bottom every layer is one outer wall loop (the regions stage lays one
 * wall and nothing inside it); the planner prints that loop as one turn of a spiral:
 *
 * - the turn is opened at the point of the loop nearest to where the nozzle is (the previous turn's end,
 *   which is put in front of it so no travel is needed: the few µm from one turn's outline to the next are
 *   extruded), and goes once round, back to that point;
 * - its Z rises linearly in the distance along it from the previous layer's Z to this layer's, riding on the
 *   plan's per-point Z channel (so the G-code writer writes Z on every point, and nothing here knows G-code);
 * - a first turn (after the flat bottom, or after a layer that could not spiral) lays on a flat surface, so
 *   the bead under the rising nozzle grows from nothing to the layer height: its flow grows with it, 0 to 1
 *   along the turn (as PrusaSlicer and CuraEngine do);
 * - the last turn of a spiral (the top, or before a layer that cannot spiral) leaves a surface that slopes
 *   by one layer height round the turn: a flat finishing turn over the same loop at the last turn's Z lays
 *   the missing wedge, its flow shrinking from 1 to 0, so the rim is level with no step or blob.
 *
 * The flow rides on the per-point widths (filament follows the width), as scarf seams' does.
 * What spirals: a layer whose only paths are one island's one closed wall loop. The regions stage has
 * already dropped holes and specks beside the main island (vaseOutline in layer-regions.ts: a cup modelled
 * hollow spirals on its outside). A layer still of several islands (two objects, a vase that splits in two)
 * or with open wall lines (a thin tip) is printed flat, and the turn after it starts a new spiral
 * (PrusaSlicer, too, spirals single-island layers only, and prints the others as they are).
 */
import { hypot, type Pt } from '../geometry/types.js';

/** A closed loop as the planner holds it, or an open run it prints. */
export interface VaseRun {
  points: Pt[];
  closed: boolean;
  /** Bead width, mm, where `widths` is null. */
  width: number;
  widths: Float64Array | null;
  z: Float64Array | null;
  /** One flag per edge (for a loop the last edge closes it), or null. */
  flags: Uint8Array | null;
}

/** A point on a loop this close to a corner is that corner (no sliver of a move), µm. */
const VASE_POINT_AT_CORNER_UM = 5;

/** Where a loop comes nearest to a point: on edge `edge` (from point edge to edge + 1), at `at`. */
export interface NearestOnLoop {
  edge: number;
  /** The nearest point, rounded to the µm; a corner of the loop when it is within VASE_POINT_AT_CORNER_UM of one. */
  at: Pt;
  /** Fraction of the edge's length from its start to `at`, 0..1. */
  t: number;
}

/** The point of the closed loop `points` nearest to `p`. */
export function nearestOnLoop(points: readonly Pt[], p: Pt): NearestOnLoop {
  const n = points.length;
  let best = Infinity;
  let edge = 0;
  let bestT = 0;
  for (let k = 0; k < n; k++) {
    const a = points[k],
      b = points[k + 1 === n ? 0 : k + 1];
    const dx = b.x - a.x,
      dy = b.y - a.y;
    const len2 = dx * dx + dy * dy;
    let t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const ex = a.x + t * dx - p.x,
      ey = a.y + t * dy - p.y;
    const d2 = ex * ex + ey * ey;
    if (d2 < best) {
      best = d2;
      edge = k;
      bestT = t;
    }
  }
  const a = points[edge],
    b = points[edge + 1 === n ? 0 : edge + 1];
  const len = hypot(b.x - a.x, b.y - a.y);
  if (bestT * len <= VASE_POINT_AT_CORNER_UM) return { edge, at: a, t: 0 };
  if ((1 - bestT) * len <= VASE_POINT_AT_CORNER_UM) return { edge: edge + 1 === n ? 0 : edge + 1, at: b, t: 0 };
  return { edge, at: { x: Math.round(a.x + bestT * (b.x - a.x)), y: Math.round(a.y + bestT * (b.y - a.y)) }, t: bestT };
}

/**
 * The closed loop opened at the point nearest to `near` and followed once round, back to that point: an open
 * run whose first and last points are that point (with its widths and edge flags).
 */
export function openLoopNear(loop: VaseRun, near: Pt): VaseRun {
  const pts = loop.points;
  const n = pts.length;
  const { edge, at, t } = nearestOnLoop(pts, near);
  // a point inside edge `edge` starts the run, and the loop's corners follow from the edge's end;
  // on a corner, the run starts and ends there
  const inside = t > 0;
  const first = inside ? (edge + 1) % n : edge;
  const count = n + (inside ? 2 : 1);
  const points: Pt[] = new Array(count);
  const widthAt = (k: number) => (loop.widths ? loop.widths[k] : loop.width);
  const atWidth = inside ? widthAt(edge) + t * (widthAt((edge + 1) % n) - widthAt(edge)) : widthAt(edge);
  const widths = loop.widths ? new Float64Array(count) : null;
  const flags = loop.flags ? new Uint8Array(count - 1) : null;
  let j = 0;
  if (inside) {
    points[j] = at;
    if (widths) widths[j] = atWidth;
    if (flags) flags[j] = loop.flags![edge];
    j++;
  }
  for (let k = 0; k < n; k++, j++) {
    const i = (first + k) % n;
    points[j] = pts[i];
    if (widths) widths[j] = widthAt(i);
    // the edge that leaves this corner (the last corner's leads back into the start edge)
    if (flags && j < count - 1) flags[j] = loop.flags![i];
  }
  points[j] = at;
  if (widths) widths[j] = atWidth;
  return { points, closed: false, width: loop.width, widths, z: null, flags };
}

/** Distance from the run's start to each of its points, µm. */
function distances(points: readonly Pt[]): Float64Array {
  const d = new Float64Array(points.length);
  for (let k = 1; k < points.length; k++)
    d[k] = d[k - 1] + hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y);
  return d;
}

/** The run's widths scaled by `share(fraction of the way along)`. */
function scaledWidths(run: VaseRun, d: Float64Array, share: (f: number) => number): Float64Array {
  const total = d[d.length - 1];
  const out = new Float64Array(run.points.length);
  for (let k = 0; k < out.length; k++)
    out[k] = (run.widths ? run.widths[k] : run.width) * share(total > 0 ? d[k] / total : 1);
  return out;
}

/**
 * One spiral turn over `opened` (a loop opened by openLoopNear), from `from` when it is not the run's first
 * point (the previous turn's end, joined to it by a short extrusion rather than a travel).
 * @param drop the previous layer's Z less this layer's, mm (negative): the turn's Z offset at its start,
 *   rising linearly in the distance along it to 0 at its end
 * @param rampUp a first turn: the flow grows from 0 to 1 along it
 */
export function spiralTurn(opened: VaseRun, from: Pt | null, drop: number, rampUp: boolean): VaseRun {
  let run = opened;
  const start = opened.points[0];
  if (from && (from.x !== start.x || from.y !== start.y)) {
    const count = opened.points.length + 1;
    const widths = opened.widths ? new Float64Array(count) : null;
    if (widths) {
      widths[0] = opened.widths![0];
      widths.set(opened.widths!, 1);
    }
    let flags: Uint8Array | null = null;
    if (opened.flags) {
      flags = new Uint8Array(count - 1);
      flags[0] = opened.flags[0];
      flags.set(opened.flags, 1);
    }
    run = { ...opened, points: [from, ...opened.points], widths, flags };
  }
  const d = distances(run.points);
  const total = d[d.length - 1];
  const z = new Float64Array(run.points.length);
  for (let k = 0; k < z.length; k++) z[k] = k === z.length - 1 || !(total > 0) ? 0 : drop * (1 - d[k] / total);
  const widths = rampUp ? scaledWidths(run, d, (f) => f) : run.widths;
  return { ...run, z, widths };
}

/**
 * The flat finishing turn after a spiral's last turn (`opened`, the loop that turn went round, from the
 * same start): at the last turn's Z, its flow shrinking from 1 to 0 along it, filling the wedge the rising
 * turn left above the one before, so the spiral ends level.
 */
export function finishingTurn(opened: VaseRun): VaseRun {
  const d = distances(opened.points);
  return { ...opened, z: null, widths: scaledWidths(opened, d, (f) => 1 - f) };
}
