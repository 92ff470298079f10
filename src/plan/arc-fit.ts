/**
 * Arc fitting: runs of short segments that follow a circle are replaced by one arc segment (written as
 * G2/G3), walls and curved infill (gyroid, concentric, spiral) alike.
 *
 * A run P[i..j] becomes an arc when one of the circles through P[i] and P[j] (the one that fits best):
 * - has a radius between MIN_ARC_RADIUS_MM and MAX_ARC_RADIUS_MM (larger is a straight line to a
 *   firmware, which would cut it into many pieces for nothing);
 * - passes within `tolerance` of every point of the run, and within SEGMENT_TOLERANCE_FACTOR times it
 *   of the middle of every segment (so it follows the path all along, and no corner is rounded off);
 * - is gone round in one direction, every segment turning the same way, by at most half a turn; and the
 *   run has at least MIN_ARC_SEGMENTS segments.
 * Runs are grown greedily from each start: doubling while the fit holds, then bisecting to the longest
 * run that fits. The arc's end points are points of the original path, so the path still passes through
 * them; E, time and filament follow the arc's own length (plan/moves.ts). A path whose width varies gets
 * arcs only along runs whose widths agree (within ARC_WIDTH_TOLERANCE), so an arc keeps one width; a path
 * whose Z varies gets none.
 */
import { hypot, type Pt } from '../geometry/types.js';
import type { ExtrudeStep, PlanArc, PrintPlan } from './types.js';
import { MIN_SAGITTA_MM } from '../geometry/tolerances.js';

/** Fewest segments worth one arc. */
export const MIN_ARC_SEGMENTS = 2;
/** Smallest arc radius, mm: tighter turns are corners, not curves. */
export const MIN_ARC_RADIUS_MM = 0.1;
/** Largest arc radius, mm. */
export const MAX_ARC_RADIUS_MM = 1000;

/**
 * A segment's middle may lie this many times the tolerance from the arc, its end points once: a chord
 * already lies off the curve it stands for by its sagitta, on the inside, where the arc does not.
 */
export const SEGMENT_TOLERANCE_FACTOR = 2;

/** Steps of the golden-section search for an arc's bulge (each narrows the range by 0.618). */
const BULGE_SEARCH_STEPS = 36;
const GOLDEN = (Math.sqrt(5) - 1) / 2;

/**
 * The arc from path[i] to path[j] that stays within `tol` µm of the run between them, or null.
 *
 * The arc must start and end at the run's end points, so it is one of the circles through both: a
 * single unknown, the signed sagitta `s` (how far the arc bulges from the chord, left positive; |s| = h
 * is a half circle). The deviation of every point and every segment middle from the arc is a monotonic
 * function of `s`, so the largest of them has one minimum, found by golden-section search; the arc at
 * that bulge is accepted when it is within tolerance, turns one way all along and its radius is in range.
 */
function fitRun(path: readonly Pt[], i: number, j: number, tol: number, samples: Float64Array): PlanArc | null {
  const a = path[i]!;
  const b = path[j]!;
  const chord = hypot(b.x - a.x, b.y - a.y);
  if (!(chord > 0)) return null;
  const h = chord / 2;
  const tx = (b.x - a.x) / chord,
    ty = (b.y - a.y) / chord;
  const mx = (a.x + b.x) / 2,
    my = (a.y + b.y) / 2;
  // samples in the chord's frame: u along the chord from its middle, v to its left
  // (u, v, weight): a segment middle counts its distance divided by SEGMENT_TOLERANCE_FACTOR
  const midWeight = 1 / SEGMENT_TOLERANCE_FACTOR;
  let n = 0;
  for (let k = i; k < j; k++) {
    const p = path[k]!,
      q = path[k + 1]!;
    const hx = (p.x + q.x) / 2 - mx,
      hy = (p.y + q.y) / 2 - my;
    samples[n++] = hx * tx + hy * ty;
    samples[n++] = hy * tx - hx * ty;
    samples[n++] = midWeight;
    if (k + 1 < j) {
      const qx = q.x - mx,
        qy = q.y - my;
      samples[n++] = qx * tx + qy * ty;
      samples[n++] = qy * tx - qx * ty;
      samples[n++] = 1;
    }
  }
  const h2 = h * h;
  /** Largest |distance| of a sample from the arc of sagitta s (never exactly 0). */
  const worst = (s: number): number => {
    // centre at the chord middle − q·normal, radius² = h² + q²
    const q = (h2 - s * s) / (2 * s);
    const r = Math.sqrt(h2 + q * q);
    let max = 0;
    for (let k = 0; k < n; k += 3) {
      const u = samples[k]!,
        v = samples[k + 1]!;
      // |p − c|² − r², then the distance from the circle without cancelling large numbers
      const num = u * u + v * v + 2 * v * q - h2;
      const d = (num / (Math.sqrt(Math.max(0, r * r + num)) + r)) * samples[k + 2]!;
      const ad = d < 0 ? -d : d;
      if (ad > max) max = ad;
    }
    return max;
  };
  const nonZero = (s: number) => (s === 0 ? MIN_SAGITTA_MM : s);
  let lo = -h,
    hi = h;
  let x1 = hi - GOLDEN * (hi - lo),
    x2 = lo + GOLDEN * (hi - lo);
  let f1 = worst(nonZero(x1)),
    f2 = worst(nonZero(x2));
  for (let it = 0; it < BULGE_SEARCH_STEPS; it++) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - GOLDEN * (hi - lo);
      f1 = worst(nonZero(x1));
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + GOLDEN * (hi - lo);
      f2 = worst(nonZero(x2));
    }
  }
  const s = nonZero(f1 <= f2 ? x1 : x2);
  if ((f1 <= f2 ? f1 : f2) > tol) return null;
  const q = (h2 - s * s) / (2 * s);
  const r = Math.sqrt(h2 + q * q);
  if (!(r >= MIN_ARC_RADIUS_MM * 1000 && r <= MAX_ARC_RADIUS_MM * 1000)) return null;
  // centre: from the chord middle, q against the left normal (−ty, tx)
  const cx = mx + q * ty;
  const cy = my - q * tx;
  // bulging left (s > 0) the centre lies to the right: the arc turns clockwise
  const clockwise = s > 0;
  for (let k = i; k < j; k++) {
    const p = path[k]!,
      nq = path[k + 1]!;
    const turn = (p.x - cx) * (nq.y - cy) - (p.y - cy) * (nq.x - cx);
    if (turn === 0 || turn < 0 !== clockwise) return null;
  }
  return { cx, cy, clockwise };
}

