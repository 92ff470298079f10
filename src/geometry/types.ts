/**
 * Plain-data 2D geometry. Every polygon that goes through clipping is in integer
 * micrometres (µm); a `Pt` is a plain object so it crosses worker boundaries without a codec.
 */

/** Micrometres per millimetre: the one integer scale used for all clipping. */
export const UM_PER_MM = 1000;

/** A point in integer micrometres. */
export interface Pt {
  x: number;
  y: number;
}

/** A closed ring (last point not repeated). Outer rings counter-clockwise, holes clockwise. */
export type Polygon = Pt[];

/** An open path (polyline). */
export type Polyline = Pt[];

/** One connected area: an outer ring and the holes inside it. */
export interface ExPolygon {
  outer: Polygon;
  holes: Polygon[];
}

/** Axis-aligned bounds in µm. */
export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/**
 * Length of the vector (dx, dy). Math.hypot guards against overflow no coordinate here comes near, and
 * V8 does not inline it: every call boxes its result, and in the planner's and the tree support's loops
 * that garbage was megabytes a slice.
 */
export function hypot(dx: number, dy: number): number {
  return Math.sqrt(dx * dx + dy * dy);
}

/** Squared distance from (px, py) to the segment (ax, ay)–(bx, by). */
export function segmentDistance2(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax,
    dy = by - ay;
  const len2 = dx * dx + dy * dy;
  let t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const ex = ax + t * dx - px,
    ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}

/** Convert millimetres to integer micrometres. */
export function mmToUm(mm: number): number {
  return Math.round(mm * UM_PER_MM);
}

/** Convert micrometres to millimetres. */
export function umToMm(um: number): number {
  return um / UM_PER_MM;
}
