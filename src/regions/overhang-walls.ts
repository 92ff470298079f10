/**
 * Extra walls on overhangs (extraPerimetersOnOverhangs, after PrusaSlicer's "extra perimeters on overhangs"):
 * where an island's inside (inside its walls) hangs over nothing and cannot bridge, because the layer below
 * holds it on one side only (a cantilever, the inside of a steep flaring wall), it is filled with lines
 * parallel to the island's walls instead of skin and infill. Each ring of lines runs from the part the layer
 * below holds (the anchor), over the overhang and back, and the rings are printed from the anchor outwards, so
 * every line is laid beside one already there instead of dangling from one end as a bridge line would.
 *
 * What is done: per piece of overhang (with a band of the anchor round it, up to 3 mm or a line more than the
 * walls), the bridge test (is the overhang mostly inside the convex hull of its anchors, held on more than
 * one side?); rings shrunk from the free edges towards the anchor, one line width apart, clipped to the piece,
 * until they no longer reach the overhang (and two more, over the anchor); what the rings cover is taken out of
 * the skin and infill; the strip the last ring leaves is gap-filled as between walls (gap loops, where
 * PrusaSlicer lays a medial-axis line). What is not: PrusaSlicer's span test of the bridge direction, and its
 * ordering of each line after the lines it touches (here a ring prints after the ring nearer the anchor, its
 * own lines nearest-first).
 */
import { area, clipLines, difference, intersection, offset, opening, union } from '../geometry/clip.js';
import { convexHull } from '../geometry/convex-hull.js';
import { hypot, UM_PER_MM, type ExPolygon, type Polyline, type Pt } from '../geometry/types.js';
import { gapLoops } from './gap-loops.js';
import type { ExtraWallRing } from './types.js';

/** The anchor band round an overhang reaches at most this far into the held part, µm (PrusaSlicer: 3 mm). */
const ANCHOR_MAX_UM = 3000;
/** An overhang whose share outside its anchors' convex hull is below this bridges (it is held round it). */
const BRIDGEABLE_SHARE = 0.2;
/** Rings made after the rings stop reaching the overhang (over the anchor, to hold the rest). */
const RINGS_PAST_OVERHANG = 2;
/** No piece gets more rings than this (a piece 8 cm across at 0.4 mm lines). */
const MAX_EXTRA_WALL_RINGS = 100;
/** Lines shorter than this many line widths are left out (specks between a ring's clipped pieces). */
const MIN_LINE_WIDTHS = 3;

export interface OverhangWalls {
  /** The rings' lines in print order (the ring nearest the anchor first). */
  rings: ExtraWallRing[];
  /** The area the rings fill: skin and infill stay out of it. */
  covered: ExPolygon[];
}

/**
 * The extra walls over the overhangs of an island's inside.
 * @param inner the area inside the island's walls, µm
 * @param below the section of the layer below, µm
 * @param walls the island's wall count (the anchor band is a line wider than they are)
 */
export function overhangWalls(
  inner: readonly ExPolygon[],
  below: readonly ExPolygon[],
  lineWidthUm: number,
  walls: number,
): OverhangWalls | null {
  const w = lineWidthUm;
  if (inner.length === 0 || below.length === 0) return null;
  // slivers thinner than half a line rest on the walls beside them
  const overhang = opening(difference(inner, below), w / 4);
  if (overhang.length === 0) return null;
  const anchors = intersection(inner, below);
  const band = Math.min(ANCHOR_MAX_UM, w * (walls + 1));
  // the held part beyond the band: what the rings are anchored in
  const held = difference(anchors, offset(overhang, band + 0.1 * w, 'square'));
  const rings: ExtraWallRing[] = [];
  const covered: ExPolygon[] = [];
  for (const piece of difference(inner, held)) {
    const own = intersection([piece], overhang);
    if (own.length === 0) continue;
    const anchoring = held.length ? intersection(offset([piece], 1.1 * w), held) : [];
    if (bridges(own, anchoring)) continue;
    const made = ringsOver(piece, own, anchoring, w);
    if (!made) continue;
    // printed from the anchor outwards: the rings were made from the free edges in
    for (let k = made.rings.length - 1; k >= 0; k--) rings.push(made.rings[k]);
    for (const c of made.covered) covered.push(c);
  }
  return rings.length ? { rings, covered } : null;
}