/** The longest run from `i` (at least MIN_ARC_SEGMENTS segments) that fits an arc, or null. */
function longestRun(
  path: readonly Pt[],
  i: number,
  lastIndex: number,
  tol: number,
  samples: Float64Array,
): { end: number; arc: PlanArc } | null {
  let good = i + MIN_ARC_SEGMENTS;
  if (good > lastIndex) return null;
  let arc = fitRun(path, i, good, tol, samples);
  if (!arc) return null;
  let bad = -1;
  for (let step = MIN_ARC_SEGMENTS; good < lastIndex; step *= 2) {
    const next = Math.min(lastIndex, good + step);
    const fit = fitRun(path, i, next, tol, samples);
    if (!fit) {
      bad = next;
      break;
    }
    good = next;
    arc = fit;
  }
  while (bad - good > 1) {
    const mid = (good + bad) >> 1;
    const fit = fitRun(path, i, mid, tol, samples);
    if (fit) {
      good = mid;
      arc = fit;
    } else bad = mid;
  }
  return { end: good, arc };
}

/** Fit arcs into one extrusion (in place). Returns how many segments arcs replaced. */
export function fitStepArcs(step: ExtrudeStep, toleranceMm: number): number {
  // a rising or falling path stays in straight segments
  if (step.arcs || step.z || step.points.length < MIN_ARC_SEGMENTS) return 0;
  const widths = step.widths;
  const n = step.points.length;
  const tol = toleranceMm * 1000;
  const path = step.closed ? [...step.points, step.points[0]!] : step.points;
  const kept: Pt[] = [path[0]!];
  const arcs: Array<PlanArc | undefined> = [undefined];
  let replaced = 0;
  const samples = new Float64Array(6 * path.length);
  const keptIndex: number[] = [0];
  for (let i = 0; i < path.length - 1; ) {
    const run = longestRun(
      path,
      i,
      widths ? sameWidthUntil(widths, n, i, path.length - 1) : path.length - 1,
      tol,
      samples,
    );
    if (run) {
      kept.push(path[run.end]!);
      keptIndex.push(run.end % n);
      arcs.push(run.arc);
      replaced += run.end - i;
      i = run.end;
    } else {
      kept.push(path[i + 1]!);
      keptIndex.push((i + 1) % n);
      arcs.push(undefined);
      i++;
    }
  }
  if (replaced === 0) return 0;
  // a closed step's last kept point is its first again: its segment is the closing one
  step.points = step.closed ? kept.slice(0, -1) : kept;
  if (widths) step.widths = Float64Array.from(step.closed ? keptIndex.slice(0, -1) : keptIndex, (k) => widths[k]!);
  step.arcs = arcs;
  return replaced;
}

/** Widths within this fraction of each other along a run count as one width (an arc keeps one). */
export const ARC_WIDTH_TOLERANCE = 0.01;

/** The last path index from `i` (at most `last`) up to which every width agrees with the width at `i`. */
function sameWidthUntil(widths: Float64Array, n: number, i: number, last: number): number {
  const w = widths[i % n]!;
  const tol = w * ARC_WIDTH_TOLERANCE;
  let j = i;
  while (j < last && Math.abs(widths[(j + 1) % n]! - w) <= tol) j++;
  return j;
}

/** Fit arcs into every extrusion of the plan. */
export function fitPlanArcs(plan: PrintPlan, toleranceMm: number): void {
  for (const layer of plan.layers) {
    for (const step of layer.steps) if (step.kind === 'extrude') fitStepArcs(step, toleranceMm);
  }
}
