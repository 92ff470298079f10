/**
 * Shortening a tour found nearest-first (nearest.ts): 2-opt (a stretch of the tour printed the other way round,
 * each line in it reversed) and or-opt (one to three paths moved elsewhere in the tour, either way round),
 * repeated while a move shortens the travel. Each stop of the tour is entered at one point and left at another (a
 * line's two ends; a loop's entry twice) and may be printed backwards (entered where it was left). The travel
 * counted runs from the start point through every stop and, when one is given, on to the end point (where the
 * nozzle goes next), so the tour also ends near where it is followed. Long tours are shortened a window at a time,
 * so the work grows with the number of stops times the window, not its square.
 */
import type { Pt } from '../geometry/types.js';

/** A stop of the tour as it is printed: entered at `in`, left at `out`. */
export interface TourStop {
  in: Pt;
  out: Pt;
}

/** Stops shortened together (a longer tour is shortened a window at a time, windows overlapping by half). */
const WINDOW = 96;
/** Passes over a window at most (each looks at every move once; most windows settle in two or three). */
const MAX_PASSES = 6;
/** A move is made when it shortens the travel by more than this, µm (no churning on rounding). */
const GAIN = 1;
/** Longest run of stops or-opt moves. */
const MAX_MOVE = 3;
/**
 * Or-opt passes over a place only when the axis steps of its legs exceed what the move may cost by this, µm: far
 * more than the rounding of the distances it bounds (whole-µm points, sums of a few square roots), so the places
 * passed over are exactly those the full test would refuse.
 */
const PRUNE_MARGIN_UM = 1e-3;

/**
 * A shorter order of `stops` (given in print order, from `from`, then on to `to` when given): the stops'
 * indices in the new order, and for each of them whether it is printed backwards (entered at its `out`).
 */
export function shortenTour(
  stops: readonly TourStop[],
  from: Pt,
  to: Pt | null,
): { order: Int32Array; reversed: Uint8Array } {
  const n = stops.length;
  const order = new Int32Array(n);
  for (let k = 0; k < n; k++) order[k] = k;
  const reversed = new Uint8Array(n);
  if (n < 2 && !to) return { order, reversed };
  // entry and exit points by position, kept in step with `order`
  const t: Tour = {
    ix: new Float64Array(n),
    iy: new Float64Array(n),
    ox: new Float64Array(n),
    oy: new Float64Array(n),
    order,
    reversed,
  };
  for (let k = 0; k < n; k++) {
    t.ix[k] = stops[k].in.x;
    t.iy[k] = stops[k].in.y;
    t.ox[k] = stops[k].out.x;
    t.oy[k] = stops[k].out.y;
  }
  if (n <= WINDOW) {
    shortenWindow(t, 0, n, from, to);
    return { order, reversed };
  }
  for (let lo = 0; lo < n; lo += WINDOW / 2) {
    const hi = Math.min(n, lo + WINDOW);
    const a = lo === 0 ? from : { x: t.ox[lo - 1], y: t.oy[lo - 1] };
    const b = hi === n ? to : { x: t.ix[hi], y: t.iy[hi] };
    shortenWindow(t, lo, hi, a, b);
    if (hi === n) break;
  }
  return { order, reversed };
}

interface Tour {
  ix: Float64Array;
  iy: Float64Array;
  ox: Float64Array;
  oy: Float64Array;
  order: Int32Array;
  reversed: Uint8Array;
}

function dist(ax: number, ay: number, bx: number, by: number): number {
  const dx = ax - bx,
    dy = ay - by;
  return Math.sqrt(dx * dx + dy * dy);
}

/**
 * The travel into each position lo … hi of a window (`gap[k - lo]`; into position hi: on to the end point, 0 when
 * there is none), kept in step with the window's order by `refresh` as stretches of it change.
 */
class Gaps {
  readonly gap: Float64Array;
  constructor(
    private readonly t: Tour,
    private readonly lo: number,
    private readonly hi: number,
    private readonly from: Pt,
    private readonly to: Pt | null,
  ) {
    this.gap = new Float64Array(hi - lo + 1);
    this.refresh(lo, hi);
  }

  /** The travel into positions a … b again (lo ≤ a ≤ b ≤ hi). */
  refresh(a: number, b: number): void {
    const { ox, oy } = this.t;
    const { lo, from, gap } = this;
    for (let k = a; k <= b; k++) {
      gap[k - lo] = k === lo ? this.into(from.x, from.y, k) : this.into(ox[k - 1], oy[k - 1], k);
    }
  }

  /** The travel from (x, y) into position k (lo ≤ k ≤ hi; into hi: on to the end point, 0 when there is none). */
  into(x: number, y: number, k: number): number {
    if (k === this.hi) return this.to === null ? 0 : dist(x, y, this.to.x, this.to.y);
    return dist(x, y, this.t.ix[k], this.t.iy[k]);
  }
}

