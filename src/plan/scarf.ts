/**
 * Scarf joint seams. A wall loop, already turned to start at its seam, prints as three runs end to end:
 *
 * 1. the ramp: from the seam along the loop for the scarf's length, the nozzle rising from the start height
 *    (a fraction of the layer height above the layer below) to the layer's Z, the flow growing with the
 *    height under the nozzle (a fraction r of the layer height gets r of the bead);
 * 2. the rest of the loop, as it was, back to the seam;
 * 3. the ramp again at the layer's Z, the flow shrinking from what the ramp left unfilled to nothing: each
 *    point of the ramp gets one bead in all.
 *
 * So the seam is a long, shallow slope instead of a blob where the loop meets itself (OrcaSlicer's and
 * PrusaSlicer 2.9's scarf joint: Orca lays the flow this way; PrusaSlicer grows it with the distance
 * alone, the same when the ramp starts on the layer below). The Z and widths ride on the plan's per-point
 * channels (E follows the width), so nothing here knows about G-code.
 *
 * The ramp is cut into `steps` pieces of equal length (the loop's own corners within it are kept too), and
 * Z and flow are linear in the distance along it. The nozzle never comes closer than SCARF_CLEARANCE_MM to
 * the top of the layer below. A loop shorter than the ramp keeps its plain seam, and so does one whose seam
 * is in a sharp corner when the scarf is conditional (an aligned seam hides there already).
 */
import { hypot, UM_PER_MM, type Pt } from '../geometry/types.js';
import type { ScarfStyle } from '../paths/roles.js';

/** Closest the nozzle comes to the top of the layer below at the start of a ramp, mm. */
export const SCARF_CLEARANCE_MM = 0.02;
/**
 * A seam is in a sharp corner when the loop turns by this much or more, measured from a line width before it
 * to a line width after it, radians (the corners seam.ts's aligned seams look for).
 */
export const SCARF_SHARP_CORNER = (40 * Math.PI) / 180;
/** A cut of the ramp this close to a corner of the loop is that corner (no sliver of a move), µm. */
const RAMP_CUT_AT_CORNER_UM = 20;

/** A loop as the planner holds it, turned to start at its seam. */
export interface ScarfLoop {
  points: Pt[];
  /** Bead width, mm, where `widths` is null. */
  width: number;
  widths: Float64Array | null;
  z: Float64Array | null;
  /** One flag per edge (the last edge closes the loop), or null. */
  flags: Uint8Array | null;
}

/** One of the three open runs a scarfed loop prints as. */
export interface ScarfRun {
  points: Pt[];
  closed: false;
  width: number;
  widths: Float64Array | null;
  z: Float64Array | null;
  flags: Uint8Array | null;
}

/**
 * The loop as a ramp, the rest of the loop and the ramp again (see above), or null when it keeps a plain
 * seam: too short, in a sharp corner (conditional), already with a Z of its own, or a layer too thin to ramp.
 * @param layerHeight the layer's thickness, mm
 */