/** Whether an overhang is held round it, so that bridge lines from anchor to anchor suit it better. */
function bridges(overhang: readonly ExPolygon[], anchoring: readonly ExPolygon[]): boolean {
  if (anchoring.length === 0) return false;
  const hull = convexHull(anchoring.flatMap((a) => a.outer));
  if (hull.length < 3) return false;
  const outside = area(difference(overhang, [{ outer: hull, holes: [] }]));
  return outside < BRIDGEABLE_SHARE * area(overhang);
}

/**
 * Rings over one piece: each the outline of the piece (with its anchoring) shrunk from the free edges by
 * one more line, clipped to the piece, so that its lines end in the anchor; the strip the last one leaves
 * inside it filled as gaps are (gap-loops.ts). Null when no line is long enough.
 */
function ringsOver(
  piece: ExPolygon,
  overhang: readonly ExPolygon[],
  anchoring: readonly ExPolygon[],
  w: number,
): OverhangWalls | null {
  const reach = offset([piece], 1.1 * w);
  const clip = offset([piece], -0.1 * w);
  const minLength = MIN_LINE_WIDTHS * w;
  let ring = offset(anchoring.length ? union(offset([piece], 0.1 * w), anchoring) : [piece], -0.6 * w);
  const rings: ExtraWallRing[] = [];
  let past = RINGS_PAST_OVERHANG;
  for (let r = 0; r < MAX_EXTRA_WALL_RINGS && ring.length > 0; r++) {
    const lines = joinEnds(clipLines(closedLines(ring), clip), w / 10).filter((l) => lineLengthUm(l) >= minLength);
    // the next ring: one line further from the free edges, the anchoring side kept where it is
    const next = intersection(offset(anchoring.length ? union(ring, anchoring) : ring, -w), reach);
    if (next.length === 0) {
      // the last ring, where there is room for its line, and gap fill in the strip it leaves
      const room = lines.length > 0 && offset(ring, -0.3 * w).length > 0;
      if (room) rings.push({ paths: lines, widths: null });
      const gaps = gapLoops(intersection(room ? offset(ring, -w / 2) : ring, clip), w);
      if (gaps.length)
        rings.push({
          paths: gaps.map((g) => [...g.loop, g.loop[0]]),
          widths: gaps.map((g) => new Float64Array(g.loop.length + 1).fill(g.widthUm / UM_PER_MM)),
        });
      ring = next;
      break;
    }
    if (lines.length) rings.push({ paths: lines, widths: null });
    if (intersection(next, overhang).length === 0 && past-- <= 0) {
      ring = next;
      break;
    }
    if (sameAreas(next, ring)) break;
    ring = next;
  }
  if (rings.length === 0) return null;
  // the rings fill the piece but for what is left inside the last one
  const covered = ring.length ? difference([piece], offset(ring, w / 2)) : [piece];
  return { rings, covered };
}

/** Each ring of the areas as an open line round it (back to its first point). */
function closedLines(areas: readonly ExPolygon[]): Polyline[] {
  const out: Polyline[] = [];
  for (const a of areas) for (const ring of [a.outer, ...a.holes]) if (ring.length > 2) out.push([...ring, ring[0]]);
  return out;
}

function lineLengthUm(l: readonly Pt[]): number {
  let len = 0;
  for (let i = 1; i < l.length; i++) len += hypot(l[i].x - l[i - 1].x, l[i].y - l[i - 1].y);
  return len;
}

/** Lines that end where another starts (a ring clipped where it began) joined into one, within `tolUm`. */
function joinEnds(lines: Polyline[], tolUm: number): Polyline[] {
  const near = (a: Pt, b: Pt) => Math.abs(a.x - b.x) <= tolUm && Math.abs(a.y - b.y) <= tolUm;
  const out = lines.slice();
  for (let i = 0; i < out.length; i++) {
    for (let j = 0; j < out.length; j++) {
      if (i === j) continue;
      const a = out[i],
        b = out[j];
      if (near(a[a.length - 1], b[0])) {
        out[i] = a.concat(b.slice(1));
        out.splice(j, 1);
        if (j < i) i--;
        j = -1;
      }
    }
  }
  return out;
}

/** Two clipper results that are the same areas (the ring stopped shrinking). */
function sameAreas(a: readonly ExPolygon[], b: readonly ExPolygon[]): boolean {
  return a.length === b.length && Math.abs(area(a) - area(b)) < 1;
}