/** Positions lo … hi - 1 of the tour, between the fixed points `from` and `to` (none: the tour ends there). */
function shortenWindow(t: Tour, lo: number, hi: number, from: Pt, to: Pt | null): void {
  const { ix, iy, ox, oy } = t;
  const fx = from.x,
    fy = from.y;
  const open = to === null;
  const tx = to?.x ?? 0,
    ty = to?.y ?? 0;
  const gaps = new Gaps(t, lo, hi, from, to);
  const gap = gaps.gap;
  for (let pass = 0; pass < MAX_PASSES; pass++) {
    let improved = false;
    // 2-opt: positions i … j the other way round
    for (let i = lo; i < hi; i++) {
      const px = i === lo ? fx : ox[i - 1],
        py = i === lo ? fy : oy[i - 1];
      for (let j = i; j < hi; j++) {
        const before = gap[i - lo] + gap[j + 1 - lo];
        // the exit before i into j's exit (now the stretch's entry), and i's entry (now its exit) on into j + 1
        const after = dist(px, py, ox[j], oy[j]) + gaps.into(ix[i], iy[i], j + 1);
        if (after < before - GAIN) {
          reverse(t, i, j);
          gaps.refresh(i, j + 1);
          improved = true;
        }
      }
    }
    // or-opt: a run of 1 … MAX_MOVE stops moved between two others, either way round
    for (let len = 1; len <= MAX_MOVE; len++) {
      for (let s = lo; s + len <= hi; s++) {
        const e = s + len - 1;
        const sx = s === lo ? fx : ox[s - 1],
          sy = s === lo ? fy : oy[s - 1];
        // travel saved by taking the run out
        const gain = gap[s - lo] + gap[e + 1 - lo] - gaps.into(sx, sy, e + 1);
        if (gain <= GAIN) continue;
        const inX = ix[s],
          inY = iy[s],
          outX = ox[e],
          outY = oy[e];
        let best = 0,
          bestAt = -1,
          bestBack = false;
        for (let p = lo; p <= hi; p++) {
          if (p >= s && p <= e + 1) continue;
          // inserted before position p: from the exit before p, into p
          const qx = p === lo ? fx : ox[p - 1],
            qy = p === lo ? fy : oy[p - 1];
          const g = gap[p - lo];
          // a move is worth it only when its cost is under gain - best - GAIN; no leg is shorter than its longer
          // axis step, so a place both ways of which cost more than that even so is passed over (a margin keeps
          // rounding from passing over one the exact test would take)
          const limit = gain - best - GAIN + PRUNE_MARGIN_UM + g;
          const endX = p === hi ? tx : ix[p],
            endY = p === hi ? ty : iy[p];
          const last = p === hi && open;
          if (
            axisStep(qx, qy, inX, inY) + (last ? 0 : axisStep(outX, outY, endX, endY)) > limit &&
            axisStep(qx, qy, outX, outY) + (last ? 0 : axisStep(inX, inY, endX, endY)) > limit
          )
            continue;
          const fwd = dist(qx, qy, inX, inY) + (last ? 0 : dist(outX, outY, endX, endY)) - g;
          const back = dist(qx, qy, outX, outY) + (last ? 0 : dist(inX, inY, endX, endY)) - g;
          const cost = Math.min(fwd, back);
          if (gain - cost > best + GAIN) {
            best = gain - cost;
            bestAt = p;
            bestBack = back < fwd;
          }
        }
        if (bestAt >= 0) {
          moveRun(t, s, e, bestAt, bestBack);
          gaps.refresh(lo, hi);
          improved = true;
        }
      }
    }
    if (!improved) break;
  }
}

/** The larger of the two axis steps from (ax, ay) to (bx, by): never more than their distance. */
function axisStep(ax: number, ay: number, bx: number, by: number): number {
  const dx = Math.abs(ax - bx),
    dy = Math.abs(ay - by);
  return dx > dy ? dx : dy;
}

/** Positions i … j in reverse order, each stop printed the other way round. */
function reverse(t: Tour, i: number, j: number): void {
  const { ix, iy, ox, oy, order, reversed } = t;
  for (let a = i, b = j; a <= b; a++, b--) {
    const aix = ix[a],
      aiy = iy[a],
      aox = ox[a],
      aoy = oy[a],
      ao = order[a],
      ar = reversed[a];
    // a takes b's place turned round, and b a's
    ix[a] = ox[b];
    iy[a] = oy[b];
    ox[a] = ix[b];
    oy[a] = iy[b];
    order[a] = order[b];
    reversed[a] = reversed[b] ^ 1;
    ix[b] = aox;
    iy[b] = aoy;
    ox[b] = aix;
    oy[b] = aiy;
    order[b] = ao;
    reversed[b] = ar ^ 1;
  }
}

/** The run at positions s … e moved to before position p (outside it), turned round when `back`. */
function moveRun(t: Tour, s: number, e: number, p: number, back: boolean): void {
  if (back) reverse(t, s, e);
  // the stretch between the run and p turned round so that the run lands before p
  if (p > e) rotate(t, s, p - 1, e - s + 1);
  else rotate(t, p, e, s - p);
}

/** Positions a … b rotated left by k (the stop at a + k comes first). */
function rotate(t: Tour, a: number, b: number, k: number): void {
  const n = b - a + 1;
  k %= n;
  if (k === 0) return;
  for (const arr of [t.ix, t.iy, t.ox, t.oy, t.order, t.reversed]) {
    const copy = arr.slice(a, b + 1);
    for (let q = 0; q < n; q++) arr[a + q] = copy[(q + k) % n];
  }
}