export function scarfRuns(loop: ScarfLoop, scarf: ScarfStyle, layerHeight: number): ScarfRun[] | null {
  const pts = loop.points;
  const n = pts.length;
  if (n < 3 || loop.z) return null;
  const start = Math.max(scarf.startHeight, SCARF_CLEARANCE_MM / layerHeight);
  if (!(start < 1)) return null;
  const edges = new Float64Array(n);
  let total = 0;
  for (let k = 0; k < n; k++) {
    const a = pts[k],
      b = pts[k + 1 === n ? 0 : k + 1];
    total += edges[k] = hypot(b.x - a.x, b.y - a.y);
  }
  const length = scarf.length * UM_PER_MM;
  if (total < length || length <= 0) return null;
  if (scarf.conditional && turnAtStart(pts, edges, loop.width * UM_PER_MM) >= SCARF_SHARP_CORNER) return null;

  const widthAt = (k: number) => (loop.widths ? loop.widths[k] : loop.width);
  // the ramp's points: the seam, each cut and each corner of the loop up to the last cut
  const ramp: Pt[] = [pts[0]];
  const dist: number[] = [0];
  const width: number[] = [widthAt(0)];
  /** Per ramp segment, the loop's edge it lies on. */
  const onEdge: number[] = [];
  const steps = Math.max(1, Math.round(scarf.steps));
  let cut = 1;
  const cutAt = (i: number) => (i === steps ? length : (length * i) / steps);
  let k = 0;
  let along = 0;
  /** Where the ramp ends: inside edge `k` (at the last ramp point), or on the loop's corner `endCorner`. */
  let endCorner = -1;
  for (;;) {
    const a = pts[k],
      b = pts[k + 1 === n ? 0 : k + 1];
    const end = along + edges[k];
    while (cut <= steps && cutAt(cut) < end - RAMP_CUT_AT_CORNER_UM) {
      const t = (cutAt(cut) - along) / edges[k];
      ramp.push({ x: Math.round(a.x + t * (b.x - a.x)), y: Math.round(a.y + t * (b.y - a.y)) });
      dist.push(cutAt(cut));
      width.push(widthAt(k) + t * (widthAt(k + 1 === n ? 0 : k + 1) - widthAt(k)));
      onEdge.push(k);
      cut++;
    }
    if (cut > steps) break;
    // the corner at the edge's end, which is the next cut when it lies on it
    ramp.push(b);
    const onCut = cutAt(cut) <= end + RAMP_CUT_AT_CORNER_UM;
    dist.push(onCut ? cutAt(cut) : end);
    width.push(widthAt(k + 1 === n ? 0 : k + 1));
    onEdge.push(k);
    if (onCut) cut++;
    if (cut > steps) {
      endCorner = k + 1 === n ? 0 : k + 1;
      break;
    }
    along = end;
    k++;
  }

  const r = ramp.length;
  const rampZ = new Float64Array(r);
  const rampWidths = new Float64Array(r);
  const wipeWidths = new Float64Array(r);
  for (let j = 0; j < r; j++) {
    // the share of the layer height under the nozzle on the ramp
    const share = j === r - 1 ? 1 : start + ((1 - start) * dist[j]) / length;
    rampZ[j] = j === r - 1 ? 0 : -(1 - share) * layerHeight;
    rampWidths[j] = width[j] * share;
    wipeWidths[j] = width[j] * (1 - share);
  }
  let rampFlags: Uint8Array | null = null;
  if (loop.flags) {
    rampFlags = new Uint8Array(r - 1);
    for (let j = 0; j + 1 < r; j++) rampFlags[j] = loop.flags[onEdge[j]];
  }
  const runs: ScarfRun[] = [
    { points: ramp, closed: false, width: loop.width, widths: rampWidths, z: rampZ, flags: rampFlags },
  ];

  // the rest of the loop, from the ramp's end back to the seam
  if (endCorner !== 0) {
    const first = endCorner > 0 ? endCorner : k + 1; // the first corner after the ramp's end
    const rest: Pt[] = endCorner > 0 ? [] : [ramp[r - 1]];
    const restWidths: number[] = endCorner > 0 ? [] : [width[r - 1]];
    const restFlags: number[] = endCorner > 0 ? [] : [loop.flags ? loop.flags[k] : 0];
    for (let i = first; i < n; i++) {
      rest.push(pts[i]);
      restWidths.push(widthAt(i));
      restFlags.push(loop.flags ? loop.flags[i] : 0);
    }
    rest.push(pts[0]);
    restWidths.push(widthAt(0));
    runs.push({
      points: rest,
      closed: false,
      width: loop.width,
      widths: loop.widths ? Float64Array.from(restWidths) : null,
      z: null,
      flags: loop.flags ? Uint8Array.from(restFlags) : null,
    });
  }

  // over the ramp again, at the layer's Z
  runs.push({ points: ramp, closed: false, width: loop.width, widths: wipeWidths, z: null, flags: rampFlags });
  return runs;
}

/**
 * How far the loop turns at its first point, radians: between the direction from a point `arm` µm before it
 * (along the loop) and the direction to a point `arm` after it.
 */
export function turnAtStart(pts: readonly Pt[], edges: Float64Array, arm: number): number {
  const n = pts.length;
  let total = 0;
  for (let k = 0; k < n; k++) total += edges[k];
  const reach = Math.min(arm, total / 3);
  const after = pointAlong(pts, edges, reach, 1);
  const before = pointAlong(pts, edges, reach, -1);
  const p = pts[0];
  const ux = p.x - before.x,
    uy = p.y - before.y,
    vx = after.x - p.x,
    vy = after.y - p.y;
  return Math.abs(Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy));
}

/** The point `d` µm from the loop's first point, forwards (dir 1) or backwards (dir -1), not rounded. */
function pointAlong(pts: readonly Pt[], edges: Float64Array, d: number, dir: 1 | -1): { x: number; y: number } {
  const n = pts.length;
  let left = d;
  let i = 0;
  for (let count = 0; count < n; count++) {
    const j = dir === 1 ? (i + 1) % n : (i - 1 + n) % n;
    const len = edges[dir === 1 ? i : j];
    if (len >= left && len > 0) {
      const t = left / len;
      return { x: pts[i].x + t * (pts[j].x - pts[i].x), y: pts[i].y + t * (pts[j].y - pts[i].y) };
    }
    left -= len;
    i = j;
  }
  return pts[i];
}
